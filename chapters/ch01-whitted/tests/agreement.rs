//! Agreement with Mitsuba 3's stored renders of the chapter's scenes (see
//! `ch01_whitted::agreement`): our render at the same sample count must be as unbiased as
//! Mitsuba's own second render against Mitsuba's reference, and no noisier.

use ch01_whitted::agreement::{AGREEMENT_SCENES, mitsuba_dir, render_agreement_scene};
use common::metrics::ReferenceRenders;

#[test]
fn whitted_renders_agree_with_the_stored_mitsuba_renders() {
    for (name, checks) in AGREEMENT_SCENES {
        let renders = ReferenceRenders::load(&mitsuba_dir(), name).unwrap();
        let ours = render_agreement_scene(name).unwrap();
        let agreement = renders.agreement(&ours);
        assert!(
            agreement.unbiased(0.005),
            "{name} ({checks}) looks biased: {agreement:?}"
        );
        assert!(
            agreement.noise_no_worse(1.05),
            "{name} ({checks}) is noisier than Mitsuba: {agreement:?}"
        );
    }
}
