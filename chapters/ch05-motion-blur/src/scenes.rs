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
use crate::shutter::Shutter;
use crate::world::MotionScene;
use ch01_whitted::scenes::{Builtin as WhittedBuiltin, DEFAULT_MAX_DEPTH as WHITTED_MAX_DEPTH};
use common::geometry::{Parallelogram, Shape, Sphere};
use common::scene::{
    Camera, CameraFrame, Checkerboard, FilmSettings, Material, PointLight, Scene, SceneBuilder,
    Texture,
};
use glam::{Mat4, Vec2, Vec3};

/// The scenes `render --builtin NAME` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum Builtin {
    /// A fast and a slow sphere, a spinning cube and a mirror: the chapter's scene.
    Street,
    /// A cube spinning by more than a full turn.
    Spinner,
    /// Chapter 01's spheres seen by a moving camera.
    Pan,
}

/// The recursion limit of the built-in scenes: chapter 01's.
pub const DEFAULT_MAX_DEPTH: u32 = WHITTED_MAX_DEPTH;

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

    /// The scene, seen through `shutter`.
    pub fn scene(self, max_depth: u32, shutter: Shutter) -> Scene {
        let mut scene = match self {
            Builtin::Street => street(max_depth),
            Builtin::Spinner => spinner(max_depth),
            Builtin::Pan => pan(max_depth),
        };
        with_shutter(&mut scene, shutter);
        scene
    }

    /// The scene, seen through `shutter`, made ready for tracing.
    pub fn build(self, max_depth: u32, shutter: Shutter) -> MotionScene {
        MotionScene::still(self.scene(max_depth, shutter))
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
    Material::TexturedDiffuse {
        texture: Texture::Checkerboard(Checkerboard::scaled(colour0, colour1, Vec2::splat(scale))),
        two_sided: false,
    }
}

/// The six faces of the cube `[-h, h]^3`, normals out.
pub fn cube_faces(h: f32) -> [Shape; 6] {
    let quad =
        |corner: Vec3, e1: Vec3, e2: Vec3| Shape::Parallelogram(Parallelogram::new(corner, e1, e2));
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

/// Sets the shutter through which `scene` is seen.
fn with_shutter(scene: &mut Scene, shutter: Shutter) {
    scene.camera.shutter_open = shutter.open;
    scene.camera.shutter_close = shutter.close;
}

/// `builder` with a sphere of `radius` sliding from `from` to `to` over the shutter's default
/// interval.
fn sliding_sphere(
    builder: SceneBuilder,
    radius: f32,
    from: Vec3,
    to: Vec3,
    material: Material,
) -> SceneBuilder {
    let keyframes = vec![
        (DEFAULT_SHUTTER.open, Mat4::from_translation(from)),
        (DEFAULT_SHUTTER.close, Mat4::from_translation(to)),
    ];
    builder.moving(
        Shape::Sphere(Sphere::new(Vec3::ZERO, radius)),
        keyframes,
        material,
    )
}

/// `builder` with the faces of a cube of half-size `h` spinning by `turns` about `axis`,
/// placed by `place`.
fn spinning_cube(
    mut builder: SceneBuilder,
    h: f32,
    axis: Vec3,
    turns: f32,
    place: Mat4,
    material: Material,
) -> SceneBuilder {
    let motion = AnimatedTransform::spin(
        axis.normalize(),
        turns,
        DEFAULT_SHUTTER.open,
        DEFAULT_SHUTTER.close,
        place,
    );
    let keyframes: Vec<(f32, Mat4)> = motion
        .keyframes()
        .iter()
        .map(|keyframe| (keyframe.time, keyframe.matrix))
        .collect();
    for face in cube_faces(h) {
        builder = builder.moving(face, keyframes.clone(), material.clone());
    }
    builder
}

/// Where the fast sphere of `street` starts and ends: far outside the frame on both sides.
pub const FAST_SPHERE_PATH: (Vec3, Vec3) = (Vec3::new(-4.0, 0.6, 1.6), Vec3::new(4.0, 0.6, 1.6));

fn street(max_depth: u32) -> Scene {
    let floor = Shape::Parallelogram(Parallelogram::new(
        Vec3::new(-8.0, 0.0, -8.0),
        14.0 * Vec3::Z,
        16.0 * Vec3::X,
    ));
    let mirror = Shape::Parallelogram(Parallelogram::new(
        Vec3::new(-5.0, 0.0, -4.0),
        10.0 * Vec3::X,
        3.5 * Vec3::Y,
    ));
    let scene = SceneBuilder::new()
        .environment(Vec3::new(0.45, 0.6, 0.85))
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
    let scene = sliding_sphere(
        scene,
        0.6,
        FAST_SPHERE_PATH.0,
        FAST_SPHERE_PATH.1,
        Material::diffuse(Vec3::new(0.95, 0.3, 0.1)),
    );
    let scene = sliding_sphere(
        scene,
        0.6,
        Vec3::new(-2.2, 0.6, -1.0),
        Vec3::new(-1.7, 0.6, -1.0),
        Material::diffuse(Vec3::new(0.2, 0.45, 0.85)),
    );
    let scene = spinning_cube(
        scene,
        0.55,
        Vec3::Y,
        SPIN_TURNS,
        Mat4::from_translation(Vec3::new(1.9, 0.55, -0.8)),
        checkered(Vec3::new(0.95, 0.8, 0.2), Vec3::new(0.1, 0.35, 0.15), 1.0),
    );
    scene.build(
        Camera::pinhole(frame, 50.0),
        FilmSettings::new(320, 200),
        max_depth,
    )
}

fn spinner(max_depth: u32) -> Scene {
    let scene = SceneBuilder::new()
        .environment(Vec3::new(0.05, 0.05, 0.07))
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
    spinning_cube(
        scene,
        0.7,
        Vec3::new(0.3, 1.0, 0.2),
        SPIN_TURNS,
        Mat4::IDENTITY,
        checkered(Vec3::new(0.9, 0.85, 0.8), Vec3::new(0.7, 0.1, 0.1), 1.0),
    )
    .build(
        Camera::pinhole(frame, 40.0),
        FilmSettings::new(200, 200),
        max_depth,
    )
}

fn pan(max_depth: u32) -> Scene {
    let mut scene = WhittedBuiltin::Spheres.build(max_depth);
    let start = scene.camera.frame;
    let end = CameraFrame::look_at(Vec3::new(0.8, 1.6, 5.0), Vec3::new(0.4, 0.7, 0.0), Vec3::Y)
        .expect("the camera looks along a valid direction");
    scene.camera.keyframes = vec![
        (DEFAULT_SHUTTER.open, start.to_matrix()),
        (DEFAULT_SHUTTER.close, end.to_matrix()),
    ];
    scene
}

/// The scene of the motion-bounds measurements: `rows x rows` small spheres on a floor, each
/// sliding sideways by `travel` while the shutter is open (alternate rows in opposite
/// directions). With a long travel, every sphere's box over the whole shutter covers most of
/// its row, and a ray must test all of the row's spheres.
pub fn swarm(rows: u32, travel: f32, shutter: Shutter) -> MotionScene {
    let floor = Shape::Parallelogram(Parallelogram::new(
        Vec3::new(-12.0, 0.0, -14.0),
        20.0 * Vec3::Z,
        24.0 * Vec3::X,
    ));
    let scene = SceneBuilder::new()
        .environment(Vec3::new(0.45, 0.6, 0.85))
        .shape(floor, Material::diffuse(Vec3::splat(0.6)))
        .light(PointLight {
            position: Vec3::new(-3.0, 8.0, 6.0),
            intensity: Vec3::splat(120.0),
        });
    let frame = CameraFrame::look_at(Vec3::new(0.0, 5.0, 9.0), Vec3::new(0.0, 0.0, -3.0), Vec3::Y)
        .expect("the camera looks along a valid direction");
    let mut scene = scene;
    let spacing = 16.0 / rows as f32;
    let radius = 0.35 * spacing;
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
            scene = sliding_sphere(scene, radius, start, end, Material::diffuse(albedo));
        }
    }
    let mut scene = scene.build(
        Camera::pinhole(frame, 60.0),
        FilmSettings::new(240, 160),
        DEFAULT_MAX_DEPTH,
    );
    with_shutter(&mut scene, shutter);
    MotionScene::still(scene)
}
