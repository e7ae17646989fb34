//! The furnace: a world that glows with radiance 1 in every direction.
//!
//! Under such light a white surface receives 1 from everywhere, so the radiance it sends back
//! is exactly its albedo, the share of the light it reflects: at most 1, or the estimator (or
//! the material) creates energy. Here a white glossy floor is lit so, and rays arrive at a
//! chosen angle of incidence; the energy test and the below-surface figure both measure with
//! it.

use crate::lighting::PointLights;
use crate::tracer::{TraceOptions, Tracer};
use ch05_motion_blur::MotionScene;
use common::Ray;
use common::geometry::{Parallelogram, Shape};
use common::sampler::{IndependentSampler, Sampler};
use common::scene::{Camera, CameraFrame, FilmSettings, Material, SceneBuilder};
use glam::{UVec2, Vec3};

/// A scene of `shapes` with their `materials` in a world of uniform radiance `background`, no
/// lights, seen by a camera at `eye` looking at `target`.
pub fn scene_of(
    shapes: Vec<(Shape, Material)>,
    background: Vec3,
    eye: Vec3,
    target: Vec3,
    max_depth: u32,
) -> MotionScene {
    let mut builder = SceneBuilder::new().environment(background);
    for (shape, material) in shapes {
        builder = builder.shape(shape, material);
    }
    let frame = CameraFrame::look_at(eye, target, Vec3::Y).expect("a valid camera");
    let camera = Camera::pinhole(frame, 40.0);
    MotionScene::still(builder.build(camera, FilmSettings::new(64, 48), max_depth))
}

/// A white glossy floor of `exponent` at y = 0, 2000 wide, in the furnace.
pub fn white_floor(exponent: f32) -> MotionScene {
    let floor = Parallelogram::new(Vec3::new(-1e3, 0.0, -1e3), 2e3 * Vec3::Z, 2e3 * Vec3::X);
    scene_of(
        vec![(
            Shape::Parallelogram(floor),
            Material::glossy(Vec3::ONE, exponent),
        )],
        Vec3::ONE,
        Vec3::new(0.0, 2.0, 5.0),
        Vec3::ZERO,
        4,
    )
}

/// A ray that reaches the origin at `degrees` from the normal +y, starting where it is at
/// height 1 (far off for a grazing ray, but always above the floor).
pub fn incoming(degrees: f32) -> Ray {
    let theta = degrees.to_radians();
    let to_surface = Vec3::new(theta.sin(), -theta.cos(), 0.0);
    Ray::new(-to_surface / theta.cos().max(1e-3), to_surface)
}

/// The mean of the radiance along `ray` (its green channel) over `n` samples traced with
/// `options`, and the standard error of that mean. Panics on a non-finite sample: in the
/// furnace there is no excuse for one.
pub fn mean_radiance(world: &MotionScene, options: TraceOptions, ray: &Ray, n: u64) -> (f64, f64) {
    let tracer = Tracer {
        world,
        lighting: &PointLights,
        options,
    };
    let mut sampler = IndependentSampler::new(11);
    let (mut sum, mut sum2) = (0.0f64, 0.0f64);
    for i in 0..n {
        sampler.start_pixel_sample(UVec2::ZERO, i);
        let l = tracer.trace(ray, 1, &mut sampler);
        assert!(l.is_finite(), "radiance {l} along {ray:?}");
        let x = f64::from(l.y);
        sum += x;
        sum2 += x * x;
    }
    let mean = sum / n as f64;
    let variance = (sum2 / n as f64 - mean * mean).max(0.0);
    (mean, (variance / n as f64).sqrt())
}
