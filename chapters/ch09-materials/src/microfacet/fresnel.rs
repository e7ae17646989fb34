//! The Fresnel reflectance at a microfacet, and the refracted direction, with Mitsuba 3's
//! conventions (`fresnel.h`): a relative index `eta = n_inside / n_outside` and a cosine whose
//! sign says which side the light comes from. A metal's facets use the smooth metal's
//! [`fresnel_conductor_rgb`](crate::bsdf::conductor::fresnel_conductor_rgb): one formula for
//! both.

use ch01_whitted::optics::{fresnel_dielectric, reflect};
use glam::Vec3;

/// What light meeting a dielectric interface does, Mitsuba's `fresnel()`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DielectricFresnel {
    /// The share reflected (1 under total internal reflection).
    pub reflectance: f32,
    /// `cos θ_t` of the refracted direction, of the sign opposite to `cos θ_i` (0 under
    /// total internal reflection).
    pub cos_theta_t: f32,
    /// The relative index in the direction of travel, `n_t / n_i`.
    pub eta_it: f32,
    /// Its inverse, `n_i / n_t`: also the factor of the refracted direction's tangential part.
    pub eta_ti: f32,
}

impl DielectricFresnel {
    /// The Fresnel terms for a direction at `cos_theta_i` to the normal (positive on the side the
    /// normal points to, the outside) at an interface of relative index `eta`.
    pub fn new(cos_theta_i: f32, eta: f32) -> Self {
        let (eta_it, eta_ti) = if cos_theta_i >= 0.0 {
            (eta, 1.0 / eta)
        } else {
            (1.0 / eta, eta)
        };
        let cos2_t = 1.0 - (1.0 - cos_theta_i * cos_theta_i) * eta_ti * eta_ti;
        let cos_t = cos2_t.max(0.0).sqrt();
        Self {
            // Chapter 01's formula; it takes `n_i / n_t` and returns 1 at grazing incidence.
            reflectance: fresnel_dielectric(cos_theta_i.abs(), eta_ti),
            cos_theta_t: if cos_theta_i >= 0.0 { -cos_t } else { cos_t },
            eta_it,
            eta_ti,
        }
    }
}

/// The direction refracted through the facet `m` from `w`, given the Fresnel terms of
/// `cos θ = w·m`: Mitsuba's `refract(wi, m, cos_theta_t, eta_ti)`.
///
/// "Away" because `w` and the answer both point away from the interface, as a BSDF's `wo` and
/// `wi` do; chapter 01's `optics::refract` follows the ray instead (its `d` points at the
/// surface) and decides total internal reflection itself, where this one is handed the
/// decision in `fresnel`.
pub fn refract_away(w: Vec3, m: Vec3, fresnel: &DielectricFresnel) -> Vec3 {
    m * (w.dot(m) * fresnel.eta_ti + fresnel.cos_theta_t) - w * fresnel.eta_ti
}

/// The mirror image of `w` about the facet normal `m`, both pointing away from the surface:
/// chapter 01's `optics::reflect`, which follows the ray (its `d` points at the surface), fed
/// the ray that arrives along `-w`.
pub fn reflect_away(w: Vec3, m: Vec3) -> Vec3 {
    reflect(-w, m)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Refraction keeps the tangential part scaled by `eta_ti` and leaves a unit vector on
    /// the other side, under Snell's law.
    #[test]
    fn refraction_obeys_snell_from_both_sides() {
        let m = Vec3::Z;
        for (w, eta) in [
            (Vec3::new(0.6, 0.0, 0.8), 1.5f32),
            (Vec3::new(0.3, 0.0, -(1.0f32 - 0.09).sqrt()), 1.5),
        ] {
            let f = DielectricFresnel::new(w.z, eta);
            let t = refract_away(w, m, &f);
            assert!((t.length() - 1.0).abs() < 1e-5, "{t}");
            assert!(t.z * w.z < 0.0, "{t} on the side of {w}");
            // n_i sin θ_i = n_t sin θ_t, the tangential parts opposite.
            assert!((w.x + f.eta_it * t.x).abs() < 1e-5, "{w} -> {t}");
        }
    }
}
