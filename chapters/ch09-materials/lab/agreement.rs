//! Checking the renderer of real scene files against Mitsuba 3's `path` and `direct`
//! integrators on scenes with Mitsuba's materials: metals by name and by index, plastic smooth
//! and rough, thin and tinted glass, masks, the microfacet models (isotropic, anisotropic,
//! textured roughness), and textures on their parameters. The lecture's scenes are chapter
//! 08's; on them this crate gives chapter 08's image, bit for bit.

use ch05_motion_blur::lab::scene_file::for_agreement;
use ch08_path_tracing::Method;
use ch08_path_tracing::lab::scene_file::path_options;
use common::image::Image;
use std::path::Path;
use workbench::agreement::{AgreementScene, AgreementSet, MITSUBA_VARIANT};

use crate::render_with;

/// The crate's scene files compared with Mitsuba 3, with what each one checks.
pub const AGREEMENT: AgreementSet = AgreementSet {
    label: "chapter 09",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[
        AgreementScene {
            name: "metals",
            checks: "smooth conductors: gold by Mitsuba's name (a sphere, and a sheet on the floor seen at grazing angles), eta and k given as colours, a chromium panel; the conductor Fresnel equations",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "coated-and-thin",
            checks: "smooth plastic (linear and nonlinear) under an area light, with its light sample and MIS, and a thin glass pane that shows the light in its reflection and casts a shadow",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "rough-metals",
            checks: "roughconductor: GGX gold, Beckmann aluminium and an anisotropic GGX copper sheet (alpha_u 0.05 along x, alpha_v 0.3) seen at grazing angles; visible-normal sampling, Smith's shadowing and the facets' Fresnel term, with light samples and MIS",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "rough-plastic-and-glass",
            checks: "roughplastic with Beckmann and GGX coatings (linear and nonlinear) and a GGX roughdielectric sphere: the coating's tabulated transmittance, reflection and refraction through facets",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "veach-plates",
            checks: "Veach's multiple-importance plates, our own: the direct integrator (one light and one BSDF sample per hit, power heuristic) on four roughplastic plates from alpha 0.02 to 0.25 under four sphere lights of equal power from radius 0.1 to 0.8, hidden from the camera (which then sees through them, as Mitsuba's hide_emitters does)",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "veach-plates-counts",
            checks: "the same plates with the direct integrator's emitter_samples 3 and bsdf_samples 2: the multi-sample power heuristic, each density weighed by its count, each estimate divided by it",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "masked",
            checks: "mask: a two-sided card with holes cut by a checkerboard opacity and a one-sided card of opacity 0.4, with the sphere and box behind them seen through, their shadows (shadow rays stopped by a mask, as in Mitsuba) and light passing through them",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "textured-more",
            checks: "textures beyond a diffuse reflectance: a bitmap as a rough plastic's base, a checkerboard as a smooth plastic's base and as a factor on rough gold's reflection, the bitmap again as a mirror's reflectance, smooth and rough glass with factors on their reflection and transmission (one a checkerboard), and two lights whose radiance is a checkerboard (a wall seen directly, the main light above), read where rays hit them and where light samples land on them",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "rough-textured",
            checks: "roughness as a texture: a GGX gold floor whose alpha is a checkerboard of 0.1 and 0.35, a Beckmann glass sphere whose alpha is a checkerboard of 0.05 and 0.4; each width read as Mitsuba reads one number from a texture",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "envmap",
            checks: "an environment map (envmap): a Radiance HDR sky with a small sun, scaled and turned by its to_world, seen directly, in a smooth chromium sphere and a rough gold one, and lighting a matte sphere and floor; its lookup, its light samples and their density in MIS",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "sunlit",
            checks: "two directional lights (Mitsuba's directional: infinitely far away, one given by its direction, one by its to_world) with a constant sky: deltas connected through one shadow ray each, sharp shadows, their highlights on rough gold",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "brushed",
            checks: "anisotropic roughness (alpha_u and alpha_v) brushed along each shape's dp/du as Mitsuba's shading frame takes it: a turned sphere along its parallels, a mesh along its texture's u (not its edges), a disk along its radii, a copper panel and a rough glass pane turned about their normals",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "mesh-lamp",
            checks: "emitters made of pieces: a lamp whose bulb is a mesh of 528 triangles of very different areas, in a shade of rough aluminium, and a small sphere light, path-traced to depth 3; a light sample picks each emitting shape with the same chance (not each triangle) and a triangle by its area, as Mitsuba does, and MIS weighs a BSDF ray that hits the bulb with that density",
            variant: MITSUBA_VARIANT,
        },
    ],
    render: render_scene_file,
};

/// Our render of a scene file at [`AGREEMENT_SPP`](workbench::agreement::AGREEMENT_SPP) samples
/// per pixel, with the file's integrator settings and every material it names.
pub fn render_scene_file(path: &Path) -> Result<Image, String> {
    let (world, side, settings, sampler) = for_agreement(path, &crate::lab::CAPABILITIES)?;
    let options = path_options(&world.scene);
    let rendered = render_with(
        &world,
        Method::new(options),
        &side.lens,
        &settings,
        &sampler,
        &side.film.filter,
    );
    Ok(rendered.image)
}
