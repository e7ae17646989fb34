//! Agreement with Mitsuba 3's stored renders of the chapter's scenes (see
//! `ch07_soft_shadows::lab::agreement`): our render at the same sample count must be as unbiased as
//! Mitsuba's own second render against Mitsuba's reference, and no noisier.

use ch07_soft_shadows::lab::agreement::AGREEMENT;

#[test]
fn renders_agree_with_the_stored_mitsuba_renders() {
    AGREEMENT.check_stored().unwrap();
}
