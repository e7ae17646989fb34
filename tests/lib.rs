//! Cross-chapter tests of the workbook: properties that must hold for every chapter's tracer
//! at once (scale invariance, determinism, finite pixels). The tests live in `tests/tests/`;
//! this library holds the scenes and helpers they share.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod binaries;

use ch01_whitted::camera::{CameraFrame, PinholeCamera};
use ch01_whitted::light::PointLight;
use ch01_whitted::material::Material;
use ch01_whitted::scene::{Scene, SceneBuilder};
use common::geometry::{Quad, Shape, Sphere, Triangle};
use glam::Vec3;

/// A small Whitted scene with every shape kind (quad floor, spheres, a triangle), a mirror,
/// glass and shadows, scaled by `scale` and moved by `offset`.
///
/// Light intensities grow with `scale^2`, so irradiance (intensity over squared distance) and
/// hence the image stay the same at every scale.
pub fn scaled_whitted_scene(scale: f32, offset: Vec3, size: u32) -> Scene {
    let at = |p: Vec3| p * scale + offset;
    let floor = Quad::new(
        at(Vec3::new(-2.0, 0.0, 2.0)),
        4.0 * scale * Vec3::X,
        -4.0 * scale * Vec3::Z,
    );
    // A wall standing on the floor, touching it along an edge: light must not leak through.
    let wall = Quad::new(
        at(Vec3::new(-2.0, 0.0, -1.0)),
        4.0 * scale * Vec3::X,
        2.0 * scale * Vec3::Y,
    );
    let triangle = Triangle::new(
        at(Vec3::new(0.6, 0.0, 0.2)),
        at(Vec3::new(1.4, 0.0, 0.2)),
        at(Vec3::new(1.0, 1.0, 0.0)),
    );
    let frame = CameraFrame::look_at(
        at(Vec3::new(0.0, 1.2, 3.5)),
        at(Vec3::new(0.0, 0.4, 0.0)),
        Vec3::Y,
    )
    .expect("a valid camera frame");
    let mut camera = PinholeCamera::new(frame, 55.0, size, size);
    camera.near_clip *= scale;
    SceneBuilder::new()
        .background(Vec3::new(0.4, 0.55, 0.8))
        .shape(Shape::Quad(floor), Material::diffuse(Vec3::splat(0.7)))
        .shape(
            Shape::Quad(wall),
            Material::diffuse(Vec3::new(0.7, 0.3, 0.2)),
        )
        .shape(
            Shape::Triangle(triangle),
            Material::two_sided_diffuse(Vec3::new(0.2, 0.6, 0.3)),
        )
        .shape(
            Shape::Sphere(Sphere::new(at(Vec3::new(-0.8, 0.5, 0.0)), 0.5 * scale)),
            Material::mirror(),
        )
        .shape(
            Shape::Sphere(Sphere::new(at(Vec3::new(0.1, 0.35, 0.9)), 0.35 * scale)),
            Material::glass(1.5),
        )
        .light(PointLight {
            position: at(Vec3::new(1.0, 3.0, 2.0)),
            intensity: Vec3::splat(15.0 * scale * scale),
        })
        .build(camera, 10)
}
