//! Mitsuba 3's `roughplastic`: a diffuse base under a rough dielectric coating. Two lobes add:
//!
//! - the coating's reflection, a rough dielectric's: `F(wo·h) D G / (4 cos θ_o)`;
//! - the base, seen through the coating: `ρ' / π · cos θ_i · T(cos θ_o) T(cos θ_i) / η²`,
//!   with `T` the [`Coating`]'s tabulated transmittance, `1/η²` the widening of the beam as the
//!   light leaves the denser coating into the air (on the way in, the base reflects the power
//!   that reaches it, which the narrowing does not change), and `ρ' = ρ / (1 - R_int)` the
//!   base's albedo raised by the light the coating reflects back down onto it (Mitsuba's linear
//!   approximation, its default; `nonlinear` sums the series, `ρ / (1 - ρ R_int)`).
//!
//! Sampling picks the coating's lobe (visible normals) or the base's (cosine) with
//! probabilities proportional to `(1 - T(cos θ_o)) w` and `T(cos θ_o) (1 - w)`, where `w` is
//! Mitsuba's `specular_sampling_weight`, the specular reflectance's mean over the sum of both
//! reflectances' means. The density is the mixture of both, so the weight is `eval / pdf`.
//!
//! Directions are in the local frame (`z` the normal) and point away from the surface: `wo`
//! towards where the path came from, `wi` towards the light. One-sided and isotropic, as
//! Mitsuba's.

use super::coating::Coating;
use super::distribution::NormalDistribution;
use super::fresnel;
use ch02_monte_carlo::warps::cosine::{cosine_hemisphere_pdf, sample_cosine_hemisphere};
use ch08_path_tracing::BsdfSample;
use common::scene::MicrofacetDistribution;
use glam::{Vec2, Vec3};
use std::f32::consts::FRAC_1_PI;

/// A rough plastic, over its coating's tables.
#[derive(Clone, Debug, PartialEq)]
pub struct RoughPlastic<'a> {
    distribution: NormalDistribution,
    eta: f32,
    diffuse_reflectance: Vec3,
    specular_reflectance: Vec3,
    nonlinear: bool,
    coating: &'a Coating,
    specular_sampling_weight: f32,
}

/// What [`RoughPlastic::new`] takes: Mitsuba's parameters of `roughplastic`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughPlasticParameters {
    /// Beckmann or GGX.
    pub kind: MicrofacetDistribution,
    /// The coating's roughness (Mitsuba's `roughplastic` is isotropic).
    pub alpha: f32,
    /// `int_ior / ext_ior` of the coating, not 1.
    pub eta: f32,
    /// The base's albedo `ρ`.
    pub diffuse_reflectance: Vec3,
    /// A factor on the coating's reflection (1: none).
    pub specular_reflectance: Vec3,
    /// Mitsuba's `nonlinear`: the base's inter-reflections tint its colour.
    pub nonlinear: bool,
}

impl RoughPlasticParameters {
    /// The facets of the coat: Mitsuba's `roughplastic` is isotropic.
    pub fn distribution(&self) -> NormalDistribution {
        NormalDistribution::isotropic(self.kind, self.alpha)
    }

    /// Tabulates the coat's coating (some 10⁶ sampled normals, as in Mitsuba): for a plastic
    /// made on its own; a render takes its plastics' coatings from
    /// [`Coatings`](super::coating::Coatings), made before it starts.
    pub fn coating(&self) -> Coating {
        Coating::new(&self.distribution(), self.eta)
    }
}

impl<'a> RoughPlastic<'a> {
    /// The plastic over `coating`, its coat's tables ([`RoughPlasticParameters::coating`]).
    pub fn new(p: RoughPlasticParameters, coating: &'a Coating) -> Self {
        let distribution = p.distribution();
        let mean = |c: Vec3| (c.x + c.y + c.z) / 3.0;
        let specular = mean(p.specular_reflectance);
        Self {
            distribution,
            eta: p.eta,
            diffuse_reflectance: p.diffuse_reflectance,
            specular_reflectance: p.specular_reflectance,
            nonlinear: p.nonlinear,
            coating,
            specular_sampling_weight: specular / (mean(p.diffuse_reflectance) + specular),
        }
    }

    /// The coating's tables.
    pub fn coating(&self) -> &Coating {
        self.coating
    }

    // ANCHOR: rough_plastic_eval
    /// `f(wo, wi) cos θ_i`.
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return Vec3::ZERO;
        }
        let h = (wo + wi).normalize();
        let f = fresnel::DielectricFresnel::new(wo.dot(h), self.eta).reflectance;
        let coating = f * self.distribution.d(h) * self.distribution.g(wo, wi, h) / (4.0 * wo.z);
        let r_int = self.coating.internal_reflectance;
        let albedo = if self.nonlinear {
            self.diffuse_reflectance / (Vec3::ONE - self.diffuse_reflectance * r_int)
        } else {
            self.diffuse_reflectance / (1.0 - r_int)
        };
        let through = self.coating.transmittance(wo.z) * self.coating.transmittance(wi.z);
        self.specular_reflectance * coating
            + albedo * (FRAC_1_PI / (self.eta * self.eta) * wi.z * through)
    }
    // ANCHOR_END: rough_plastic_eval

    /// The probability of sampling the coating's lobe for `wo` above the surface.
    fn coating_probability(&self, cos_theta_o: f32) -> f32 {
        let t = self.coating.transmittance(cos_theta_o);
        let w = self.specular_sampling_weight;
        let (coating, base) = ((1.0 - t) * w, t * (1.0 - w));
        coating / (coating + base)
    }

    /// The density per unit solid angle with which [`sample`](Self::sample) picks `wi`.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return 0.0;
        }
        let h = (wo + wi).normalize();
        let coating = self.distribution.d(h) * self.distribution.g1(wo, h) / (4.0 * wo.z);
        let p = self.coating_probability(wo.z);
        p * coating + (1.0 - p) * cosine_hemisphere_pdf(wi.z)
    }

    /// A direction from the coating's lobe or the base's, `choice` picking which and `u`
    /// where; `None` below the surface.
    pub fn sample(&self, wo: Vec3, choice: f32, u: Vec2) -> Option<BsdfSample> {
        if wo.z <= 0.0 {
            return None;
        }
        let wi = if choice < self.coating_probability(wo.z) {
            let m = self.distribution.sample_visible_normal(wo, u);
            fresnel::reflect_away(wo, m)
        } else {
            sample_cosine_hemisphere(u)
        };
        let pdf = self.pdf(wo, wi);
        if pdf.is_nan() || pdf <= 0.0 {
            return None;
        }
        Some(BsdfSample {
            wi,
            weight: self.eval(wo, wi) / pdf,
            pdf,
            eta_scale: 1.0,
        })
    }
}
