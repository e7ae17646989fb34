//! # Beyond the lecture: optimal multiple importance sampling
//!
//! Chapter 08 lights a surface twice, by a light sample and by a BSDF sample, and combines the
//! two with a heuristic weight (balance or power) fixed in advance, whatever the scene. The
//! weights are free, as long as they sum to one at every direction; Kondapaneni, Vévoda,
//! Grittmann, Skřivan, Slusallek and Křivánek (*Optimal Multiple Importance Sampling*,
//! SIGGRAPH 2019) found the ones that make the combined estimator's variance smallest, and
//! showed how to use them without knowing them in advance: per pixel, a few sums over the
//! pixel's own samples, a 2 × 2 linear system, and the sum of its solution.
//!
//! - [`techniques`]: at the surface a camera ray meets, one light sample and one BSDF sample,
//!   each with the integrand's value and *both* techniques' densities at its direction, and
//!   what needs no combining (light seen directly, point lights, mirror directions);
//! - [`optimal`]: the sums a pixel accumulates, and their solve (the paper's "direct
//!   estimator"), with the balance heuristic's estimate from the same samples to fall back on,
//!   and the progressive, unbiased variant ([`optimal::ProgressiveOptimal`]);
//! - [`pixel`]: one pixel's value from its samples, combined by a heuristic or optimally;
//!   [`render_direct`] renders a scene that way;
//! - [`path`]: the same two techniques at every vertex of chapter 08's path, kept per depth,
//!   which [`render_path_with`] combines per pixel and per depth.
//!
//! The crate's workbench (its binary, `render --mis optimal|power|balance`, and the figures)
//! is `lab`, in the folder `lab/` beside `src/`, built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;
pub mod optimal;
pub mod path;
pub mod pixel;
pub mod techniques;

pub use optimal::{OptimalSums, ProgressiveOptimal};
pub use pixel::Combination;

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene, TimeSampler};
use ch06_fuzzy_reflections::FuzzMethod;
use ch07_soft_shadows::{AreaLights, LightSampling};
use ch08_path_tracing::{Materials, PathOptions, PathTracer, SceneLights};
use ch09_materials::SceneMaterials;
use common::render::{RenderOutput, RenderSettings, render_per_pixel};

/// Renders the light reaching the surfaces the camera sees straight from the lights (Mitsuba's
/// `direct` integrator with one light and one BSDF sample), every material a scene file names,
/// each pixel from its own samples combined as `combination` says ([`pixel::pixel_value`]).
/// The same seed gives the same image on any number of threads.
pub fn render_direct<S: TimeSampler>(
    world: &MotionScene,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    combination: Combination,
) -> RenderOutput {
    let materials = SceneMaterials::of(&world.scene, FuzzMethod::Lobe);
    let options = PathOptions::default();
    render_direct_with(
        world,
        materials,
        options,
        lens,
        settings,
        sampler,
        combination,
    )
}

/// [`render_direct`] with the materials given (their tables made beforehand, so that a
/// series of renders of one scene makes them once) and the file's options, of which the
/// direct light reads `hide_emitters`: the camera then sees through what glows.
pub fn render_direct_with<S: TimeSampler, M: Materials>(
    world: &MotionScene,
    materials: M,
    options: PathOptions,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    combination: Combination,
) -> RenderOutput {
    render_pixels(
        world,
        materials,
        options,
        lens,
        settings,
        sampler,
        combination,
        false,
    )
}

/// Renders whole paths, as chapter 08's path tracer does with `options` (depth, roulette,
/// `hide_emitters`), but with the light sample and the BSDF sample at every vertex combined
/// as `combination` says, per pixel and per depth ([`pixel::path_pixel_value`]). The power
/// heuristic renders what chapter 08 renders; the same seed gives the same image on any number
/// of threads.
pub fn render_path_with<S: TimeSampler, M: Materials>(
    world: &MotionScene,
    materials: M,
    options: PathOptions,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    combination: Combination,
) -> RenderOutput {
    render_pixels(
        world,
        materials,
        options,
        lens,
        settings,
        sampler,
        combination,
        true,
    )
}

/// The render of [`render_direct_with`] (`paths` false) and of [`render_path_with`] (true):
/// the same tracer and camera rays, each pixel from its own samples.
#[allow(clippy::too_many_arguments)]
fn render_pixels<S: TimeSampler, M: Materials>(
    world: &MotionScene,
    materials: M,
    options: PathOptions,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    combination: Combination,
    paths: bool,
) -> RenderOutput {
    let camera_rays = CameraRays::new(world, lens, settings.width, settings.height);
    let area_lights = AreaLights::of(&world.scene);
    let tracer = PathTracer {
        world,
        lights: SceneLights::of(world, &area_lights, LightSampling::solid_angle()),
        options,
        materials,
    };
    render_per_pixel(settings, sampler, |pixel, spp, sampler| {
        if paths {
            pixel::path_pixel_value(&tracer, &camera_rays, pixel, spp, sampler, combination)
        } else {
            pixel::pixel_value(&tracer, &camera_rays, pixel, spp, sampler, combination)
        }
    })
}
