//! Checking chapter 04 against Mitsuba 3: the thin lens.
//!
//! The scene is direct light from a point light on matte surfaces at three depths, which the
//! chapter computes exactly, seen through Mitsuba's `thinlens` sensor: the same lens model
//! (a disc sampled with the concentric map, focused on a plane) must give the same blur.

use crate::lab::scene_file::for_agreement;
use crate::render_with;
use common::image::Image;
use std::path::Path;
use workbench::agreement::{AgreementScene, AgreementSet, MITSUBA_VARIANT};

/// The chapter's scene files compared with Mitsuba 3, with what each one checks.
pub const AGREEMENT: AgreementSet = AgreementSet {
    label: "ours (thin lens)",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[AgreementScene {
        name: "thinlens-spheres",
        checks: "thin lens: aperture radius, focus plane, concentric disc samples",
        variant: MITSUBA_VARIANT,
    }],
    render: render_scene_file,
};

/// Our render of a scene file at [`AGREEMENT_SPP`](workbench::agreement::AGREEMENT_SPP) samples per pixel, through the file's
/// lens, with the pixel sampler and the filter the file asks for.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    let (scene, side, settings, sampler) = for_agreement(path, &crate::lab::CAPABILITIES)?;
    Ok(render_with(&scene, &side.lens, &settings, &sampler, &side.film.filter).image)
}
