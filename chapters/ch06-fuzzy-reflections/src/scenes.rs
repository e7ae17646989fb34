//! The chapter's built-in scenes. Each has one roughness, the exponent `n` of its lobes,
//! which `render --exponent` and the figures change.
//!
//! - `floor`: a glossy floor in front of a checkered wall, with three matte balls and a
//!   mirror ball on it and a low lamp behind them: the reflections of the balls, the wall and
//!   the lamp blur as the floor gets rougher.
//! - `frosted`: a pane of frosted glass in front of coloured balls and a checkered wall.
//! - `plates`: two glossy plates facing each other, two balls between them: reflections of
//!   reflections, each one blurrier than the last.
//! - `panes`: four smooth glass panes and a glass ball in front of a checkered wall: every
//!   ray splits at eight or more surfaces, where following both rays explodes.

use ch05_motion_blur::MotionScene;
use common::geometry::{Parallelogram, Shape, Sphere};
use common::scene::{
    Camera, CameraFrame, Checkerboard, FilmSettings, Material, PointLight, Scene, SceneBuilder,
    Texture,
};
use glam::{Vec2, Vec3};

/// The scenes `render --builtin NAME` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum Builtin {
    /// A glossy floor reflecting balls, a wall and a lamp: the chapter's scene.
    Floor,
    /// A frosted glass pane in front of balls and a wall.
    Frosted,
    /// Two glossy plates facing each other.
    Plates,
    /// Smooth glass panes and a glass ball: where tracing both rays explodes.
    Panes,
}

/// The recursion limit of the built-in scenes.
pub const DEFAULT_MAX_DEPTH: u32 = 12;

impl Builtin {
    /// Every built-in scene.
    pub const ALL: [Builtin; 4] = [
        Builtin::Floor,
        Builtin::Frosted,
        Builtin::Plates,
        Builtin::Panes,
    ];

    /// The scene with lobes of `exponent`, made ready for tracing.
    pub fn build(self, max_depth: u32, exponent: f32) -> MotionScene {
        MotionScene::still(self.scene(max_depth, exponent))
    }

    /// The scene with lobes of `exponent`.
    pub fn scene(self, max_depth: u32, exponent: f32) -> Scene {
        match self {
            Builtin::Floor => floor(max_depth, exponent),
            Builtin::Frosted => frosted(max_depth, exponent),
            Builtin::Plates => plates(max_depth, exponent),
            Builtin::Panes => panes(max_depth),
        }
    }

    /// The exponent the scene is shown with by default.
    pub fn default_exponent(self) -> f32 {
        match self {
            Builtin::Floor => 100.0,
            Builtin::Frosted => 10.0,
            Builtin::Plates => 1000.0,
            Builtin::Panes => 1e6,
        }
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Builtin::Floor => "floor",
            Builtin::Frosted => "frosted",
            Builtin::Plates => "plates",
            Builtin::Panes => "panes",
        }
    }
}

/// Shapes with materials and point lights, built into a still scene.
struct Builder {
    scene: SceneBuilder,
}

impl Builder {
    fn new(background: Vec3) -> Self {
        Self {
            scene: SceneBuilder::new().environment(background),
        }
    }

    fn shape(mut self, shape: Shape, material: Material) -> Self {
        self.scene = self.scene.shape(shape, material);
        self
    }

    fn shapes(self, shapes: impl IntoIterator<Item = Shape>, material: Material) -> Self {
        shapes.into_iter().fold(self, |builder, shape| {
            builder.shape(shape, material.clone())
        })
    }

    fn light(mut self, position: Vec3, intensity: Vec3) -> Self {
        self.scene = self.scene.light(PointLight {
            position,
            intensity,
        });
        self
    }

    fn build(self, (camera, film): (Camera, FilmSettings), max_depth: u32) -> Scene {
        self.scene.build(camera, film, max_depth)
    }
}

fn matte(albedo: Vec3) -> Material {
    Material::diffuse(albedo)
}

fn checkered(colour0: Vec3, colour1: Vec3, scale: Vec2) -> Material {
    Material::TexturedDiffuse {
        texture: Texture::Checkerboard(Checkerboard::scaled(colour0, colour1, scale)),
        two_sided: false,
    }
}

fn quad(corner: Vec3, e1: Vec3, e2: Vec3) -> Shape {
    Shape::Parallelogram(Parallelogram::new(corner, e1, e2))
}

fn sphere(center: Vec3, radius: f32) -> Shape {
    Shape::Sphere(Sphere::new(center, radius))
}

/// The six faces of the box `[min, max]`, normals out.
pub fn box_faces(min: Vec3, max: Vec3) -> [Shape; 6] {
    let d = max - min;
    let (dx, dy, dz) = (d.x * Vec3::X, d.y * Vec3::Y, d.z * Vec3::Z);
    [
        quad(Vec3::new(min.x, min.y, max.z), dx, dy), // +z
        quad(min, dy, dx),                            // -z
        quad(Vec3::new(max.x, min.y, min.z), dy, dz), // +x
        quad(min, dz, dy),                            // -x
        quad(Vec3::new(min.x, max.y, min.z), dz, dx), // +y
        quad(min, dx, dz),                            // -y
    ]
}

fn camera(origin: Vec3, target: Vec3, fov_x_degrees: f32) -> (Camera, FilmSettings) {
    let frame = CameraFrame::look_at(origin, target, Vec3::Y)
        .expect("the camera looks along a valid direction");
    (
        Camera::pinhole(frame, fov_x_degrees),
        FilmSettings::new(320, 240),
    )
}

/// A checkered wall facing +z at depth `z`, `width` wide and `height` high, standing on y = 0.
fn wall(z: f32, width: f32, height: f32) -> Shape {
    quad(
        Vec3::new(-0.5 * width, 0.0, z),
        width * Vec3::X,
        height * Vec3::Y,
    )
}

const WALL_LIGHT: Vec3 = Vec3::new(0.85, 0.85, 0.8);
const WALL_DARK: Vec3 = Vec3::new(0.15, 0.2, 0.35);
const SKY: Vec3 = Vec3::new(0.35, 0.45, 0.6);

fn floor(max_depth: u32, exponent: f32) -> Scene {
    Builder::new(SKY)
        // The floor, facing up: e1 x e2 = z x x = +y.
        .shape(
            quad(Vec3::new(-8.0, 0.0, -8.0), 16.0 * Vec3::Z, 16.0 * Vec3::X),
            Material::glossy(Vec3::splat(0.8), exponent),
        )
        .shape(
            wall(-3.0, 16.0, 6.0),
            checkered(WALL_LIGHT, WALL_DARK, Vec2::new(8.0, 3.0)),
        )
        .shape(
            sphere(Vec3::new(-1.6, 0.5, -0.8), 0.5),
            matte(Vec3::new(0.8, 0.15, 0.1)),
        )
        .shape(sphere(Vec3::new(-0.3, 0.7, -1.4), 0.7), Material::mirror())
        .shape(
            sphere(Vec3::new(0.9, 0.45, -0.2), 0.45),
            matte(Vec3::new(0.15, 0.6, 0.2)),
        )
        .shape(
            sphere(Vec3::new(2.0, 0.35, 0.5), 0.35),
            matte(Vec3::new(0.15, 0.3, 0.85)),
        )
        .light(Vec3::new(-3.0, 6.0, 4.0), Vec3::splat(60.0))
        // Low and behind the balls: its highlight on the floor is in view.
        .light(Vec3::new(1.2, 1.0, -2.2), Vec3::new(3.0, 2.6, 2.0))
        .build(
            camera(Vec3::new(0.0, 0.9, 5.0), Vec3::new(0.0, 0.45, 0.0), 45.0),
            max_depth,
        )
}

fn frosted(max_depth: u32, exponent: f32) -> Scene {
    Builder::new(SKY)
        .shape(
            quad(Vec3::new(-8.0, 0.0, -8.0), 16.0 * Vec3::Z, 16.0 * Vec3::X),
            matte(Vec3::splat(0.6)),
        )
        .shape(
            wall(-2.5, 16.0, 6.0),
            checkered(WALL_LIGHT, WALL_DARK, Vec2::new(16.0, 6.0)),
        )
        .shape(
            sphere(Vec3::new(-0.6, 0.45, -1.2), 0.45),
            matte(Vec3::new(0.85, 0.2, 0.1)),
        )
        .shape(
            sphere(Vec3::new(0.6, 0.6, -1.6), 0.6),
            matte(Vec3::new(0.2, 0.4, 0.9)),
        )
        // The pane: 2.4 wide, 1.8 high, 0.1 thick, standing in front of the balls.
        .shapes(
            box_faces(Vec3::new(-1.2, 0.0, -0.05), Vec3::new(1.2, 1.8, 0.05)),
            Material::rough_glass(1.5, exponent),
        )
        .light(Vec3::new(-2.0, 5.0, 3.0), Vec3::splat(40.0))
        .light(Vec3::new(2.0, 3.0, -0.5), Vec3::splat(8.0))
        .build(
            camera(Vec3::new(0.0, 1.0, 4.0), Vec3::new(0.0, 0.8, 0.0), 45.0),
            max_depth,
        )
}

fn plates(max_depth: u32, exponent: f32) -> Scene {
    let plate = Material::glossy(Vec3::new(0.9, 0.85, 0.7), exponent);
    Builder::new(SKY)
        .shape(
            quad(Vec3::new(-8.0, 0.0, -8.0), 16.0 * Vec3::Z, 16.0 * Vec3::X),
            checkered(WALL_LIGHT, WALL_DARK, Vec2::splat(16.0)),
        )
        // Two plates facing each other across x = 0, 2.4 apart: normals +x and -x.
        .shape(
            quad(Vec3::new(-1.2, 0.0, -5.0), 2.0 * Vec3::Y, 8.0 * Vec3::Z),
            plate.clone(),
        )
        .shape(
            quad(Vec3::new(1.2, 0.0, -5.0), 8.0 * Vec3::Z, 2.0 * Vec3::Y),
            plate,
        )
        .shape(
            sphere(Vec3::new(0.3, 0.4, -1.0), 0.4),
            matte(Vec3::new(0.85, 0.2, 0.1)),
        )
        .shape(
            sphere(Vec3::new(-0.5, 0.3, -2.5), 0.3),
            matte(Vec3::new(0.2, 0.4, 0.9)),
        )
        .light(Vec3::new(0.0, 5.0, 2.0), Vec3::splat(40.0))
        .build(
            camera(Vec3::new(0.9, 0.9, 1.5), Vec3::new(-1.2, 0.6, -1.0), 55.0),
            max_depth,
        )
}

fn panes(max_depth: u32) -> Scene {
    let glass = Material::glass(1.5);
    let mut builder = Builder::new(SKY)
        .shape(
            quad(Vec3::new(-8.0, 0.0, -8.0), 16.0 * Vec3::Z, 16.0 * Vec3::X),
            matte(Vec3::splat(0.6)),
        )
        .shape(
            wall(-3.0, 16.0, 6.0),
            checkered(WALL_LIGHT, WALL_DARK, Vec2::new(16.0, 6.0)),
        )
        .shape(sphere(Vec3::new(-0.9, 0.5, 0.6), 0.5), glass.clone());
    for k in 0..4 {
        let z = -2.2 + 0.5 * k as f32;
        builder = builder.shapes(
            box_faces(Vec3::new(-0.2, 0.0, z), Vec3::new(1.8, 1.6, z + 0.06)),
            glass.clone(),
        );
    }
    builder
        .light(Vec3::new(-2.0, 5.0, 3.0), Vec3::splat(40.0))
        .build(
            camera(Vec3::new(0.0, 1.0, 4.0), Vec3::new(0.2, 0.7, 0.0), 45.0),
            max_depth,
        )
}
