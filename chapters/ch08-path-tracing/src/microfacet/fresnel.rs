//! The Fresnel reflectance at a microfacet, and the refracted direction, with Mitsuba 3's
//! conventions (`fresnel.h`): a relative index `eta = n_inside / n_outside` and a cosine whose
//! sign says which side the light comes from.

use ch01_whitted::optics::fresnel_dielectric;
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

/// The Fresnel terms for a direction at `cos_theta_i` to the normal (positive on the side the
/// normal points to, the outside) at an interface of relative index `eta`.
pub fn dielectric(cos_theta_i: f32, eta: f32) -> DielectricFresnel {
    let (eta_it, eta_ti) = if cos_theta_i >= 0.0 {
        (eta, 1.0 / eta)
    } else {
        (1.0 / eta, eta)
    };
    let cos2_t = 1.0 - (1.0 - cos_theta_i * cos_theta_i) * eta_ti * eta_ti;
    let cos_t = cos2_t.max(0.0).sqrt();
    DielectricFresnel {
        // Chapter 01's formula; it takes `n_i / n_t` and returns 1 at grazing incidence.
        reflectance: fresnel_dielectric(cos_theta_i.abs(), eta_ti),
        cos_theta_t: if cos_theta_i >= 0.0 { -cos_t } else { cos_t },
        eta_it,
        eta_ti,
    }
}

/// The direction refracted through the facet `m` from `w` (both pointing away from the
/// interface), given the Fresnel terms of `cos θ = w·m`: Mitsuba's `refract(wi, m, cos_theta_t,
/// eta_ti)`.
pub fn refract(w: Vec3, m: Vec3, fresnel: &DielectricFresnel) -> Vec3 {
    m * (w.dot(m) * fresnel.eta_ti + fresnel.cos_theta_t) - w * fresnel.eta_ti
}

/// The mirror image of `w` about the facet normal `m`, both pointing away from the surface.
pub fn reflect(w: Vec3, m: Vec3) -> Vec3 {
    2.0 * w.dot(m) * m - w
}

/// The unpolarised reflectance of a conductor of complex relative index `eta + i k`, per
/// colour channel, for light at `cos_theta_i` (in `[0, 1]`) from the normal. Mitsuba's formula
/// (after Moeller's *Optics*), which assumes the light arrives from outside the metal.
///
/// Writing `a² + b² = |(eta + i k)² - sin² θ|` and `a = Re √((eta + i k)² - sin² θ)`:
/// `R_s = (a² + b² + cos² θ - 2 a cos θ) / (a² + b² + cos² θ + 2 a cos θ)` and
/// `R_p = R_s (a² + b²) cos² θ + sin⁴ θ - 2 a cos θ sin² θ) / (... + ...)`.
pub fn conductor(cos_theta_i: f32, eta: Vec3, k: Vec3) -> Vec3 {
    Vec3::new(
        conductor_channel(cos_theta_i, eta.x, k.x),
        conductor_channel(cos_theta_i, eta.y, k.y),
        conductor_channel(cos_theta_i, eta.z, k.z),
    )
}

fn conductor_channel(cos_theta_i: f32, eta: f32, k: f32) -> f32 {
    let cos2 = cos_theta_i * cos_theta_i;
    let sin2 = 1.0 - cos2;
    let sin4 = sin2 * sin2;
    let t1 = eta * eta - k * k - sin2;
    let a2_plus_b2 = (t1 * t1 + 4.0 * k * k * eta * eta).max(0.0).sqrt();
    let a = (0.5 * (a2_plus_b2 + t1)).max(0.0).sqrt();
    let term1 = a2_plus_b2 + cos2;
    let term2 = 2.0 * cos_theta_i * a;
    let r_s = (term1 - term2) / (term1 + term2);
    let term3 = a2_plus_b2 * cos2 + sin4;
    let term4 = term2 * sin2;
    let r_p = r_s * (term3 - term4) / (term3 + term4);
    0.5 * (r_s + r_p)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A conductor of `k = 0` is a dielectric seen from outside: both formulas must agree.
    #[test]
    fn a_conductor_without_absorption_is_a_dielectric() {
        for eta in [1.2f32, 1.5, 2.4] {
            for i in 0..=20 {
                let cos = i as f32 / 20.0;
                let metal = conductor(cos, Vec3::splat(eta), Vec3::ZERO).x;
                let glass = dielectric(cos, eta).reflectance;
                assert!(
                    (metal - glass).abs() < 1e-5,
                    "eta {eta}, cos {cos}: {metal} vs {glass}"
                );
            }
        }
    }

    /// At normal incidence a metal reflects `((eta - 1)² + k²) / ((eta + 1)² + k²)`; Mitsuba's
    /// default `eta = 0, k = 1` reflects everything at every angle.
    #[test]
    fn conductor_reflectance_at_normal_incidence_and_the_perfect_mirror() {
        let (eta, k) = (0.2f32, 3.9f32);
        let expected = ((eta - 1.0).powi(2) + k * k) / ((eta + 1.0).powi(2) + k * k);
        let got = conductor(1.0, Vec3::splat(eta), Vec3::splat(k)).x;
        assert!((got - expected).abs() < 1e-6, "{got} vs {expected}");
        for i in 0..=10 {
            let f = conductor(i as f32 / 10.0, Vec3::ZERO, Vec3::ONE);
            assert!((f - Vec3::ONE).abs().max_element() < 1e-6, "{f}");
        }
    }

    /// Refraction keeps the tangential part scaled by `eta_ti` and leaves a unit vector on
    /// the other side, under Snell's law.
    #[test]
    fn refraction_obeys_snell_from_both_sides() {
        let m = Vec3::Z;
        for (w, eta) in [
            (Vec3::new(0.6, 0.0, 0.8), 1.5f32),
            (Vec3::new(0.3, 0.0, -(1.0f32 - 0.09).sqrt()), 1.5),
        ] {
            let f = dielectric(w.z, eta);
            let t = refract(w, m, &f);
            assert!((t.length() - 1.0).abs() < 1e-5, "{t}");
            assert!(t.z * w.z < 0.0, "{t} on the side of {w}");
            // n_i sin θ_i = n_t sin θ_t, the tangential parts opposite.
            assert!((w.x + f.eta_it * t.x).abs() < 1e-5, "{w} -> {t}");
        }
    }
}
