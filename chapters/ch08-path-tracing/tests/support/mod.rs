//! Shared helpers: the mean radiance of many paths through fixed film positions, with its
//! standard error, and the chapter's scene files.
#![allow(dead_code)]

use ch03_anti_aliasing::{FilterKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::CameraRays;
use ch07_soft_shadows::SoftShadowScene;
use ch08_path_tracing::{Method, PathOptions, PathTracer, SceneLights, render_with};
use common::render::{RenderOutput, RenderSettings, SampleCounters};
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2};

/// A scene file of the chapter, converted, with its options.
pub fn scene_file(name: &str) -> ch08_path_tracing::scene_file::ConvertedScene {
    let path = ch08_path_tracing::agreement::scenes_dir().join(name);
    let loaded = common::scene::load_scene_file(&path, &[]).expect("the scene loads");
    ch08_path_tracing::scene_file::convert(&loaded.scene).expect("the scene converts")
}

/// `scene` path-traced through a pinhole at `width` x `height` with `spp` samples per pixel
/// (box filter, independent samples from `seed`), with `options` and the default method.
pub fn render_pinhole(
    scene: &SoftShadowScene,
    options: PathOptions,
    (width, height, spp): (u32, u32, u64),
    seed: u64,
) -> RenderOutput {
    let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
    render_with(
        scene,
        Method::new(options),
        &Lens::PINHOLE,
        &RenderSettings::new(width, height, spp),
        &IndependentSampler::new(seed),
        &filter,
    )
}

/// The mean luminance-free green channel of `n` paths through each film position of
/// `pixels`, and the standard error of that mean. Panics on a non-finite sample.
pub fn estimate(
    scene: &SoftShadowScene,
    method: Method,
    pixels: &[Vec2],
    n: u64,
    seed: u64,
) -> (f64, f64) {
    let world = &scene.scene.world;
    let camera = world.scene.camera;
    let rays = CameraRays::new(world, &Lens::PINHOLE, camera.width, camera.height);
    let tracer = PathTracer {
        scene,
        lights: SceneLights::of(scene, method.light_sampling),
        options: method.options,
        fuzz: method.fuzz,
    };
    let mut sampler = IndependentSampler::new(seed);
    let (mut sum, mut sum2, mut count) = (0.0f64, 0.0f64, 0u64);
    for (p, &p_film) in pixels.iter().enumerate() {
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::new(p as u32, 0), i);
            let ray = rays.generate(world, p_film, &mut sampler);
            let mut counters = SampleCounters::default();
            let l = tracer.radiance(&ray, &mut sampler, &mut counters);
            assert!(l.is_finite(), "radiance {l} at {p_film}");
            let x = f64::from(l.y);
            sum += x;
            sum2 += x * x;
            count += 1;
        }
    }
    let mean = sum / count as f64;
    let variance = (sum2 / count as f64 - mean * mean).max(0.0);
    (mean, (variance / count as f64).sqrt())
}

/// A `k x k` grid of film positions over a `width x height` image (pixel centres).
pub fn grid(width: u32, height: u32, k: u32) -> Vec<Vec2> {
    let mut points = Vec::new();
    for j in 0..k {
        for i in 0..k {
            points.push(Vec2::new(
                ((i * width / k) as f32 + 0.5).min(width as f32 - 0.5),
                ((j * height / k) as f32 + 0.5).min(height as f32 - 0.5),
            ));
        }
    }
    points
}
