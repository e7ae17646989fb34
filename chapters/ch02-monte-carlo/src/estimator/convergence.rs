//! Error against the number of samples, and against time.
//!
//! For each strategy and sample count `n`, the estimate is repeated with independent random
//! numbers and its error against the known value is measured over all repetitions. On log-log
//! axes, error `∝ n^k` is a straight line of slope `k`: `-1/2` for independent sampling, steeper
//! for stratified sampling of a smooth integrand. Error against *time* decides which strategy
//! is worth it: a strategy that costs more per sample must win by more than it costs.

use std::time::Instant;

use common::metrics::ConvergenceRecord;

use super::{Integrand, Strategy, repetition_rng};

/// Sample counts for convergence experiments: powers of four from 4 to 4096. They are square
/// numbers, as stratifying a 2D integrand requires, and double the resolution of a jittered
/// grid at each step.
pub const SAMPLE_COUNTS: [usize; 6] = [4, 16, 64, 256, 1024, 4096];

/// Measures every strategy at every sample count on `integrand`: one record per strategy and
/// count, strategy by strategy, counts in the order given.
///
/// Each record holds, over `repetitions` independent runs (repetition `r` uses
/// [`repetition_rng`]`(seed, r)`, the same for every strategy and count):
/// - `technique`: the strategy's name; `spp`: the sample count `n`;
/// - `seconds`: the mean wall-clock time of one estimate, random number generation included;
/// - `rmse`: `sqrt(mean((estimate - value)²))`, the typical error of one estimate;
/// - `relmse`: `mean((estimate - value)²) / value²`, the squared error relative to the value.
///
/// # Panics
///
/// If `repetitions` is 0, or for a sample count a strategy cannot use (see
/// [`Strategy::estimate`]).
pub fn convergence<X: Copy>(
    integrand: &Integrand<X>,
    strategies: &[Strategy],
    sample_counts: &[usize],
    repetitions: usize,
    seed: u64,
) -> Vec<ConvergenceRecord> {
    assert!(repetitions > 0, "convergence needs at least one repetition");
    let mut records = Vec::with_capacity(strategies.len() * sample_counts.len());
    for &strategy in strategies {
        for &n in sample_counts {
            let mut sum_of_squared_errors = 0.0;
            let start = Instant::now();
            for repetition in 0..repetitions as u64 {
                let mut rng = repetition_rng(seed, repetition);
                let estimate = strategy.estimate(integrand, n, &mut rng);
                sum_of_squared_errors += (estimate - integrand.value).powi(2);
            }
            let seconds = start.elapsed().as_secs_f64() / repetitions as f64;
            let mean_squared_error = sum_of_squared_errors / repetitions as f64;
            records.push(ConvergenceRecord {
                technique: strategy.name().to_string(),
                spp: n as u64,
                seconds,
                rmse: mean_squared_error.sqrt(),
                relmse: mean_squared_error / integrand.value.powi(2),
            });
        }
    }
    records
}

/// The slope of the least-squares line through `points` on log-log axes: the `k` of the power
/// law `y ∝ x^k` that fits them best.
///
/// Points that a logarithm cannot take (`x` or `y` zero, negative or not finite) are left out;
/// with fewer than two distinct `x` left, the slope is `NaN`.
pub fn log_log_slope(points: impl IntoIterator<Item = (f64, f64)>) -> f64 {
    let logs: Vec<(f64, f64)> = points
        .into_iter()
        .filter(|&(x, y)| x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite())
        .map(|(x, y)| (x.ln(), y.ln()))
        .collect();
    let count = logs.len() as f64;
    let mean_x = logs.iter().map(|p| p.0).sum::<f64>() / count;
    let mean_y = logs.iter().map(|p| p.1).sum::<f64>() / count;
    let covariance: f64 = logs.iter().map(|p| (p.0 - mean_x) * (p.1 - mean_y)).sum();
    let spread_x: f64 = logs.iter().map(|p| (p.0 - mean_x).powi(2)).sum();
    if spread_x > 0.0 {
        covariance / spread_x
    } else {
        f64::NAN
    }
}

/// The convergence rate of `technique` in `records`: the [`log_log_slope`] of its RMSE against
/// its sample count. About `-0.5` for independent sampling.
pub fn convergence_rate(records: &[ConvergenceRecord], technique: &str) -> f64 {
    log_log_slope(
        records
            .iter()
            .filter(|record| record.technique == technique)
            .map(|record| (record.spp as f64, record.rmse)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::estimator::x_squared;
    use approx::assert_relative_eq;

    #[test]
    fn slopes_of_exact_power_laws() {
        let points = |k: f64| (1..6).map(move |i| (f64::from(i), 3.0 * f64::from(i).powf(k)));
        assert_relative_eq!(log_log_slope(points(-0.5)), -0.5, max_relative = 1e-12);
        assert_relative_eq!(log_log_slope(points(2.0)), 2.0, max_relative = 1e-12);
        // Unusable points are skipped; too few points give NaN.
        let with_zero = points(-1.0).chain([(7.0, 0.0), (0.0, 1.0)]);
        assert_relative_eq!(log_log_slope(with_zero), -1.0, max_relative = 1e-12);
        assert!(log_log_slope([(2.0, 1.0)]).is_nan());
        assert!(log_log_slope([(2.0, 1.0), (2.0, 3.0)]).is_nan());
    }

    #[test]
    fn one_record_per_strategy_and_count_with_consistent_errors() {
        let integrand = x_squared();
        let counts = [4, 16, 64];
        let records = convergence(&integrand, &Strategy::ALL, &counts, 20, 11);
        assert_eq!(records.len(), 9);
        for (record, (strategy, n)) in records
            .iter()
            .zip(Strategy::ALL.iter().flat_map(|s| counts.map(|n| (s, n))))
        {
            assert_eq!(record.technique, strategy.name());
            assert_eq!(record.spp, n as u64);
            assert!(record.seconds >= 0.0 && record.seconds.is_finite());
            assert!(record.rmse > 0.0);
            assert_relative_eq!(
                record.relmse,
                record.rmse.powi(2) / integrand.value.powi(2),
                max_relative = 1e-12
            );
        }
    }

    #[test]
    fn convergence_is_reproducible_in_everything_but_time() {
        let errors = |seed| -> Vec<(f64, f64)> {
            convergence(&x_squared(), &[Strategy::Uniform], &[16, 64], 10, seed)
                .iter()
                .map(|r| (r.rmse, r.relmse))
                .collect()
        };
        assert_eq!(errors(3), errors(3));
        assert_ne!(errors(3), errors(4));
    }
}
