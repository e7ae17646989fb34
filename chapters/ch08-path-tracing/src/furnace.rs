//! The white furnace: a world of uniform radiance 1 and white surfaces. Every path must carry
//! exactly 1 home, so anything else is a bug in the estimator (energy created or lost), and
//! because the answer is known the tests need no reference image.

use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::furnace::scene_of;
use common::geometry::{Shape, Sphere};
use common::scene::Material;
use glam::Vec3;

/// Spheres of the given materials, side by side along x and touching, in an environment of
/// radiance 1, seen from the front, with the depth limit `max_depth`.
pub fn spheres(materials: &[Material], max_depth: u32) -> MotionScene {
    let n = materials.len() as f32;
    let shapes = materials
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let x = 2.0 * i as f32 - (n - 1.0);
            (
                Shape::Sphere(Sphere::new(Vec3::new(x, 0.0, 0.0), 1.0)),
                m.clone(),
            )
        })
        .collect();
    scene_of(
        shapes,
        Vec3::ONE,
        Vec3::new(0.0, 0.5, 2.5 + 1.5 * n),
        Vec3::ZERO,
        max_depth,
    )
}
