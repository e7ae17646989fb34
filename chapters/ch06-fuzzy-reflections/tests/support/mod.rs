//! What the chapter's integration tests share: small renders, and scenes built for one test.
#![allow(dead_code)]

use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::{PointLights, TraceOptions, render_with};
use common::film::PixelBoxFilter;
use common::image::Image;
use common::render::{RenderOutput, RenderSettings};
use common::sampler::IndependentSampler;

/// Renders `scene` at `width x height` with `spp` independent samples, box-filtered.
pub fn render(
    scene: &MotionScene,
    options: TraceOptions,
    width: u32,
    height: u32,
    spp: u64,
    seed: u64,
) -> RenderOutput {
    let settings = RenderSettings::new(width, height, spp);
    render_with(
        scene,
        &PointLights,
        options,
        &Lens::PINHOLE,
        &settings,
        &IndependentSampler::new(seed),
        &PixelBoxFilter,
    )
}

/// Asserts that every pixel of `image` is finite and not negative.
pub fn assert_finite(image: &Image, what: &str) {
    for (i, p) in image.pixels.iter().enumerate() {
        assert!(
            p.is_finite() && p.min_element() >= 0.0,
            "{what}: pixel {i} is {p}"
        );
    }
}
