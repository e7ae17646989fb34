//! Snapshot tests: tiny fixed renders whose summaries are compared with the stored ones.
//!
//! The summary is a 10-level luminance picture (`workbench::test_support::image_summary`) (catches moved or missing geometry, shadows,
//! reflections) plus the image's mean colour to four decimals and the ray count (catch shading
//! and recursion changes). Whitted's tracer is deterministic; the
//! summaries are compared up to floating-point noise (`workbench::assert_close_snapshot!`), so a
//! student's correct answer written differently still passes.

use ch01_whitted::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch01_whitted::{PixelPattern, render};
use common::render::RenderSettings;
use workbench::test_support::image_summary;

fn snapshot_of(builtin: Builtin, pattern: PixelPattern, spp: u64) -> String {
    let scene = builtin.build(DEFAULT_MAX_DEPTH);
    let settings = RenderSettings::new(48, 32, spp);
    let out = render(&scene, &settings, pattern, 0).expect("a valid pattern");
    assert_eq!(out.stats.nonfinite_samples, 0);
    image_summary(&out.image, out.stats.rays)
}

#[test]
fn spheres_one_ray_per_pixel() {
    workbench::assert_close_snapshot!(
        "spheres_one_ray_per_pixel",
        snapshot_of(Builtin::Spheres, PixelPattern::Centre, 1)
    );
}

#[test]
fn spheres_grid_supersampled() {
    workbench::assert_close_snapshot!(
        "spheres_grid_supersampled",
        snapshot_of(Builtin::Spheres, PixelPattern::Grid, 4)
    );
}

#[test]
fn cornell_one_ray_per_pixel() {
    workbench::assert_close_snapshot!(
        "cornell_one_ray_per_pixel",
        snapshot_of(Builtin::Cornell, PixelPattern::Centre, 1)
    );
}
