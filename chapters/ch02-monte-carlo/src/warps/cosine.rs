//! Cosine-weighted directions by Malley's method: a uniform disc, lifted to the hemisphere.
//!
//! Light arriving at a matte surface counts with `cos θ` (Lambert), so a diffuse bounce
//! wants directions with density `p(ω) = cos θ / π` (the `π` normalises:
//! `∫ cos θ dω = π` over the hemisphere).
//!
//! Malley's observation gives this density for free. Take a uniform point of the unit disc
//! and lift it straight up onto the unit hemisphere above it (how high is the exercise). The
//! disc is the hemisphere's orthographic projection, and a patch `dω` of the hemisphere
//! projects to a patch of area `dA = cos θ dω` (it is tilted by `θ` against the disc). The
//! probability in a patch is the same above and below, so
//! `p(ω) dω = p(A) dA = (1 / π) cos θ dω`, which is exactly `cos θ / π`.
//!
//! Any uniform disc warp gives this density; this one lifts the concentric map's point,
//! which keeps stratified samples compact.

use std::f32::consts::FRAC_1_PI;

use glam::{Vec2, Vec3};

use super::concentric;

// ANCHOR: cosine_hemisphere
/// A direction of the hemisphere around +z with density `cos θ / π`
/// ([`cosine_hemisphere_pdf`]): a uniform disc point (the concentric map) lifted to the unit
/// hemisphere above it.
///
/// The answer is a unit direction with `z ≥ 0` for every `u` of the square, its edges
/// included: there the disc point lies on the rim, where rounding can carry it a hair outside
/// the disc.
pub fn sample_cosine_hemisphere(u: Vec2) -> Vec3 {
    // BEGIN SOLUTION
    let d = concentric::sample_uniform_disc_concentric(u);
    let z = (1.0 - d.length_squared()).max(0.0).sqrt();
    Vec3::new(d.x, d.y, z)
    // END SOLUTION
}
// ANCHOR_END: cosine_hemisphere

/// The density of [`sample_cosine_hemisphere`] per unit solid angle, `cos θ / π`, and 0 below
/// the horizon.
pub fn cosine_hemisphere_pdf(cos_theta: f32) -> f32 {
    cos_theta.max(0.0) * FRAC_1_PI
}

/// The `u` that [`sample_cosine_hemisphere`] maps to `d`: drop `d` straight down onto the
/// disc and invert the concentric map there.
pub fn invert_cosine_hemisphere(d: Vec3) -> Vec2 {
    concentric::invert_uniform_disc_concentric(d.truncate())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chi2::{chi2_test, significance_level};
    use crate::warps::Warp;
    use crate::warps::test_support::{
        edge_points, integrate_rotationally_symmetric, interior_grid, midpoint_grid,
    };
    use approx::assert_relative_eq;

    #[test]
    fn exercise_cosine_hemisphere_gives_unit_directions_above_the_horizon() {
        for u in edge_points().into_iter().chain(interior_grid(30)) {
            let d = sample_cosine_hemisphere(u);
            let problem = if !d.is_finite() {
                "is not a number: at the rim of the disc rounding can carry the point a hair \
                 outside it, where there is no hemisphere above it to lift it to; the lift has to \
                 give the horizon there"
                    .to_string()
            } else if (d.length() - 1.0).abs() >= 1e-5 {
                format!(
                    "has length {}, not 1: the disc point has to be lifted onto the unit \
                     hemisphere, whose points are all at distance 1 from the centre",
                    d.length()
                )
            } else if d.z < 0.0 {
                "points below the horizon: the hemisphere is the half around +z".to_string()
            } else {
                continue;
            };
            panic!("sample_cosine_hemisphere: ξ = {u} gave {d}, which {problem}");
        }
    }

    #[test]
    fn exercise_cosine_hemisphere_stands_above_the_concentric_disc() {
        // The direction is the concentric disc point, lifted straight up.
        for u in interior_grid(12) {
            let d = sample_cosine_hemisphere(u);
            let disc = concentric::sample_uniform_disc_concentric(u);
            assert!(
                (d.truncate() - disc).length() < 1e-5,
                "sample_cosine_hemisphere: ξ = {u} gave {d}, which does not stand above the \
                 concentric map's point {disc} of the disc: the direction is that point lifted \
                 straight up onto the hemisphere (another disc map would give other directions \
                 for the same ξ)"
            );
        }
    }

    #[test]
    fn exercise_cosine_hemisphere_has_the_cosine_density() {
        let result = chi2_test(&Warp::CosineHemisphere, 200_000, 3, (16, 16));
        assert!(
            result.p_value > significance_level(1, 0.01),
            "sample_cosine_hemisphere: the directions do not follow the density cos θ / π \
             (chi-square test, p = {:.2e})",
            result.p_value
        );
    }

    #[test]
    fn exercise_cosine_hemisphere_leans_towards_the_normal() {
        // E[cos θ] = ∫ cos θ (cos θ / π) dω = 2/3; a uniform hemisphere would give 1/2.
        let grid = midpoint_grid(200);
        let mean = grid
            .iter()
            .map(|&u| sample_cosine_hemisphere(u).z as f64)
            .sum::<f64>()
            / grid.len() as f64;
        assert!(
            (mean - 2.0 / 3.0).abs() < 0.01,
            "sample_cosine_hemisphere: the mean cos θ of your directions is {mean:.3}; the \
             density cos θ / π gives 2/3, a uniform hemisphere 1/2: directions near the normal \
             should be the more likely"
        );
    }

    #[test]
    fn the_density_integrates_to_one() {
        let integral = integrate_rotationally_symmetric(cosine_hemisphere_pdf);
        assert_relative_eq!(integral, 1.0, epsilon = 1e-6);
        assert_eq!(cosine_hemisphere_pdf(-0.5), 0.0);
    }

    #[test]
    fn inverse_round_trips() {
        for u in interior_grid(20) {
            let d = sample_cosine_hemisphere(u);
            assert_relative_eq!(invert_cosine_hemisphere(d), u, epsilon = 2e-5);
        }
        let d = Vec3::new(0.3, -0.5, 0.0).normalize();
        let d = Vec3::new(d.x * 0.8, d.y * 0.8, 0.6);
        assert_relative_eq!(
            sample_cosine_hemisphere(invert_cosine_hemisphere(d)),
            d,
            epsilon = 1e-5
        );
    }
}
