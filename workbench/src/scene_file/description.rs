//! The neutral scene description: what a scene file says, resolved, as plain data.
//!
//! Defaults are substituted, `<ref>`s followed and transforms composed into matrices, but no
//! rendering decision is taken: turning a description into a chapter's scene is the chapter's
//! job. Transforms are glam `Mat4` (`f32`), like the rest of the workbook's geometry; colours are
//! linear RGB triples stored in a `Vec3`.

use std::path::PathBuf;

use glam::{Mat4, Vec2, Vec3};

use super::TextPosition;
use super::spectrum::Spectrum;
use common::scene::{AreaEmitter, Bitmap, CameraModel, EnvironmentMap, FilmFilter, Material};

/// Everything a scene file describes.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneDescription {
    /// How light transport is computed (`path` when the file names no integrator, as in Mitsuba).
    pub integrator: Integrator,
    /// Where the `<integrator>` element is; `None` when the file has none.
    pub integrator_position: Option<TextPosition>,
    /// The integrator's `hide_emitters`: camera rays do not see what glows.
    pub hide_emitters: bool,
    /// The camera with its film and sampler.
    pub sensor: Sensor,
    /// Every shape, in file order, each with its material and optional area light.
    pub shapes: Vec<ShapeDescription>,
    /// The lights that are not shapes (`point` and `constant`), in file order.
    pub emitters: Vec<EmitterDescription>,
    /// The images the materials' bitmap textures read ([`Texture::Bitmap`](common::scene::Texture)
    /// numbers them).
    pub bitmaps: Vec<Bitmap>,
}

/// The integrator, the light transport algorithm.
#[derive(Clone, Debug, PartialEq)]
pub enum Integrator {
    /// Mitsuba's `path`: unidirectional path tracing.
    Path {
        /// Path segments including the camera ray; -1 means unlimited (Mitsuba's default).
        max_depth: i32,
        /// The depth from which Russian roulette may stop a path (default 5).
        rr_depth: i32,
    },
    /// Mitsuba's `direct`: light and BSDF samples at the surface the camera sees, as many
    /// as it says.
    Direct(common::scene::DirectSamples),
}

/// A property's value as written in the file.
#[derive(Clone, Debug, PartialEq)]
pub enum PropertyValue {
    /// `<float>`.
    Float(f32),
    /// `<integer>`.
    Integer(i64),
    /// `<boolean>`.
    Boolean(bool),
    /// `<string>`.
    String(String),
    /// `<rgb>`.
    Rgb(Vec3),
    /// `<point>`.
    Point(Vec3),
    /// `<vector>`.
    Vector(Vec3),
    /// `<transform>`, composed into one matrix.
    Transform(Mat4),
    /// `<animation>` (the workbook's extension): `(time, matrix)` keyframes, times increasing.
    Animation(Vec<(f32, Mat4)>),
    /// `<spectrum>`, kept as written: a reflectance and an emitter's radiance turn the same
    /// spectrum into different RGB.
    Spectrum(Spectrum),
}

/// A camera: where it is, what it sees, and how its image is sampled and stored.
#[derive(Clone, Debug, PartialEq)]
pub struct Sensor {
    /// Where the `<sensor>` element is.
    pub position: TextPosition,
    /// Pinhole or thin lens.
    pub model: CameraModel,
    /// The horizontal field of view in degrees, already converted from the file's `fov` and
    /// `fov_axis` with the film's aspect ratio, as Mitsuba 3 does.
    pub fov_x_degrees: f32,
    /// Mitsuba's `principal_point_offset_x` and `_y`: the image's centre moved off the camera's
    /// axis by these fractions of the image's width and height (0 for the usual camera).
    pub principal_point_offset: Vec2,
    /// Rays start this far along the camera axis (default 0.01).
    pub near_clip: f32,
    /// Rays end this far along the camera axis (default 10 000).
    pub far_clip: f32,
    /// Start of the shutter interval (default 0).
    pub shutter_open: f32,
    /// End of the shutter interval (default 0: no motion blur).
    pub shutter_close: f32,
    /// Camera to world. Camera space has +z forward, +y up and **+x to the image's left**.
    /// For a moving camera, the first keyframe's matrix.
    pub to_world: Mat4,
    /// A moving camera's `(time, camera to world)` keyframes, from an
    /// `<animation name="to_world">` (the workbook's extension, see [`ShapeDescription`]);
    /// empty for a camera that does not move.
    pub to_world_keyframes: Vec<(f32, Mat4)>,
    /// The image the camera records.
    pub film: FilmDescription,
    /// How many samples each pixel gets, and from which seed.
    pub sampler: SamplerDescription,
}

/// An `hdrfilm`.
#[derive(Clone, Debug, PartialEq)]
pub struct FilmDescription {
    /// Width in pixels (default 768).
    pub width: u32,
    /// Height in pixels (default 576).
    pub height: u32,
    /// The reconstruction filter (`gaussian` by default, as in Mitsuba).
    pub filter: FilmFilter,
    /// Where the `<rfilter>` element is; `None` when Mitsuba's default applies.
    pub filter_position: Option<TextPosition>,
    /// Mitsuba's `pixel_format` (default "rgb"); recorded, not interpreted.
    pub pixel_format: String,
    /// Mitsuba's `component_format` (default "float16"); recorded, not interpreted.
    pub component_format: String,
}

/// The sampler: any type is accepted and recorded; chapters pick their own strategies.
#[derive(Clone, Debug, PartialEq)]
pub struct SamplerDescription {
    /// The `type` attribute, such as "independent".
    pub type_name: String,
    /// Samples per pixel (default 4).
    pub sample_count: u32,
    /// The seed (default 0).
    pub seed: u32,
}

/// One shape with everything attached to it.
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeDescription {
    /// The geometry in the shape's own space.
    pub geometry: ShapeGeometry,
    /// Object to world. For a sphere, `center` and `radius` are applied *before* it. For a
    /// moving shape, the first keyframe's matrix.
    pub to_world: Mat4,
    /// A moving shape's `(time, object to world)` keyframes, at least two, with strictly
    /// increasing times, each matrix invertible; empty for a shape that does not move.
    ///
    /// Mitsuba 3 has no animated transforms: this is the workbook's own extension, written as
    /// Mitsuba 0.6 wrote it, `<animation name="to_world">` holding `<transform time="...">`
    /// keyframes in place of `<transform name="to_world">`. Chapter 05 renders it; earlier
    /// chapters refuse it.
    pub to_world_keyframes: Vec<(f32, Mat4)>,
    /// The material: inline, referenced, or Mitsuba's default diffuse 0.5.
    pub material: Material,
    /// The area light, when the shape glows.
    pub emitter: Option<AreaEmitter>,
    /// Whether the normals point the other way.
    pub flip_normals: bool,
    /// Where the `<shape>` element starts in its file, so that a chapter refusing the shape
    /// can point at it.
    pub position: TextPosition,
}

/// What Mitsuba 3 gives a shape without a BSDF: diffuse with reflectance 0.5.
pub fn mitsuba_default_material() -> Material {
    Material::diffuse(Vec3::splat(0.5))
}

/// What Mitsuba 3 gives a shape that glows and has no BSDF: black diffuse, so that a lamp
/// written without a material reflects nothing (0.5 would add light bounced off its face).
pub fn mitsuba_default_emitter_material() -> Material {
    Material::diffuse(Vec3::ZERO)
}

/// The geometry of a shape, in Mitsuba 3's object space.
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeGeometry {
    /// A sphere with outward normals.
    Sphere {
        /// Centre in object space (default the origin).
        center: Vec3,
        /// Radius, always positive (default 1).
        radius: f32,
    },
    /// The square [-1, 1]^2 in the xy-plane, normal +z.
    Rectangle,
    /// The unit disc in the xy-plane, normal +z.
    Disc,
    /// The cube [-1, 1]^3.
    Cube,
    /// A Wavefront OBJ mesh, not loaded yet.
    Obj {
        /// The mesh file, resolved relative to the scene file's directory.
        filename: PathBuf,
        /// Mitsuba's `face_normals`: shade every triangle flat, ignoring the file's normals.
        /// When it is off and the file has no normals, smooth vertex normals are computed (as
        /// Mitsuba does), so a faceted mesh looks faceted only with `face_normals` on.
        face_normals: bool,
    },
    /// A PLY mesh (ASCII or binary), not loaded yet.
    Ply {
        /// The mesh file, resolved relative to the scene file's directory.
        filename: PathBuf,
        /// Mitsuba's `face_normals`, as for [`Obj`](Self::Obj).
        face_normals: bool,
        /// Mitsuba's `flip_tex_coords` (off for PLY): store each texture coordinate `(u, v)`
        /// as `(u, 1 - v)`.
        flip_tex_coords: bool,
    },
    /// A mesh of a Mitsuba `.serialized` file, not loaded yet.
    Serialized {
        /// The mesh file, resolved relative to the scene file's directory.
        filename: PathBuf,
        /// Which of the file's meshes (Mitsuba's `shape_index`, 0 for the first).
        shape_index: u32,
        /// Mitsuba's `face_normals`, as for [`Obj`](Self::Obj).
        face_normals: bool,
    },
}

/// A light that is not a shape.
#[derive(Clone, Debug, PartialEq)]
pub enum EmitterDescription {
    /// A point light.
    Point {
        /// World position (from `position`, or the translation of `to_world`).
        position: Vec3,
        /// Radiant intensity in W/sr (default 1).
        intensity: Vec3,
    },
    /// A light infinitely far away that shines one way.
    Directional {
        /// The unit direction the light travels in.
        direction: Vec3,
        /// Irradiance on a surface facing it (default 1).
        irradiance: Vec3,
        /// Where the `<emitter>` element is.
        position: TextPosition,
    },
    /// Radiance arriving from every direction that leaves the scene.
    Constant {
        /// Radiance (default 1).
        radiance: Vec3,
        /// Where the `<emitter>` element is.
        position: TextPosition,
    },
    /// Radiance from an image around the scene (Mitsuba's `envmap`), its scale applied.
    EnvironmentMap {
        /// The image, read and ready to sample (boxed: it is large beside the other lights).
        map: Box<EnvironmentMap>,
        /// Where the `<emitter>` element is.
        position: TextPosition,
    },
}
