//! The chapter's built-in scenes. Each takes a light scale, which `render --light-scale` and
//! the figures change: every area light grows (or shrinks) about its centre by the factor,
//! its radiance divided by the factor squared, so its power `π L A` stays the same and only
//! the shadows change.
//!
//! - `small` and `large`: the lecture's pair, one square panel over a ball and a block on a
//!   floor; a panel 0.25 wide casts nearly hard shadows, one 2.5 wide soft ones.
//! - `shapes`: one light of each shape (a parallelogram, a triangle, a disc, a sphere), each
//!   over its own ball.
//! - `several`: a red, a green and a blue disc light and a dim point light over one ball:
//!   every light casts its own shadow, coloured by the others.
//! - `glossy`: chapter 06's glossy floor reflecting a sphere light and a panel, with a mirror
//!   ball: the lights reach the floor's reflection only through the rays it traces.

use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::scenes::box_faces;
use common::geometry::{Disc, Parallelogram, Shape, Sphere, Triangle};
use common::scene::{Camera, CameraFrame, FilmSettings, Material, PointLight, SceneBuilder};
use glam::Vec3;

/// The scenes `render --builtin NAME` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum Builtin {
    /// The lecture's small light: a panel 0.25 wide, nearly hard shadows.
    Small,
    /// The lecture's large light: a panel 2.5 wide, soft shadows.
    Large,
    /// One light of each shape: parallelogram, triangle, disc, sphere.
    Shapes,
    /// Red, green and blue disc lights and a point light over one ball.
    Several,
    /// A glossy floor reflecting a sphere light and a panel.
    Glossy,
}

/// The recursion limit of the built-in scenes.
pub const DEFAULT_MAX_DEPTH: u32 = 12;

/// The side of the small panel; the large one is ten times wider.
pub const SMALL_PANEL: f32 = 0.25;

impl Builtin {
    /// Every built-in scene.
    pub const ALL: [Builtin; 5] = [
        Builtin::Small,
        Builtin::Large,
        Builtin::Shapes,
        Builtin::Several,
        Builtin::Glossy,
    ];

    /// Builds the scene with every area light scaled by `light_scale` (power kept).
    pub fn build(self, max_depth: u32, light_scale: f32) -> MotionScene {
        match self {
            Builtin::Small => panel(SMALL_PANEL * light_scale, max_depth),
            Builtin::Large => panel(10.0 * SMALL_PANEL * light_scale, max_depth),
            Builtin::Shapes => shapes(light_scale, max_depth),
            Builtin::Several => several(light_scale, max_depth),
            Builtin::Glossy => glossy(light_scale, max_depth),
        }
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Builtin::Small => "small",
            Builtin::Large => "large",
            Builtin::Shapes => "shapes",
            Builtin::Several => "several",
            Builtin::Glossy => "glossy",
        }
    }
}

/// Shapes with materials, area lights and point lights.
pub struct Builder {
    scene: SceneBuilder,
}

impl Builder {
    /// An empty scene with a black background.
    pub fn new() -> Self {
        Self {
            scene: SceneBuilder::new(),
        }
    }

    /// Adds a shape made of `material`.
    pub fn shape(mut self, shape: Shape, material: Material) -> Self {
        self.scene = self.scene.shape(shape, material);
        self
    }

    /// Adds the six faces of the box `[min, max]`.
    pub fn block(self, min: Vec3, max: Vec3, material: Material) -> Self {
        box_faces(min, max)
            .into_iter()
            .fold(self, |builder, face| builder.shape(face, material.clone()))
    }

    /// Adds an area light: `shape` glowing with `radiance` on its front side, its surface
    /// black (a lamp that reflects nothing).
    pub fn area_light(mut self, shape: Shape, radiance: Vec3) -> Self {
        self.scene = self.scene.area_light(shape, matte(Vec3::ZERO), radiance);
        self
    }

    /// Adds a point light.
    pub fn point_light(mut self, position: Vec3, intensity: Vec3) -> Self {
        self.scene = self.scene.light(PointLight {
            position,
            intensity,
        });
        self
    }

    /// Builds the BVH and the scene.
    pub fn build(self, (camera, film): (Camera, FilmSettings), max_depth: u32) -> MotionScene {
        MotionScene::still(self.scene.build(camera, film, max_depth))
    }
}

impl Default for Builder {
    fn default() -> Self {
        Self::new()
    }
}

/// A matte material of `albedo`.
pub fn matte(albedo: Vec3) -> Material {
    Material::diffuse(albedo)
}

/// The camera of the built-in scenes: 320 x 240, looking from `origin` at `target`.
pub fn camera(origin: Vec3, target: Vec3, fov_x_degrees: f32) -> (Camera, FilmSettings) {
    let frame = CameraFrame::look_at(origin, target, Vec3::Y)
        .expect("the camera looks along a valid direction");
    (
        Camera::pinhole(frame, fov_x_degrees),
        FilmSettings::new(320, 240),
    )
}

/// The square panel of side `side` centred at `center`, facing down (`e1 × e2 = x × z = -y`).
pub fn ceiling_panel(center: Vec3, side: f32) -> Shape {
    let half = 0.5 * side;
    Shape::Parallelogram(Parallelogram::new(
        center - Vec3::new(half, 0.0, half),
        side * Vec3::X,
        side * Vec3::Z,
    ))
}

/// A floor `2 half` wide at `y = 0`, facing up.
pub fn floor(half: f32) -> Shape {
    Shape::Parallelogram(Parallelogram::new(
        Vec3::new(-half, 0.0, -half),
        2.0 * half * Vec3::Z,
        2.0 * half * Vec3::X,
    ))
}

fn sphere(center: Vec3, radius: f32) -> Shape {
    Shape::Sphere(Sphere::new(center, radius))
}

/// The power of every built-in light, as radiance times area.
const RADIANCE_AREA: f32 = 10.0;

const FLOOR: Vec3 = Vec3::new(0.7, 0.7, 0.7);
const RED: Vec3 = Vec3::new(0.8, 0.2, 0.15);
const BLUE: Vec3 = Vec3::new(0.2, 0.35, 0.8);

/// The lecture's scene: a panel of side `side` at height 3 over a ball and a block.
fn panel(side: f32, max_depth: u32) -> MotionScene {
    let radiance = Vec3::splat(RADIANCE_AREA / (side * side));
    Builder::new()
        .shape(floor(8.0), matte(FLOOR))
        .shape(
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(-8.0, 0.0, -2.5),
                16.0 * Vec3::X,
                6.0 * Vec3::Y,
            )),
            matte(Vec3::splat(0.6)),
        )
        .shape(sphere(Vec3::new(-0.9, 0.6, 0.3), 0.6), matte(RED))
        .block(
            Vec3::new(0.5, 0.0, -0.6),
            Vec3::new(1.4, 0.9, 0.3),
            matte(BLUE),
        )
        .area_light(ceiling_panel(Vec3::new(0.0, 3.0, 0.5), side), radiance)
        .build(
            camera(Vec3::new(0.0, 2.0, 6.5), Vec3::new(0.0, 0.6, 0.0), 42.0),
            max_depth,
        )
}

/// One light of each shape, each over its own ball, all of the same power.
fn shapes(scale: f32, max_depth: u32) -> MotionScene {
    let s = scale;
    let h = 2.2;
    let radiance = |area: f32| Vec3::new(1.0, 0.95, 0.85) * (0.5 * RADIANCE_AREA / area);
    // A parallelogram tilted towards the camera, a triangle, a disc, a sphere: each 0.6 across.
    let e1 = 0.6 * s * Vec3::X;
    let e2 = 0.6 * s * Vec3::new(0.3, 0.2, 1.0).normalize();
    let parallelogram = Parallelogram::new(Vec3::new(-3.0, h, -0.3) - 0.5 * (e1 + e2), e1, e2);
    let triangle = Triangle::new(
        Vec3::new(-1.0, h, -0.35 * s),
        Vec3::new(-1.0 + 0.35 * s, h, 0.3 * s),
        Vec3::new(-1.0 - 0.35 * s, h, 0.3 * s),
    );
    let disc = Disc::new(Vec3::new(1.0, h, 0.0), -Vec3::Y, 0.35 * s);
    let ball = Sphere::new(Vec3::new(3.0, h, 0.0), 0.3 * s);
    let mut builder = Builder::new().shape(floor(10.0), matte(FLOOR));
    for (x, colour) in [
        (-3.0, RED),
        (-1.0, Vec3::new(0.2, 0.7, 0.3)),
        (1.0, BLUE),
        (3.0, Vec3::new(0.85, 0.75, 0.2)),
    ] {
        builder = builder.shape(sphere(Vec3::new(x, 0.45, 0.0), 0.45), matte(colour));
    }
    builder
        .area_light(
            Shape::Parallelogram(parallelogram),
            radiance(parallelogram.area()),
        )
        .area_light(Shape::Triangle(triangle), radiance(triangle.area()))
        .area_light(Shape::Disc(disc), radiance(disc.area()))
        // A sphere of the same power shines with a quarter of a panel's radiance per area.
        .area_light(Shape::Sphere(ball), radiance(ball.area()))
        .build(
            camera(Vec3::new(0.0, 1.3, 7.5), Vec3::new(0.0, 1.1, 0.0), 55.0),
            max_depth,
        )
}

/// Red, green and blue discs and a dim white point light over one ball.
fn several(scale: f32, max_depth: u32) -> MotionScene {
    let radius = 0.4 * scale;
    let area = std::f32::consts::PI * radius * radius;
    let mut builder = Builder::new()
        .shape(floor(8.0), matte(Vec3::splat(0.8)))
        .shape(
            sphere(Vec3::new(0.0, 0.6, 0.0), 0.6),
            matte(Vec3::splat(0.8)),
        )
        .point_light(Vec3::new(0.0, 5.0, 3.0), Vec3::splat(3.0));
    for (angle, colour) in [
        (90.0f32, Vec3::new(1.0, 0.1, 0.1)),
        (210.0, Vec3::new(0.1, 1.0, 0.1)),
        (330.0, Vec3::new(0.1, 0.1, 1.0)),
    ] {
        let (sin, cos) = angle.to_radians().sin_cos();
        let center = Vec3::new(1.5 * cos, 3.0, 1.5 * sin);
        // Each disc faces the ball.
        let normal = (Vec3::new(0.0, 0.6, 0.0) - center).normalize();
        builder = builder.area_light(
            Shape::Disc(Disc::new(center, normal, radius)),
            colour * (RADIANCE_AREA / area),
        );
    }
    builder.build(
        camera(Vec3::new(0.0, 3.5, 6.0), Vec3::new(0.0, 0.4, 0.0), 45.0),
        max_depth,
    )
}

/// Chapter 06's glossy floor reflecting a sphere light and a panel; a mirror ball.
fn glossy(scale: f32, max_depth: u32) -> MotionScene {
    let ball = Sphere::new(Vec3::new(1.2, 1.2, -1.5), 0.25 * scale);
    let side = 1.2 * scale;
    Builder::new()
        .shape(floor(8.0), Material::glossy(Vec3::splat(0.8), 200.0))
        .shape(
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(-8.0, 0.0, -3.0),
                16.0 * Vec3::X,
                6.0 * Vec3::Y,
            )),
            matte(Vec3::splat(0.6)),
        )
        .shape(sphere(Vec3::new(-1.3, 0.5, -0.6), 0.5), matte(RED))
        .shape(sphere(Vec3::new(0.1, 0.6, -1.0), 0.6), Material::mirror())
        .shape(sphere(Vec3::new(1.5, 0.4, 0.2), 0.4), matte(BLUE))
        .area_light(
            Shape::Sphere(ball),
            Vec3::new(1.0, 0.85, 0.6) * (RADIANCE_AREA / ball.area()),
        )
        .area_light(
            ceiling_panel(Vec3::new(-0.8, 3.0, 0.5), side),
            Vec3::splat(RADIANCE_AREA / (side * side)),
        )
        .build(
            camera(Vec3::new(0.0, 0.9, 5.0), Vec3::new(0.0, 0.5, 0.0), 45.0),
            max_depth,
        )
}
