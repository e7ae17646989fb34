//! The spherical cap: uniform directions within an angle `θ_max` of +z.
//!
//! Seen from a point, a spherical light covers a cap of directions; sampling the cap instead
//! of the whole sphere sends every shadow ray towards the light (chapter 07). pbrt-v4 calls
//! it a cone (`SampleUniformCone`).
//!
//! The hat-box theorem of [`super::sphere`] does most of the work: in the coordinates
//! `(z = cos θ, φ)` the sphere is a flat rectangle, and a cap is a part of it. How large a part,
//! and what does that make its solid angle? Which coordinate is then uniform, and over what
//! range? As for the sphere and the hemisphere, `ξ2 = 0` is the pole and `ξ2 → 1` the rim; with
//! `cos θ_max = -1` the cap is the whole sphere and the warp is [`super::sample_uniform_sphere`].
//!
//! A small light far away makes a tiny cap, `1 - cos θ_max` of 10^-8 and below, where `cos θ`
//! itself rounds to 1 in `f32`. Which quantity still holds its digits there, and can `sin θ` be
//! computed from it rather than from `cos θ` (see the notes of [`super::lobe`])? The caller
//! should likewise pass an accurate `cos θ_max`; for the tiniest caps the API would better take
//! `1 - cos θ_max` itself.

use glam::{Vec2, Vec3};

// ANCHOR: spherical_cap_pdf
/// The density of [`sample_spherical_cap`] per unit solid angle, for directions inside the
/// cap of directions within `θ_max` of +z (`-1 ≤ cos_theta_max < 1`): every direction of the
/// cap equally likely. It must hold down to the tiniest cap an `f32` can describe
/// (`cos_theta_max` the largest float below 1).
pub fn spherical_cap_pdf(cos_theta_max: f32) -> f32 {
    // BEGIN SOLUTION
    use std::f32::consts::TAU;

    1.0 / (TAU * (1.0 - cos_theta_max))
    // END SOLUTION
}
// ANCHOR_END: spherical_cap_pdf

// ANCHOR: spherical_cap
/// A uniform direction of the cap of directions within `θ_max` of +z, for
/// `-1 ≤ cos_theta_max < 1`, with `φ = 2π ξ1` (from +x towards +y) and `ξ2 = 0` at the pole;
/// with `cos_theta_max = -1` it is [`super::sample_uniform_sphere`]. Density
/// [`spherical_cap_pdf`].
///
/// It must keep its shape down to the tiniest cap an `f32` can describe (`cos_theta_max` the
/// largest float below 1, `1 - cos_theta_max` = 6e-8), where `cos θ` of most of its
/// directions rounds to 1: their `sin θ` must keep its digits there.
pub fn sample_spherical_cap(u: Vec2, cos_theta_max: f32) -> Vec3 {
    // BEGIN SOLUTION
    use super::sphere::spherical_direction;
    use std::f32::consts::TAU;

    let one_minus_cos = u.y * (1.0 - cos_theta_max);
    let cos_theta = 1.0 - one_minus_cos;
    let sin_theta = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
    spherical_direction(sin_theta, cos_theta, TAU * u.x)
    // END SOLUTION
}
// ANCHOR_END: spherical_cap

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chi2::{chi2_test, significance_level};
    use crate::warps::disc::azimuth;
    use crate::warps::test_support::{edge_points, integrate_over_sphere, interior_grid};
    use crate::warps::{Warp, sample_uniform_sphere};
    use approx::assert_relative_eq;
    use std::f32::consts::TAU;
    use std::f64::consts::PI;

    const CAPS: [f32; 5] = [-1.0, -0.5, 0.0, 0.8, 0.999_9];

    /// The smallest cap an `f32` `cos θ_max` can describe: the largest float below 1, so that
    /// `1 - cos θ_max = 6e-8`. Its directions lie about 2.4e-4 radians from the pole.
    const TINY_CAP: f32 = 0.999_999_94;

    /// The density of a uniform direction of the cap of each `cos θ_max`, worked out
    /// beforehand from the cap's solid angle (to 7 digits, for the `f32` value of `cos θ_max`).
    const CAP_DENSITIES: [(f32, f64); 6] = [
        (0.0, 0.159_154_9),
        (0.8, 0.795_774_8),
        (-0.5, 0.106_103_3),
        (-1.0, 0.079_577_47),
        (0.999_9, 1_591.285),
        (TINY_CAP, 2_670_177.0),
    ];

    /// What is wrong with `pdf`, an answer to `spherical_cap_pdf(cos_max)` whose right value
    /// is `expected`, in words; `None` if it is right.
    fn cap_pdf_mistake(cos_max: f32, expected: f64, pdf: f32) -> Option<String> {
        let pdf = f64::from(pdf);
        // The density is constant over the cap, so its integral over the cap is its ratio
        // to the right density.
        let integral = pdf / expected;
        if (integral - 1.0).abs() < 1e-5 {
            return None;
        }
        let near = |x: f64| (integral - x).abs() < 1e-4 * x;
        let mistake = if !pdf.is_finite() {
            "it is not a finite number".to_string()
        } else if cos_max != 0.0 && (pdf - 0.5 / PI).abs() < 1e-6 {
            "that is the hemisphere's density, 1/(2π), whatever the cap: a smaller cap holds \
             its directions in less solid angle, so each is more likely"
                .to_string()
        } else if near(0.5) {
            "it is half the density: is the solid angle of the cap twice what it should be \
             (4π belongs to the whole sphere, whose band of heights is 2 long)?"
                .to_string()
        } else if near(2.0 * PI) {
            "it is 2π times too large: the azimuth φ sweeps a whole turn".to_string()
        } else if near(2.0) || near(PI) || near(1.0 / PI) {
            format!(
                "it is off by a constant factor ({integral:.4}): the density of a uniform \
                 direction is one over the cap's solid angle"
            )
        } else {
            format!(
                "over the cap it integrates to {integral:.5}, not 1: the density of a uniform \
                 direction is one over the cap's solid angle"
            )
        };
        Some(format!(
            "{mistake}.\n  cos θ_max = {cos_max}: your spherical_cap_pdf gave {pdf}, expected \
             {expected}"
        ))
    }

    #[test]
    fn exercise_spherical_cap_pdf_integrates_to_one() {
        for (cos_max, expected) in &CAP_DENSITIES[..4] {
            let pdf = spherical_cap_pdf(*cos_max);
            if let Some(mistake) = cap_pdf_mistake(*cos_max, *expected, pdf) {
                panic!("spherical_cap_pdf: {mistake}");
            }
        }
        // And numerically, over the sphere, as a density must.
        for cos_max in [-0.5, 0.0, 0.8] {
            let integral = integrate_over_sphere(
                |d| {
                    if d.z >= cos_max {
                        spherical_cap_pdf(cos_max)
                    } else {
                        0.0
                    }
                },
                1000,
            );
            assert_relative_eq!(integral, 1.0, epsilon = 1e-3);
        }
    }

    #[test]
    fn exercise_spherical_cap_pdf_of_a_tiny_cap() {
        for (cos_max, expected) in &CAP_DENSITIES[4..] {
            let pdf = spherical_cap_pdf(*cos_max);
            if let Some(mistake) = cap_pdf_mistake(*cos_max, *expected, pdf) {
                panic!("spherical_cap_pdf of a tiny cap: {mistake}");
            }
        }
    }

    /// Directions of [`sample_spherical_cap`] worked out beforehand (in `f64`, to 8 decimals):
    /// `(ξ, cos θ_max, the direction)`.
    const CAP_DIRECTIONS: [(Vec2, f32, Vec3); 7] = [
        (
            Vec2::new(0.1, 0.3),
            -0.5,
            Vec3::new(0.675_662_4, 0.490_897_48, 0.549_999_98),
        ),
        (
            Vec2::new(0.6, 0.85),
            -0.5,
            Vec3::new(-0.777_824_63, -0.565_122_85, -0.275_000_04),
        ),
        (
            Vec2::new(0.1, 0.3),
            0.8,
            Vec3::new(0.276_015_9, 0.200_537_3, 0.94),
        ),
        (
            Vec2::new(0.6, 0.85),
            0.8,
            Vec3::new(-0.451_24, -0.327_845_2, 0.83),
        ),
        (
            Vec2::new(0.1, 0.3),
            0.999_9,
            Vec3::new(0.006_267_09, 0.004_553_31, 0.999_97),
        ),
        (
            Vec2::new(0.6, 0.85),
            0.999_9,
            Vec3::new(-0.010_548_94, -0.007_664_26, 0.999_915),
        ),
        // Half way into the tiniest cap: sin θ = 2^-12, and cos θ rounds to 1.
        (
            Vec2::new(0.0, 0.5),
            TINY_CAP,
            Vec3::new(2.441_406_2e-4, 0.0, 1.0),
        ),
    ];

    /// What is wrong with `d = sample_spherical_cap(u, cos_max)`, where the lecture's uniform
    /// direction (`φ = 2π ξ1`, `ξ2 = 0` at the pole) is `expected`, in words; `None` if it is
    /// right.
    fn cap_mistake(u: Vec2, cos_max: f32, expected: Vec3, d: Vec3) -> Option<String> {
        if d.is_finite() && (d - expected).length() < 1e-6 {
            return None;
        }
        let mistake = if !d.is_finite() {
            "it is not a finite direction".to_string()
        } else if (d.length() - 1.0).abs() > 1e-5 {
            format!("it has length {}, not 1", d.length())
        } else if d.z < cos_max - 1e-6 {
            format!(
                "it lies outside the cap: cos θ = {} is below cos θ_max",
                d.z
            )
        } else if (d.z - expected.z).abs() > 1e-5 {
            format!(
                "cos θ = {} is not where a uniform direction's height lies (it should be {}): \
                 which coordinate is uniform over the cap, and over what range?",
                d.z, expected.z
            )
        } else if (d.truncate().length() - expected.truncate().length()).abs() > 1e-6 {
            format!(
                "sin θ = {} lost its digits (it should be {}): near the pole cos θ rounds to 1; \
                 compute sin θ from 1 - cos θ, which keeps them",
                d.truncate().length(),
                expected.truncate().length()
            )
        } else {
            "the height is right but the azimuth is not: φ = 2π ξ1, measured from +x towards +y"
                .to_string()
        };
        Some(format!(
            "{mistake}.\n  ξ = {u}, cos θ_max = {cos_max}: your sample_spherical_cap gave {d}, \
             expected {expected}"
        ))
    }

    /// What is wrong with `d = sample_spherical_cap(u, cos_max)` that every direction of the
    /// cap shows, in words; `None` if nothing is.
    fn cap_property_mistake(u: Vec2, cos_max: f32, d: Vec3) -> Option<String> {
        let pole = u.y == 0.0;
        let mistake = if !d.is_finite() {
            "it is not a finite direction".to_string()
        } else if (d.length() - 1.0).abs() > 1e-5 {
            format!("it has length {}, not 1", d.length())
        } else if d.z < cos_max - 1e-6 {
            format!(
                "it lies outside the cap: cos θ = {} is below cos θ_max",
                d.z
            )
        } else if pole && (d.z - cos_max).abs() < 1e-5 {
            "ξ2 = 0 gives the rim and ξ2 → 1 the pole: the chapter's warps start at the pole, \
             ξ2 = 0"
                .to_string()
        } else if pole && d.z < 1.0 - 1e-6 {
            format!(
                "ξ2 = 0 should give the pole, cos θ = 1, not cos θ = {}",
                d.z
            )
        } else if d.truncate().length() > 1e-3
            && (azimuth(d.truncate()) / TAU - u.x).abs() > 1e-4
            && u.x < 0.999
        {
            format!(
                "its azimuth is {:.4} of a turn, where φ = 2π ξ1 is {:.4} of a turn, measured \
                 from +x towards +y",
                azimuth(d.truncate()) / TAU,
                u.x
            )
        } else {
            return None;
        };
        Some(format!(
            "{mistake}.\n  ξ = {u}, cos θ_max = {cos_max}: your sample_spherical_cap gave {d}"
        ))
    }

    #[test]
    fn exercise_spherical_cap_follows_the_chapters_parametrisation() {
        // What every direction shows first, everywhere: a wrong height also spoils sin θ.
        for cos_max in CAPS {
            for u in edge_points().into_iter().chain(interior_grid(12)) {
                let d = sample_spherical_cap(u, cos_max);
                if let Some(mistake) = cap_property_mistake(u, cos_max, d) {
                    panic!("sample_spherical_cap: {mistake}");
                }
            }
        }
        for (u, cos_max, expected) in CAP_DIRECTIONS {
            if let Some(mistake) =
                cap_mistake(u, cos_max, expected, sample_spherical_cap(u, cos_max))
            {
                panic!("sample_spherical_cap: {mistake}");
            }
        }
        // With cos θ_max = -1 the cap is the whole sphere.
        for u in interior_grid(10) {
            assert_relative_eq!(
                sample_spherical_cap(u, -1.0),
                sample_uniform_sphere(u),
                epsilon = 1e-6
            );
        }
    }

    #[test]
    fn exercise_spherical_cap_keeps_a_tiny_cap_in_shape() {
        let (u, cos_max, expected) = CAP_DIRECTIONS[6];
        if let Some(mistake) = cap_mistake(u, cos_max, expected, sample_spherical_cap(u, cos_max)) {
            panic!("sample_spherical_cap, the tiniest cap: {mistake}");
        }
    }

    #[test]
    fn exercise_spherical_cap_has_its_density() {
        // The pdf is yours too (the exercise before): it must integrate to one...
        for (cos_max, expected) in &CAP_DENSITIES[..3] {
            let pdf = spherical_cap_pdf(*cos_max);
            if let Some(mistake) = cap_pdf_mistake(*cos_max, *expected, pdf) {
                panic!("spherical_cap_pdf: {mistake}");
            }
        }
        // ... and the directions must follow it.
        for cos_max in [0.0, 0.8] {
            let warp = Warp::SphericalCap {
                cos_theta_max: cos_max,
            };
            let result = chi2_test(&warp, 100_000, 5, (16, 16));
            if result.p_value <= significance_level(2, 0.01) {
                let points: Vec<Vec2> = interior_grid(150)
                    .into_iter()
                    .map(|u| {
                        let d = sample_spherical_cap(u, cos_max);
                        Vec2::new(azimuth(d.truncate()) / TAU, d.z)
                    })
                    .collect();
                let density = move |p: Vec2| {
                    if p.y >= cos_max {
                        1.0 / (1.0 - f64::from(cos_max))
                    } else {
                        0.0
                    }
                };
                panic!(
                    "{} (cos θ_max = {cos_max}, drawn in (φ/2π, cos θ), where equal areas are \
                     equal solid angles)",
                    workbench::test_support::not_uniform(
                        "ch02-spherical-cap",
                        "sample_spherical_cap",
                        "cap",
                        result.p_value,
                        &points,
                        &density,
                        [Vec2::new(0.0, cos_max), Vec2::ONE],
                    )
                );
            }
        }
    }
}
