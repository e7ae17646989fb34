//! Snapshot tests: tiny fixed renders whose summaries are compared with the stored ones.
//!
//! The summary is an 8-level luminance picture (catches moved or missing geometry, shadows,
//! reflections) plus the image's mean colour to four decimals and the ray count (catch shading
//! and recursion changes). Whitted's tracer is deterministic, so the summary is exact.

use ch01_whitted::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch01_whitted::{PixelPattern, render};
use common::image::Image;
use common::render::RenderSettings;

/// Characters from dark to bright.
const RAMP: &[u8] = b" .:-=+*#%@";

fn summary(image: &Image, rays: u64) -> String {
    let mut text = String::new();
    for y in 0..image.height {
        for x in 0..image.width {
            let p = image.get(x, y);
            let luminance = 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
            // Quantise the sRGB-like value so that tiny float changes do not flip characters
            // unless they cross a level.
            let level = (luminance.clamp(0.0, 1.0).powf(1.0 / 2.2) * (RAMP.len() - 1) as f32)
                .round() as usize;
            text.push(RAMP[level] as char);
        }
        text.push('\n');
    }
    let n = image.pixels.len() as f64;
    let mean = image.pixels.iter().fold([0.0f64; 3], |acc, p| {
        [
            acc[0] + f64::from(p.x) / n,
            acc[1] + f64::from(p.y) / n,
            acc[2] + f64::from(p.z) / n,
        ]
    });
    text.push_str(&format!(
        "mean rgb: {:.4} {:.4} {:.4}\nrays: {rays}\n",
        mean[0], mean[1], mean[2]
    ));
    text
}

fn snapshot_of(builtin: Builtin, pattern: PixelPattern, spp: u64) -> String {
    let scene = builtin.build(DEFAULT_MAX_DEPTH);
    let settings = RenderSettings::new(48, 32, spp);
    let out = render(&scene, &settings, pattern, 0).expect("a valid pattern");
    assert_eq!(out.stats.nonfinite_samples, 0);
    summary(&out.image, out.stats.rays)
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
