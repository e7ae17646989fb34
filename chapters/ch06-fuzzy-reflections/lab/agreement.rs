//! Checking chapter 06 against Mitsuba 3: smooth glass, whichever ray is chosen.
//!
//! Mitsuba's `dielectric` picks reflection with the probability of the Fresnel term, one of
//! this chapter's three strategies; the other two (both rays, one with probability 1/2) must
//! give the same image on average. The scene is built, like chapter 01's, so that the light
//! this chapter leaves out (indirect light on matte surfaces) is too faint to show. Rough
//! materials are not compared here: Mitsuba's are microfacet models, this chapter's are
//! `cos^n` lobes of about the same width, and the book shows how far apart they are.

use crate::{GlassStrategy, PointLights, TraceOptions, render_with};
use ch05_motion_blur::lab::scene_file::for_agreement;
use common::image::Image;
use std::path::Path;
use workbench::agreement::{AgreementScene, AgreementSet, MITSUBA_VARIANT};

/// The chapter's scene files compared with Mitsuba 3, with what each one checks.
pub const AGREEMENT: AgreementSet = AgreementSet {
    label: "chapter 06",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[AgreementScene {
        name: "glass-panes",
        checks: "smooth glass with one ray chosen by the Fresnel term",
        variant: MITSUBA_VARIANT,
    }],
    render: render_scene_file,
};

/// Our render of a scene file at [`AGREEMENT_SPP`](workbench::agreement::AGREEMENT_SPP) samples per pixel, choosing the ray at
/// glass by `glass`, with the pixel sampler and the filter the file asks for.
pub fn render_scene_file_with(path: &Path, glass: GlassStrategy) -> Result<Image, String> {
    let (world, side, settings, sampler) = for_agreement(path, &crate::lab::CAPABILITIES)?;
    let options = TraceOptions {
        glass,
        ..TraceOptions::default()
    };
    let rendered = render_with(
        &world,
        &PointLights,
        options,
        &side.lens,
        &settings,
        &sampler,
        &side.film.filter,
    );
    Ok(rendered.image)
}

/// [`render_scene_file_with`] the Fresnel choice, as Mitsuba chooses.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    render_scene_file_with(path, GlassStrategy::Fresnel)
}
