//! A small catalogue of integrals whose exact values we know, to test estimators against.
//!
//! Each [`Integrand`] carries its function, its exact value, and two ways to sample its
//! domain: uniformly, and by importance with a density shaped like the function. All points
//! are made from uniform numbers `u` in the unit square by a warp, so that the same integrand
//! can be fed independent or stratified `u` (see [`super::Strategy`]).
//!
//! | integrand | exact value | importance density | variance per sample, uniform → importance |
//! |---|---|---|---|
//! | [`x_squared`]: `∫₀¹ x² dx` | 1/3 | `2x` | 4/45 ≈ 0.089 → 1/72 ≈ 0.014 |
//! | [`peaked_quartic`]: `∫₀¹ 5x⁴ dx` | 1 | `4x³` | 16/9 ≈ 1.78 → 1/24 ≈ 0.042 |
//! | [`sky_irradiance`]: `∫_{H²} L cos θ dω` | π L | `cos θ / π` | π²/3 · L² ≈ 3.3 L² → 0 |
//!
//! The variances are `E[(f/p)²] - I²`; for example uniform sampling of `5x⁴` gives
//! `∫₀¹ 25 x⁸ dx - 1 = 25/9 - 1`. The peaked integrand is where importance sampling pays most
//! (43 times less variance), and the sky is the famous case where it is perfect: `f / p` is the
//! constant `π L`.

use std::f64::consts::{PI, TAU};

use glam::{Vec2, Vec3};

use crate::warps::{cosine_hemisphere_pdf, sample_cosine_hemisphere, sample_uniform_hemisphere};

/// How many uniform numbers one point of an integrand's domain is made from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimensions {
    /// An interval: only `u.x` is used.
    One,
    /// A surface, such as the hemisphere of directions: `u.x` and `u.y`.
    Two,
}

/// A way of drawing points other than uniformly: a warp of uniform numbers and the density of
/// the points it makes.
#[derive(Clone, Copy, Debug)]
pub struct ImportanceSampling<X> {
    /// The density in words, for tables and legends, e.g. `"p(x) = 2x"`.
    pub density: &'static str,
    /// Turns uniform numbers into a point.
    pub warp: fn(Vec2) -> X,
    /// The density `p(x)` of the points `warp` makes from uniform numbers.
    pub pdf: fn(X) -> f64,
}

/// An integral `∫_D f(x) dx` with a known value, and ways to sample its domain `D`.
///
/// `X` is the type of a point of the domain: `f64` on an interval, a unit [`Vec3`] on the
/// hemisphere of directions.
#[derive(Clone, Copy, Debug)]
pub struct Integrand<X> {
    /// Short name for tables and file names, e.g. `"x_squared"`.
    pub name: &'static str,
    /// The integral in mathematical notation, for captions.
    pub formula: &'static str,
    /// The exact value of the integral.
    pub value: f64,
    /// The function being integrated.
    pub f: fn(X) -> f64,
    /// The measure (length, area, solid angle) of the domain `D`.
    pub domain_measure: f64,
    /// How many uniform numbers make a point.
    pub dimensions: Dimensions,
    /// Turns uniform numbers into a uniformly distributed point of `D`.
    pub uniform_warp: fn(Vec2) -> X,
    /// Importance sampling with a density shaped like `f`.
    pub importance: ImportanceSampling<X>,
}

/// `∫₀¹ x² dx = 1/3`: smooth and gentle, the first integral anyone estimates.
///
/// Importance sampling with `p(x) = 2x` (a straight line, roughly the shape of `x²`) cuts the
/// variance about sixfold; stratification does better still, as `f` is smooth.
pub fn x_squared() -> Integrand<f64> {
    Integrand {
        name: "x_squared",
        formula: "∫₀¹ x² dx",
        value: 1.0 / 3.0,
        f: |x| x * x,
        domain_measure: 1.0,
        dimensions: Dimensions::One,
        uniform_warp: uniform_unit_interval,
        importance: ImportanceSampling {
            density: "p(x) = 2x",
            // Inverting the CDF F(x) = x²: x = sqrt(ξ), written with 1 - ξ in (0, 1] so that
            // x = 0, where p = 0, is never drawn.
            warp: |u| (1.0 - f64::from(u.x)).sqrt(),
            pdf: |x| 2.0 * x,
        },
    }
}

/// `∫₀¹ 5x⁴ dx = 1`: nearly all of the integral sits near `x = 1`, so uniform points are
/// mostly wasted on a region that contributes almost nothing.
///
/// Importance sampling with `p(x) = 4x³` puts the points where the integral is and lowers
/// the variance from 16/9 to 1/24, by a factor of about 43.
pub fn peaked_quartic() -> Integrand<f64> {
    Integrand {
        name: "peaked_quartic",
        formula: "∫₀¹ 5x⁴ dx",
        value: 1.0,
        f: |x| 5.0 * x.powi(4),
        domain_measure: 1.0,
        dimensions: Dimensions::One,
        uniform_warp: uniform_unit_interval,
        importance: ImportanceSampling {
            density: "p(x) = 4x³",
            // Inverting F(x) = x⁴, again with 1 - ξ so that x > 0.
            warp: |u| (1.0 - f64::from(u.x)).powf(0.25),
            pdf: |x| 4.0 * x.powi(3),
        },
    }
}

/// The radiance of the uniform sky in [`sky_irradiance`].
pub const SKY_RADIANCE: f64 = 1.0;

/// The irradiance under a uniform sky of radiance `L`:
/// `E = ∫_{H²} L cos θ dω = π L`, the integral behind every diffuse surface in a renderer.
///
/// Uniform directions of the hemisphere (density `1 / 2π`) give a noisy estimate, since
/// grazing directions contribute almost nothing. Cosine-weighted directions (density
/// `cos θ / π`) make every term `L cos θ / (cos θ / π) = π L`: zero variance, the exact answer
/// from a single sample.
pub fn sky_irradiance() -> Integrand<Vec3> {
    Integrand {
        name: "sky_irradiance",
        formula: "∫_H² L cos θ dω",
        value: PI * SKY_RADIANCE,
        f: |direction| SKY_RADIANCE * cos_theta(direction),
        domain_measure: TAU,
        dimensions: Dimensions::Two,
        uniform_warp: sample_uniform_hemisphere,
        importance: ImportanceSampling {
            density: "p(ω) = cos θ / π",
            warp: sample_cosine_hemisphere,
            pdf: |direction| f64::from(cosine_hemisphere_pdf(direction.z)),
        },
    }
}

/// A uniform number of `[0, 1)` from `u.x`.
fn uniform_unit_interval(u: Vec2) -> f64 {
    f64::from(u.x)
}

/// `cos θ` of a unit direction around +z, and 0 below the horizon (where no sky light comes
/// from).
fn cos_theta(direction: Vec3) -> f64 {
    f64::from(direction.z).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// Midpoint-rule integral of `g` over `[0, 1]` with many points: a deterministic check of
    /// the catalogue's closed forms.
    fn quadrature(g: impl Fn(f64) -> f64) -> f64 {
        let n = 100_000;
        (0..n).map(|i| g((i as f64 + 0.5) / n as f64)).sum::<f64>() / n as f64
    }

    #[test]
    fn one_dimensional_values_and_densities_are_right() {
        for integrand in [x_squared(), peaked_quartic()] {
            assert_relative_eq!(
                quadrature(integrand.f),
                integrand.value,
                max_relative = 1e-8
            );
            // The importance density integrates to 1 over the domain ...
            assert_relative_eq!(
                quadrature(integrand.importance.pdf),
                1.0,
                max_relative = 1e-8
            );
            // ... and is the density of its warp: the warp sends ξ to the point whose CDF
            // is 1 - ξ, and the pdf is the derivative of that CDF.
            let cdf = |x: f64| quadrature(|t| (integrand.importance.pdf)(t * x)) * x;
            for xi in [0.1f32, 0.5, 0.9] {
                let x = (integrand.importance.warp)(Vec2::new(xi, 0.0));
                assert_relative_eq!(cdf(x), 1.0 - f64::from(xi), max_relative = 1e-6);
            }
        }
    }

    #[test]
    fn the_uniform_density_of_the_hemisphere_is_one_over_its_solid_angle() {
        assert_relative_eq!(
            f64::from(crate::warps::uniform_hemisphere_pdf()),
            1.0 / sky_irradiance().domain_measure,
            max_relative = 1e-6
        );
    }

    #[test]
    fn importance_warps_never_reach_a_zero_density() {
        for integrand in [x_squared(), peaked_quartic()] {
            for xi in [0.0, 0.5, 1.0 - f32::EPSILON / 2.0] {
                let x = (integrand.importance.warp)(Vec2::new(xi, 0.0));
                assert!(
                    (integrand.importance.pdf)(x) > 0.0,
                    "{}: {xi}",
                    integrand.name
                );
            }
        }
    }
}
