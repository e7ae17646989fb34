//! Checking chapter 07 against Mitsuba 3: area lights and their soft shadows.
//!
//! The scenes are direct light from area lights on matte surfaces, which both this chapter and
//! Mitsuba 3's `direct` integrator (or `path` with `max_depth` 2) compute without bias: the
//! same lights, the same one-sided emission, the same cosines and visibility must give the same
//! penumbrae. Mitsuba combines a light sample with a BSDF sample by multiple importance
//! sampling; we send one shadow ray per light, so the noise differs a little, the mean not.

use crate::{LightOptions, render_with};
use ch05_motion_blur::lab::scene_file::for_agreement;
use ch06_fuzzy_reflections::TraceOptions;
use common::image::Image;
use std::path::Path;
use workbench::agreement::{AgreementScene, AgreementSet, MITSUBA_VARIANT};

/// The chapter's scene files compared with Mitsuba 3, with what each one checks.
pub const AGREEMENT: AgreementSet = AgreementSet {
    label: "chapter 07",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[
        AgreementScene {
            name: "rectangle-light",
            checks: "a rectangle light over spheres: area sampling, one-sided emission, penumbrae",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "disc-light",
            checks: "a disk light, tilted: the concentric disc, the light's cosine",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "sphere-light",
            checks: "a sphere light: the cone sampled by solid angle, seen directly",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "affine-lights",
            checks: "a disk squashed into an ellipse, a disk scaled in its plane only, a sheared rectangle",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "several-lights",
            checks: "a cube light (six parallelograms), a triangle mesh light and a point light",
            variant: MITSUBA_VARIANT,
        },
    ],
    render: render_scene_file,
};

/// Our render of a scene file at [`AGREEMENT_SPP`](workbench::agreement::AGREEMENT_SPP) samples per pixel, with the file's lens,
/// pixel sampler and filter, one shadow ray per light per hit.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    let (world, side, settings, sampler) = for_agreement(path, &crate::lab::CAPABILITIES)?;
    let rendered = render_with(
        &world,
        LightOptions::default(),
        TraceOptions::default(),
        &side.lens,
        &settings,
        &sampler,
        &side.film.filter,
    );
    Ok(rendered.image)
}
