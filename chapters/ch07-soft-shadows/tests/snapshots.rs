//! Snapshot tests: tiny fixed renders of the built-in scenes whose summaries are compared with
//! the stored ones.
//!
//! The summary (`workbench::test_support::image_summary`) is a 10-level luminance picture plus
//! the mean colour and the ray count: it catches a shadow in the wrong place, a light that is
//! missing or black, a penumbra that hardened. Seeds are fixed; the summary
//! is compared up to floating-point noise (`workbench::assert_close_snapshot!`).

mod support;

use ch07_soft_shadows::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch07_soft_shadows::{DiscWarp, LightOptions};
use workbench::test_support::image_summary;

fn snapshot_of(builtin: Builtin, options: LightOptions) -> String {
    let scene = builtin.build(DEFAULT_MAX_DEPTH, 1.0);
    let out = support::render(&scene, options, 48, 36, 8, 0);
    support::assert_finite(&out, builtin.name());
    image_summary(&out.image, out.stats.rays)
}

#[test]
fn small_light_hard_shadows() {
    workbench::assert_close_snapshot!(
        "small_light_hard_shadows",
        snapshot_of(Builtin::Small, LightOptions::with_samples(4))
    );
}

#[test]
fn large_light_soft_shadows() {
    workbench::assert_close_snapshot!(
        "large_light_soft_shadows",
        snapshot_of(Builtin::Large, LightOptions::with_samples(4))
    );
}

#[test]
fn one_light_of_each_shape() {
    workbench::assert_close_snapshot!(
        "one_light_of_each_shape",
        snapshot_of(Builtin::Shapes, LightOptions::default())
    );
}

#[test]
fn several_coloured_lights() {
    workbench::assert_close_snapshot!(
        "several_coloured_lights",
        snapshot_of(Builtin::Several, LightOptions::with_samples(2))
    );
}

#[test]
fn several_coloured_lights_with_the_naive_disc() {
    workbench::assert_close_snapshot!(
        "several_coloured_lights_with_the_naive_disc",
        snapshot_of(
            Builtin::Several,
            LightOptions::with_samples(2).with_disc_warp(DiscWarp::Naive)
        )
    );
}

#[test]
fn a_glossy_floor_reflecting_the_lights() {
    workbench::assert_close_snapshot!(
        "a_glossy_floor_reflecting_the_lights",
        snapshot_of(Builtin::Glossy, LightOptions::default())
    );
}
