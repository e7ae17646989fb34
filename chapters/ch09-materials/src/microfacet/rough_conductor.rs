//! Mitsuba 3's `roughconductor`: a metal made of mirror facets, Walter et al.'s model
//! `f(wo, wi) = F(wo·h) D(h) G(wo, wi, h) / (4 cos θ_o cos θ_i)` with `h` the half vector, the
//! conductor's complex Fresnel term at the facet, and sampling of the visible normals, so a
//! sample's weight never exceeds 1.
//!
//! Directions are in the local frame (`z` the normal) and point away from the surface: `wo`
//! towards where the path came from, `wi` towards the light. One-sided, as Mitsuba's: black
//! unless both are above the surface.

use super::distribution::NormalDistribution;
use crate::bsdf::conductor::fresnel_conductor_rgb;
use ch08_path_tracing::BsdfSample;
use glam::{Vec2, Vec3};

/// A rough metal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughConductor {
    /// Its facets' normals.
    pub distribution: NormalDistribution,
    /// The real part of the relative index of refraction, per colour channel.
    pub eta: Vec3,
    /// The imaginary part (absorption), per colour channel.
    pub k: Vec3,
    /// Mitsuba's `specular_reflectance`: a factor on top of the Fresnel term (1: none).
    pub specular_reflectance: Vec3,
}

impl RoughConductor {
    /// A rough conductor that reflects everything at every facet (Mitsuba's default `eta = 0`,
    /// `k = 1`): what it loses it loses to shadowing alone, which is what the white furnace
    /// measures.
    pub fn white(kind: common::scene::MicrofacetDistribution, alpha: f32) -> Self {
        Self {
            distribution: NormalDistribution::isotropic(kind, alpha),
            eta: Vec3::ZERO,
            k: Vec3::ONE,
            specular_reflectance: Vec3::ONE,
        }
    }

    // ANCHOR: rough_conductor_eval
    /// `f(wo, wi) cos θ_i`.
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return Vec3::ZERO;
        }
        let h = (wo + wi).normalize();
        let d = self.distribution.d(h);
        if d == 0.0 {
            return Vec3::ZERO;
        }
        let g = self.distribution.g(wo, wi, h);
        self.fresnel(wo.dot(h)) * (d * g / (4.0 * wo.z))
    }
    // ANCHOR_END: rough_conductor_eval

    /// The density per unit solid angle with which [`sample`](Self::sample) picks `wi`: the
    /// visible-normal density of the half vector, carried over from normals to the directions
    /// they mirror `wo` into.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return 0.0;
        }
        let h = (wo + wi).normalize();
        // Facets seen from the back, from either side, are never sampled.
        if wo.dot(h) <= 0.0 || wi.dot(h) <= 0.0 {
            return 0.0;
        }
        self.distribution.d(h) * self.distribution.g1(wo, h) / (4.0 * wo.z)
    }

    // ANCHOR: rough_conductor_sample
    /// A direction mirrored about a facet normal visible from `wo`, drawn with the two
    /// numbers `u`, with its density per unit solid angle and its weight `f cos θ_i / pdf` (a
    /// reflection scales no radiance: `eta_scale` 1);
    /// `None` when `wo` is below the surface or the mirrored direction is (the path ends: that
    /// share of the light is what the single-scattering model loses).
    pub fn sample(&self, wo: Vec3, u: Vec2) -> Option<BsdfSample> {
        // BEGIN SOLUTION
        use crate::microfacet::fresnel;
        if wo.z <= 0.0 {
            return None;
        }
        let m = self.distribution.sample_visible_normal(wo, u);
        let pdf_m = self.distribution.visible_normal_pdf(wo, m);
        let wi = fresnel::reflect_away(wo, m);
        if pdf_m == 0.0 || wi.z <= 0.0 {
            return None;
        }
        // `f cos θ_i / pdf`: of `F D G1(wo) G1(wi) / (4 cos θ_o)` over
        // `G1(wo) (wo·m) D / (4 cos θ_o (wi·m))` only `F G1(wi)` is left (`wo·m = wi·m`).
        let weight = self.fresnel(wo.dot(m)) * self.distribution.g1(wi, m);
        Some(BsdfSample {
            wi,
            weight,
            pdf: pdf_m / (4.0 * wi.dot(m)),
            eta_scale: 1.0,
        })
        // END SOLUTION
    }
    // ANCHOR_END: rough_conductor_sample

    /// The facet's Fresnel reflectance at `cos θ = w·m`, times the specular reflectance.
    pub fn fresnel(&self, cos_theta: f32) -> Vec3 {
        fresnel_conductor_rgb(cos_theta, self.eta, self.k) * self.specular_reflectance
    }
}
