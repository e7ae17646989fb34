//! Checking chapter 04 against Mitsuba 3: the thin lens.
//!
//! The scene is direct light from a point light on matte surfaces at three depths, which the
//! chapter computes exactly, seen through Mitsuba's `thinlens` sensor: the same lens model
//! (a disc sampled with the concentric map, focused on a plane) must give the same blur.

use crate::render_with;
use crate::scene_file::lens_of;
use ch03_anti_aliasing::scene_file::{filter_of, sampler_of};
use common::image::Image;
use common::metrics::{AGREEMENT_SPP, AgreementScene, MITSUBA_VARIANT};
use common::render::{Budget, RenderSettings};
use common::scene_file::load_scene_file;
use std::path::{Path, PathBuf};

/// The scenes compared, with what each one checks.
pub const AGREEMENT_SCENES: &[AgreementScene] = &[AgreementScene {
    name: "thinlens-spheres",
    checks: "thin lens: aperture radius, focus plane, concentric disc samples",
    variant: MITSUBA_VARIANT,
}];

/// The chapter's scene directory.
pub fn scenes_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

/// Our render of a scene file at [`AGREEMENT_SPP`] samples per pixel, through the file's
/// lens, with the pixel sampler and the filter the file asks for.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    let loaded = load_scene_file(path, &[]).map_err(|e| e.to_string())?;
    let scene = loaded.scene;
    let in_file = |e: String| format!("{}: {e}", path.display());
    crate::CAPABILITIES.check(&scene).map_err(in_file)?;
    let lens = lens_of(&scene.camera).map_err(in_file)?;
    let filter = filter_of(scene.film.filter).map_err(in_file)?;
    let (sampler_kind, _) = sampler_of(&scene.sampler.type_name);
    let settings = RenderSettings::new(scene.film.width, scene.film.height, AGREEMENT_SPP);
    let sampler = ch03_anti_aliasing::cli::AntiAliasingArgs::default()
        .pixel_sampler(sampler_kind, &Budget::Samples(AGREEMENT_SPP), 0)
        .map_err(|e| e.to_string())?;
    let rendered = render_with(&scene, &lens, &settings, &sampler, &filter);
    Ok(rendered.image)
}
