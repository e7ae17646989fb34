//! Snapshot tests: tiny fixed renders whose summaries are compared with the stored ones.
//!
//! The summary (`workbench::test_support::image_summary`) is a 10-level luminance picture plus
//! the mean colour and the ray count: it catches a moving object in the wrong place, a blur
//! that is missing or too long, a camera that moves the wrong way. Seeds are fixed; the
//! summary is compared up to floating-point noise (`workbench::assert_close_snapshot!`).

use ch04_depth_of_field::Lens;
use ch05_motion_blur::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch05_motion_blur::{Shutter, StratifiedTime, render_with};
use common::film::PixelBoxFilter;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use workbench::test_support::image_summary;

fn snapshot_of(builtin: Builtin, open: f32, close: f32) -> String {
    let world = builtin.build(DEFAULT_MAX_DEPTH, Shutter::new(open, close).unwrap());
    let spp = 16;
    let settings = RenderSettings::new(48, 30, spp);
    let sampler = StratifiedTime::new(IndependentSampler::new(0), spp, 0);
    let out = render_with(&world, &Lens::PINHOLE, &settings, &sampler, &PixelBoxFilter);
    assert_eq!(out.stats.nonfinite_samples, 0);
    image_summary(&out.image, out.stats.rays)
}

#[test]
fn street_still_at_the_start() {
    workbench::assert_close_snapshot!(
        "street_still_at_the_start",
        snapshot_of(Builtin::Street, 0.0, 0.0)
    );
}

#[test]
fn street_blurred_over_the_whole_motion() {
    workbench::assert_close_snapshot!(
        "street_blurred_over_the_whole_motion",
        snapshot_of(Builtin::Street, 0.0, 1.0)
    );
}

#[test]
fn street_blurred_over_a_short_shutter() {
    workbench::assert_close_snapshot!(
        "street_blurred_over_a_short_shutter",
        snapshot_of(Builtin::Street, 0.45, 0.55)
    );
}

#[test]
fn spinner_past_a_full_turn() {
    workbench::assert_close_snapshot!(
        "spinner_past_a_full_turn",
        snapshot_of(Builtin::Spinner, 0.0, 1.0)
    );
}

#[test]
fn pan_with_a_moving_camera() {
    workbench::assert_close_snapshot!(
        "pan_with_a_moving_camera",
        snapshot_of(Builtin::Pan, 0.0, 1.0)
    );
}
