//! Agreement with Mitsuba 3's stored renders of the chapter's scenes (see
//! `ch06_fuzzy_reflections::lab::agreement`): our render at the same sample count must be as
//! unbiased as Mitsuba's own second render against Mitsuba's reference, and no noisier. Every
//! way of choosing the ray at glass is held to the first; the second only to the choice
//! Mitsuba makes itself (by the Fresnel term): the other two are noisier by design.

use ch06_fuzzy_reflections::GlassStrategy;
use ch06_fuzzy_reflections::lab::agreement::{AGREEMENT, render_scene_file_with};
use workbench::agreement::{BIAS_SLACK, ReferenceRenders};

#[test]
fn renders_agree_with_the_stored_mitsuba_renders() {
    AGREEMENT.check_stored().unwrap();
}

#[test]
fn every_choice_at_glass_is_unbiased_against_mitsuba() {
    for scene in AGREEMENT.scenes {
        let renders = ReferenceRenders::load(&AGREEMENT.stored_renders_dir(), scene.name)
            .expect("the stored renders");
        for glass in GlassStrategy::ALL {
            let ours = render_scene_file_with(&AGREEMENT.file(scene), glass).unwrap();
            let agreement = renders.agreement(&ours);
            assert!(
                agreement.unbiased(BIAS_SLACK),
                "{} with {glass:?}: {agreement:?}",
                scene.name
            );
        }
    }
}
