//! Snapshot tests: tiny fixed renders whose summaries are compared with the stored ones.
//!
//! The same summary as chapter 01's: a 10-level luminance picture (`workbench::test_support::image_summary`) (catches moved or missing
//! geometry and lost texture) plus the mean colour to four decimals and the ray count (catch
//! shading, filter and sampler changes). Every render is deterministic for its seed.

use ch03_anti_aliasing::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch03_anti_aliasing::{
    FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter, render_with,
};
use common::render::RenderSettings;
use workbench::test_support::image_summary;

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
    image_summary(&out.image, out.stats.rays)
}

#[test]
fn edges_one_sample_at_the_centre() {
    workbench::assert_close_snapshot!(
        "edges_one_sample_at_the_centre",
        snapshot_of(Builtin::Edges, PixelSamplerKind::Centre, FilterKind::Box, 1)
    );
}

#[test]
fn edges_stratified_box() {
    workbench::assert_close_snapshot!(
        "edges_stratified_box",
        snapshot_of(
            Builtin::Edges,
            PixelSamplerKind::Stratified,
            FilterKind::Box,
            4
        )
    );
}

#[test]
fn checkerboard_random_tent() {
    workbench::assert_close_snapshot!(
        "checkerboard_random_tent",
        snapshot_of(
            Builtin::Checkerboard,
            PixelSamplerKind::Random,
            FilterKind::Tent,
            4
        )
    );
}

#[test]
fn checkerboard_halton_mitchell() {
    workbench::assert_close_snapshot!(
        "checkerboard_halton_mitchell",
        snapshot_of(
            Builtin::Checkerboard,
            PixelSamplerKind::Halton,
            FilterKind::Mitchell,
            4
        )
    );
}

#[test]
fn checkerboard_stratified_gaussian() {
    workbench::assert_close_snapshot!(
        "checkerboard_stratified_gaussian",
        snapshot_of(
            Builtin::Checkerboard,
            PixelSamplerKind::Stratified,
            FilterKind::Gaussian,
            4
        )
    );
}
