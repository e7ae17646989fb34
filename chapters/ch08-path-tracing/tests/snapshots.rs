//! Snapshot tests: tiny fixed renders of the chapter's scenes, their summaries compared with
//! the stored ones (a 10-level luminance picture, the mean colour, the ray count).

mod support;

use ch03_anti_aliasing::{FilterKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch08_path_tracing::{Method, PathOptions, render_with};
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use workbench::test_support::image_summary;

fn snapshot_of(file: &str, options: impl Fn(PathOptions) -> PathOptions) -> String {
    let scene = support::scene_file(file);
    let settings = RenderSettings::new(24, 24, 8);
    let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
    let out = render_with(
        &scene.world,
        Method::new(options(scene.options)),
        &Lens::PINHOLE,
        &settings,
        &IndependentSampler::new(0),
        &filter,
    );
    image_summary(&out.image, out.stats.rays)
}

#[test]
fn cornell_box_path_traced() {
    workbench::assert_close_snapshot!(
        "cornell_box_path_traced",
        snapshot_of("cornell-box.xml", |o| o)
    );
}

#[test]
fn point_and_sky_without_nee() {
    workbench::assert_close_snapshot!(
        "point_and_sky_without_nee",
        snapshot_of("point-and-sky.xml", |o| PathOptions { nee: false, ..o })
    );
}
