//! The estimators tested as statistics: unbiased on every integrand, of zero variance where
//! theory says so, with the variances and convergence rates theory predicts.
//!
//! Every test runs with fixed seeds, so it is deterministic; its tolerance is derived from the
//! estimator's own variance (a few standard errors), so that a correct estimator passes by a
//! wide margin while a biased one, or one with the wrong variance, fails.

use std::f64::consts::PI;

use super::*;

/// How many standard errors an average may stray from its expectation. With fixed seeds the
/// tests are deterministic; 5 standard errors would be exceeded by a correct estimator about
/// once in 1.7 million seeds.
const STANDARD_ERRORS: f64 = 5.0;

/// Relative slack for the rounding of `f32` directions and densities: the cosine-weighted
/// estimator is exact up to this, where its standard error is 0.
const ROUNDING: f64 = 1e-6;

/// Asserts that the mean of `repetitions` estimates with `n` samples each is within
/// [`STANDARD_ERRORS`] of the integral, for every strategy.
fn assert_unbiased<X: Copy>(integrand: &Integrand<X>, n: usize, repetitions: usize) {
    for strategy in Strategy::ALL {
        let estimates =
            repeated_estimates(repetitions, 1, |rng| strategy.estimate(integrand, n, rng));
        let (mean, variance) = sample_mean_and_variance(&estimates);
        let standard_error = (variance / repetitions as f64).sqrt();
        let tolerance = STANDARD_ERRORS * standard_error + ROUNDING * integrand.value;
        assert!(
            (mean - integrand.value).abs() <= tolerance,
            "{} with {strategy}, n = {n}: mean {mean}, expected {} ± {tolerance}",
            integrand.name,
            integrand.value
        );
    }
}

#[test]
fn every_strategy_is_unbiased_with_few_samples() {
    // Small n makes normalisation mistakes large: a 1/(n+1) would be 20 % off at n = 4.
    assert_unbiased(&x_squared(), 4, 4000);
    assert_unbiased(&peaked_quartic(), 4, 4000);
    assert_unbiased(&sky_irradiance(), 4, 4000);
}

#[test]
fn every_strategy_is_unbiased_with_many_samples() {
    assert_unbiased(&x_squared(), 4096, 40);
    assert_unbiased(&peaked_quartic(), 4096, 40);
    assert_unbiased(&sky_irradiance(), 4096, 40);
}

#[test]
fn cosine_weighted_irradiance_has_zero_variance() {
    let sky = sky_irradiance();
    for n in [1, 7, 1000] {
        for seed in 0..5 {
            let estimate = Strategy::Importance.estimate(&sky, n, &mut repetition_rng(seed, 0));
            let error = (estimate - PI * SKY_RADIANCE).abs();
            assert!(error <= ROUNDING * PI, "n = {n}: {estimate}");
        }
    }
    let variance = estimator_variance(200, 3, |rng| Strategy::Importance.estimate(&sky, 1, rng));
    assert!(variance < 1e-12, "{variance}");
}

/// Asserts that the variance of one-sample estimates (`σ²`, the variance of `f/p`) is
/// `expected`, to 10 % (the sample variance of 20 000 values is good to about 2 %).
fn assert_sample_variance<X: Copy>(integrand: &Integrand<X>, strategy: Strategy, expected: f64) {
    let variance = estimator_variance(20_000, 2, |rng| strategy.estimate(integrand, 1, rng));
    assert!(
        (variance / expected - 1.0).abs() < 0.1,
        "{} with {strategy}: variance {variance}, theory {expected}",
        integrand.name
    );
}

#[test]
fn variances_per_sample_match_theory() {
    // σ² = E[(f/p)²] - I², worked out in the integrand module's table.
    assert_sample_variance(&x_squared(), Strategy::Uniform, 4.0 / 45.0);
    assert_sample_variance(&x_squared(), Strategy::Importance, 1.0 / 72.0);
    assert_sample_variance(&peaked_quartic(), Strategy::Uniform, 16.0 / 9.0);
    assert_sample_variance(&peaked_quartic(), Strategy::Importance, 1.0 / 24.0);
    let sky_variance = PI * PI / 3.0 * SKY_RADIANCE * SKY_RADIANCE;
    assert_sample_variance(&sky_irradiance(), Strategy::Uniform, sky_variance);
}

#[test]
fn importance_sampling_pays_most_on_the_peak() {
    let peak = peaked_quartic();
    let variance_with =
        |strategy: Strategy| estimator_variance(1000, 4, |rng| strategy.estimate(&peak, 16, rng));
    let gain = variance_with(Strategy::Uniform) / variance_with(Strategy::Importance);
    // Theory: (16/9) / (1/24) ≈ 43.
    assert!((30.0..60.0).contains(&gain), "{gain}");
}

#[test]
fn variance_falls_as_one_over_n() {
    let integrand = x_squared();
    let variance_at = |n| {
        estimator_variance(2000, 5, |rng| {
            Strategy::Uniform.estimate(&integrand, n, rng)
        })
    };
    // Sixteen times the samples, a sixteenth of the variance (each measured to about 3 %).
    let ratio = variance_at(16) / variance_at(256);
    assert!((13.0..19.5).contains(&ratio), "{ratio}");
}

/// Counts for the slope tests: over two decades, with the smallest counts left out (where the
/// asymptotic rate of stratification has not set in yet).
const SLOPE_COUNTS: [usize; 5] = [16, 64, 256, 1024, 4096];

/// The RMSE slope of `strategy` on `integrand`, from 200 repetitions per count.
fn rmse_slope<X: Copy>(integrand: &Integrand<X>, strategy: Strategy) -> f64 {
    let records = convergence(integrand, &[strategy], &SLOPE_COUNTS, 200, 6);
    convergence_rate(&records, strategy.name())
}

#[test]
fn independent_sampling_converges_as_one_over_sqrt_n() {
    let cases = [
        (
            x_squared().name,
            rmse_slope(&x_squared(), Strategy::Uniform),
        ),
        (
            x_squared().name,
            rmse_slope(&x_squared(), Strategy::Importance),
        ),
        (
            peaked_quartic().name,
            rmse_slope(&peaked_quartic(), Strategy::Uniform),
        ),
        (
            peaked_quartic().name,
            rmse_slope(&peaked_quartic(), Strategy::Importance),
        ),
        (
            sky_irradiance().name,
            rmse_slope(&sky_irradiance(), Strategy::Uniform),
        ),
    ];
    for (name, slope) in cases {
        assert!((-0.6..=-0.4).contains(&slope), "{name}: slope {slope}");
    }
}

#[test]
fn stratified_sampling_of_smooth_integrands_converges_faster() {
    // Theory: variance ∝ n^-(1 + 2/d), so RMSE ∝ n^-1.5 in 1D and n^-1 in 2D.
    for integrand in [x_squared(), peaked_quartic()] {
        let slope = rmse_slope(&integrand, Strategy::Stratified);
        assert!(
            (-1.7..=-1.3).contains(&slope),
            "{}: slope {slope}",
            integrand.name
        );
    }
    let slope = rmse_slope(&sky_irradiance(), Strategy::Stratified);
    assert!(
        (-1.2..=-0.8).contains(&slope),
        "sky_irradiance: slope {slope}"
    );
}
