//! What the chapter's integration tests share: small renders, one-ray estimates, and scenes
//! built for one test.
#![allow(dead_code)]

use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::{TraceOptions, Tracer};
use ch07_soft_shadows::scenes::{Builder, camera, floor, matte};
use ch07_soft_shadows::{AreaLights, LightOptions, render_with};
use common::Ray;
use common::film::PixelBoxFilter;
use common::geometry::{Parallelogram, Shape, Sphere};
use common::image::Image;
use common::render::{RenderOutput, RenderSettings};
use common::sampler::{IndependentSampler, Sampler};
use common::scene::FilmSettings;
use glam::{UVec2, Vec3};

/// Renders `scene` at `width x height` with `spp` independent samples, box-filtered.
pub fn render(
    scene: &MotionScene,
    lights: LightOptions,
    width: u32,
    height: u32,
    spp: u64,
    seed: u64,
) -> RenderOutput {
    let settings = RenderSettings::new(width, height, spp);
    render_with(
        scene,
        lights,
        TraceOptions::default(),
        &Lens::PINHOLE,
        &settings,
        &IndependentSampler::new(seed),
        &PixelBoxFilter,
    )
}

/// Asserts that every pixel of `out` is finite and not negative, and that the render left
/// out no sample.
pub fn assert_finite(out: &RenderOutput, what: &str) {
    assert_eq!(out.stats.nonfinite_samples, 0, "{what}: non-finite samples");
    for (i, p) in out.image.pixels.iter().enumerate() {
        assert!(
            p.is_finite() && p.min_element() >= 0.0,
            "{what}: pixel {i} is {p}"
        );
    }
}

/// The mean and standard error (green channel) of the radiance along `ray` over `n` samples,
/// each with its own stream.
pub fn mean_radiance(
    scene: &MotionScene,
    lights: LightOptions,
    ray: &Ray,
    n: u64,
    seed: u64,
) -> (f64, f64) {
    let area_lights = AreaLights::of(&scene.scene);
    let lighting = area_lights.lighting(lights);
    let tracer = Tracer {
        world: scene,
        lighting: &lighting,
        options: TraceOptions::default(),
    };
    let mut sampler = IndependentSampler::new(seed);
    let values: Vec<f64> = (0..n)
        .map(|i| {
            sampler.start_pixel_sample(UVec2::new(1, 2), i);
            let value = tracer.trace(ray, 1, &mut sampler).y as f64;
            assert!(value.is_finite(), "sample {i}: {value}");
            value
        })
        .collect();
    let mean = values.iter().sum::<f64>() / n as f64;
    let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    (mean, (variance / n as f64).sqrt())
}

/// The RMSE of `image` against `reference`, relative to the reference's mean (green channel).
pub fn relative_rmse(image: &Image, reference: &Image) -> f64 {
    let rmse = common::metrics::rmse(image, reference);
    rmse / common::metrics::mean(reference).y
}

/// The floor's albedo in the test scenes.
pub const ALBEDO: f32 = 0.5;

/// A test scene at `scale`: a floor, a ball and a box on it, lit by `light` (a shape and its
/// radiance, already at scale), seen from above at an angle; 64 x 48.
pub fn scene_with_light(
    scale: f32,
    light: Option<(Shape, Vec3)>,
    point: Option<Vec3>,
) -> MotionScene {
    let s = scale;
    let mut builder = Builder::new()
        .shape(scaled_floor(s), matte(Vec3::splat(ALBEDO)))
        .shape(
            Shape::Sphere(Sphere::new(s * Vec3::new(-0.5, 0.4, 0.0), 0.4 * s)),
            matte(Vec3::new(0.8, 0.3, 0.2)),
        )
        .block(
            s * Vec3::new(0.3, 0.0, -0.4),
            s * Vec3::new(0.9, 0.5, 0.2),
            matte(Vec3::new(0.2, 0.4, 0.8)),
        );
    if let Some((shape, radiance)) = light {
        builder = builder.area_light(shape, radiance);
    }
    if let Some(intensity) = point {
        builder = builder.point_light(s * Vec3::new(0.0, 2.0, 0.0), intensity * s * s);
    }
    let (mut camera, _) = camera(
        s * Vec3::new(0.0, 1.8, 3.5),
        s * Vec3::new(0.0, 0.3, 0.0),
        50.0,
    );
    // Rays start at the near clip plane, 0.01 by default: it scales with the scene.
    camera.near_clip *= s;
    builder.build((camera, FilmSettings::new(64, 48)), 12)
}

fn scaled_floor(s: f32) -> Shape {
    match floor(4.0) {
        Shape::Parallelogram(q) => {
            Shape::Parallelogram(Parallelogram::new(s * q.corner(), s * q.e1(), s * q.e2()))
        }
        other => other,
    }
}

/// A square panel light of side `side` at height 2 above the origin (times `scale`), facing
/// down.
pub fn panel(scale: f32, side: f32) -> Shape {
    ch07_soft_shadows::scenes::ceiling_panel(scale * Vec3::new(0.0, 2.0, 0.0), scale * side)
}
