//! Mirror reflection, Snell's law and the Fresnel equations: the optics of Whitted's tracer.
//!
//! Directions follow the ray: `d` is the unit direction the ray travels in (towards the
//! surface) and `n` the unit normal on the side the ray comes from, so `d.dot(n) < 0`.
//! `eta` is the *relative* index of refraction `eta_i / eta_t`: the medium the ray comes from
//! over the medium it enters (1/1.5 from air into glass, 1.5 from glass out into air).

use glam::Vec3;

// ANCHOR: reflect
/// The mirror direction of `d` about the normal `n`: the tangential part of `d` is kept and
/// the normal part flipped, so the angle of reflection equals the angle of incidence.
pub fn reflect(d: Vec3, n: Vec3) -> Vec3 {
    // BEGIN SOLUTION
    d - 2.0 * d.dot(n) * n
    // END SOLUTION
}
// ANCHOR_END: reflect

// ANCHOR: refract
/// The direction of `d` after refraction into the medium behind the surface, by Snell's law
/// `eta_i sin(theta_i) = eta_t sin(theta_t)`, or `None` when there is no refracted ray: total
/// internal reflection, when `sin(theta_t) = eta sin(theta_i)` would exceed 1.
///
/// Exactly at the critical angle `sin(theta_t) = 1` and the refracted ray runs along the
/// surface; it is returned, and the Fresnel reflectance there is 1, so it carries no light.
pub fn refract(d: Vec3, n: Vec3, eta: f32) -> Option<Vec3> {
    // BEGIN SOLUTION
    let cos_i = (-d.dot(n)).clamp(0.0, 1.0);
    let sin2_i = (1.0 - cos_i * cos_i).max(0.0);
    let sin2_t = eta * eta * sin2_i;
    if sin2_t > 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    // The tangential part scales by eta (Snell), the normal part is rebuilt from cos_t.
    Some(eta * d + (eta * cos_i - cos_t) * n)
    // END SOLUTION
}
// ANCHOR_END: refract

// ANCHOR: fresnel
/// The share of unpolarised light a smooth dielectric interface reflects, from the Fresnel
/// equations: the mean of the squared amplitude ratios for light polarised perpendicular
/// (`r_s`) and parallel (`r_p`) to the plane of incidence.
///
/// `cos_i` is the cosine between the incident ray and the normal (in `[0, 1]`), `eta` the
/// relative index `eta_i / eta_t`. The refracted share is `1 - fresnel_dielectric(...)`.
#[inline]
pub fn fresnel_dielectric(cos_i: f32, eta: f32) -> f32 {
    // BEGIN SOLUTION
    if eta == 1.0 {
        // Index-matched media: there is no interface to reflect from.
        return 0.0;
    }
    let cos_i = cos_i.clamp(0.0, 1.0);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t > 1.0 {
        return 1.0; // total internal reflection
    }
    let cos_t = (1.0 - sin2_t).max(0.0).sqrt();
    let r_s = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    let r_p = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    0.5 * (r_s * r_s + r_p * r_p)
    // END SOLUTION
}
// ANCHOR_END: fresnel

/// The angle of incidence beyond which light going from index `eta_i` into the lower index
/// `eta_t` is totally reflected, or `None` when `eta_i <= eta_t` (no such angle).
pub fn critical_angle(eta_i: f32, eta_t: f32) -> Option<f32> {
    (eta_i > eta_t).then(|| (eta_t / eta_i).asin())
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// A unit direction hitting the plane z = 0 from above at `theta` from the normal.
    fn incoming(theta: f32) -> Vec3 {
        Vec3::new(theta.sin(), 0.0, -theta.cos())
    }

    const UP: Vec3 = Vec3::Z;

    #[test]
    fn exercise_reflect_keeps_the_angle_and_flips_the_normal_part() {
        for theta in [0.0f32, 0.3, 1.0, 1.5] {
            let d = incoming(theta);
            let r = reflect(d, UP);
            assert_relative_eq!(r, Vec3::new(d.x, d.y, -d.z), epsilon = 1e-6);
            assert_relative_eq!(r.length(), 1.0, epsilon = 1e-6);
        }
        // Any orientation: reflecting twice gives the ray back.
        let n = Vec3::new(1.0, 2.0, -0.5).normalize();
        let d = Vec3::new(-0.3, -0.9, 0.2).normalize();
        assert_relative_eq!(reflect(reflect(d, n), n), d, epsilon = 1e-6);
    }

    #[test]
    fn exercise_refract_obeys_snells_law() {
        for (theta_i, eta_i, eta_t) in [
            (0.5f32, 1.0f32, 1.5f32),
            (0.2, 1.5, 1.0),
            (1.2, 1.0, 1.33),
            (0.0, 1.0, 2.4),
        ] {
            let t = refract(incoming(theta_i), UP, eta_i / eta_t)
                .expect("no total internal reflection here");
            assert_relative_eq!(t.length(), 1.0, epsilon = 1e-5);
            assert!(t.z < 0.0, "the refracted ray continues through the surface");
            let sin_t = t.x.hypot(t.y);
            assert_relative_eq!(eta_i * theta_i.sin(), eta_t * sin_t, epsilon = 1e-5);
        }
    }

    #[test]
    fn exercise_refract_reports_total_internal_reflection() {
        let critical = critical_angle(1.5, 1.0).unwrap();
        assert!(refract(incoming(critical + 1e-3), UP, 1.5).is_none());
        assert!(refract(incoming(1.5), UP, 1.5).is_none());
        assert!(refract(incoming(critical - 1e-3), UP, 1.5).is_some());
    }

    #[test]
    fn exercise_refract_at_index_one_goes_straight_through() {
        for theta in [0.0f32, 0.7, 1.5, std::f32::consts::FRAC_PI_2] {
            let d = incoming(theta);
            assert_relative_eq!(refract(d, UP, 1.0).unwrap(), d, epsilon = 1e-6);
        }
    }

    #[test]
    fn exercise_fresnel_matches_known_values() {
        // Normal incidence: ((n1 - n2) / (n1 + n2))^2 = 0.04 for air to glass of 1.5.
        assert_relative_eq!(fresnel_dielectric(1.0, 1.0 / 1.5), 0.04, epsilon = 1e-6);
        assert_relative_eq!(fresnel_dielectric(1.0, 1.5), 0.04, epsilon = 1e-6);
        // Brewster's angle, tan(theta_B) = 1.5: r_p vanishes, leaving r_s^2 / 2.
        let brewster = 1.5f32.atan();
        let expected_rs = ((brewster.cos() - 1.5 * (1.0 - (brewster.sin() / 1.5).powi(2)).sqrt())
            / (brewster.cos() + 1.5 * (1.0 - (brewster.sin() / 1.5).powi(2)).sqrt()))
        .powi(2);
        assert_relative_eq!(
            fresnel_dielectric(brewster.cos(), 1.0 / 1.5),
            0.5 * expected_rs,
            epsilon = 1e-5
        );
        // Grazing incidence reflects everything.
        assert_relative_eq!(fresnel_dielectric(0.0, 1.0 / 1.5), 1.0, epsilon = 1e-6);
    }

    #[test]
    fn exercise_fresnel_is_total_beyond_the_critical_angle() {
        let critical = critical_angle(1.5, 1.0).unwrap();
        for theta in [
            critical + 1e-4,
            critical + 0.1,
            1.5,
            std::f32::consts::FRAC_PI_2,
        ] {
            assert_eq!(fresnel_dielectric(theta.cos(), 1.5), 1.0, "theta = {theta}");
        }
        // The reflectance rises steeply but continuously to 1 at the critical angle.
        let below = fresnel_dielectric((critical - 1e-3).cos(), 1.5);
        assert!(below > 0.5 && below < 1.0, "{below}");
        let at = fresnel_dielectric(critical.cos(), 1.5);
        assert!(at.is_finite() && at > 0.9, "{at}");
    }

    #[test]
    fn exercise_fresnel_at_index_one_reflects_nothing() {
        for cos_i in [0.0f32, 1e-7, 0.5, 1.0] {
            assert_eq!(fresnel_dielectric(cos_i, 1.0), 0.0);
        }
    }

    #[test]
    fn fresnel_stays_finite_and_in_range_everywhere() {
        for eta in [0.2f32, 0.5, 1.0 / 1.5, 0.999, 1.0, 1.001, 1.5, 2.4, 5.0] {
            for i in 0..=1000 {
                let cos_i = i as f32 / 1000.0;
                let f = fresnel_dielectric(cos_i, eta);
                assert!((0.0..=1.0).contains(&f), "eta {eta}, cos {cos_i}: {f}");
            }
        }
    }

    #[test]
    fn refraction_at_the_critical_angle_is_finite() {
        let critical = critical_angle(1.5, 1.0).unwrap();
        // Walk a few floats either side of the critical angle: never NaN, never longer than 1.
        let mut theta = critical - 8.0 * f32::EPSILON;
        while theta <= critical + 8.0 * f32::EPSILON {
            if let Some(t) = refract(incoming(theta), UP, 1.5) {
                assert!(t.is_finite() && t.length() <= 1.0 + 1e-5 && t.z <= 0.0);
            }
            theta = theta.next_up();
        }
    }
}
