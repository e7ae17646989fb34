//! # Chapter 03: Anti-aliasing
//!
//! A pixel is a small square, not a point, and its value is an integral over that square.
//! Chapter 01 evaluated the image at each pixel's centre: every edge became a staircase and
//! every fine pattern a false, coarse one (aliasing). This chapter estimates the integral with
//! several samples per pixel placed at random, stratified, or along a low-discrepancy
//! sequence, and combines nearby samples with a reconstruction filter.
//!
//! - [`pixel_samplers`]: where in its pixel each sample looks.
//! - [`filters`]: how samples are weighted into pixels, `Σ f L / Σ f`.
//! - [`reconstruction`]: that weighted average gathered for one pixel, as the lecture writes it,
//!   and the render that draws every pixel of the chapter's images with it.
//! - [`scenes`]: scenes that alias.
//! - [`coverage`]: one pixel cut by an edge, the samplers' error in its purest form.
//!
//! The tracer is chapter 01's, unchanged: anti-aliasing only changes which camera rays are
//! shot and how their radiance is averaged.
//!
//! The chapter's workbench (its binary and options, reading a scene file's film and sampler,
//! the book's figures, agreement with Mitsuba 3) is `lab`, in the folder `lab/` beside `src/`,
//! built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod coverage;
pub mod filters;
pub mod pixel_samplers;
pub mod reconstruction;
pub mod scenes;

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;

pub use filters::{FilterKind, ReconstructionFilter};
pub use pixel_samplers::{PixelSampler, PixelSamplerKind};

use ch01_whitted::camera::PinholeCamera;
use common::film::Filter;
use common::render::{RenderOutput, RenderSettings};
use common::sampler::Sampler;
use common::scene::Scene;

// ANCHOR: render_with
/// Renders a chapter 01 `scene` with Whitted's tracer: pixel positions from `sampler`, each
/// sample one camera ray, and every pixel reconstructed with `filter` by
/// [`reconstruction::filtered_pixel`].
pub fn render_with<S: Sampler>(
    scene: &Scene,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let camera = PinholeCamera::of(&scene.camera, settings.width, settings.height);
    reconstruction::render(settings, sampler, filter, |p_film, _sampler| {
        ch01_whitted::tracer::trace(scene, &camera.generate_ray(p_film), 1)
    })
}
// ANCHOR_END: render_with
