//! # Chapter 07: soft shadows
//!
//! A point light casts a hard shadow: a receiver either sees it or does not. A real lamp has a
//! size, and a receiver in the penumbra sees part of it. Cook, Porter and Carpenter (1984)
//! turned that into one more dimension of the distribution: each shadow ray goes to a
//! *random point on the light*, and the average over many rays is the fraction of the light
//! that is visible, weighted the way the light arrives. In the lecture's words: "random sample
//! point on surface of light source; scale intensity by area and cosine".
//!
//! This crate is that idea as a library; the tracer that uses it comes with the chapter's
//! renderer.
//!
//! - [`light`]: area lights of finite size, one-sided (Mitsuba 3's `area` emitter).
//! - [`disc_warp`]: which of chapter 02's disc warps puts points on a disc light.
//! - [`light_sample`]: a sampled point with its density and its shadow ray.
//! - [`area_sampling`]: points uniform by area on parallelograms, triangles, discs, spheres.
//! - [`solid_angle`]: a sphere sampled by the cone of directions it subtends, and the change of
//!   density between area and solid angle.
//! - [`estimator`]: the direct-light estimate of irradiance at a matte receiver.
//! - [`mod@light_samples`]: the `u` of the shadow rays, independent or stratified.
//! - [`mod@reference`]: exact irradiance from polygons, discs and spheres, for the tests.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod area_sampling;
pub mod disc_warp;
pub mod estimator;
pub mod light;
pub mod light_sample;
pub mod light_samples;
pub mod reference;
pub mod solid_angle;

#[cfg(test)]
pub(crate) mod test_support;

pub use disc_warp::DiscWarp;
pub use estimator::{estimate_irradiance, light_sample_contribution, matte_reflected_radiance};
pub use light::{AreaLight, LightShape};
pub use light_sample::{LightSample, LightSampling, Strategy};
pub use light_samples::light_samples;
