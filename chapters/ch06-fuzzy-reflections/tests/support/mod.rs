//! What the chapter's integration tests share: small renders, and scenes built for one test.
#![allow(dead_code)]

use ch01_whitted::camera::{CameraFrame, PinholeCamera};
use ch01_whitted::material::Material as SmoothMaterial;
use ch01_whitted::scene::SceneBuilder;
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::{
    FuzzyScene, Material, PointLights, TraceOptions, Tracer, render_with,
};
use common::Ray;
use common::film::PixelBoxFilter;
use common::geometry::Shape;
use common::image::Image;
use common::render::{RenderOutput, RenderSettings, SampleCounters};
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec3};

/// Renders `scene` at `width x height` with `spp` independent samples, box-filtered.
pub fn render(
    scene: &FuzzyScene,
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

/// A scene of `shapes` with `materials` in a world of uniform radiance `background`, no
/// lights, seen by a camera at `eye` looking at `target`.
pub fn scene_of(
    shapes: Vec<(Shape, Material)>,
    background: Vec3,
    eye: Vec3,
    target: Vec3,
    max_depth: u32,
) -> FuzzyScene {
    let mut builder = SceneBuilder::new().background(background);
    let mut materials = Vec::new();
    for (shape, material) in shapes {
        builder = builder.shape(shape, SmoothMaterial::diffuse(Vec3::ZERO));
        materials.push(material);
    }
    let frame = CameraFrame::look_at(eye, target, Vec3::Y).expect("a valid camera");
    let camera = PinholeCamera::new(frame, 40.0, 64, 48);
    FuzzyScene::new(
        MotionScene::still(builder.build(camera, max_depth)),
        materials,
    )
    .expect("one material per shape")
}

/// The mean and standard error of the radiance along `ray` over `n` samples (luminance-free:
/// the green channel), traced with `options`.
pub fn mean_radiance(scene: &FuzzyScene, options: TraceOptions, ray: &Ray, n: u64) -> (f64, f64) {
    let tracer = Tracer {
        scene,
        lighting: &PointLights,
        options,
    };
    let mut sampler = IndependentSampler::new(11);
    let (mut sum, mut sum2) = (0.0f64, 0.0f64);
    for i in 0..n {
        sampler.start_pixel_sample(UVec2::ZERO, i);
        let mut counters = SampleCounters::default();
        let l = tracer.trace(ray, 1, &mut sampler, &mut counters);
        assert!(l.is_finite(), "radiance {l} along {ray:?}");
        let x = f64::from(l.y);
        sum += x;
        sum2 += x * x;
    }
    let mean = sum / n as f64;
    let variance = (sum2 / n as f64 - mean * mean).max(0.0);
    (mean, (variance / n as f64).sqrt())
}
