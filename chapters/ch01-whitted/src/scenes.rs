//! The chapter's built-in scenes.

use common::geometry::{Parallelogram, Shape, Sphere};
use common::scene::{Camera, CameraFrame, FilmSettings, Material, PointLight, Scene, SceneBuilder};
use glam::Vec3;

/// The scenes `render --builtin NAME` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum Builtin {
    /// Whitted's classic: a glass and a mirror sphere over a checkerboard, under two lights.
    Spheres,
    /// A Cornell box lit by a point light, with a mirror and a glass sphere.
    Cornell,
}

impl Builtin {
    /// Every built-in scene, in the order they are listed.
    pub const ALL: [Builtin; 2] = [Builtin::Spheres, Builtin::Cornell];

    /// Builds the scene with recursion limit `max_depth` (Mitsuba's count, see
    /// [`Scene::max_depth`]).
    pub fn build(self, max_depth: u32) -> Scene {
        match self {
            Builtin::Spheres => spheres(max_depth),
            Builtin::Cornell => cornell(max_depth),
        }
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Builtin::Spheres => "spheres",
            Builtin::Cornell => "cornell",
        }
    }
}

/// The default recursion limit: enough bounces for light to pass through a glass sphere
/// and reflect in a mirror a few times.
pub const DEFAULT_MAX_DEPTH: u32 = 12;

fn spheres(max_depth: u32) -> Scene {
    let mut builder = SceneBuilder::new().environment(Vec3::new(0.45, 0.6, 0.85));
    // An 8 x 8 checkerboard of 1 x 1 tiles on the plane y = 0: hard edges to alias, and a
    // pattern to see distorted through the glass.
    let tiles = 8;
    for i in 0..tiles {
        for j in 0..tiles {
            let corner = Vec3::new(i as f32 - 4.0, 0.0, j as f32 - 5.0);
            let albedo = if (i + j) % 2 == 0 {
                Vec3::new(0.85, 0.85, 0.8)
            } else {
                Vec3::new(0.8, 0.15, 0.1)
            };
            // e1 x e2 = (0, 0, 1) x (1, 0, 0) = +y: the tiles face up.
            let tile = Parallelogram::new(corner, Vec3::Z, Vec3::X);
            builder = builder.shape(Shape::Parallelogram(tile), Material::diffuse(albedo));
        }
    }
    let scene = builder
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(0.3, 0.8, 0.6), 0.8)),
            Material::glass(1.5),
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(-1.4, 1.0, -1.6), 1.0)),
            Material::mirror(),
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(1.9, 0.6, -1.2), 0.6)),
            Material::diffuse(Vec3::new(0.2, 0.45, 0.8)),
        )
        .light(PointLight {
            position: Vec3::new(-3.0, 6.0, 4.0),
            intensity: Vec3::splat(45.0),
        })
        .light(PointLight {
            position: Vec3::new(4.0, 4.0, 1.0),
            intensity: Vec3::new(12.0, 10.0, 7.0),
        });
    let frame = CameraFrame::look_at(Vec3::new(0.0, 1.6, 5.2), Vec3::new(0.0, 0.7, 0.0), Vec3::Y)
        .expect("the camera looks along a valid direction");
    scene.build(
        Camera::pinhole(frame, 50.0),
        FilmSettings::new(320, 240),
        max_depth,
    )
}

fn cornell(max_depth: u32) -> Scene {
    let white = Material::diffuse(Vec3::splat(0.73));
    let red = Material::diffuse(Vec3::new(0.65, 0.05, 0.05));
    let green = Material::diffuse(Vec3::new(0.12, 0.45, 0.15));
    // Each wall is a parallelogram whose normal e1 x e2 faces into the room.
    let wall =
        |corner: Vec3, e1: Vec3, e2: Vec3| Shape::Parallelogram(Parallelogram::new(corner, e1, e2));
    let scene = SceneBuilder::new()
        .shape(
            wall(Vec3::new(-1.0, -1.0, 1.0), 2.0 * Vec3::X, -2.0 * Vec3::Z),
            white.clone(),
        ) // floor
        .shape(
            wall(Vec3::new(-1.0, 1.0, -1.0), 2.0 * Vec3::X, 2.0 * Vec3::Z),
            white.clone(),
        ) // ceiling
        .shape(
            wall(Vec3::new(-1.0, -1.0, -1.0), 2.0 * Vec3::X, 2.0 * Vec3::Y),
            white,
        ) // back
        .shape(
            wall(Vec3::new(-1.0, -1.0, 1.0), -2.0 * Vec3::Z, 2.0 * Vec3::Y),
            red,
        ) // left
        .shape(
            wall(Vec3::new(1.0, -1.0, -1.0), 2.0 * Vec3::Z, 2.0 * Vec3::Y),
            green,
        ) // right
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(-0.45, -0.65, -0.3), 0.35)),
            Material::mirror(),
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(0.45, -0.65, 0.3), 0.35)),
            Material::glass(1.5),
        )
        .light(PointLight {
            // Where the ceiling lamp of the area-light version hangs, radiating as much
            // straight down as that lamp does (radiance times area).
            position: Vec3::new(0.0, 0.9, 0.0),
            intensity: Vec3::new(17.0, 12.0, 4.0) * 0.25,
        });
    let frame = CameraFrame::look_at(Vec3::new(0.0, 0.0, 3.9), Vec3::ZERO, Vec3::Y)
        .expect("the camera looks along a valid direction");
    scene.build(
        Camera::pinhole(frame, 40.0),
        FilmSettings::new(256, 256),
        max_depth,
    )
}
