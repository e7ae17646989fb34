//! Agreement with Mitsuba 3's stored renders of the crate's scenes (see
//! `ch10_optimal_mis::lab::agreement`): our optimal combination at the same sample count must
//! be as unbiased as Mitsuba's own second render against Mitsuba's reference, and no noisier.

use ch10_optimal_mis::lab::agreement::AGREEMENT;

#[test]
fn renders_agree_with_the_stored_mitsuba_renders() {
    AGREEMENT.check_stored().unwrap();
}
