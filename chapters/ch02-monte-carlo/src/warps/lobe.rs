//! The cosine-power lobe `cos^n θ` around +z: glossy reflection's narrowing beam.
//!
//! Phong's glossy highlight, and the lecture's fuzzy reflections (chapter 06), scatter light
//! into a lobe around the mirror direction whose width the exponent `n` sets: `n = 0` is the
//! uniform hemisphere, `n = 1` the cosine-weighted one, and as `n` grows the lobe narrows
//! towards the perfect mirror.
//!
//! The density per solid angle is `p(ω) = (n + 1) / 2π · cos^n θ`: integrating with
//! `dω = dz dφ`, `z = cos θ`, gives `2π ∫_0^1 (n + 1) / 2π z^n dz = 1`. It factors into a
//! uniform `φ` and a height with density `(n + 1) z^n` on `[0, 1]`, whose CDF measured from the
//! pole is `P(Z ≥ z) = 1 - z^(n+1)`. Setting that to `ξ2` and solving inverts it:
//! `cos θ = (1 - ξ2)^(1/(n+1))`.
//!
//! The textbook writes `ξ^(1/(n+1))`, with `ξ` in place of `1 - ξ` (both are uniform). Taking
//! `1 - ξ2` instead has two benefits: `ξ2 = 0` is the pole, as for the hemisphere and the cap,
//! and `1 - ξ2` is never 0 for `ξ2` in `[0, 1)`, so no sample ever lands exactly on the horizon,
//! where the density of a lobe with `n > 0` is 0 and an estimator would divide by it.
//!
//! Computing it in floating point needs care for large `n`. With `n = 10^6`, `cos θ` differs
//! from 1 by about `10^-6`, close to the spacing of `f32` near 1 (`6·10^-8`), so `cos θ` itself
//! holds few digits and `sin θ = √(1 - cos² θ)` would be mostly rounding noise. The formulas
//! below instead carry `1 - cos θ` directly, which is tiny but has full relative precision:
//! - `ln(1 - ξ2)` as `ln_1p(-ξ2)`, accurate also for small `ξ2`;
//! - `1 - cos θ = 1 - exp(t) = -expm1(t)` with `t = ln(1 - ξ2) / (n + 1)`;
//! - `sin θ = √((1 - cos θ)(1 + cos θ))`.

use std::f32::consts::{FRAC_1_PI, TAU};

use glam::{Vec2, Vec3};

use super::disc::azimuth;
use super::sphere::{one_minus_cos_theta, spherical_direction};

// ANCHOR: cos_lobe
/// A direction around +z with density `(n + 1) / 2π · cos^n θ` ([`cos_lobe_pdf`]), for a
/// finite exponent `n ≥ 0`: `cos θ = (1 - ξ2)^(1/(n+1))`, `φ = 2π ξ1`.
///
/// Stays finite and accurate from `n = 0` (uniform hemisphere) to `n = 10^6` and beyond: see
/// the module's notes on carrying `1 - cos θ`. For `ξ2` in `[0, 1)`, `ln(1 - ξ2)` is finite,
/// so `cos θ > 0` always.
pub fn sample_cos_lobe(u: Vec2, exponent: f32) -> Vec3 {
    let t = (-u.y).ln_1p() / (exponent + 1.0); // ln(cos θ) ≤ 0, finite as 1 - ξ2 ≥ 2^-24
    let one_minus_cos = -t.exp_m1();
    let cos_theta = t.exp();
    let sin_theta = (one_minus_cos * (1.0 + cos_theta)).sqrt();
    spherical_direction(sin_theta, cos_theta, TAU * u.x)
}
// ANCHOR_END: cos_lobe

/// The density of [`sample_cos_lobe`] per unit solid angle, `(n + 1) / 2π · cos^n θ`, and 0
/// below the horizon.
///
/// No overflow for any finite `n`: `cos θ` is clamped to at most 1 (a direction a rounding
/// error longer than 1 must not give `1.0000001^(10^9) = ∞`), so `cos^n θ ≤ 1` and the density
/// is at most its peak `(n + 1) / 2π`. For large `n` and `cos θ` not near 1, `cos^n θ`
/// underflows gracefully to 0.
pub fn cos_lobe_pdf(cos_theta: f32, exponent: f32) -> f32 {
    if cos_theta < 0.0 {
        return 0.0;
    }
    (exponent + 1.0) * (FRAC_1_PI / 2.0) * cos_theta.min(1.0).powf(exponent)
}

/// The `u` that [`sample_cos_lobe`] maps to `d`: `ξ2 = 1 - cos^(n+1) θ`, `ξ1 = φ / 2π`.
///
/// Computed as `-expm1((n + 1) ln_1p(-(1 - cos θ)))` from the accurate
/// [`one_minus_cos_theta`], so that even for `n = 10^6` directions a micro-radian apart
/// invert to different `ξ2`. Directions on or below the horizon give `ξ2 = 1`.
pub fn invert_cos_lobe(d: Vec3, exponent: f32) -> Vec2 {
    let one_minus_cos = one_minus_cos_theta(d).min(1.0);
    let ln_cos = (-one_minus_cos).ln_1p();
    let xi2 = -((exponent + 1.0) * ln_cos).exp_m1();
    Vec2::new(azimuth(d.truncate()) / TAU, xi2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::warps::test_support::{
        edge_points, integrate_rotationally_symmetric, interior_grid, midpoint_grid,
    };
    use crate::warps::{sample_uniform_hemisphere, uniform_hemisphere_pdf};
    use approx::assert_relative_eq;

    const EXPONENTS: [f32; 6] = [0.0, 1.0, 10.0, 100.0, 1e3, 1e6];

    #[test]
    fn edge_values_give_unit_directions_above_the_horizon() {
        for exponent in EXPONENTS {
            for u in edge_points() {
                let d = sample_cos_lobe(u, exponent);
                assert!(d.is_finite(), "n = {exponent}, u = {u}: {d}");
                assert!(
                    (d.length() - 1.0).abs() < 1e-5,
                    "n = {exponent}, u = {u}: {d}"
                );
                assert!(d.z > 0.0, "n = {exponent}, u = {u}: {d}");
                let pdf = cos_lobe_pdf(d.z, exponent);
                assert!(
                    pdf.is_finite() && pdf >= 0.0,
                    "n = {exponent}, u = {u}: {pdf}"
                );
            }
        }
    }

    #[test]
    fn the_density_integrates_to_one_for_every_exponent() {
        for exponent in EXPONENTS {
            let integral = integrate_rotationally_symmetric(|z| cos_lobe_pdf(z, exponent));
            assert_relative_eq!(integral, 1.0, epsilon = 1e-3);
        }
    }

    #[test]
    fn the_peak_density_is_finite_even_for_huge_exponents() {
        for exponent in [1e6, 1e12, 1e30] {
            let peak = cos_lobe_pdf(1.0, exponent);
            assert!(peak.is_finite(), "n = {exponent}: {peak}");
            assert_relative_eq!(peak, (exponent + 1.0) / TAU, max_relative = 1e-6);
            // A rounding error above 1 must not overflow either.
            assert_eq!(cos_lobe_pdf(1.000_000_1, exponent), peak);
        }
    }

    #[test]
    fn exponents_zero_and_one_are_the_hemisphere_and_the_cosine() {
        for u in interior_grid(10) {
            let d = sample_cos_lobe(u, 0.0);
            assert_relative_eq!(d, sample_uniform_hemisphere(u), epsilon = 1e-6);
        }
        assert_relative_eq!(cos_lobe_pdf(0.3, 0.0), uniform_hemisphere_pdf());
        assert_relative_eq!(cos_lobe_pdf(0.3, 1.0), 0.3 / std::f32::consts::PI);
    }

    #[test]
    fn inverse_round_trips_for_every_exponent() {
        for exponent in EXPONENTS {
            for u in interior_grid(20) {
                let d = sample_cos_lobe(u, exponent);
                let back = invert_cos_lobe(d, exponent);
                assert_relative_eq!(back, u, epsilon = 1e-4);
                assert_relative_eq!(sample_cos_lobe(back, exponent), d, epsilon = 1e-5);
            }
        }
    }

    #[test]
    fn the_lobe_narrows_to_a_delta() {
        // E[cos θ] = ∫ z (n + 1) z^n dz = (n + 1) / (n + 2), which tends to 1.
        let grid = midpoint_grid(300);
        let mut previous_mean = 0.0;
        for exponent in EXPONENTS {
            let mean = grid
                .iter()
                .map(|&u| sample_cos_lobe(u, exponent).z as f64)
                .sum::<f64>()
                / grid.len() as f64;
            let expected = (exponent as f64 + 1.0) / (exponent as f64 + 2.0);
            assert_relative_eq!(mean, expected, epsilon = 1e-4);
            assert!(mean > previous_mean, "n = {exponent}: the mean must grow");
            previous_mean = mean;
        }
    }

    #[test]
    fn at_a_million_every_sample_is_within_a_degree_of_the_pole() {
        // 1 - cos θ = -ln(1 - ξ2) / (n + 1) ≤ ln(2^24) / 10^6 ≈ 1.7e-5 for any ξ2 < 1.
        let mut rng = rand_pcg::Pcg32::new(7, 1);
        for _ in 0..100_000 {
            let u = Vec2::new(
                common::sampler::unit_f32(rand::Rng::next_u32(&mut rng)),
                common::sampler::unit_f32(rand::Rng::next_u32(&mut rng)),
            );
            let d = sample_cos_lobe(u, 1e6);
            assert!(d.is_finite() && d.z > 0.9999, "u = {u}: {d}");
        }
        let corner = sample_cos_lobe(Vec2::splat(f32::from_bits(0x3f7f_ffff)), 1e6);
        assert!(corner.z > 0.9999, "{corner}");
    }
}
