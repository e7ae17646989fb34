//! Plastic (Mitsuba 3's smooth `plastic`): a matte base under a clear dielectric coat.
//!
//! The coat reflects `F_i = F(cos θ_o)` of the light as a mirror (scaled by the
//! `specular_reflectance`). The rest enters, scatters at the base and leaves through the coat,
//! losing `F_o = F(cos θ_i)` on the way out and spreading over a solid angle `eta²` times wider
//! (the `1 / eta²`); light the coat sends back down scatters again. Summed over those bounces
//! the base is `ρ / (1 - F_dr ρ)` (`nonlinear`) or Mitsuba's default `ρ / (1 - F_dr)`, which
//! keeps the base's hue, with `F_dr` the coat's reflectance for diffuse light from inside
//! ([`diffuse_fresnel_reflectance`]). So, for `wi` and `wo` above the surface,
//!
//! `f cos θ_i = base · (1 - F_i)(1 - F_o) / eta² · cos θ_i / π`, plus the coat's delta.
//!
//! Sampling picks the coat with probability `F_i w / (F_i w + (1 - F_i)(1 - w))`, where
//! `w = s / (d + s)` weighs the mean specular reflectance `s` against the mean base albedo `d`
//! (Mitsuba's `specular_sampling_weight`), else a cosine-weighted direction. A rough coat
//! (`roughplastic`) is [`super::microfacet`]'s.

use ch01_whitted::optics::{fresnel_dielectric, reflect};
use ch02_monte_carlo::warps::{cosine_hemisphere_pdf, sample_cosine_hemisphere};
use ch08_path_tracing::bsdf::{BsdfSample, facing_normal, to_world};
use common::geometry::SurfaceHit;
use common::scene::Plastic;
use glam::{Vec2, Vec3};
use std::f32::consts::FRAC_1_PI;

/// The share of diffuse light (uniform radiance over the hemisphere) that an interface of
/// relative index `eta` reflects, from fits to the exact integral: Egan and Hilgeman (1973)
/// below 1, d'Eon and Irving (2011) above, as Mitsuba's `fresnel_diffuse_reflectance` picks.
pub fn diffuse_fresnel_reflectance(eta: f32) -> f32 {
    if eta < 1.0 {
        -1.4399 * eta * eta + 0.7099 * eta + 0.6681 + 0.0636 / eta
    } else {
        let inv = 1.0 / eta;
        0.919317
            + inv * (-3.4793 + inv * (6.75335 + inv * (-7.80989 + inv * (4.98554 - 1.36881 * inv))))
    }
}

/// What a plastic is at one hit: the side's normal and the numbers every query needs.
struct Local {
    normal: Vec3,
    fresnel_o: f32,
    relative_eta: f32,
    base: Vec3,
    coat_probability: f32,
}

impl Local {
    /// `None` from behind a one-sided plastic (Mitsuba's is black there).
    fn at(hit: &SurfaceHit, wo: Vec3, plastic: &Plastic) -> Option<Self> {
        let normal = facing_normal(hit, wo, plastic.two_sided)?;
        let cos_o = wo.dot(normal).min(1.0);
        if cos_o <= 0.0 {
            return None;
        }
        let relative_eta = plastic.int_ior / plastic.ext_ior;
        let fresnel_o = fresnel_dielectric(cos_o, 1.0 / relative_eta);
        let inside = diffuse_fresnel_reflectance(1.0 / relative_eta);
        let albedo = plastic.diffuse_reflectance;
        let base = if plastic.nonlinear {
            albedo / (Vec3::ONE - albedo * inside)
        } else {
            albedo / (1.0 - inside)
        };
        let specular_mean = mean(plastic.specular_reflectance);
        let means = mean(albedo) + specular_mean;
        let weight = if means > 0.0 {
            specular_mean / means
        } else {
            0.5
        };
        let coat = fresnel_o * weight;
        let under = (1.0 - fresnel_o) * (1.0 - weight);
        // Both 0 only for a black coat over nothing to see, or the reverse: either will do.
        let coat_probability = if coat + under > 0.0 {
            coat / (coat + under)
        } else {
            0.5
        };
        Some(Local {
            normal,
            fresnel_o,
            relative_eta,
            base,
            coat_probability,
        })
    }

    /// The base's `f cos θ_i` towards `wi` (0 below the surface).
    fn base_eval(&self, wi: Vec3) -> Vec3 {
        let cos_i = wi.dot(self.normal);
        if cos_i <= 0.0 {
            return Vec3::ZERO;
        }
        let fresnel_i = fresnel_dielectric(cos_i.min(1.0), 1.0 / self.relative_eta);
        self.base * ((1.0 - self.fresnel_o) * (1.0 - fresnel_i) * cos_i * FRAC_1_PI)
            / (self.relative_eta * self.relative_eta)
    }
}

fn mean(c: Vec3) -> f32 {
    (c.x + c.y + c.z) / 3.0
}

/// Picks the coat's mirror direction or the base with `choice`, then the base's direction
/// with `u`.
pub fn sample(
    hit: &SurfaceHit,
    wo: Vec3,
    plastic: &Plastic,
    choice: f32,
    u: Vec2,
) -> Option<BsdfSample> {
    let local = Local::at(hit, wo, plastic)?;
    if choice < local.coat_probability {
        return Some(BsdfSample {
            wi: reflect(-wo, local.normal),
            weight: plastic.specular_reflectance * local.fresnel_o / local.coat_probability,
            pdf: f32::INFINITY,
            eta_scale: 1.0,
        });
    }
    let wi = to_world(local.normal, sample_cosine_hemisphere(u));
    let pdf = pdf(hit, wo, wi, plastic);
    (pdf > 0.0).then(|| BsdfSample {
        wi,
        weight: eval(hit, wo, wi, plastic) / pdf,
        pdf,
        eta_scale: 1.0,
    })
}

/// `f(wo, wi) cos θ_i` without the coat's delta: the base's.
pub fn eval(hit: &SurfaceHit, wo: Vec3, wi: Vec3, plastic: &Plastic) -> Vec3 {
    Local::at(hit, wo, plastic).map_or(Vec3::ZERO, |local| local.base_eval(wi))
}

/// The density of [`sample`] at `wi`, the smooth coat's delta left out.
pub fn pdf(hit: &SurfaceHit, wo: Vec3, wi: Vec3, plastic: &Plastic) -> f32 {
    let Some(local) = Local::at(hit, wo, plastic) else {
        return 0.0;
    };
    let cos_i = wi.dot(local.normal);
    if cos_i <= 0.0 {
        return 0.0;
    }
    (1.0 - local.coat_probability) * cosine_hemisphere_pdf(cos_i.min(1.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn diffuse_fresnel_matches_mitsuba() {
        // Mitsuba 3.9.1's `mi.fresnel_diffuse_reflectance` at 1/1.49 and 1.49.
        assert!((diffuse_fresnel_reflectance(1.0 / 1.49) - 0.5907325).abs() < 1e-5);
        assert!((diffuse_fresnel_reflectance(1.49) - 0.09029996).abs() < 1e-5);
        // No interface reflects nothing (to the fits' accuracy).
        assert!(diffuse_fresnel_reflectance(1.0).abs() < 2e-3);
    }
}
