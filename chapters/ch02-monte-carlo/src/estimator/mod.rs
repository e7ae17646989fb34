//! The Monte Carlo estimator: integrals as averages of random samples.
//!
//! The lecture's one formula, `∫ f ≈ (1/n) Σ f(x_i) / p(x_i)`, and the experiments that show
//! what it does:
//!
//! | file | idea |
//! |---|---|
//! | [`monte_carlo`](estimate) | the estimator, uniform and general, and why it is unbiased |
//! | [`integrand`](Integrand) | integrals with known values: `x²`, a peak, the sky's irradiance |
//! | [`strategy`](Strategy) | uniform, importance and stratified sampling of the same integral |
//! | [`variance`](sample_mean_and_variance) | measuring the noise of an estimator over repeated runs |
//! | [`irradiance`](estimate_irradiance) | the capstone: a sun and a sky, warps, densities, a standard error |
//! | [`convergence`](convergence()) | error against samples and time, and its slope |
//!
//! The statistical tests of this module check the theory, not just the code: every strategy
//! is unbiased, the cosine-weighted irradiance estimator has zero variance, the error of
//! independent sampling falls as `1/√n` and stratified sampling's falls faster.

mod convergence;
mod integrand;
mod irradiance;
mod monte_carlo;
mod strategy;
mod variance;

#[cfg(test)]
mod statistical_tests;

pub use convergence::{SAMPLE_COUNTS, convergence, convergence_rate, log_log_slope};
pub use integrand::{
    Dimensions, ImportanceSampling, Integrand, SKY_RADIANCE, peaked_quartic, sky_irradiance,
    x_squared,
};
pub use irradiance::{DirectionSampling, Estimate, SunAndSky, estimate_irradiance};
pub use monte_carlo::{estimate, estimate_uniform};
pub use strategy::Strategy;
pub use variance::{
    estimator_variance, repeated_estimates, repetition_rng, sample_mean_and_variance,
};
