//! # Chapter 01: Whitted ray tracing
//!
//! Where the lecture starts: one ray per pixel, point lights with hard shadows, matte
//! surfaces, perfect mirrors and glass. Everything is deterministic, which is exactly what the
//! later chapters change: each one replaces a single fixed choice here (the pixel centre, the
//! pinhole, the instant of time, the perfect mirror, the point light) by an integral sampled
//! at random.
//!
//! - [`optics`]: reflection, Snell's law, the Fresnel equations.
//! - [`camera`]: the pinhole camera.
//! - [`world`]: the two questions the tracer asks of the world (the world itself is the
//!   workbook's scene model, `common::scene`); [`scenes`]: the chapter's built-in scenes.
//! - [`tracer`]: the recursive tracer.
//! - [`pixel`]: where in its pixel a ray goes (the centre, or a regular grid).
//!
//! The chapter's workbench (its binary, what of a scene file it renders, the book's figures,
//! agreement with Mitsuba 3) is `lab`, in the folder `lab/` beside `src/`, built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod camera;
pub mod optics;
pub mod pixel;
pub mod scenes;
pub mod tracer;
pub mod world;

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;

use camera::PinholeCamera;
use common::film::PixelBoxFilter;
use common::render::{self, RenderOutput, RenderSettings};
use common::sampler::Sampler;
use common::scene::Scene;
use pixel::{CentreSampler, GridSampler};

/// Where the samples of a pixel go.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum PixelPattern {
    /// Every sample through the pixel centre: Whitted's one ray per pixel.
    Centre,
    /// A regular `k x k` grid of samples per pixel; the sample count must be a square.
    Grid,
}

/// Renders `scene` with Whitted's tracer.
///
/// Returns `None` for a grid whose sample count is not a perfect square (or a timed
/// budget, whose count is not known in advance).
pub fn render(
    scene: &Scene,
    settings: &RenderSettings,
    pattern: PixelPattern,
    seed: u64,
) -> Option<RenderOutput> {
    match pattern {
        PixelPattern::Centre => Some(render_with(scene, settings, &CentreSampler::new(seed))),
        PixelPattern::Grid => {
            let render::Budget::Samples(spp) = settings.budget else {
                return None;
            };
            let grid = GridSampler::for_spp(spp, seed)?;
            Some(render_with(scene, settings, &grid))
        }
    }
}

// ANCHOR: render_with
/// Renders `scene` with pixel positions from `sampler`: each sample traces one camera ray.
pub fn render_with<S: Sampler>(
    scene: &Scene,
    settings: &RenderSettings,
    sampler: &S,
) -> RenderOutput {
    let camera = PinholeCamera::of(&scene.camera, settings.width, settings.height);
    render::render(settings, sampler, &PixelBoxFilter, |p_film, _sampler| {
        tracer::trace(scene, &camera.generate_ray(p_film), 1)
    })
}
// ANCHOR_END: render_with
