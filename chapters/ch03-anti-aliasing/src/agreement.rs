//! Checking chapter 03 against Mitsuba 3: pixel samplers and reconstruction filters.
//!
//! Both scenes are direct light from a point light on matte surfaces, which the chapter
//! computes exactly, so what is compared is the anti-aliasing: where in the pixel the samples
//! go (the file's `stratified` or `independent` sampler) and how they are weighted into
//! pixels (a tent of radius 1.5 and a Gaussian of standard deviation 1/4). Mitsuba's scalar
//! variant tabulates a filter in steps, which widens it slightly; the stored renders come
//! from its JIT variant, which evaluates the filter exactly as we do (see
//! `common::metrics::MITSUBA_JIT_VARIANT`).

use crate::render_with;
use crate::scene_file::{filter_of, sampler_of};
use common::image::Image;
use common::metrics::{AGREEMENT_SPP, AgreementScene, MITSUBA_JIT_VARIANT};
use common::render::{Budget, RenderSettings};
use common::scene_file::load_scene_file;
use std::path::{Path, PathBuf};

/// The scenes compared, with what each one checks.
pub const AGREEMENT_SCENES: &[AgreementScene] = &[
    AgreementScene {
        name: "tent-spheres",
        checks: "stratified pixel samples, tent filter of radius 1.5",
        variant: MITSUBA_JIT_VARIANT,
    },
    AgreementScene {
        name: "gaussian-bars",
        checks: "independent pixel samples, Gaussian filter of standard deviation 1/4",
        variant: MITSUBA_JIT_VARIANT,
    },
];

/// The chapter's scene directory.
pub fn scenes_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")
}

/// Our render of a scene file at [`AGREEMENT_SPP`] samples per pixel, with the pixel sampler
/// and the filter the file asks for.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    let loaded = load_scene_file(path, &[]).map_err(|e| e.to_string())?;
    let scene = loaded.scene;
    let in_file = |e: String| format!("{}: {e}", path.display());
    crate::CAPABILITIES.check(&scene).map_err(in_file)?;
    let filter = filter_of(scene.film.filter).map_err(in_file)?;
    let (kind, _) = sampler_of(&scene.sampler.type_name);
    let settings = RenderSettings::new(scene.film.width, scene.film.height, AGREEMENT_SPP);
    let sampler = crate::cli::AntiAliasingArgs::default()
        .pixel_sampler(kind, &Budget::Samples(AGREEMENT_SPP), 0)
        .map_err(|e| e.to_string())?;
    Ok(render_with(&scene, &settings, &sampler, &filter).image)
}
