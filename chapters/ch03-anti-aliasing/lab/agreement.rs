//! Checking chapter 03 against Mitsuba 3: pixel samplers and reconstruction filters.
//!
//! Both scenes are direct light from a point light on matte surfaces, which the chapter
//! computes exactly, so what is compared is the anti-aliasing: where in the pixel the samples
//! go (the file's `stratified` or `independent` sampler) and how they are weighted into
//! pixels (a tent of radius 1.5 and a Gaussian of standard deviation 1/4). Mitsuba's scalar
//! variant tabulates a filter in steps, which widens it slightly; the stored renders come
//! from its JIT variant, which evaluates the filter exactly as we do (see
//! `workbench::agreement::MITSUBA_JIT_VARIANT`).

use crate::lab::scene_file::for_agreement;
use crate::render_with;
use common::image::Image;
use std::path::Path;
use workbench::agreement::{AgreementScene, AgreementSet, MITSUBA_JIT_VARIANT};

/// The chapter's scene files compared with Mitsuba 3, with what each one checks.
pub const AGREEMENT: AgreementSet = AgreementSet {
    label: "ours",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[
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
    ],
    render: render_scene_file,
};

/// Our render of a scene file at [`AGREEMENT_SPP`](workbench::agreement::AGREEMENT_SPP) samples per pixel, with the pixel sampler
/// and the filter the file asks for.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    let (scene, film, settings, sampler) = for_agreement(path, &crate::lab::CAPABILITIES)?;
    Ok(render_with(&scene, &settings, &sampler, &film.filter).image)
}
