//! Checking the path tracer against Mitsuba 3's `path` integrator.
//!
//! The scenes need indirect light (`max_depth` above 2), which no earlier chapter computes:
//! a Cornell box of matte walls, a mirror and glass, lit by a ceiling panel; a room lit by a
//! point light and the environment. Both renderers pick one light uniformly and combine light
//! and BSDF samples with the power heuristic, so even the noise should be alike.

use crate::lab::scene_file::path_options;
use crate::{Method, render_with};
use ch05_motion_blur::lab::scene_file::for_agreement;
use common::image::Image;
use std::path::Path;
use workbench::agreement::{AgreementScene, AgreementSet, MITSUBA_VARIANT};

/// The chapter's scene files compared with Mitsuba 3, with what each one checks.
pub const AGREEMENT: AgreementSet = AgreementSet {
    label: "chapter 08",
    scenes_dir: concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"),
    scenes: &[
        AgreementScene {
            name: "cornell-box",
            checks: "indirect diffuse light, colour bleeding, a mirror and a glass sphere, max_depth 8, roulette",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "cornell-box-stratified",
            checks: "the Cornell box with Mitsuba's stratified sampler: every dimension of a path stratified over a pixel's samples, each in an order of its own; the noise, not only the mean, is Mitsuba's",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "cornell-box-multijitter",
            checks: "the Cornell box with Mitsuba's multijitter sampler, rendered by chapter 03's multi-jittered sampler in every dimension",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "cornell-box-ldsampler",
            checks: "the Cornell box with Mitsuba's ldsampler, rendered by chapter 03's Owen-scrambled Sobol sampler in every dimension",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "point-and-sky",
            checks: "a point light and a constant environment picked among three lights, a glass sphere, max_depth 5",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "textured",
            checks: "textures: a checkerboard scaled by its to_uv on a floor and on a disk, an sRGB bitmap read bilinearly and repeated on a wall and on a cube's faces, the same image read nearest and mirrored on a sphere turned by its to_world (its uv turn with it); each shape's uv as Mitsuba's",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "written-apart",
            checks: "a scene spread over two files: an <include> found through <path>, a lamp and materials referenced before they are declared, a sensor with focal_length and a principal point offset, hide_emitters, an ellipse (a disc under a non-uniform scale), a sphere with centre and radius moved by to_world",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "dome",
            checks: "spheres with flip_normals: a dome whose area light faces inwards, sampled by area from inside, and a one-sided matte sphere turned inside out, black from outside",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "smooth-mesh",
            checks: "a coarse mesh sphere with vertex normals as glass and as a mirror: both turn light about the interpolated shading normal, as Mitsuba's shading frame does, so they look round rather than cut",
            variant: MITSUBA_VARIANT,
        },
        AgreementScene {
            name: "textured-light",
            checks: "a panel light whose radiance is an image with bright patches on a dim background: its light samples picked where the image is bright, as Mitsuba picks them by the texture (picked by area they are far noisier)",
            variant: MITSUBA_VARIANT,
        },
    ],
    render: render_scene_file,
};

/// Our render of a scene file at [`AGREEMENT_SPP`](workbench::agreement::AGREEMENT_SPP) samples per pixel, with the file's
/// integrator settings.
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
