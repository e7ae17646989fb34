//! Three ways to estimate the same integral: uniform, importance and stratified sampling.
//!
//! All three are the estimator of [`super::estimate`]; they differ only in where the points
//! come from. *Uniform* and *importance* sampling warp independent uniform numbers, into
//! uniform points or into points shaped like `f`. *Stratified* sampling warps stratified
//! numbers (one per stratum of `[0, 1)`, or one per cell of a grid on the square) into
//! uniform points: the same density as uniform sampling, so the same estimator, but more
//! evenly spread.

use std::fmt;

use common::sampler::unit_f32;
use glam::Vec2;
use rand::Rng;

use super::{Dimensions, Integrand, estimate, estimate_uniform};
use crate::stratified::{jittered_2d, stratified_1d};

/// A sampling strategy for the Monte Carlo estimator.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Strategy {
    /// Independent uniform points: `(|D| / n) Σ f(x_i)`.
    Uniform,
    /// Independent points from the integrand's importance density: `(1/n) Σ f(x_i) / p(x_i)`.
    Importance,
    /// Uniform points, one per stratum (1D) or per grid cell (2D): `(|D| / n) Σ f(x_i)`.
    Stratified,
}

impl Strategy {
    /// The three strategies, in the order the chapter introduces them.
    pub const ALL: [Strategy; 3] = [
        Strategy::Uniform,
        Strategy::Importance,
        Strategy::Stratified,
    ];

    /// The strategy's name in tables and legends.
    pub fn name(self) -> &'static str {
        match self {
            Strategy::Uniform => "uniform",
            Strategy::Importance => "importance",
            Strategy::Stratified => "stratified",
        }
    }

    /// One estimate of `integrand` from `n` points drawn with this strategy from `rng`.
    ///
    /// # Panics
    ///
    /// Stratified sampling of a two-dimensional integrand jitters a square grid, so `n` must
    /// then be a square number (4, 16, 64, ...); any other `n` panics.
    pub fn estimate<X: Copy, R: Rng + ?Sized>(
        self,
        integrand: &Integrand<X>,
        n: usize,
        rng: &mut R,
    ) -> f64 {
        let dimensions = integrand.dimensions;
        match self {
            Strategy::Uniform => estimate_uniform(
                integrand.domain_measure,
                n,
                || (integrand.uniform_warp)(independent_point(dimensions, rng)),
                integrand.f,
            ),
            Strategy::Importance => estimate(
                n,
                &mut || (integrand.importance.warp)(independent_point(dimensions, rng)),
                integrand.f,
                integrand.importance.pdf,
            ),
            Strategy::Stratified => {
                let mut points = stratified_points(dimensions, n, rng).into_iter();
                estimate_uniform(
                    integrand.domain_measure,
                    n,
                    || (integrand.uniform_warp)(points.next().expect("n stratified points")),
                    integrand.f,
                )
            }
        }
    }
}

impl fmt::Display for Strategy {
    fn fmt(&self, formatter: &mut fmt::Formatter<'_>) -> fmt::Result {
        formatter.write_str(self.name())
    }
}

/// Fresh uniform numbers for one point: one number (in `x`; `y` is 0) or two.
fn independent_point<R: Rng + ?Sized>(dimensions: Dimensions, rng: &mut R) -> Vec2 {
    match dimensions {
        Dimensions::One => Vec2::new(unit_f32(rng.next_u32()), 0.0),
        Dimensions::Two => {
            let x = unit_f32(rng.next_u32());
            let y = unit_f32(rng.next_u32());
            Vec2::new(x, y)
        }
    }
}

/// `n` stratified uniform points: `n` strata of `[0, 1)` in one dimension, a jittered
/// `√n x √n` grid in two.
fn stratified_points<R: Rng + ?Sized>(dimensions: Dimensions, n: usize, rng: &mut R) -> Vec<Vec2> {
    match dimensions {
        Dimensions::One => stratified_1d(n, rng)
            .into_iter()
            .map(|x| Vec2::new(x, 0.0))
            .collect(),
        Dimensions::Two => {
            let per_side = n.isqrt();
            assert_eq!(
                per_side * per_side,
                n,
                "stratifying a 2D integrand needs a square number of samples, not {n}"
            );
            jittered_2d(per_side, rng)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimator::{peaked_quartic, sky_irradiance};
    use rand::SeedableRng;
    use rand_pcg::Pcg32;

    #[test]
    fn names_are_distinct_and_displayed() {
        let names: Vec<String> = Strategy::ALL.iter().map(ToString::to_string).collect();
        assert_eq!(names, ["uniform", "importance", "stratified"]);
    }

    #[test]
    fn the_same_seed_gives_the_same_estimate() {
        for strategy in Strategy::ALL {
            let once = strategy.estimate(&peaked_quartic(), 64, &mut Pcg32::seed_from_u64(9));
            let again = strategy.estimate(&peaked_quartic(), 64, &mut Pcg32::seed_from_u64(9));
            assert_eq!(once, again, "{strategy}");
        }
    }

    #[test]
    #[should_panic(expected = "square number")]
    fn stratifying_the_hemisphere_needs_a_square_count() {
        Strategy::Stratified.estimate(&sky_irradiance(), 10, &mut Pcg32::seed_from_u64(1));
    }
}
