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
//! - [`fresnel`]: the dielectric Fresnel term, reflection and refraction about a facet (the
//!   conductor's is the smooth metal's, [`crate::bsdf::conductor`]).
//! - [`rough_conductor`], [`rough_dielectric`], [`rough_plastic`] (with its [`coating`]
//!   tables and their [`gauss_legendre`] rule): Mitsuba's `roughconductor`,
//!   `roughdielectric`, `roughplastic`.
//! - [`local`]: the one trait the three share; [`albedo`]: `∫ f cos θ` by quadrature over the
//!   facets, for the tests and the furnace figure.
//!
//! The figures (the `cos^n` lobe against GGX and Beckmann, the white furnace, the samplers'
//! chi-square table) are the chapter's workbench, `lab`.
//!
//! Where this differs from Mitsuba, on purpose: Beckmann's visible slopes are inverted in
//! double precision (and kept inside the domain of `erf⁻¹` at grazing incidence, where
//! Mitsuba's single-precision Newton steps can leave it); plain normal sampling computes
//! `sin θ` as `tan θ cos θ` (Mitsuba's `√(1 - cos² θ)` loses small angles, which the
//! chi-square test sees at `alpha = 0.02`); a facet on edge in GGX's sampler stays finite.
//! Left out: `sample_visible = false` in the BSDFs (with Walter's widening of `alpha` in
//! `roughdielectric`), textured roughness, and polarisation. Every BSDF is single
//! scattering, so rough surfaces lose energy as Mitsuba's do (see the furnace figure).

pub mod albedo;
pub mod coating;
pub mod distribution;
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
