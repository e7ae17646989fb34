//! Mirror reflection, Snell's law and the Fresnel equations: the optics of Whitted's tracer.
//!
//! Directions follow the ray: `d` is the unit direction the ray travels in (towards the
//! surface) and `n` the unit normal on the side the ray comes from, so `d.dot(n) < 0`.
//! `eta` is the *relative* index of refraction `eta_i / eta_t`: the medium the ray comes from
//! over the medium it enters (1/1.5 from air into glass, 1.5 from glass out into air).

use glam::Vec3;

// ANCHOR: reflect
/// The mirror direction of `d` about the normal `n`: in the plane of `d` and `n`, at an angle
/// of reflection equal to the angle of incidence.
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
/// `d` is a unit direction towards the surface, `n` the unit normal on the side `d` comes from
/// (`d.dot(n) < 0`), and `eta` the relative index `eta_i / eta_t`, of the medium the ray leaves
/// over the one it enters. The answer is a unit direction too.
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
/// equations for light polarised perpendicular (`r_s`) and parallel (`r_p`) to the plane of
/// incidence.
///
/// `cos_i` is the cosine between the incident ray and the normal (in `[0, 1]`, 0 at grazing
/// incidence), `eta` the relative index `eta_i / eta_t`. The refracted share is
/// `1 - fresnel_dielectric(...)`. The answer is a share for every `cos_i` in `[0, 1]`, at
/// grazing incidence too, and whatever `eta` is, 1 included (the same index on both sides).
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

    /// A unit direction hitting the plane z = 0 from above at `theta` from the normal.
    fn incoming(theta: f32) -> Vec3 {
        Vec3::new(theta.sin(), 0.0, -theta.cos())
    }

    const UP: Vec3 = Vec3::Z;

    /// What is wrong with `r`, an answer to `reflect(d, n)`, in words; `None` if it is right.
    /// A mirror direction is known by its two parts: along the surface it is d's, along n it
    /// is d's with the sign turned.
    fn reflect_mistake(d: Vec3, n: Vec3, r: Vec3) -> Option<String> {
        if !r.is_finite() {
            return Some(format!("the result {r} is not a finite vector"));
        }
        let (dn, rn) = (d.dot(n), r.dot(n));
        let along_surface_kept = ((r - rn * n) - (d - dn * n)).length() <= 1e-5;
        if along_surface_kept && (rn + dn).abs() <= 1e-5 {
            return None;
        }
        let mistake = if !along_surface_kept {
            "the part of d along the surface changed: a mirror keeps it as it is and flips only \
             the part along n"
                .to_string()
        } else if rn.abs() < 1e-5 {
            "the part of d along n vanished instead of flipping: it has to be taken away twice, \
             not once"
                .to_string()
        } else if (rn - dn).abs() < 1e-5 {
            "the part of d along n kept its sign: the ray goes on through the mirror".to_string()
        } else if (rn - 3.0 * dn).abs() < 1e-4 {
            "the part of d along n grew to three times its size: look at the sign of what is \
             added (d . n is negative for a ray that hits the surface)"
                .to_string()
        } else {
            format!("the part along n is {rn}, where it should be {}", -dn)
        };
        Some(format!(
            "{mistake}.\n  d = {d}, n = {n}: your reflect gave {r}, whose part along n is {rn} \
             (d's is {dn})"
        ))
    }

    #[test]
    fn exercise_reflect_keeps_the_angle_and_flips_the_normal_part() {
        let n = Vec3::new(1.0, 2.0, -0.5).normalize();
        // Oblique rays first: they show a mistake more plainly than one along the normal.
        let cases = [1.0f32, 0.3, 1.5, 0.0]
            .map(|theta| (incoming(theta), UP))
            .into_iter()
            .chain([(Vec3::new(-0.3, -0.9, 0.2).normalize(), n)]);
        for (d, n) in cases {
            if let Some(mistake) = reflect_mistake(d, n, reflect(d, n)) {
                panic!("reflect: {mistake}");
            }
        }
    }

    /// What is wrong with `t`, an answer to `refract(d, UP, eta)` where a refracted ray
    /// exists, in words; `None` if it is right.
    fn refract_mistake(d: Vec3, eta: f32, t: Option<Vec3>) -> Option<String> {
        let Some(t) = t else {
            return Some(
                "it returned None, but here sin(theta_t) = eta sin(theta_i) is below 1, so there is \
                 a refracted ray"
                    .to_string(),
            );
        };
        let sin_i = d.x.hypot(d.y);
        let sin_t = t.x.hypot(t.y);
        let mistake = if !t.is_finite() {
            format!("the result {t} is not a finite vector")
        } else if t.z >= 0.0 && d.z < 0.0 && t != Vec3::ZERO {
            "the refracted ray turned back: it must go on through the surface, its part along n \
             of the same sign as d's"
                .to_string()
        } else if (t.length() - 1.0).abs() > 1e-4 {
            format!(
                "the result has length {}, not 1: the part along n must come from \
                 cos(theta_t) = sqrt(1 - sin^2(theta_t))",
                t.length()
            )
        } else if sin_i > 1e-3 && (sin_t - sin_i / eta).abs() < 1e-4 && (eta - 1.0).abs() > 1e-3 {
            "the ray bends the wrong way: sin(theta_t) came out as sin(theta_i) / eta. eta is \
             eta_i / eta_t, the index the ray leaves over the one it enters, and \
             sin(theta_t) = eta sin(theta_i)"
                .to_string()
        } else if (sin_t - eta * sin_i).abs() > 1e-4 {
            format!(
                "Snell's law does not hold: sin(theta_t) should be eta sin(theta_i) = {}, it is {sin_t}",
                eta * sin_i
            )
        } else {
            return None;
        };
        Some(format!(
            "{mistake}.\n  d = {d}, n = {UP}, eta = {eta}: your refract gave {t}"
        ))
    }

    #[test]
    fn exercise_refract_obeys_snells_law() {
        for (theta_i, eta_i, eta_t) in [
            (0.5f32, 1.0f32, 1.5f32),
            (0.2, 1.5, 1.0),
            (1.2, 1.0, 1.33),
            (0.0, 1.0, 2.4),
            (0.7, 1.0, 1.0),
        ] {
            let (d, eta) = (incoming(theta_i), eta_i / eta_t);
            if let Some(mistake) = refract_mistake(d, eta, refract(d, UP, eta)) {
                panic!("refract: {mistake}");
            }
        }
    }

    #[test]
    fn exercise_refract_reports_total_internal_reflection() {
        let critical = critical_angle(1.5, 1.0).unwrap();
        for theta in [critical + 1e-3, 1.0, 1.5] {
            if let Some(t) = refract(incoming(theta), UP, 1.5) {
                panic!(
                    "refract: leaving glass (eta = 1.5) at {theta:.3} rad, beyond the critical \
                     angle {critical:.3}, sin(theta_t) = eta sin(theta_i) would be {:.3}, above 1: \
                     there is no refracted ray (total internal reflection), and refract must say so \
                     with None. It gave Some({t}).",
                    1.5 * theta.sin()
                );
            }
        }
        let just_below = incoming(critical - 1e-3);
        if let Some(mistake) = refract_mistake(just_below, 1.5, refract(just_below, UP, 1.5)) {
            panic!("refract, just inside the critical angle: {mistake}");
        }
    }

    #[test]
    fn exercise_refract_at_index_one_goes_straight_through() {
        for theta in [0.0f32, 0.7, 1.5, std::f32::consts::FRAC_PI_2] {
            let d = incoming(theta);
            let t = refract(d, UP, 1.0);
            assert!(
                t.is_some_and(|t| (t - d).length() < 1e-5),
                "refract: with eta = 1 both sides have the same index, so the ray goes straight \
                 on, even at {theta:.3} rad{}. d = {d}: your refract gave {t:?}",
                if t.is_none() {
                    ", where sin(theta_t) = eta sin(theta_i) is 1 or just below: there is a \
                     refracted ray unless sin(theta_t) exceeds 1"
                } else {
                    ""
                }
            );
        }
    }

    /// A case of `fresnel_dielectric(cos_i, eta)` where a refracted ray exists, worked out
    /// beforehand from the Fresnel equations (in `f32`, to 6 digits): the reflectance of
    /// unpolarised light, and the reflectances `r_s^2` and `r_p^2` of light polarised
    /// perpendicular and parallel to the plane of incidence, to name a mistake.
    struct Reflection {
        cos_i: f32,
        eta: f32,
        reflectance: f32,
        r_s2: f32,
        r_p2: f32,
    }

    /// Air into glass of index 1.5 (`eta = 1 / 1.5`) square on, at Brewster's angle
    /// (`tan(theta_B) = 1.5`, where `r_p` vanishes), obliquely and at grazing incidence; glass
    /// and water into air square on and obliquely, and glass into air just inside the critical
    /// angle, where the reflectance climbs steeply towards 1.
    const REFLECTIONS: [Reflection; 9] = [
        // Air into glass.
        Reflection {
            cos_i: 1.0,
            eta: 1.0 / 1.5,
            reflectance: 0.04,
            r_s2: 0.04,
            r_p2: 0.04,
        },
        Reflection {
            cos_i: 0.554_700_2,
            eta: 1.0 / 1.5,
            reflectance: 0.073_964_5,
            r_s2: 0.147_929,
            r_p2: 0.0,
        },
        Reflection {
            cos_i: 0.9,
            eta: 1.0 / 1.5,
            reflectance: 0.040_791_9,
            r_s2: 0.052_537_8,
            r_p2: 0.029_046,
        },
        Reflection {
            cos_i: 0.5,
            eta: 1.0 / 1.5,
            reflectance: 0.089_186_7,
            r_s2: 0.176_571,
            r_p2: 0.001_801_94,
        },
        Reflection {
            cos_i: 0.2,
            eta: 1.0 / 1.5,
            reflectance: 0.338_894,
            r_s2: 0.490_770,
            r_p2: 0.187_019,
        },
        Reflection {
            cos_i: 0.0,
            eta: 1.0 / 1.5,
            reflectance: 1.0,
            r_s2: 1.0,
            r_p2: 1.0,
        },
        // Glass and water into air.
        Reflection {
            cos_i: 1.0,
            eta: 1.5,
            reflectance: 0.04,
            r_s2: 0.04,
            r_p2: 0.04,
        },
        Reflection {
            cos_i: 0.9,
            eta: 1.33,
            reflectance: 0.022_332_8,
            r_s2: 0.036_090_7,
            r_p2: 0.008_574_96,
        },
        Reflection {
            cos_i: 0.746,
            eta: 1.5,
            reflectance: 0.767_063,
            r_s2: 0.846_821,
            r_p2: 0.687_304,
        },
    ];

    /// What is wrong with `f`, an answer to `fresnel_dielectric(case.cos_i, case.eta)`, in
    /// words; `None` if it is right.
    fn fresnel_mistake(case: &Reflection, f: f32) -> Option<String> {
        let &Reflection {
            cos_i,
            eta,
            reflectance,
            r_s2,
            r_p2,
        } = case;
        // Just inside the critical angle the reflectance is steep in cos_i: a correct answer
        // written another way rounds differently there.
        let tolerance = if eta > 1.0 && reflectance > 0.5 {
            1e-4
        } else {
            1e-5
        };
        if (f - reflectance).abs() <= tolerance {
            return None;
        }
        let near = |x: f32| (f - x).abs() <= 1e-5;
        let halves = "unpolarised light is half s-polarised and half p-polarised, and each half \
                      is reflected by its own share";
        let mistake = if !f.is_finite() {
            "the result is not a number".to_string()
        } else if near(r_s2) {
            format!("that is r_s^2 alone: {halves}")
        } else if near(r_p2) {
            format!("that is r_p^2 alone: {halves}")
        } else if near(0.5 * (r_s2.sqrt() + r_p2.sqrt())) {
            "that is the mean of the amplitude ratios |r_s| and |r_p|: a reflectance is a share \
             of the energy, which goes with the square of an amplitude"
                .to_string()
        } else if near(r_s2 + r_p2) {
            format!(
                "that is the sum of r_s^2 and r_p^2: {halves}; summed, grazing light would \
                 reflect twice what arrives"
            )
        } else {
            let r0 = ((1.0 - eta) / (1.0 + eta)).powi(2);
            let schlick = r0 + (1.0 - r0) * (1.0 - cos_i).powi(5);
            if near(schlick) {
                "that is Schlick's approximation: the exercise asks for the Fresnel equations \
                 themselves"
                    .to_string()
            } else {
                format!(
                    "it is not what the Fresnel equations give for unpolarised light (here \
                     r_s^2 = {r_s2} and r_p^2 = {r_p2}, with cos(theta_t) from Snell's law)"
                )
            }
        };
        Some(format!(
            "{mistake}.\n  cos_i = {cos_i}, eta = {eta}: your fresnel_dielectric gave {f}, \
             the reflectance is {reflectance}"
        ))
    }

    #[test]
    fn exercise_fresnel_matches_known_values() {
        for case in &REFLECTIONS {
            if let Some(mistake) = fresnel_mistake(case, fresnel_dielectric(case.cos_i, case.eta)) {
                panic!("fresnel_dielectric: {mistake}");
            }
        }
    }

    /// Fails unless `fresnel_dielectric(cos_i, eta)` reflects everything, for a `cos_i` beyond
    /// the critical angle of `eta`.
    fn check_total_reflection(cos_i: f32, eta: f32) {
        let f = fresnel_dielectric(cos_i, eta);
        if !f.is_finite() || (f - 1.0).abs() > 1e-5 {
            let critical = critical_angle(eta, 1.0).expect("eta above 1 has a critical angle");
            panic!(
                "fresnel_dielectric: at {:.4} rad, beyond the critical angle {critical:.4}, \
                 sin(theta_t) = eta sin(theta_i) would be {:.4}, above 1: there is no refracted \
                 ray and all the light is reflected (total internal reflection), so the \
                 reflectance is 1.\n  cos_i = {cos_i}, eta = {eta}: your fresnel_dielectric \
                 gave {f}",
                cos_i.acos(),
                eta * (1.0 - cos_i * cos_i).sqrt()
            );
        }
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
            check_total_reflection(theta.cos(), 1.5);
        }
        // Out of water, beyond its critical angle of 0.85 rad.
        check_total_reflection(0.5, 1.33);
        check_total_reflection(0.2, 1.33);
        // The reflectance rises steeply but continuously to 1 at the critical angle.
        let at = fresnel_dielectric(critical.cos(), 1.5);
        assert!(
            at.is_finite() && at > 0.9,
            "fresnel_dielectric: at the critical angle the reflectance is about 1, not {at}"
        );
    }

    #[test]
    fn exercise_fresnel_at_index_one_reflects_nothing() {
        for cos_i in [0.0f32, 1e-7, 0.5, 1.0] {
            let f = fresnel_dielectric(cos_i, 1.0);
            assert!(
                f.abs() <= 1e-6,
                "fresnel_dielectric: with eta = 1 both sides have the same index: there is no \
                 interface, and nothing is reflected at any angle, even at grazing incidence \
                 (cos_i = 0), where the formulas divide 0 by 0.\n  cos_i = {cos_i}, eta = 1: \
                 your fresnel_dielectric gave {f}, the reflectance is 0"
            );
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
