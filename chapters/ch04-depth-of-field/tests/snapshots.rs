//! Snapshot tests: tiny fixed renders whose summaries are compared with the stored ones.
//!
//! The summary is a 10-level luminance picture (`workbench::test_support::image_summary`) (catches moved geometry, a lens focused at the
//! wrong distance, a missing blur) plus the image's mean colour to four decimals and the ray
//! count. The renders are random, but their seeds are fixed; the summary is compared
//! up to floating-point noise (`workbench::assert_close_snapshot!`).

use ch04_depth_of_field::scenes::{BOKEH_SPHERE_DEPTHS, Builtin, DEFAULT_MAX_DEPTH};
use ch04_depth_of_field::{Aperture, Lens, LensWarp, render_with};
use common::film::PixelBoxFilter;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use workbench::test_support::image_summary;

fn snapshot_of(lens: Lens) -> String {
    let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
    let spp = 16;
    let settings = RenderSettings::new(48, 32, spp);
    // common's independent sampler and box filter: the snapshots change only when this
    // chapter (or the tracer) does, not when chapter 03 refines its samplers.
    let out = render_with(
        &scene,
        &lens,
        &settings,
        &IndependentSampler::new(0),
        &PixelBoxFilter,
    );
    assert_eq!(out.stats.nonfinite_samples, 0);
    image_summary(&out.image, out.stats.rays)
}

#[test]
fn bokeh_pinhole() {
    workbench::assert_close_snapshot!("bokeh_pinhole", snapshot_of(Lens::PINHOLE));
}

#[test]
fn bokeh_focused_near_concentric() {
    workbench::assert_close_snapshot!(
        "bokeh_focused_near_concentric",
        snapshot_of(Lens::new(0.2, BOKEH_SPHERE_DEPTHS[0]).unwrap())
    );
}

#[test]
fn bokeh_focused_near_naive() {
    let lens = Lens::new(0.2, BOKEH_SPHERE_DEPTHS[0])
        .unwrap()
        .with_warp(LensWarp::Naive);
    workbench::assert_close_snapshot!("bokeh_focused_near_naive", snapshot_of(lens));
}

#[test]
fn bokeh_focused_far_hexagon() {
    let lens = Lens::new(0.2, BOKEH_SPHERE_DEPTHS[2])
        .unwrap()
        .with_aperture(Aperture::polygon(6, 0.0).unwrap());
    workbench::assert_close_snapshot!("bokeh_focused_far_hexagon", snapshot_of(lens));
}
