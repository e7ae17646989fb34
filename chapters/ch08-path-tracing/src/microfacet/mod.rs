//! Beyond the lecture: microfacet BSDFs as Mitsuba 3 renders them.
//!
//! Chapter 06 stands a `cos^n` lobe in for a file's rough materials. Here they are what
//! Mitsuba makes of them: surfaces of tiny mirror facets whose normals follow Beckmann's or
//! GGX's distribution, with Smith's shadowing and the Fresnel term at each facet, sampled by
//! the facets the viewer can see. Each material takes plain parameters and directions in the
//! local frame (`z` the normal), so that it can serve any caller.
//!
//! - [`distribution`]: `D`, `G1`, `G` and both samplers; [`visible_facets`]: the core of
//!   visible-normal sampling.
//! - [`fresnel`]: the dielectric and conductor Fresnel terms, reflection and refraction about
//!   a facet.
//! - [`rough_conductor`], [`rough_dielectric`], [`rough_plastic`] (with its [`coating`]
//!   tables and their [`gauss_legendre`] rule): Mitsuba's `roughconductor`,
//!   `roughdielectric`, `roughplastic`.
//! - [`figures`]: the `cos^n` lobe against GGX and Beckmann; the white furnace.

pub mod albedo;
pub mod coating;
pub mod distribution;
pub mod figures;
pub mod fresnel;
pub mod gauss_legendre;
pub mod local;
pub mod rough_conductor;
pub mod rough_dielectric;
pub mod rough_plastic;
pub mod visible_facets;

#[cfg(test)]
mod tests;

pub use distribution::{MIN_ALPHA, NormalDistribution};
pub use local::LocalBsdf;
pub use rough_conductor::RoughConductor;
pub use rough_dielectric::RoughDielectric;
pub use rough_plastic::{RoughPlastic, RoughPlasticParameters};
