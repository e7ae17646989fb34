//! Scene files in the XML format of Mitsuba 3, read into the [scene model](common::scene).
//!
//! The workbook's scenes can be written as files that Mitsuba 3 also renders, so every image can
//! be checked against an independent renderer. This module reads the subset of the format the
//! workbook renders in two steps: first *what the file says*, resolved, as a
//! [`SceneDescription`] (`$name` parameters substituted from `<default>`s and the caller's
//! overrides, as Mitsuba's `-D name=value`; `<ref>`s followed; defaults filled in with
//! Mitsuba's values; each `<transform>` composed into one matrix); then that description made
//! into the [`Scene`] every chapter renders, its shapes placed in world space. Which chapter can
//! render the scene is not decided here: each chapter's
//! [`Capabilities`](crate::capabilities::Capabilities) say so.
//!
//! Every problem is a [`SceneError`] naming the file, line and column; things that are merely
//! ignored (an unknown property name, say) become [`SceneWarning`]s returned with the scene, so
//! the library never prints. No input makes it panic.
//!
//! The subset:
//! - `integrator`: `path` (`max_depth`, `rr_depth`), `direct`.
//! - `sensor`: `perspective`, `thinlens`, with `to_world`, an `hdrfilm` (with `rfilter`) and a
//!   sampler of any type.
//! - `shape`: `sphere`, `rectangle`, `disk`, `cube`, and meshes from `obj`, `ply` and
//!   `serialized` files, each with a `bsdf` (inline or `<ref>`), an optional `area` emitter and
//!   `flip_normals`.
//! - `bsdf`: `diffuse`, `conductor` (a named `material` of Mitsuba's list, or `eta` and `k`),
//!   `dielectric` and `thindielectric` (indices of refraction by number or by name), `plastic`,
//!   `twosided`, `roughconductor`, `roughplastic` and `roughdielectric` (rendered as `cos^n`
//!   lobes of about the same width), and the workbook's `phong` (Mitsuba 0.6's name and exponent; the lobe is chapter 06's
//!   normalised `cos^n` density, not 0.6's `(n + 2) / 2π` normalisation).
//! - `emitter`: `area` (in a shape), `point`, `constant`.
//! - `transform`: `lookat`, `translate`, `rotate`, `scale`, `matrix`.
//! - `spectrum` (`value="λ:v, ..."`, one number, or `filename="....spd"`), turned into linear
//!   sRGB as Mitsuba 3's RGB variants do: a reflectance differently from an emitter's radiance.
//! - `animation` (the workbook's extension, in Mitsuba 0.6's syntax, for chapter 05's motion
//!   blur): `<animation name="to_world">` with `<transform time="...">` keyframes, in a shape
//!   or a sensor.

mod animation;
mod bitmap;
mod bounded_read;
mod camera;
mod description;
mod document;
mod element;
mod environment_map;
mod error;
mod integrator;
mod lights;
mod materials;
mod obj;
mod ply;
mod properties;
mod reader;
mod sample_counts;
mod serialized;
mod shapes;
mod spectrum;
mod textures;
mod to_geometry;
mod to_scene;
mod transform;
mod values;

#[cfg(test)]
mod tests;

use std::path::Path;

use common::scene::Scene;

pub use bitmap::{DecodedImage, load_bitmap, parse_bitmap};
pub use camera::horizontal_fov;
pub use description::{
    EmitterDescription, FilmDescription, Integrator, PropertyValue, SamplerDescription,
    SceneDescription, Sensor, ShapeDescription, ShapeGeometry,
};
pub use error::{SceneError, SceneWarning, TextPosition};
pub use materials::{named_ior, named_ior_names};
// The table of named metals is the scene model's (`common`): the live demos read it too.
pub use common::scene::{named_metal, named_metal_names};
pub use obj::{load_obj, parse_obj};
pub use ply::{load_ply, parse_ply};
pub use serialized::{load_serialized, parse_serialized};
pub use spectrum::{
    LinearSrgb, MAX_VALUE, MAX_WAVELENGTH, SampledSpectrum, Spectrum, SpectrumRole, parse_spd,
    parse_spectrum, read_spd_file,
};
pub use to_geometry::world_shapes;

/// A scene read from a file, with what the loader ignored.
#[derive(Clone, Debug)]
pub struct LoadedScene {
    /// The scene.
    pub scene: Scene,
    /// Things that were ignored, each with its line; the caller decides whether to print them.
    pub warnings: Vec<SceneWarning>,
}

/// What a scene file describes, before it is made into a [`Scene`], with the warnings.
#[derive(Clone, Debug, PartialEq)]
pub struct LoadedDescription {
    /// What the file describes, resolved.
    pub scene: SceneDescription,
    /// Things that were ignored, each with its line.
    pub warnings: Vec<SceneWarning>,
}

/// Reads the scene file at `path`. `overrides` set `$name` parameters, winning over the file's
/// `<default>`s; a name the file does not declare is allowed, as in Mitsuba 3.
pub fn load_scene_file(
    path: &Path,
    overrides: &[(String, String)],
) -> Result<LoadedScene, SceneError> {
    let text = bounded_read::read_text(path, "scene file", bounded_read::SCENE_FILE_LIMIT)
        .map_err(|message| SceneError {
            file: path.to_path_buf(),
            line: 0,
            column: 0,
            message,
        })?;
    parse_scene(&text, path, overrides)
}

/// Parses the text of a scene file into the scene model. `file` names it in messages, and
/// relative paths inside it (an OBJ's `filename`) are resolved against its directory.
pub fn parse_scene(
    text: &str,
    file: &Path,
    overrides: &[(String, String)],
) -> Result<LoadedScene, SceneError> {
    let described = parse_description(text, file, overrides)?;
    Ok(LoadedScene {
        scene: to_scene::to_scene(&described.scene, file)?,
        warnings: described.warnings,
    })
}

/// Parses the text of a scene file into what it describes, with defaults substituted,
/// references followed and transforms composed, but nothing placed or checked against what
/// the workbook renders.
pub fn parse_description(
    text: &str,
    file: &Path,
    overrides: &[(String, String)],
) -> Result<LoadedDescription, SceneError> {
    document::parse_document(text, file, overrides)
}
