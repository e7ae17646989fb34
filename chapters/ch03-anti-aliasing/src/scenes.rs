//! Scenes that alias: hard edges and a pattern running to the horizon.
//!
//! Both are as simple as possible so that what the figures show is sampling, not lighting:
//! dark shapes against a bright sky (edges at every angle, bars thinner than a pixel), and an
//! endless checkerboard whose squares shrink towards the horizon until many fall into one
//! pixel. One sample at the pixel centre turns the first into staircases and broken bars, and
//! the second into moiré: false, large patterns near the horizon.

use common::geometry::{Parallelogram, Shape, Sphere};
use common::scene::{
    Camera, CameraFrame, Checkerboard, FilmSettings, Material, PointLight, Scene, SceneBuilder,
    Texture,
};
use glam::{Vec2, Vec3};

/// Enough recursion for these scenes: they have no mirrors or glass.
pub const DEFAULT_MAX_DEPTH: u32 = 4;

/// The scenes `render --builtin NAME` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum Builtin {
    /// Dark bars of decreasing width and a sphere against a bright sky: jagged edges.
    Edges,
    /// A checkerboard plane running to the horizon: moiré.
    Checkerboard,
}

impl Builtin {
    /// Every built-in scene, in the order they are listed.
    pub const ALL: [Builtin; 2] = [Builtin::Edges, Builtin::Checkerboard];

    /// Builds the scene with recursion limit `max_depth` (Mitsuba's count).
    pub fn build(self, max_depth: u32) -> Scene {
        match self {
            Builtin::Edges => edges(max_depth),
            Builtin::Checkerboard => checkerboard(max_depth),
        }
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Builtin::Edges => "edges",
            Builtin::Checkerboard => "checkerboard",
        }
    }
}

/// A bar of `length x width` centred at `centre` in the plane `z = centre.z`, turned by
/// `degrees` from the horizontal, facing `+z`.
fn bar(centre: Vec3, length: f32, width: f32, degrees: f32) -> Shape {
    let (sin, cos) = degrees.to_radians().sin_cos();
    let along = Vec3::new(cos, sin, 0.0) * length;
    let across = Vec3::new(-sin, cos, 0.0) * width;
    // along x across points along +z, towards the camera.
    Shape::Parallelogram(Parallelogram::new(
        centre - 0.5 * (along + across),
        along,
        across,
    ))
}

fn edges(max_depth: u32) -> Scene {
    let dark = Material::two_sided_diffuse(Vec3::splat(0.08));
    // The image is 3.6 units wide at z = 0; at 320 pixels a pixel is about 0.011 units, so the
    // bars are about 4, 1 and 1/3 pixels wide there, all tilted a few degrees from the
    // horizontal: the angle that gives the longest, most visible stairs.
    let mut builder = SceneBuilder::new().environment(Vec3::new(0.95, 0.93, 0.88));
    for (i, (width, degrees)) in [(0.045, 4.0), (0.011, 6.0), (0.004, 8.0)]
        .into_iter()
        .enumerate()
    {
        let centre = Vec3::new(-0.35, 0.75 - 0.35 * i as f32, 0.0);
        builder = builder.shape(bar(centre, 2.6, width, degrees), dark.clone());
    }
    // A steep bar, nearly vertical, and a sphere: edges at every angle.
    builder = builder
        .shape(
            bar(Vec3::new(-1.2, -0.55, 0.0), 1.2, 0.02, 80.0),
            dark.clone(),
        )
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(0.7, -0.55, 0.0), 0.5)),
            Material::diffuse(Vec3::new(0.15, 0.2, 0.35)),
        )
        .light(PointLight {
            position: Vec3::new(3.0, 3.0, 5.0),
            intensity: Vec3::splat(20.0),
        });
    let frame = CameraFrame::look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y)
        .expect("the camera looks along a valid direction");
    builder.build(
        Camera::pinhole(frame, 40.0),
        FilmSettings::new(320, 240),
        max_depth,
    )
}

/// Half the side of the checkerboard plane: far enough that it meets the sky a few hundredths of
/// a degree below the horizon.
const PLANE_HALF_SIDE: f32 = 1000.0;

fn checkerboard(max_depth: u32) -> Scene {
    let side = 2.0 * PLANE_HALF_SIDE;
    // One period of the texture is two squares; squares of 1 x 1 world units.
    let checks = Checkerboard::scaled(
        Vec3::splat(0.85),
        Vec3::splat(0.08),
        Vec2::splat(side / 2.0),
    );
    let floor = Parallelogram::new(
        Vec3::new(-PLANE_HALF_SIDE, 0.0, -PLANE_HALF_SIDE),
        Vec3::new(0.0, 0.0, side),
        Vec3::new(side, 0.0, 0.0),
    );
    let scene = SceneBuilder::new()
        .environment(Vec3::new(0.55, 0.7, 0.95))
        .shape(
            Shape::Parallelogram(floor),
            Material::TexturedDiffuse {
                texture: Texture::Checkerboard(checks),
                two_sided: false,
            },
        )
        // A light so high above that the whole plane is lit almost evenly, like the sun:
        // irradiance about I / h^2 = 3 everywhere.
        .light(PointLight {
            position: Vec3::new(0.0, 1.0e4, 0.0),
            intensity: Vec3::splat(3.0e8),
        });
    let frame = CameraFrame::look_at(
        Vec3::new(0.3, 1.0, 4.0),
        Vec3::new(0.0, 0.15, -6.0),
        Vec3::Y,
    )
    .expect("the camera looks along a valid direction");
    scene.build(
        Camera::pinhole(frame, 60.0),
        FilmSettings::new(320, 240),
        max_depth,
    )
}
