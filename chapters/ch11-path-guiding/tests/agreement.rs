//! Agreement with Mitsuba 3's stored renders of the crate's scenes (see
//! `ch11_path_guiding::lab::agreement`): our guided render at the same sample count (its training included) must
//! be as unbiased as Mitsuba's own second render against Mitsuba's reference, and no noisier.

use ch11_path_guiding::lab::agreement::{
    AGREEMENT, HEAVY_TAILED, HEAVY_TAILED_REFERENCE_SPP, HEAVY_TAILED_SPP,
};

#[test]
fn renders_agree_with_the_stored_mitsuba_renders() {
    AGREEMENT.check_stored().unwrap();
}

#[test]
fn heavy_tailed_scenes_agree_at_their_own_sample_count() {
    for scene in HEAVY_TAILED.scenes {
        let (_, renders, _) = HEAVY_TAILED.stored(scene).unwrap();
        assert_eq!(
            (renders.provenance.spp, renders.provenance.reference_spp),
            (HEAVY_TAILED_SPP, HEAVY_TAILED_REFERENCE_SPP),
            "{}: Mitsuba's renders were made with other counts",
            scene.name
        );
    }
    HEAVY_TAILED.check_stored().unwrap();
}
