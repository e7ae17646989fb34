//! Mitsuba 3's `roughdielectric`: frosted glass as Walter et al. (2007) model it. Each facet
//! reflects or refracts; the BSDF adds the two over the facets:
//!
//! - reflection: `F D G / (4 |cos θ_o|)` (that is `f cos θ_i`), `h` the half vector;
//! - refraction: `(1 - F) D G η² |wo·h| |wi·h| / (|cos θ_o| (wo·h + η wi·h)²)`, `h` the
//!   generalised half vector `-(wo + η wi)` and `η = n_t / n_i`, times `1/η²`: in radiance
//!   mode (the path tracer's) the radiance is scaled by `(n_i / n_t)²` as the beam narrows.
//!
//! Sampling draws a facet normal visible from `wo` (on `wo`'s side), then reflects with the
//! probability `F` of that facet and refracts otherwise, as Mitsuba does: the weight is then
//! only the shadowing the facet's density does not already hold (times `1/η²` through
//! refraction).
//!
//! Directions are in the local frame (`z` the normal, pointing outside, where the index is
//! `ext_ior`) and point away from the surface: `wo` towards where the path came from, `wi`
//! towards the light. Both sides are glass.

use super::distribution::NormalDistribution;
use super::fresnel::{self, DielectricFresnel};
use ch08_path_tracing::BsdfSample;
use glam::{Vec2, Vec3};

/// Rough glass between the outside (above) and the inside (below).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoughDielectric {
    /// Its facets' normals.
    pub distribution: NormalDistribution,
    /// `int_ior / ext_ior`, not 1.
    pub eta: f32,
    /// Mitsuba's `specular_reflectance`, a factor on the reflected light (1: none).
    pub specular_reflectance: Vec3,
    /// Mitsuba's `specular_transmittance`, a factor on the refracted light (1: none).
    pub specular_transmittance: Vec3,
}

/// The facet normal a pair of directions implies, on the outside, and what else both `eval`
/// and `pdf` need.
struct Facet {
    m: Vec3,
    reflect: bool,
    /// `n_t / n_i` seen from `wo`'s side.
    eta: f32,
}

impl RoughDielectric {
    /// Glass of relative index `int_ior / ext_ior` with no extra factors.
    pub fn new(distribution: NormalDistribution, int_ior: f32, ext_ior: f32) -> Self {
        Self {
            distribution,
            eta: int_ior / ext_ior,
            specular_reflectance: Vec3::ONE,
            specular_transmittance: Vec3::ONE,
        }
    }

    /// The facet through which `wi` reflects or refracts into `wo`, `None` when there is none
    /// (`wo` grazing, or the two directions cancel).
    fn facet(&self, wo: Vec3, wi: Vec3) -> Option<Facet> {
        if wo.z == 0.0 {
            return None;
        }
        let reflect = wo.z * wi.z > 0.0;
        let eta = if wo.z > 0.0 { self.eta } else { 1.0 / self.eta };
        let sum = if reflect { wo + wi } else { wo + wi * eta };
        let m = sum.try_normalize()?;
        // The normal on the outside, as `D` is defined there.
        let m = if m.z < 0.0 { -m } else { m };
        Some(Facet { m, reflect, eta })
    }

    /// `f(wo, wi) cos θ_i`, for reflection (`wo`, `wi` on one side) or refraction.
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        let Some(Facet { m, reflect, eta }) = self.facet(wo, wi) else {
            return Vec3::ZERO;
        };
        let d = self.distribution.d(m);
        let f = fresnel::DielectricFresnel::new(wo.dot(m), self.eta).reflectance;
        let g = self.distribution.g(wo, wi, m);
        if reflect {
            self.specular_reflectance * (f * d * g / (4.0 * wo.z.abs()))
        } else {
            let (om, im) = (wo.dot(m), wi.dot(m));
            let value = (1.0 - f) * d * g * eta * eta * om * im
                / (wo.z * (om + eta * im).powi(2))
                / (eta * eta);
            self.specular_transmittance * value.abs()
        }
    }

    /// The density per unit solid angle with which [`sample`](Self::sample) picks `wi`: the
    /// visible-normal density of the facet, times the branch's probability (`F` or `1 - F`),
    /// times `dm / dwi`.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        let Some(Facet { m, reflect, eta }) = self.facet(wo, wi) else {
            return 0.0;
        };
        let (om, im) = (wo.dot(m), wi.dot(m));
        // Facets seen from the back, from either side, are never sampled.
        if om * wo.z <= 0.0 || im * wi.z <= 0.0 {
            return 0.0;
        }
        let dm_dwi = if reflect {
            1.0 / (4.0 * im)
        } else {
            eta * eta * im / (om + eta * im).powi(2)
        };
        let seen_from = wo * wo.z.signum();
        let f = fresnel::DielectricFresnel::new(om, self.eta).reflectance;
        let branch = if reflect { f } else { 1.0 - f };
        (self.distribution.visible_normal_pdf(seen_from, m) * branch * dm_dwi).abs()
    }

    /// Reflects or refracts `wo` at a facet visible from it: `choice` picks the branch by the
    /// facet's Fresnel term, `u` the facet. `None` for a grazing `wo`, and when the direction
    /// leaves on the wrong side (a reflection below the surface; Mitsuba gives it weight 0).
    pub fn sample(&self, wo: Vec3, choice: f32, u: Vec2) -> Option<BsdfSample> {
        if wo.z == 0.0 {
            return None;
        }
        let seen_from = wo * wo.z.signum();
        let m = self.distribution.sample_visible_normal(seen_from, u);
        let pdf_m = self.distribution.visible_normal_pdf(seen_from, m);
        if pdf_m == 0.0 {
            return None;
        }
        let fresnel = fresnel::DielectricFresnel::new(wo.dot(m), self.eta);
        let f = fresnel.reflectance;
        let (wi, weight, pdf, eta_scale) = if choice <= f {
            let wi = fresnel::reflect_away(wo, m);
            let dm_dwi = 1.0 / (4.0 * wi.dot(m));
            (wi, self.specular_reflectance, pdf_m * f * dm_dwi, 1.0)
        } else {
            let wi = fresnel::refract_away(wo, m, &fresnel);
            (
                wi,
                self.specular_transmittance * fresnel.eta_ti.powi(2),
                pdf_m * (1.0 - f) * refraction_jacobian(wo, wi, m, &fresnel),
                fresnel.eta_ti.powi(2),
            )
        };
        let g1 = self.distribution.g1(wi, m);
        let pdf = pdf.abs();
        if g1 == 0.0 || pdf.is_nan() || pdf <= 0.0 {
            return None;
        }
        Some(BsdfSample {
            wi,
            weight: weight * g1,
            pdf,
            eta_scale,
        })
    }
}

/// `dm / dwi` of refraction through `m`: `η² |wi·m| / (wo·m + η wi·m)²`.
fn refraction_jacobian(wo: Vec3, wi: Vec3, m: Vec3, fresnel: &DielectricFresnel) -> f32 {
    let eta = fresnel.eta_it;
    let (om, im) = (wo.dot(m), wi.dot(m));
    eta * eta * im / (om + eta * im).powi(2)
}
