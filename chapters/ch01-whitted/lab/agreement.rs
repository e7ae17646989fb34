//! Checking chapter 01 against Mitsuba 3 on the scenes where Whitted's method is exact.
//!
//! Whitted's tracer leaves out light that reaches a matte surface from other surfaces, so it
//! agrees with a full renderer only where there is none of that light. Each scene here is
//! built so that there is none (or, for the glass sphere, about 1e-4 of a pixel's value, far
//! below the noise compared): matte surfaces lit by a point light, seen directly, in a mirror
//! or through glass. Mitsuba's stored renders of them sit in `scenes/mitsuba/`; the tests and
//! the book compare our render with them (see `common::metrics::agreement`).

use crate::lab::CAPABILITIES;
use crate::{PixelPattern, render};
use common::image::Image;
use common::render::RenderSettings;
use std::path::Path;
use workbench::agreement::{AGREEMENT_SPP, AgreementScene, AgreementSet, MITSUBA_VARIANT};
use workbench::scene_file::load_scene_file;

/// The chapter's scene files compared with Mitsuba 3, with what each one checks.
pub const AGREEMENT: AgreementSet = AgreementSet {
    label: "ours (Whitted)",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[
        AgreementScene {
            name: "matte-spheres",
            checks: "camera, one-sided diffuse, point light, shadows",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "glass-mirror",
            checks: "perfect mirror, dielectric (Fresnel, refraction), max_depth",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "meshes",
            checks: "OBJ meshes: file normals, recomputed smooth normals, face_normals",
            variant: MITSUBA_VARIANT,
        },
    ],
    render: render_scene_file,
};

/// Our render of a scene file at [`AGREEMENT_SPP`] samples per pixel, at the size the file
/// asks for. Mitsuba spreads its samples at random over each pixel; a regular 8x8 grid
/// integrates the same pixel area, with less noise.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    let loaded = load_scene_file(path, &[]).map_err(|e| e.to_string())?;
    let mut scene = loaded.scene;
    CAPABILITIES
        .check(&scene)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    CAPABILITIES.put_in_stand_ins(&mut scene);
    let settings = RenderSettings::new(scene.film.width, scene.film.height, AGREEMENT_SPP);
    let rendered = render(&scene, &settings, PixelPattern::Grid, 0)
        .expect("64 is a square, so the grid exists");
    Ok(rendered.image)
}
