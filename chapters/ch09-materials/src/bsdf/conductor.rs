//! A smooth metal (Mitsuba's `conductor`): the mirror direction only, carrying the share
//! `F(cos θ)` that the Fresnel equations give for a complex index of refraction `eta + i k`,
//! times the `specular_reflectance`. Gold reflects 0.9 of red square on but only 0.4 of blue,
//! and every colour tends to 1 at grazing angles.
//!
//! A rough metal (`roughness: Some`) is Mitsuba's `roughconductor` ([`super::microfacet`]),
//! whose facets reflect with the same [`fresnel_conductor_rgb`].

use ch01_whitted::optics::reflect;
use ch08_path_tracing::bsdf::{BsdfSample, facing_normal};
use common::geometry::SurfaceHit;
use common::scene::Conductor;
use glam::Vec3;

/// The unpolarised Fresnel reflectance of light arriving at `cos_i` (in `[0, 1]`) from a
/// dielectric onto a conductor of relative complex index `eta + i k`: the mean of the `s` and
/// `p` reflectances. It is the dielectric's for `k = 0` and tends to 1 as `k` grows.
///
/// With `a² + b² = |(eta + i k)² - sin² θ|` and `a` the real part of its square root
/// (the textbook form, as in Mitsuba's `fresnel_conductor`):
/// `r_s = (a² + b² - 2 a cos θ + cos² θ) / (a² + b² + 2 a cos θ + cos² θ)` and
/// `r_p = r_s (P - 2 a cos θ sin² θ) / (P + 2 a cos θ sin² θ)`, with
/// `P = cos² θ (a² + b²) + sin⁴ θ`.
pub fn fresnel_conductor(cos_i: f32, eta: f32, k: f32) -> f32 {
    let cos2 = cos_i * cos_i;
    let sin2 = 1.0 - cos2;
    // (eta + i k)² - sin² θ = (eta² - k² - sin² θ) + i (2 eta k).
    let real = eta * eta - k * k - sin2;
    let norm = (real * real + 4.0 * eta * eta * k * k).sqrt(); // a² + b²
    let a = (0.5 * (norm + real)).max(0.0).sqrt();
    let two_a_cos = 2.0 * a * cos_i;
    let r_s = (norm + cos2 - two_a_cos) / (norm + cos2 + two_a_cos);
    let p_base = cos2 * norm + sin2 * sin2;
    let p_cross = two_a_cos * sin2;
    let r_p = r_s * (p_base - p_cross) / (p_base + p_cross);
    let reflectance = 0.5 * (r_s + r_p);
    // 0/0 only at exactly grazing incidence on an index-matched surface (eta = 1, k = 0):
    // take the grazing limit of every other index, a full reflection.
    if reflectance.is_nan() {
        1.0
    } else {
        reflectance
    }
}

/// [`fresnel_conductor`] per colour channel.
pub fn fresnel_conductor_rgb(cos_i: f32, eta: Vec3, k: Vec3) -> Vec3 {
    Vec3::new(
        fresnel_conductor(cos_i, eta.x, k.x),
        fresnel_conductor(cos_i, eta.y, k.y),
        fresnel_conductor(cos_i, eta.z, k.z),
    )
}

/// The mirror direction on `wo`'s side with weight `specular_reflectance · F(cos θ)`; `None`
/// from behind a one-sided metal (Mitsuba's `conductor` is black there).
pub fn sample(hit: &SurfaceHit, wo: Vec3, conductor: &Conductor) -> Option<BsdfSample> {
    let normal = facing_normal(hit, wo, conductor.two_sided)?;
    let cos_o = wo.dot(normal).clamp(0.0, 1.0);
    let fresnel = fresnel_conductor_rgb(cos_o, conductor.eta, conductor.k);
    Some(BsdfSample {
        wi: reflect(-wo, normal),
        weight: conductor.specular_reflectance * fresnel,
        pdf: f32::INFINITY,
        eta_scale: 1.0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use ch01_whitted::optics::fresnel_dielectric;

    #[test]
    fn without_absorption_it_is_the_dielectric_fresnel() {
        for cos in [1.0, 0.9, 0.5, 0.2, 0.05] {
            let conductor = fresnel_conductor(cos, 1.5, 0.0);
            let dielectric = fresnel_dielectric(cos, 1.0 / 1.5);
            assert!(
                (conductor - dielectric).abs() < 1e-5,
                "cos {cos}: {conductor} vs {dielectric}"
            );
        }
        assert!((fresnel_conductor(1.0, 1.5, 0.0) - 0.04).abs() < 1e-6);
    }

    /// Square on, a metal reflects `((eta - 1)² + k²) / ((eta + 1)² + k²)`.
    #[test]
    fn normal_incidence_is_the_closed_form() {
        let (eta, k) = (0.2f32, 3.9f32);
        let expected = ((eta - 1.0).powi(2) + k * k) / ((eta + 1.0).powi(2) + k * k);
        let got = fresnel_conductor(1.0, eta, k);
        assert!((got - expected).abs() < 1e-6, "{got} vs {expected}");
    }

    #[test]
    fn strong_absorption_reflects_everything() {
        for cos in [1.0, 0.5, 0.1] {
            assert!(fresnel_conductor(cos, 1.0, 1e4) > 0.9999, "cos {cos}");
        }
        // eta = 0 (Mitsuba's material="none") reflects everything at every angle.
        for cos in [1.0, 0.7, 0.3, 0.0] {
            assert!(
                (fresnel_conductor(cos, 0.0, 1.0) - 1.0).abs() < 1e-6,
                "cos {cos}"
            );
        }
        assert_eq!(fresnel_conductor(0.0, 0.2, 3.0), 1.0);
    }

    #[test]
    fn gold_at_normal_incidence_is_the_closed_form_and_yellow() {
        let gold = Conductor {
            eta: Vec3::new(0.14303598, 0.37530708, 1.4420453),
            k: Vec3::new(3.982997, 2.3855565, 1.6033592),
            specular_reflectance: Vec3::ONE,
            specular_texture: None,
            two_sided: false,
            roughness: None,
        };
        let f0 = fresnel_conductor_rgb(1.0, gold.eta, gold.k);
        assert!((f0 - gold.normal_incidence_fresnel()).abs().max_element() < 1e-5);
        // Mitsuba 3.9.1's own `mi.fresnel_conductor` for these indices, at three angles.
        let mitsuba = [
            (1.0, Vec3::new(0.9666793, 0.8020102, 0.3241214)),
            (0.5, Vec3::new(0.9622104, 0.8043708, 0.3711752)),
            (0.1, Vec3::new(0.9734342, 0.9194992, 0.7188908)),
        ];
        for (cos, expected) in mitsuba {
            let ours = fresnel_conductor_rgb(cos, gold.eta, gold.k);
            assert!(
                (ours - expected).abs().max_element() < 1e-5,
                "cos {cos}: {ours}"
            );
        }
        // Towards grazing incidence every channel rises to 1 (after the dip of p-light).
        let grazing = fresnel_conductor_rgb(0.01, gold.eta, gold.k);
        assert!(grazing.min_element() > 0.9, "{grazing}");
    }
}
