//! What the tests of the path tracer, and of the materials beyond the lecture over it, measure
//! a scene by: the mean of many paths through a few film positions, with its standard error.

use crate::bsdf::Materials;
use crate::{Method, PathTracer, SceneLights};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene};
use ch07_soft_shadows::AreaLights;
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2};

/// The mean green channel of `n` paths through each film position of `pixels` (or, for
/// `direct` sample counts in `method`, of Mitsuba's direct estimate), seen through a pinhole
/// and traced with `materials`, and the standard error of that mean. Panics on a non-finite
/// sample.
pub fn estimate<M: Materials>(
    world: &MotionScene,
    method: Method,
    materials: M,
    pixels: &[Vec2],
    n: u64,
    seed: u64,
) -> (f64, f64) {
    let film = world.scene.film;
    let rays = CameraRays::new(world, &Lens::PINHOLE, film.width, film.height);
    let area_lights = AreaLights::of(&world.scene);
    let tracer = PathTracer {
        world,
        lights: SceneLights::of(world, &area_lights, method.light_sampling),
        options: method.options,
        materials,
    };
    let mut sampler = IndependentSampler::new(seed);
    let (mut sum, mut sum2, mut count) = (0.0f64, 0.0f64, 0u64);
    for (p, &p_film) in pixels.iter().enumerate() {
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::new(p as u32, 0), i);
            let ray = rays.generate(world, p_film, &mut sampler);
            let l = match method.options.direct {
                Some(samples) => tracer.direct(&ray, samples, &mut sampler),
                None => tracer.radiance(&ray, &mut sampler),
            };
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
