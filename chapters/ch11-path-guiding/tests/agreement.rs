//! Agreement with Mitsuba 3's stored renders of the crate's scenes (see
//! `ch11_path_guiding::lab::agreement`): our guided render at the same sample count (its training included) must
//! be as unbiased as Mitsuba's own second render against Mitsuba's reference, and no noisier.

use ch11_path_guiding::lab::agreement::AGREEMENT;

#[test]
fn renders_agree_with_the_stored_mitsuba_renders() {
    AGREEMENT.check_stored().unwrap();
}
