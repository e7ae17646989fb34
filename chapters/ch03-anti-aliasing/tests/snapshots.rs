//! Snapshot tests: tiny fixed renders whose summaries are compared with the stored ones.
//!
//! The same summary as chapter 01's: an 8-level luminance picture (catches moved or missing
//! geometry and lost texture) plus the mean colour to four decimals and the ray count (catch
//! shading, filter and sampler changes). Every render is deterministic for its seed.

use ch03_anti_aliasing::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch03_anti_aliasing::{
    FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter, render_with,
};
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

fn snapshot_of(
    builtin: Builtin,
    sampler: PixelSamplerKind,
    filter: FilterKind,
    spp: u64,
) -> String {
    let scene = builtin.build(DEFAULT_MAX_DEPTH);
    let settings = RenderSettings::new(48, 32, spp);
    let sampler = PixelSampler::new(sampler, spp, 0).unwrap();
    let filter = ReconstructionFilter::new(filter, None).unwrap();
    let out = render_with(&scene, &settings, &sampler, &filter);
    assert_eq!(out.stats.nonfinite_samples, 0);
    summary(&out.image, out.stats.rays)
}

#[test]
fn edges_one_sample_at_the_centre() {
    insta::assert_snapshot!(snapshot_of(
        Builtin::Edges,
        PixelSamplerKind::Centre,
        FilterKind::Box,
        1
    ));
}

#[test]
fn edges_stratified_box() {
    insta::assert_snapshot!(snapshot_of(
        Builtin::Edges,
        PixelSamplerKind::Stratified,
        FilterKind::Box,
        4
    ));
}

#[test]
fn checkerboard_random_tent() {
    insta::assert_snapshot!(snapshot_of(
        Builtin::Checkerboard,
        PixelSamplerKind::Random,
        FilterKind::Tent,
        4
    ));
}

#[test]
fn checkerboard_halton_mitchell() {
    insta::assert_snapshot!(snapshot_of(
        Builtin::Checkerboard,
        PixelSamplerKind::Halton,
        FilterKind::Mitchell,
        4
    ));
}

#[test]
fn checkerboard_stratified_gaussian() {
    insta::assert_snapshot!(snapshot_of(
        Builtin::Checkerboard,
        PixelSamplerKind::Stratified,
        FilterKind::Gaussian,
        4
    ));
}
