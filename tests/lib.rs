//! Cross-chapter tests of the workbook: properties that must hold for every chapter's tracer
//! at once (scale invariance, determinism, finite pixels, refusals of bad input, no lost work).
//! The tests live in `tests/tests/`; this library holds the scenes and helpers they share.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod binaries;

use common::geometry::{Parallelogram, Shape, Sphere, Triangle, TriangleMesh};
use common::scene::CameraFrame;
use common::scene::Material;
use common::scene::PointLight;
use common::scene::{Camera, FilmSettings, Scene, SceneBuilder};
use glam::Vec3;

/// The knobs of [`whitted_scene`]: where it is, how it is seen and lit, and its optics.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WhittedSceneParams {
    /// Every length is multiplied by this.
    pub scale: f32,
    /// Then everything is moved by this.
    pub offset: Vec3,
    /// Film width in pixels.
    pub width: u32,
    /// Film height in pixels.
    pub height: u32,
    /// Horizontal field of view in degrees.
    pub fov_degrees: f32,
    /// Distance from the camera to the point it looks at, before scaling (3.2 by default).
    pub camera_distance: f32,
    /// Distance from the scene's centre to the point light, before scaling (about 3.7).
    pub light_distance: f32,
    /// Index of refraction of the glass sphere.
    pub glass_ior: f32,
    /// Longest path in segments (Mitsuba's `max_depth`).
    pub max_depth: u32,
}

impl Default for WhittedSceneParams {
    fn default() -> Self {
        Self {
            scale: 1.0,
            offset: Vec3::ZERO,
            width: 48,
            height: 48,
            fov_degrees: 55.0,
            camera_distance: DEFAULT_CAMERA_OFFSET.length(),
            light_distance: DEFAULT_LIGHT_POSITION.length(),
            glass_ior: 1.5,
            max_depth: 10,
        }
    }
}

/// Where the camera looks: the middle of the scene.
const TARGET: Vec3 = Vec3::new(0.0, 0.4, 0.0);
/// The camera's position relative to [`TARGET`] at the default distance.
const DEFAULT_CAMERA_OFFSET: Vec3 = Vec3::new(0.0, 0.8, 3.5);
/// The light's position (relative to the origin) at the default distance.
const DEFAULT_LIGHT_POSITION: Vec3 = Vec3::new(1.0, 3.0, 2.0);

/// A small Whitted scene with every shape kind (parallelogram floor and wall, spheres, a triangle, a
/// smooth-shaded mesh standing on the floor), a mirror, glass and shadows, scaled by `scale`
/// and moved by `offset`.
///
/// Light intensities grow with `scale^2`, so irradiance (intensity over squared distance) and
/// hence the image stay the same at every scale.
pub fn scaled_whitted_scene(scale: f32, offset: Vec3, size: u32) -> Scene {
    whitted_scene(&WhittedSceneParams {
        scale,
        offset,
        width: size,
        height: size,
        ..WhittedSceneParams::default()
    })
    .expect("a camera apart from its target")
}

/// [`scaled_whitted_scene`] with every knob of [`WhittedSceneParams`]. The light's intensity
/// also grows with the square of its distance, so the lighting stays the same wherever it is.
///
/// `None` when the camera cannot be placed: so close to its target, far from the origin, that
/// in `f32` the two are the same point and there is no viewing direction.
pub fn whitted_scene(params: &WhittedSceneParams) -> Option<Scene> {
    let scale = params.scale;
    let at = |p: Vec3| p * scale + params.offset;
    let triangle = Triangle::new(
        at(Vec3::new(0.6, 0.0, 0.2)),
        at(Vec3::new(1.4, 0.0, 0.2)),
        at(Vec3::new(1.0, 1.0, 0.0)),
    );
    let camera_offset = DEFAULT_CAMERA_OFFSET.normalize() * params.camera_distance;
    let frame = CameraFrame::look_at(at(TARGET + camera_offset), at(TARGET), Vec3::Y)?;
    let mut camera = Camera::pinhole(frame, params.fov_degrees);
    camera.near_clip *= scale;
    let light_position = DEFAULT_LIGHT_POSITION.normalize() * params.light_distance;
    let light_gain = (params.light_distance / DEFAULT_LIGHT_POSITION.length()).powi(2);
    let scene = sky_floor_and_wall(scale, at)
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
            Material::glass(params.glass_ior),
        )
        .mesh(
            &octahedron(at(Vec3::new(-0.9, 0.3, 1.3)), 0.3 * scale),
            Material::diffuse(Vec3::new(0.8, 0.7, 0.2)),
        )
        .light(PointLight {
            position: at(light_position),
            intensity: Vec3::splat(15.0 * scale * scale * light_gain),
        })
        .build(
            camera,
            FilmSettings::new(params.width, params.height),
            params.max_depth,
        );
    Some(scene)
}

/// The sky, a floor and a wall standing on it, placed by `at` and sized by `scale`: the start
/// of every scene the scale tests build. The wall touches the floor along an edge, where light
/// must not leak through.
pub fn sky_floor_and_wall(scale: f32, at: impl Fn(Vec3) -> Vec3) -> SceneBuilder {
    let floor = Parallelogram::new(
        at(Vec3::new(-2.0, 0.0, 2.0)),
        4.0 * scale * Vec3::X,
        -4.0 * scale * Vec3::Z,
    );
    let wall = Parallelogram::new(
        at(Vec3::new(-2.0, 0.0, -1.0)),
        4.0 * scale * Vec3::X,
        2.0 * scale * Vec3::Y,
    );
    SceneBuilder::new()
        .environment(Vec3::new(0.4, 0.55, 0.8))
        .shape(
            Shape::Parallelogram(floor),
            Material::diffuse(Vec3::splat(0.7)),
        )
        .shape(
            Shape::Parallelogram(wall),
            Material::diffuse(Vec3::new(0.7, 0.3, 0.2)),
        )
}

/// A smooth-shaded octahedron (a coarse sphere) of `radius` around `centre`; its lowest vertex
/// touches whatever lies `radius` below the centre.
pub fn octahedron(centre: Vec3, radius: f32) -> TriangleMesh {
    let directions = [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z];
    let positions = directions.iter().map(|&d| centre + d * radius).collect();
    let (px, nx, py, ny, pz, nz) = (0, 1, 2, 3, 4, 5);
    let indices = vec![
        [px, py, pz],
        [pz, py, nx],
        [nx, py, nz],
        [nz, py, px],
        [pz, ny, px],
        [nx, ny, pz],
        [nz, ny, nx],
        [px, ny, nz],
    ];
    TriangleMesh::new(positions, Some(directions.to_vec()), indices).expect("a valid octahedron")
}
