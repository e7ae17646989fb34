//! The chapter's built-in scenes, each with the shutter it is meant to be seen through.
//!
//! - `street`: a checkerboard floor and a mirror wall behind; a fast sphere that crosses the
//!   whole frame while the shutter is open, a slow one that moves a little, and a checkered
//!   cube spinning by one and a quarter turns. The mirror shows every motion a second time.
//! - `spinner`: the checkered cube close up, spinning by one and a quarter turns about a
//!   tilted axis: rotation blur with no translation.
//! - `pan`: chapter 01's glass and mirror spheres with nothing moving but the camera, which
//!   slides sideways and turns a little.

use crate::animated_transform::AnimatedTransform;
use crate::moving::MovingShape;
use crate::shutter::Shutter;
use crate::world::{MotionScene, matrix_of};
use ch01_whitted::camera::{CameraFrame, PinholeCamera};
use ch01_whitted::light::PointLight;
use ch01_whitted::material::{Checkerboard, Material};
use ch01_whitted::scene::SceneBuilder;
use ch01_whitted::scenes::{Builtin as WhittedBuiltin, DEFAULT_MAX_DEPTH};
use common::geometry::{Quad, Shape, Sphere};
use glam::{Mat4, Vec2, Vec3};

/// The scenes `render --builtin NAME` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Builtin {
    /// A fast and a slow sphere, a spinning cube and a mirror: the chapter's scene.
    Street,
    /// A cube spinning by more than a full turn.
    Spinner,
    /// Chapter 01's spheres seen by a moving camera.
    Pan,
}

/// The recursion limit of the built-in scenes: chapter 01's.
pub const DEFAULT_DEPTH: u32 = DEFAULT_MAX_DEPTH;

/// The shutter of the built-in scenes: open over the whole motion.
pub const DEFAULT_SHUTTER: Shutter = Shutter {
    open: 0.0,
    close: 1.0,
};

/// Turns of the spinning cubes over the shutter interval: more than one, so the blur goes all
/// the way round.
pub const SPIN_TURNS: f32 = 1.25;

impl Builtin {
    /// Every built-in scene.
    pub const ALL: [Builtin; 3] = [Builtin::Street, Builtin::Spinner, Builtin::Pan];

    /// Builds the scene, seen through `shutter`.
    pub fn build(self, max_depth: u32, shutter: Shutter) -> MotionScene {
        match self {
            Builtin::Street => street(max_depth, shutter),
            Builtin::Spinner => spinner(max_depth, shutter),
            Builtin::Pan => pan(max_depth, shutter),
        }
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Builtin::Street => "street",
            Builtin::Spinner => "spinner",
            Builtin::Pan => "pan",
        }
    }
}

/// A checkerboard material with squares `1 / (2 scale)` of the surface parameters wide.
fn checkered(colour0: Vec3, colour1: Vec3, scale: f32) -> Material {
    Material::CheckeredDiffuse {
        checkerboard: Checkerboard {
            colour0,
            colour1,
            scale: Vec2::splat(scale),
        },
        two_sided: false,
    }
}

/// The six faces of the cube `[-h, h]^3`, normals out.
pub fn cube_faces(h: f32) -> [Shape; 6] {
    let quad = |corner: Vec3, e1: Vec3, e2: Vec3| Shape::Quad(Quad::new(corner, e1, e2));
    let s = 2.0 * h;
    [
        quad(Vec3::new(-h, -h, h), s * Vec3::X, s * Vec3::Y), // +z
        quad(Vec3::new(-h, -h, -h), s * Vec3::Y, s * Vec3::X), // -z
        quad(Vec3::new(h, -h, -h), s * Vec3::Y, s * Vec3::Z), // +x
        quad(Vec3::new(-h, -h, -h), s * Vec3::Z, s * Vec3::Y), // -x
        quad(Vec3::new(-h, h, -h), s * Vec3::Z, s * Vec3::X), // +y
        quad(Vec3::new(-h, -h, -h), s * Vec3::X, s * Vec3::Z), // -y
    ]
}

/// A sphere of `radius` sliding from `from` to `to` over the shutter's default interval.
fn sliding_sphere(radius: f32, from: Vec3, to: Vec3) -> MovingShape {
    MovingShape::new(
        Shape::Sphere(Sphere::new(Vec3::ZERO, radius)),
        AnimatedTransform::new(&[
            (DEFAULT_SHUTTER.open, Mat4::from_translation(from)),
            (DEFAULT_SHUTTER.close, Mat4::from_translation(to)),
        ])
        .expect("two translations are valid keyframes"),
    )
}

/// The faces of a cube of half-size `h` spinning by `turns` about `axis`, placed by `place`.
fn spinning_cube(
    h: f32,
    axis: Vec3,
    turns: f32,
    place: Mat4,
    material: Material,
) -> Vec<(MovingShape, Material)> {
    let motion = AnimatedTransform::spin(
        axis.normalize(),
        turns,
        DEFAULT_SHUTTER.open,
        DEFAULT_SHUTTER.close,
        place,
    );
    cube_faces(h)
        .into_iter()
        .map(|face| (MovingShape::new(face, motion.clone()), material))
        .collect()
}

/// Where the fast sphere of `street` starts and ends: far outside the frame on both sides.
pub const FAST_SPHERE_PATH: (Vec3, Vec3) = (Vec3::new(-4.0, 0.6, 1.6), Vec3::new(4.0, 0.6, 1.6));

fn street(max_depth: u32, shutter: Shutter) -> MotionScene {
    let floor = Shape::Quad(Quad::new(
        Vec3::new(-8.0, 0.0, -8.0),
        14.0 * Vec3::Z,
        16.0 * Vec3::X,
    ));
    let mirror = Shape::Quad(Quad::new(
        Vec3::new(-5.0, 0.0, -4.0),
        10.0 * Vec3::X,
        3.5 * Vec3::Y,
    ));
    let scene = SceneBuilder::new()
        .background(Vec3::new(0.45, 0.6, 0.85))
        .shape(
            floor,
            checkered(Vec3::new(0.8, 0.8, 0.75), Vec3::new(0.15, 0.15, 0.18), 8.0),
        )
        .shape(
            mirror,
            Material::Mirror {
                reflectance: Vec3::splat(0.85),
            },
        )
        .light(PointLight {
            position: Vec3::new(-3.0, 6.0, 5.0),
            intensity: Vec3::splat(60.0),
        })
        .light(PointLight {
            position: Vec3::new(4.0, 4.0, 2.0),
            intensity: Vec3::new(14.0, 12.0, 8.0),
        });
    let frame = CameraFrame::look_at(Vec3::new(0.0, 2.0, 7.0), Vec3::new(0.0, 0.7, 0.0), Vec3::Y)
        .expect("the camera looks along a valid direction");
    let scene = scene.build(PinholeCamera::new(frame, 50.0, 320, 200), max_depth);
    let mut moving = vec![
        (
            sliding_sphere(0.6, FAST_SPHERE_PATH.0, FAST_SPHERE_PATH.1),
            Material::diffuse(Vec3::new(0.95, 0.3, 0.1)),
        ),
        (
            sliding_sphere(0.6, Vec3::new(-2.2, 0.6, -1.0), Vec3::new(-1.7, 0.6, -1.0)),
            Material::diffuse(Vec3::new(0.2, 0.45, 0.85)),
        ),
    ];
    moving.extend(spinning_cube(
        0.55,
        Vec3::Y,
        SPIN_TURNS,
        Mat4::from_translation(Vec3::new(1.9, 0.55, -0.8)),
        checkered(Vec3::new(0.95, 0.8, 0.2), Vec3::new(0.1, 0.35, 0.15), 1.0),
    ));
    MotionScene::new(scene, moving, None, shutter)
}

fn spinner(max_depth: u32, shutter: Shutter) -> MotionScene {
    let scene = SceneBuilder::new()
        .background(Vec3::new(0.05, 0.05, 0.07))
        .light(PointLight {
            position: Vec3::new(-2.0, 3.0, 5.0),
            intensity: Vec3::splat(70.0),
        })
        .light(PointLight {
            position: Vec3::new(3.0, -1.0, 4.0),
            intensity: Vec3::splat(20.0),
        });
    let frame = CameraFrame::look_at(Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, Vec3::Y)
        .expect("the camera looks along a valid direction");
    let scene = scene.build(PinholeCamera::new(frame, 40.0, 200, 200), max_depth);
    let moving = spinning_cube(
        0.7,
        Vec3::new(0.3, 1.0, 0.2),
        SPIN_TURNS,
        Mat4::IDENTITY,
        checkered(Vec3::new(0.9, 0.85, 0.8), Vec3::new(0.7, 0.1, 0.1), 1.0),
    );
    MotionScene::new(scene, moving, None, shutter)
}

fn pan(max_depth: u32, shutter: Shutter) -> MotionScene {
    let scene = WhittedBuiltin::Spheres.build(max_depth);
    let start = scene.camera.frame;
    let end = CameraFrame::look_at(Vec3::new(0.8, 1.6, 5.0), Vec3::new(0.4, 0.7, 0.0), Vec3::Y)
        .expect("the camera looks along a valid direction");
    let motion = AnimatedTransform::new(&[
        (DEFAULT_SHUTTER.open, matrix_of(&start)),
        (DEFAULT_SHUTTER.close, matrix_of(&end)),
    ])
    .expect("two camera frames are valid keyframes");
    MotionScene::new(scene, Vec::new(), Some(motion), shutter)
}

/// The scene of the motion-bounds measurements: `rows x rows` small spheres on a floor, each
/// sliding sideways by `travel` while the shutter is open (alternate rows in opposite
/// directions). With a long travel, every sphere's box over the whole shutter covers most of
/// its row, and a ray must test all of the row's spheres.
pub fn swarm(rows: u32, travel: f32, shutter: Shutter) -> MotionScene {
    let floor = Shape::Quad(Quad::new(
        Vec3::new(-12.0, 0.0, -14.0),
        20.0 * Vec3::Z,
        24.0 * Vec3::X,
    ));
    let scene = SceneBuilder::new()
        .background(Vec3::new(0.45, 0.6, 0.85))
        .shape(floor, Material::diffuse(Vec3::splat(0.6)))
        .light(PointLight {
            position: Vec3::new(-3.0, 8.0, 6.0),
            intensity: Vec3::splat(120.0),
        });
    let frame = CameraFrame::look_at(Vec3::new(0.0, 5.0, 9.0), Vec3::new(0.0, 0.0, -3.0), Vec3::Y)
        .expect("the camera looks along a valid direction");
    let scene = scene.build(PinholeCamera::new(frame, 60.0, 240, 160), DEFAULT_MAX_DEPTH);
    let spacing = 16.0 / rows as f32;
    let radius = 0.35 * spacing;
    let mut moving = Vec::new();
    for row in 0..rows {
        let direction = if row % 2 == 0 { 1.0 } else { -1.0 };
        for column in 0..rows {
            let start = Vec3::new(
                -8.0 + (column as f32 + 0.5) * spacing - 0.5 * direction * travel,
                radius,
                -12.0 + (row as f32 + 0.5) * spacing,
            );
            let end = start + Vec3::new(direction * travel, 0.0, 0.0);
            let hue = (row * rows + column) as f32 / (rows * rows) as f32;
            let albedo = Vec3::new(0.2 + 0.7 * hue, 0.5, 0.9 - 0.7 * hue);
            moving.push((
                sliding_sphere(radius, start, end),
                Material::diffuse(albedo),
            ));
        }
    }
    MotionScene::new(scene, moving, None, shutter)
}
