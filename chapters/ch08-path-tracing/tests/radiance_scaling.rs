//! Radiance is scaled by `η²` where it refracts, and a tracer that forgets it is wrong by
//! exactly that factor in scenes where the answer is known without rendering.
//!
//! Radiance `L` is power per area per solid angle. Light entering glass of index `η` is
//! squeezed into a cone narrower by `η²` in solid angle, so inside, in equilibrium with a
//! uniform world of radiance `L`, the radiance is `η² L`: 2.25 for glass of index 1.5 in a world
//! of radiance 1. Two scenes show it:
//!
//! - **Inside.** The camera at the centre of a glass sphere in a world of radiance 1. Every
//!   camera ray meets the sphere at normal incidence from inside; it leaves with probability
//!   `1 - F` and weight `(1.5 / 1)² = 2.25`, or is reflected (weight 1) straight across the
//!   centre to meet the sphere at normal incidence again. Every path that leaves carries 2.25
//!   home: each pixel is 2.25. Forgetting `η²` gives 1.
//! - **Outside.** The camera outside the same sphere, which now holds a black emitter of
//!   radiance 2.25 and radius 0.7, in the world of radiance 1: glass, emitter and world are in
//!   equilibrium, so each pixel is 1. A reflected ray goes straight to the world (1); a
//!   refracted one carries `1 / 2.25` and, bent to within `1 / 1.5` of the centre, meets the
//!   emitter (`2.25 / 2.25 = 1`). Forgetting `η²` gives `F + (1 - F) 2.25`, up to 2.2.
//!
//! Both estimators have (almost) no noise: a path is off only if it is still bouncing when
//! the depth limit ends it, with probability at most `F^(max_depth - 1)`.

mod support;

use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::furnace::scene_of;
use ch08_path_tracing::PathOptions;
use common::geometry::{Shape, Sphere};
use common::scene::Material as Smooth;
use common::scene::Material;
use glam::Vec3;

/// The index of the glass.
const IOR: f32 = 1.5;
/// The longest path: 63 reflections in a row, the only way to be cut off, have probability
/// `0.04^63 ≈ 10⁻⁸⁸`.
const MAX_DEPTH: u32 = 64;
/// Samples per pixel of the check.
const SPP: u64 = 4;

fn glass_sphere() -> (Shape, Material) {
    (
        Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0)),
        Smooth::glass(IOR),
    )
}

/// Renders `scene` with roulette off and checks that every pixel is `expected` to within
/// five standard errors of the estimator plus the film's rounding, when a path is 0 instead
/// with probability `cut_off` at most (the depth limit ended it); returns the pixels' largest
/// distance from `expected`.
fn assert_every_pixel(scene: &MotionScene, expected: f32, cut_off: f64) -> f32 {
    let options = PathOptions {
        rr_depth: None,
        ..PathOptions::with_depth(MAX_DEPTH)
    };
    let out = support::render_pinhole(scene, options, (16, 12, SPP), 3);
    assert_eq!(out.stats.nonfinite_samples, 0);
    // A path's standard deviation is `expected √(p (1 - p))`; a pixel averages SPP of them.
    let noise = f64::from(expected) * (cut_off * (1.0 - cut_off) / SPP as f64).sqrt();
    // The film sums SPP weighted samples in f32 and divides.
    let rounding = f64::from(expected) * SPP as f64 * f64::from(f32::EPSILON);
    let tolerance = 5.0 * noise + rounding;
    let mut largest = 0.0f32;
    for (i, pixel) in out.image.pixels.iter().enumerate() {
        for channel in pixel.to_array() {
            let off = (channel - expected).abs();
            assert!(
                f64::from(off) <= tolerance,
                "pixel {i}: {pixel}, expected {expected} (tolerance {tolerance:e})"
            );
            largest = largest.max(off);
        }
    }
    eprintln!("every pixel {expected} to within {largest:e} (tolerance {tolerance:e})");
    largest
}

#[test]
fn inside_glass_in_a_world_of_radiance_1_the_radiance_is_eta_squared() {
    let scene = scene_of(
        vec![glass_sphere()],
        Vec3::ONE,
        Vec3::ZERO,
        -Vec3::Z,
        MAX_DEPTH,
    );
    // Normal incidence: F = ((1.5 - 1) / (1.5 + 1))² = 0.04, and a path is cut off if it is
    // reflected at every one of its MAX_DEPTH - 1 bounces.
    assert_every_pixel(&scene, IOR * IOR, 0.04f64.powi(MAX_DEPTH as i32 - 1));
}

#[test]
fn outside_glass_around_an_emitter_of_eta_squared_the_world_looks_uniform() {
    let emitter = (
        Shape::Sphere(Sphere::new(Vec3::ZERO, 0.7)),
        Smooth::diffuse(Vec3::ZERO),
    );
    let mut scene = scene_of(
        vec![glass_sphere(), emitter],
        Vec3::ONE,
        Vec3::new(0.0, 0.0, 5.0),
        Vec3::ZERO,
        MAX_DEPTH,
    );
    scene.scene.surfaces[1].emitter =
        Some(common::scene::AreaEmitter::uniform(Vec3::splat(IOR * IOR)));
    // Every path ends by its third segment (the world, or the black emitter): none is cut off.
    assert_every_pixel(&scene, 1.0, 0.0);
}
