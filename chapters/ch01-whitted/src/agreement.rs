//! Checking chapter 01 against Mitsuba 3 on the scenes where Whitted's method is exact.
//!
//! Whitted's tracer leaves out light that reaches a matte surface from other surfaces, so it
//! agrees with a full renderer only where there is none of that light. Each scene here is
//! built so that there is none (or, for the glass sphere, about 1e-4 of a pixel's value, far
//! below the noise compared): matte surfaces lit by a point light, seen directly, in a mirror
//! or through glass. Mitsuba's stored renders of them sit in `scenes/mitsuba/`; the tests and
//! the book compare our render with them.

use crate::scene_file::convert;
use crate::{PixelPattern, render};
use common::image::Image;
use common::render::RenderSettings;
use common::scene::load_scene_file;
use std::path::{Path, PathBuf};

/// The scenes compared, by file stem in `scenes/`, with what each one checks.
pub const AGREEMENT_SCENES: &[(&str, &str)] = &[
    (
        "matte-spheres",
        "camera, one-sided diffuse, point light, shadows",
    ),
    (
        "glass-mirror",
        "perfect mirror, dielectric (Fresnel, refraction, (eta_i/eta_t)^2), max_depth",
    ),
    (
        "meshes",
        "OBJ meshes: file normals, recomputed smooth normals, face_normals",
    ),
];

/// Samples per pixel of the renders compared (ours and Mitsuba's second render).
pub const AGREEMENT_SPP: u64 = 64;

/// Samples per pixel of Mitsuba's reference renders.
pub const REFERENCE_SPP: u64 = 4096;

/// The chapter's scene directory.
pub fn scenes_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

/// Where Mitsuba's stored renders of the scenes are.
pub fn mitsuba_dir() -> PathBuf {
    scenes_dir().join("mitsuba")
}

/// Our render of scene `name` at [`AGREEMENT_SPP`] samples per pixel, at the size its file
/// asks for. Mitsuba spreads its samples at random over each pixel; a regular 8x8 grid
/// integrates the same pixel area, with less noise.
pub fn render_agreement_scene(name: &str) -> anyhow::Result<Image> {
    let path = scenes_dir().join(format!("{name}.xml"));
    let loaded = load_scene_file(&path, &[])?;
    let converted =
        convert(&loaded.scene).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    let camera = &converted.scene.camera;
    let settings = RenderSettings::new(camera.width, camera.height, AGREEMENT_SPP);
    let rendered = render(&converted.scene, &settings, PixelPattern::Grid, 0)
        .expect("64 is a square, so the grid exists");
    Ok(rendered.image)
}
