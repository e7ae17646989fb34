//! Checking the guided path tracer against Mitsuba 3's `path` integrator: guiding changes
//! where directions are drawn, not what is estimated, so a guided render must be as unbiased
//! as Mitsuba's own second render against Mitsuba's reference. Our renders here are guided
//! towards the variance-aware target, their training included in the budget.
//!
//! The glossy floor in indirect light (`glossy-indirect`) is checked apart, in
//! [`HEAVY_TAILED`], at [`HEAVY_TAILED_SPP`] samples per pixel against a reference of
//! [`HEAVY_TAILED_REFERENCE_SPP`]: at 64 its noise is too skewed for the block test. The median
//! pixel of a 64-spp render is 0.78 of its mean, and one in a thousand is 10 times it (by our
//! estimate the inside of the lamp's box, lit some 40 times brighter than the ceiling and found
//! by no light sample, lights the ceiling nearly as much as the lamp does). A block that draws
//! none of the few bright samples lies below the reference by more than three of the standard
//! errors its own 64 pixels give, and none is ever flagged above it. Against Mitsuba's
//! 4096-spp reference, Mitsuba's own 64-spp renders score 0.026 on average (0.009 to 0.046 over
//! 80 % of 40 seeds; its stored second render's 0.019 was a lucky one), ours unguided 0.027
//! and guided 0.034, every flagged block of the three below the reference; at 256 samples
//! Mitsuba's renders still score above 0.015, the lowest pass mark the test sets, one time in
//! four (3 of 11 seeds). At 1024 against 16384, Mitsuba's score 0.005 on average (1 of 16 seeds
//! above 0.015), ours unguided 0.001 (none above).
//!
//! The means agree, which is what the block test stands for: over 16 renders of 1024 samples
//! each, ours unguided and Mitsuba's differ by 0.00 % on the whole image (standard error
//! 0.08 %), and no 8x8 block by more than 2.9 standard errors. Guided, over 76 renders as
//! [`render_scene_file`] makes them, no block differs by more than 2.5 standard errors, but the
//! whole image is 0.22 % darker (bootstrap 95 % interval 0.04 % to 0.41 %): far below what any
//! block test here resolves, and not explained yet. (Those guided figures were measured with
//! the final pass alone making the image and the learnt fraction's floor at a twentieth.)

use ch03_anti_aliasing::PixelSampler;
use ch05_motion_blur::lab::scene_file::for_agreement;
use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::lab::scene_file::path_options;
use ch09_materials::SceneMaterials;
use common::image::Image;
use common::render::Budget;
use std::path::Path;
use workbench::agreement::{AGREEMENT_SPP, AgreementScene, AgreementSet, MITSUBA_VARIANT};

use crate::training::GuidingOptions;
use crate::{GuidingTarget, render_guided};

/// The crate's scene files compared with Mitsuba 3, with what each one checks.
pub const AGREEMENT: AgreementSet = AgreementSet {
    label: "chapter 11",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[AgreementScene {
        name: "door-gap",
        checks: "a room lit through a door ajar from a grey room whose lamp it cannot see: guided directions, the mixture's density in the light sample's MIS weights, training and final passes averaged in one budget",
        variant: MITSUBA_VARIANT,
    }],
    render: render_scene_file,
};

/// The scenes whose noise is too skewed for the block test at [`AGREEMENT_SPP`], compared with
/// Mitsuba's second render at [`HEAVY_TAILED_SPP`] samples instead, both against Mitsuba's
/// reference at [`HEAVY_TAILED_REFERENCE_SPP`].
pub const HEAVY_TAILED: AgreementSet = AgreementSet {
    label: "chapter 11",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[AgreementScene {
        name: "glossy-indirect",
        checks: "a rough aluminium floor (Beckmann, alpha 0.08) in a room lit only from the ceiling patch that a lamp hidden in an open box throws, and from the box's bright inside: guided directions at a glossy surface, a secondary source no light sample finds; at 1024 samples, its noise too skewed for the block test at 64",
        variant: MITSUBA_VARIANT,
    }],
    render: render_heavy_tailed,
};

/// Samples per pixel of the renders compared in [`HEAVY_TAILED`]: at 64 Mitsuba's own second
/// render fails the block test against its reference as often as not, at 256 (against a
/// reference of 4096) still one time in four.
pub const HEAVY_TAILED_SPP: u64 = 1024;

/// Samples per pixel of Mitsuba's reference in [`HEAVY_TAILED`]: 16 times
/// [`HEAVY_TAILED_SPP`], so that the reference's own noise, which the block test does not
/// count, adds a sixteenth to the variance of the difference.
pub const HEAVY_TAILED_REFERENCE_SPP: u64 = 16 * HEAVY_TAILED_SPP;

/// Our render of a scene file guided towards the variance-aware target, with a budget of
/// twice [`AGREEMENT_SPP`] less one samples per pixel:
/// the training takes 1 + 2 + ... of them, the final pass as many as Mitsuba's render it is
/// compared with, and the image averages every pass as the render does by default.
/// More samples than Mitsuba's make the block test stricter, not looser: its standard errors
/// come from our image's own noise.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    render_guided_file(path, AGREEMENT_SPP)
}

/// [`render_scene_file`] with [`HEAVY_TAILED_SPP`] samples per pixel in the image.
pub fn render_heavy_tailed(path: &Path) -> Result<Image, String> {
    render_guided_file(path, HEAVY_TAILED_SPP)
}

/// Our render of a scene file with `spp` samples per pixel in its final pass, the training
/// taking `spp - 1` more, all of them averaged in the image (see [`render_scene_file`]).
fn render_guided_file(path: &Path, spp: u64) -> Result<Image, String> {
    let (world, side, mut settings, _) = for_agreement(path, &crate::lab::CAPABILITIES)?;
    settings.budget = Budget::Samples((2 * spp).saturating_sub(1).max(1));
    let sampler = PixelSampler::new(side.film.sampler, spp, 0).map_err(|e| e.to_string())?;
    let options = path_options(&world.scene);
    let materials = SceneMaterials::of(&world.scene, FuzzMethod::Lobe);
    let pixels = u64::from(settings.width) * u64::from(settings.height);
    let rendered = render_guided(
        &world,
        materials,
        options,
        Some(GuidingOptions::for_image(GuidingTarget::Variance, pixels)),
        &side.lens,
        &settings,
        &sampler,
        &side.film.filter,
    );
    Ok(rendered.output.image)
}
