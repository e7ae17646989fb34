//! Snapshot tests: tiny fixed renders whose summaries are compared with the stored ones.
//!
//! The summary is a 10-level luminance picture (`common::test_support::image_summary`) (catches moved or missing geometry, shadows,
//! reflections) plus the image's mean colour to four decimals and the ray count (catch shading
//! and recursion changes). Whitted's tracer is deterministic, so the summary is exact.

use ch01_whitted::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch01_whitted::{PixelPattern, render};
use common::render::RenderSettings;
use common::test_support::image_summary;

fn snapshot_of(builtin: Builtin, pattern: PixelPattern, spp: u64) -> String {
    let scene = builtin.build(DEFAULT_MAX_DEPTH);
    let settings = RenderSettings::new(48, 32, spp);
    let out = render(&scene, &settings, pattern, 0).expect("a valid pattern");
    assert_eq!(out.stats.nonfinite_samples, 0);
    image_summary(&out.image, out.stats.rays)
}

#[test]
fn spheres_one_ray_per_pixel() {
    insta::assert_snapshot!(snapshot_of(Builtin::Spheres, PixelPattern::Centre, 1));
}

#[test]
fn spheres_grid_supersampled() {
    insta::assert_snapshot!(snapshot_of(Builtin::Spheres, PixelPattern::Grid, 4));
}

#[test]
fn cornell_one_ray_per_pixel() {
    insta::assert_snapshot!(snapshot_of(Builtin::Cornell, PixelPattern::Centre, 1));
}
