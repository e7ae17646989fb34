//! Checking the optimal combination against Mitsuba 3's `direct` integrator (one light and
//! one BSDF sample, the power heuristic): the two estimate the same image, so ours must be as
//! unbiased as Mitsuba's own second render against Mitsuba's reference, and no noisier.
//!
//! The zero-variance plane is not among them: its optimal image is exact, and the block-bias
//! measure, which takes the standard error of a block from our image's own spread, would count
//! the reference's noise as our bias (Mitsuba's 4096-sample reference is 1.00004 on average
//! where the plane is exactly 1). The tests check that image against its exact value instead.

use ch05_motion_blur::lab::scene_file::for_agreement;
use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::lab::scene_file::path_options;
use ch09_materials::SceneMaterials;
use common::image::Image;
use std::path::Path;
use workbench::agreement::{AgreementScene, AgreementSet, MITSUBA_VARIANT};

use crate::pixel::Combination;
use crate::render_direct_with;

/// The crate's scene files compared with Mitsuba 3, with what each one checks.
pub const AGREEMENT: AgreementSet = AgreementSet {
    label: "chapter 10",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[
        AgreementScene {
            name: "glossy-floor",
            checks: "a sphere light over a glossy (GGX, alpha 0.15) metal floor and a matte box: the optimal weights solved per pixel from its samples, with occlusion, empty BSDF samples and the light seen directly",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "veach-plates",
            checks: "chapter 09's Veach plates, lit directly: four glossy plates of growing roughness and four sphere lights of equal power and growing size, the light sample best on some plates and the BSDF sample on others, the lights hidden",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "cornell-box",
            checks: "chapter 08's Cornell box, lit directly: matte walls under a ceiling panel, and a mirror and a glass sphere whose delta lobes only the BSDF sample follows (kept apart from the combination), the panel hidden",
            variant: MITSUBA_VARIANT,
        },
    ],
    render: render_scene_file,
};

/// Our render of a scene file at [`AGREEMENT_SPP`](workbench::agreement::AGREEMENT_SPP) samples
/// per pixel, the two samples combined optimally.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    let (world, side, settings, sampler) = for_agreement(path, &crate::lab::CAPABILITIES)?;
    let options = path_options(&world.scene);
    let materials = SceneMaterials::of(&world.scene, FuzzMethod::Lobe);
    let rendered = render_direct_with(
        &world,
        materials,
        options,
        &side.lens,
        &settings,
        &sampler,
        Combination::Optimal,
    );
    Ok(rendered.image)
}
