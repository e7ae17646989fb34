//! The chapter's built-in scenes, each with the lens it is meant to be seen through.
//!
//! Depth of field needs depth: objects near, at middle distance and far away, so that one
//! focus setting leaves some sharp and others blurred. And it needs small bright lights out of
//! focus, because a blurred point of light draws the aperture's shape (bokeh). Chapter 01's
//! tracer has no emitting surfaces, so the lights are the bright background seen through
//! small holes in a dark far wall: city lights through a curtain, costing no light sampling.

use crate::lens::Lens;
use ch01_whitted::scenes::{Builtin as WhittedBuiltin, DEFAULT_MAX_DEPTH as WHITTED_MAX_DEPTH};
use common::geometry::{Parallelogram, Shape, Sphere};
use common::scene::CameraFrame;
use common::scene::Material;
use common::scene::PointLight;
use common::scene::{Camera, FilmSettings, Scene, SceneBuilder};
use glam::Vec3;

/// The scenes `render --builtin NAME` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum Builtin {
    /// Three spheres at three depths on a checkerboard, a dark wall far behind with small
    /// bright holes: the chapter's scene.
    Bokeh,
    /// Chapter 01's glass and mirror spheres, focused on the glass sphere.
    Spheres,
    /// Chapter 01's Cornell box, focused on the back wall.
    Cornell,
}

/// Distances from the bokeh scene's camera to its three spheres, along the viewing axis:
/// near, middle and far, the three focus settings of the chapter's figures.
pub const BOKEH_SPHERE_DEPTHS: [f32; 3] = [3.5, 7.0, 12.0];

/// The distance from the bokeh scene's camera to its far wall, along the viewing axis.
pub const BOKEH_WALL_DEPTH: f32 = 16.0;

impl Builtin {
    /// Builds the scene with recursion limit `max_depth` (Mitsuba's count).
    pub fn build(self, max_depth: u32) -> Scene {
        match self {
            Builtin::Bokeh => bokeh(max_depth),
            Builtin::Spheres => WhittedBuiltin::Spheres.build(max_depth),
            Builtin::Cornell => WhittedBuiltin::Cornell.build(max_depth),
        }
    }

    /// The lens the scene is shown with when the command line names none.
    pub fn default_lens(self) -> Lens {
        let lens = match self {
            Builtin::Bokeh => Lens::new(0.12, BOKEH_SPHERE_DEPTHS[1]),
            // The glass sphere is about 4.7 from the camera.
            Builtin::Spheres => Lens::new(0.08, 4.7),
            Builtin::Cornell => Lens::new(0.05, 4.9),
        };
        lens.expect("the built-in lenses are valid")
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Builtin::Bokeh => "bokeh",
            Builtin::Spheres => "spheres",
            Builtin::Cornell => "cornell",
        }
    }
}

/// The recursion limit of the built-in scenes: chapter 01's.
pub const DEFAULT_MAX_DEPTH: u32 = WHITTED_MAX_DEPTH;

/// Radiance of the background seen through the holes of the far wall: much brighter than any
/// lit surface, so that a hole stays bright even when its light is spread over a blur disc
/// hundreds of times its size.
pub const HOLE_RADIANCE: Vec3 = Vec3::new(12.0, 8.5, 4.5);

/// Side of a square hole in the far wall.
const HOLE_SIZE: f32 = 0.16;

/// The bokeh scene. The camera stands at z = 7 looking down -z, so a point at world z has
/// depth about `7 - z`.
fn bokeh(max_depth: u32) -> Scene {
    let camera_z = 7.0;
    let mut builder = SceneBuilder::new().environment(HOLE_RADIANCE);
    // A checkerboard floor from the camera to the wall: its lines show the blur growing with
    // distance from the focal plane.
    let wall_z = camera_z - BOKEH_WALL_DEPTH;
    for i in -7..7 {
        for j in 0..((camera_z - wall_z) as i32 + 1) {
            let corner = Vec3::new(i as f32, 0.0, wall_z + j as f32);
            let albedo = if (i + j).rem_euclid(2) == 0 {
                Vec3::new(0.75, 0.75, 0.7)
            } else {
                Vec3::new(0.12, 0.12, 0.14)
            };
            builder = builder.shape(
                Shape::Parallelogram(Parallelogram::new(corner, Vec3::Z, Vec3::X)),
                Material::diffuse(albedo),
            );
        }
    }
    let spheres = [
        (-1.1, 0.45, Vec3::new(0.8, 0.15, 0.1)),
        (0.5, 0.6, Vec3::new(0.85, 0.85, 0.8)),
        (-0.3, 0.9, Vec3::new(0.15, 0.6, 0.25)),
    ];
    for ((x, radius, albedo), depth) in spheres.into_iter().zip(BOKEH_SPHERE_DEPTHS) {
        builder = builder.shape(
            Shape::Sphere(Sphere::new(Vec3::new(x, radius, camera_z - depth), radius)),
            Material::diffuse(albedo),
        );
    }
    builder = far_wall_with_holes(builder, wall_z);
    let scene = builder
        .light(PointLight {
            position: Vec3::new(3.0, 6.0, 6.0),
            intensity: Vec3::splat(60.0),
        })
        .light(PointLight {
            position: Vec3::new(-4.0, 3.0, -2.0),
            intensity: Vec3::new(8.0, 9.0, 14.0),
        });
    let frame = CameraFrame::look_at(
        Vec3::new(0.0, 1.0, camera_z),
        Vec3::new(0.0, 0.75, 0.0),
        Vec3::Y,
    )
    .expect("the camera looks along a valid direction");
    scene.build(
        Camera::pinhole(frame, 40.0),
        FilmSettings::new(360, 240),
        max_depth,
    )
}

/// A dark wall facing the camera at `z = wall_z`, tall and wide enough to fill the view behind
/// the scene, with a row of small square holes in it at two heights.
fn far_wall_with_holes(mut builder: SceneBuilder, wall_z: f32) -> SceneBuilder {
    let dark = Material::diffuse(Vec3::splat(0.05));
    // Parallelograms facing +z (towards the camera): e1 x e2 = X x Y = +Z.
    let panel = |builder: SceneBuilder, x0: f32, x1: f32, y0: f32, y1: f32| {
        if x1 <= x0 || y1 <= y0 {
            return builder;
        }
        builder.shape(
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(x0, y0, wall_z),
                (x1 - x0) * Vec3::X,
                (y1 - y0) * Vec3::Y,
            )),
            dark.clone(),
        )
    };
    let (left, right, top) = (-16.0, 16.0, 14.0);
    let rows: [(f32, &[f32]); 2] = [
        (1.3, &[-4.2, -3.1, -1.9, -0.6, 0.8, 2.1, 3.3, 4.5]),
        (2.6, &[-3.6, -1.2, 1.5, 3.9]),
    ];
    let mut y = 0.0;
    for (row_y, xs) in rows {
        builder = panel(builder, left, right, y, row_y);
        let mut x = left;
        for &hole_x in xs {
            builder = panel(builder, x, hole_x, row_y, row_y + HOLE_SIZE);
            x = hole_x + HOLE_SIZE;
        }
        builder = panel(builder, x, right, row_y, row_y + HOLE_SIZE);
        y = row_y + HOLE_SIZE;
    }
    panel(builder, left, right, y, top)
}
