//! The unit disc in polar coordinates: the lecture's wrong first try and its correction.
//!
//! The lecture writes a disc sample as `Polar2Cartesian(R v, 2π u)`: the angle from the first
//! number `ξ1`, the radius from the second `ξ2`. Taking `v = ξ2` looks natural and is wrong;
//! the exercise finds the right `v`. Both are kept so the difference can be seen, plotted and
//! caught by the chi-square test. The concentric map in [`super::concentric`] is a third, better way.

use std::f32::consts::{FRAC_1_PI, TAU};

use glam::Vec2;

/// The lecture's `Polar2Cartesian(r, φ)`: the point at distance `r` from the origin in the
/// direction `φ`, measured from the +x axis towards +y.
pub fn polar_to_cartesian(r: f32, phi: f32) -> Vec2 {
    let (sin, cos) = phi.sin_cos();
    Vec2::new(r * cos, r * sin)
}

/// The angle `φ` of `p` from the +x axis, in `[0, 2π)`: the inverse of the angle part of
/// [`polar_to_cartesian`]. `atan2` answers in `(-π, π]`; negative angles are moved up a turn.
///
/// Just below the +x axis, `-tiny + 2π` rounds to `2π` in `f32`, so an inverse built on this
/// can answer `u = 1` there, the seam where `u = 0` and `u = 1` meet.
pub fn azimuth(p: Vec2) -> f32 {
    let phi = p.y.atan2(p.x);
    if phi < 0.0 { phi + TAU } else { phi }
}

// ANCHOR: disc_naive
/// The obvious first try, and *not* uniform: radius `r = ξ2`, angle `φ = 2π ξ1`.
///
/// Every ring `[r, r + dr]` gets the same share `dr` of the samples, because `r` is uniform.
/// But a ring's area `2π r dr` grows with its radius, so the same number of samples is spread
/// over less area near the centre: the density per unit area is
/// `p(x) = p_r(r) p_φ(φ) / r = 1 / (2π r)`, the `1 / r` coming from the polar area element
/// `r dr dφ`. Samples cluster at the centre, where the density is even infinite.
///
/// As a warp *of that density* it is perfectly correct; [`disc_naive_pdf`] is its density.
pub fn sample_disc_naive(u: Vec2) -> Vec2 {
    polar_to_cartesian(u.y, TAU * u.x)
}
// ANCHOR_END: disc_naive

/// The true density of [`sample_disc_naive`] per unit area: `1 / (2π r)` at distance `r` from
/// the centre (infinite at the centre itself), and 0 outside the unit disc. It integrates to
/// 1: `∫∫ 1 / (2π r) r dr dφ = 1`.
pub fn disc_naive_pdf(p: Vec2) -> f32 {
    let r = p.length();
    if r > 1.0 { 0.0 } else { 1.0 / (TAU * r) }
}

/// The `u` that [`sample_disc_naive`] maps to `p`: `(φ / 2π, r)`.
pub fn invert_disc_naive(p: Vec2) -> Vec2 {
    Vec2::new(azimuth(p) / TAU, p.length())
}

// ANCHOR: disc_polar
/// A uniform point of the unit disc by the lecture's `Polar2Cartesian(v, 2π ξ1)`, with the
/// radius `v` taken from `ξ2` so that every region of the disc gets its share of the area.
pub fn sample_uniform_disc_polar(u: Vec2) -> Vec2 {
    // BEGIN SOLUTION
    let r = u.y.sqrt();
    let phi = TAU * u.x;
    polar_to_cartesian(r, phi)
    // END SOLUTION
}
// ANCHOR_END: disc_polar

/// The density of a uniform point of the unit disc per unit area, `1 / π` (inside the disc),
/// for [`sample_uniform_disc_polar`] and [`super::sample_uniform_disc_concentric`].
pub fn uniform_disc_pdf() -> f32 {
    FRAC_1_PI
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chi2::{chi2_test, significance_level};
    use crate::warps::Warp;
    use crate::warps::test_support::{
        edge_points, integrate_over_rectangle, interior_grid, midpoint_grid,
    };
    use approx::assert_relative_eq;

    /// Points of the uniform polar map, worked out beforehand from the radius the exercise
    /// derives (to 6 digits): `(ξ, the point, its distance from the centre)`. ξ1 is the
    /// angle's share of a turn, so `ξ1 = 0.25` points up the y axis.
    const DISC_POLAR_POINTS: [(Vec2, Vec2, f32); 3] = [
        (Vec2::new(0.25, 0.64), Vec2::new(0.0, 0.8), 0.8),
        (Vec2::new(0.1, 0.3), Vec2::new(0.443117, 0.321943), 0.547723),
        (
            Vec2::new(0.7, 0.05),
            Vec2::new(-0.069098, -0.212663),
            0.223607,
        ),
    ];

    /// What is wrong with `p = sample_uniform_disc_polar(u)`, where the lecture's map gives
    /// `expected` at distance `radius` from the centre, in words; `None` if it is right.
    fn disc_polar_mistake(u: Vec2, expected: Vec2, radius: f32, p: Vec2) -> Option<String> {
        if p.is_finite() && (p - expected).length() < 1e-5 {
            return None;
        }
        let (r, angle) = (p.length(), azimuth(p) / TAU);
        let near = |a: f32, b: f32| (a - b).abs() < 1e-4;
        let mistake = if !p.is_finite() {
            format!("the point {p} is not finite")
        } else if near(r, u.y) {
            format!(
                "the radius came out as ξ2 = {} itself. Rings of equal width then get equal \
                 shares of the points, but an inner ring has less area than an outer one: what \
                 is the chance that a uniform point lies within distance r of the centre?",
                u.y
            )
        } else if near(angle, u.y) {
            "ξ1 and ξ2 are swapped: the lecture takes the angle from ξ1 and the radius from ξ2"
                .to_string()
        } else if near(r, radius) {
            format!(
                "the radius is right but the angle is not: 2π ξ1 is {:.4} of a turn, yours {angle:.4}",
                u.x
            )
        } else if near(r, u.y * u.y) {
            format!(
                "the radius should be {radius} here, and came out as ξ2² = {r}: that crowds the \
                 points towards the centre even more than r = ξ2 does, where the inner rings \
                 need fewer points than the outer ones, not more"
            )
        } else {
            format!(
                "the radius should be {radius} here, it is {r}: which radius holds the share ξ2 \
                 of the disc's area within it?"
            )
        };
        Some(format!(
            "{mistake}.\n  ξ = {u}: your sample_uniform_disc_polar gave {p}, the lecture's map gives {expected}"
        ))
    }

    #[test]
    fn exercise_disc_polar_stays_in_the_disc() {
        for u in edge_points().into_iter().chain(interior_grid(30)) {
            let p = sample_uniform_disc_polar(u);
            assert!(
                p.is_finite() && p.length() <= 1.0 + 1e-6,
                "sample_uniform_disc_polar: ξ = {u} gave {p}, outside the unit disc"
            );
        }
    }

    #[test]
    fn exercise_disc_polar_follows_the_lectures_parametrisation() {
        for (u, expected, radius) in DISC_POLAR_POINTS {
            if let Some(mistake) =
                disc_polar_mistake(u, expected, radius, sample_uniform_disc_polar(u))
            {
                panic!("sample_uniform_disc_polar: {mistake}");
            }
        }
    }

    #[test]
    fn exercise_disc_polar_is_uniform() {
        let result = chi2_test(&Warp::DiscPolar, 200_000, 2, (16, 16));
        if result.p_value > significance_level(1, 0.01) {
            return;
        }
        let points: Vec<Vec2> = interior_grid(300)
            .into_iter()
            .map(sample_uniform_disc_polar)
            .collect();
        panic!(
            "{}",
            workbench::test_support::not_uniform(
                "ch02-disc-polar",
                "sample_uniform_disc_polar",
                "disc",
                result.p_value,
                &points,
                &|p| if p.length() <= 1.0 {
                    f64::from(FRAC_1_PI)
                } else {
                    0.0
                },
                [Vec2::splat(-1.0), Vec2::splat(1.0)],
            )
        );
    }

    #[test]
    fn exercise_disc_polar_puts_a_quarter_of_the_samples_within_half_the_radius() {
        // A quarter of the area lies within r = 1/2; the naive map would put half there.
        let n = 100;
        let inner = midpoint_grid(n)
            .into_iter()
            .filter(|&u| sample_uniform_disc_polar(u).length() < 0.5)
            .count();
        let share = inner as f64 / (n * n) as f64;
        assert!(
            (share - 0.25).abs() < 0.005,
            "sample_uniform_disc_polar: {:.1} % of the points land within half the radius, where \
             a quarter of the disc's area lies (25 %)",
            100.0 * share
        );
    }

    #[test]
    fn the_naive_disc_is_a_correct_warp_of_its_own_density() {
        // Its true density integrates to 1 over the disc. The 1/r singularity is integrable;
        // the midpoint rule never evaluates the centre itself.
        let integral =
            integrate_over_rectangle(disc_naive_pdf, Vec2::splat(-1.0), Vec2::splat(1.0), 2000);
        assert_relative_eq!(integral, 1.0, epsilon = 2e-3);
        // Half of its samples fall within half the radius: that is the clustering.
        let n = 100;
        let inner = midpoint_grid(n)
            .into_iter()
            .filter(|&u| sample_disc_naive(u).length() < 0.5)
            .count();
        assert_relative_eq!(inner as f64 / (n * n) as f64, 0.5, epsilon = 0.005);
    }

    #[test]
    fn the_naive_inverse_round_trips() {
        for u in interior_grid(20) {
            assert_relative_eq!(invert_disc_naive(sample_disc_naive(u)), u, epsilon = 1e-5);
        }
        for p in [
            Vec2::new(0.3, -0.4),
            Vec2::new(-0.9, 0.1),
            Vec2::new(0.0, 0.7),
        ] {
            assert_relative_eq!(sample_disc_naive(invert_disc_naive(p)), p, epsilon = 1e-6);
        }
    }

    #[test]
    fn naive_edge_values_stay_in_the_disc() {
        for u in edge_points() {
            let p = sample_disc_naive(u);
            assert!(p.is_finite() && p.length() <= 1.0 + 1e-6, "u = {u}: {p}");
        }
    }
}
