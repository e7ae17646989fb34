//! # Chapter 07: soft shadows
//!
//! A point light casts a hard shadow: a receiver either sees it or does not. A real lamp has a
//! size, and a receiver in the penumbra sees part of it. Cook, Porter and Carpenter (1984)
//! turned that into one more dimension of the distribution: each shadow ray goes to a
//! *random point on the light*, and the average over many rays is the fraction of the light
//! that is visible, weighted the way the light arrives. In the lecture's words: "random sample
//! point on surface of light source; scale intensity by area and cosine".
//!
//! The library comes first, the renderer on top of it: chapter 06's tracer, lit through its
//! `Lighting` hook by [`lighting::AreaLighting`].
//!
//! - [`area_lights`]: area lights of finite size, one-sided (Mitsuba 3's `area` emitter), and
//!   a scene's lights found among its shapes.
//! - [`disc_warp`]: which of chapter 02's disc warps puts points on a disc light.
//! - [`light_sample`]: a sampled point with its density and its shadow ray; [`strategy`]: by
//!   area or by solid angle, and the one function that picks a light's sampler.
//! - [`area_sampling`]: points uniform by area on parallelograms, triangles, discs, spheres.
//! - [`solid_angle`]: a sphere sampled by the cone of directions it subtends, and the change of
//!   density between area and solid angle.
//! - [`estimator`]: the direct-light estimate of irradiance at a matte receiver.
//! - [`shadow_rays`]: how many shadow rays each light gets, and their `u`, independent or
//!   stratified.
//! - [`mod@reference`]: exact irradiance from polygons, discs and spheres, for the tests.
//! - [`sample_stream`]: the sample's numbers for the shadow rays.
//! - [`lighting`]: chapter 06's tracer lit by a scene's area lights; [`render_with`].
//! - [`scenes`]: what to look at.
//!
//! The chapter's workbench (its binary and light options, the book's figures, agreement with
//! Mitsuba 3) is `lab`, in the folder `lab/` beside `src/`, built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod area_lights;
pub mod area_sampling;
pub mod disc_warp;
pub mod estimator;
pub mod light_sample;
pub mod lighting;
pub mod reference;
pub mod sample_stream;
pub mod scenes;
pub mod shadow_rays;
pub mod solid_angle;
pub mod strategy;

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;

#[cfg(test)]
pub(crate) mod test_support;

pub use area_lights::{AreaLight, AreaLights, LightShape};
pub use disc_warp::DiscWarp;
pub use estimator::{estimate_irradiance, light_sample_contribution, matte_reflected_radiance};
pub use light_sample::LightSample;
pub use lighting::AreaLighting;
pub use shadow_rays::{LightOptions, LightStrata, light_samples};
pub use strategy::{LightSampling, Strategy};

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{MotionScene, TimeSampler};
use ch06_fuzzy_reflections::TraceOptions;
use common::film::Filter;
use common::render::{RenderOutput, RenderSettings};

// ANCHOR: render_with
/// Renders `world` through `lens` with chapter 06's tracer, its area lights sampled as
/// `lights` says. Each sample draws, in order: the pixel position, the time and the lens point
/// (each only when needed), then per bounce the glass and lobe numbers and, at a matte hit, the
/// points on each area light. Without area lights this is chapter 06's render, bit for bit.
pub fn render_with<S: TimeSampler>(
    world: &MotionScene,
    lights: LightOptions,
    options: TraceOptions,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let area_lights = AreaLights::of(&world.scene);
    let lighting = area_lights.lighting(lights);
    ch06_fuzzy_reflections::render_with(world, &lighting, options, lens, settings, sampler, filter)
}
// ANCHOR_END: render_with
