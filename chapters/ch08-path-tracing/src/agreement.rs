//! Checking the path tracer against Mitsuba 3's `path` integrator.
//!
//! The scenes need indirect light (`max_depth` above 2), which no earlier chapter computes:
//! a Cornell box of matte walls, a mirror and glass, lit by a ceiling panel; a room lit by a
//! point light and the environment. Both renderers pick one light uniformly and combine light
//! and BSDF samples with the power heuristic, so even the noise should be alike.

use crate::scene_file::convert;
use crate::{Method, render_with};
use common::image::Image;
use common::metrics::{AGREEMENT_SPP, AgreementScene, MITSUBA_VARIANT};
use common::render::{Budget, RenderSettings};
use common::scene::load_scene_file;
use std::path::{Path, PathBuf};

/// The scenes compared, with what each one checks.
pub const AGREEMENT_SCENES: &[AgreementScene] = &[
    AgreementScene {
        name: "cornell-box",
        checks: "indirect diffuse light, colour bleeding, a mirror and a glass sphere, max_depth 8, roulette",
        variant: MITSUBA_VARIANT,
    },
    AgreementScene {
        name: "point-and-sky",
        checks: "a point light and a constant environment picked among three lights, a glass sphere, max_depth 5",
        variant: MITSUBA_VARIANT,
    },
];

/// The chapter's scene directory.
pub fn scenes_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

/// Our render of a scene file at [`AGREEMENT_SPP`] samples per pixel, with the file's
/// integrator settings.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    let loaded = load_scene_file(path, &[]).map_err(|e| e.to_string())?;
    let scene = convert(&loaded.scene).map_err(|e| format!("{}: {e}", path.display()))?;
    let converted = &scene.converted;
    let camera = &converted.scene.scene.world.scene.camera;
    let settings = RenderSettings::new(camera.width, camera.height, AGREEMENT_SPP);
    let sampler = ch03_anti_aliasing::cli::AntiAliasingArgs::default()
        .pixel_sampler(converted.sampler, &Budget::Samples(AGREEMENT_SPP), 0)
        .map_err(|e| e.to_string())?;
    let rendered = render_with(
        &converted.scene,
        Method::new(scene.options),
        &converted.lens,
        &settings,
        &sampler,
        &converted.filter,
    );
    Ok(rendered.image)
}
