//! Error against the number of samples, and against time.
//!
//! For each strategy and sample count `n`, the estimate is repeated with independent random
//! numbers and its error against the known value is measured over all repetitions. On log-log
//! axes, error `∝ n^k` is a straight line of slope `k`: `-1/2` for independent sampling, steeper
//! for stratified sampling of a smooth integrand. Error against *time* decides which strategy
//! is worth it: a strategy that costs more per sample must win by more than it costs.

use common::metrics::ConvergenceRecord;

use super::{Integrand, Strategy};

/// Sample counts for convergence experiments: powers of four from 4 to 4096. They are square
/// numbers, as stratifying a 2D integrand requires, and double the resolution of a jittered
/// grid at each step.
pub const SAMPLE_COUNTS: [usize; 6] = [4, 16, 64, 256, 1024, 4096];

// ANCHOR: convergence
/// Measures every strategy at every sample count on `integrand`: one record per strategy and
/// count, strategy by strategy, counts in the order given.
///
/// Each record holds, over `repetitions` independent runs (repetition `r` uses
/// [`repetition_rng`](super::repetition_rng)`(seed, r)`, the same for every strategy and
/// count):
/// - `technique`: the strategy's name; `spp`: the sample count `n`;
/// - `seconds`: the mean wall-clock time of one estimate, random number generation included;
/// - `rmse`: the typical error of one estimate against the integral's exact value, the root of
///   the mean squared error;
/// - `relmse`: the mean squared error relative to the squared value.
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
    // BEGIN SOLUTION
    use super::repetition_rng;
    use std::time::Instant;

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
    // END SOLUTION
}
// ANCHOR_END: convergence

// ANCHOR: log_log_slope
/// The slope of the least-squares line through `points` on log-log axes: the `k` of the power
/// law `y ∝ x^k` that fits them best.
///
/// Points that a logarithm cannot take (`x` or `y` zero, negative or not finite) are left out;
/// with fewer than two distinct `x` left, the slope is `NaN`.
pub fn log_log_slope(points: impl IntoIterator<Item = (f64, f64)>) -> f64 {
    // BEGIN SOLUTION
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
    // END SOLUTION
}
// ANCHOR_END: log_log_slope

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
    use crate::estimator::{repetition_rng, x_squared};
    use approx::assert_relative_eq;
    use std::time::Instant;

    /// What is wrong with `slope`, an answer for `points`, in words; `None` if it is right.
    fn slope_mistake(points: &[(f64, f64)], slope: f64, expected: f64) -> Option<String> {
        if (slope - expected).abs() <= 1e-9 * expected.abs().max(1.0)
            || (slope.is_nan() && expected.is_nan())
        {
            return None;
        }
        let usable: Vec<(f64, f64)> = points
            .iter()
            .copied()
            .filter(|&(x, y)| x > 0.0 && y > 0.0 && x.is_finite() && y.is_finite())
            .collect();
        let fit = |xs: &dyn Fn(f64) -> f64, ys: &dyn Fn(f64) -> f64, swap: bool| {
            let (mut sx, mut sy, mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0, 0.0, 0.0);
            let n = usable.len() as f64;
            for &(x, y) in &usable {
                let (x, y) = (xs(x), ys(y));
                sx += x;
                sy += y;
                sxy += x * y;
                sxx += x * x;
                syy += y * y;
            }
            let cov = sxy - sx * sy / n;
            if swap {
                cov / (syy - sy * sy / n)
            } else {
                cov / (sxx - sx * sx / n)
            }
        };
        let near = |a: f64| (slope - a).abs() <= 1e-6 * a.abs().max(1e-3);
        let (first, last) = (usable[0], usable[usable.len() - 1]);
        let mistake = if expected.is_nan() {
            "with fewer than two distinct x no line can be fitted: the slope is NaN".to_string()
        } else if slope.is_nan() {
            "it is NaN: a point a logarithm cannot take (zero, negative or not finite) is left \
             out, not taken in"
                .to_string()
        } else if near(fit(&|x| x, &|y| y, false)) {
            "that is the slope of the points themselves: a power law is a straight line on \
             log-log axes, so fit the logarithms"
                .to_string()
        } else if near(fit(&f64::ln, &f64::ln, true)) {
            "that is the slope of ln x fitted against ln y, the other regression: fit ln y \
             against ln x"
                .to_string()
        } else if near((last.1.ln() - first.1.ln()) / (last.0.ln() - first.0.ln())) {
            "that is the slope between the first and the last point: the least-squares line \
             uses every point"
                .to_string()
        } else {
            format!("the least-squares slope of ln y against ln x is {expected}")
        };
        Some(format!(
            "{mistake}.\n  points {points:?}: your log_log_slope gave {slope}, expected {expected}"
        ))
    }

    fn check_slope(points: &[(f64, f64)], expected: f64) {
        let slope = workbench::test_support::catch_panic(|| log_log_slope(points.iter().copied()))
            .unwrap_or_else(|message| {
                panic!(
                    "log_log_slope: points {points:?} made it panic ({message}): {}",
                    if expected.is_nan() {
                        "with fewer than two distinct x no line can be fitted, and the slope is \
                         NaN"
                    } else {
                        "a point a logarithm cannot take is left out, and the others make the \
                         line"
                    }
                )
            });
        if let Some(mistake) = slope_mistake(points, slope, expected) {
            panic!("log_log_slope: {mistake}");
        }
    }

    #[test]
    fn exercise_log_log_slope_of_exact_power_laws() {
        let points = |k: f64| -> Vec<(f64, f64)> {
            (1..6)
                .map(|i| (f64::from(i), 3.0 * f64::from(i).powf(k)))
                .collect()
        };
        check_slope(&points(-0.5), -0.5);
        check_slope(&points(2.0), 2.0);
    }

    #[test]
    fn exercise_log_log_slope_of_noisy_errors() {
        // Errors of a 1/√n estimator, with noise: the line through all of them, not the ends.
        let points: [(f64, f64); 5] = [
            (4.0, 0.31),
            (16.0, 0.12),
            (64.0, 0.071),
            (256.0, 0.029),
            (1024.0, 0.017),
        ];
        let logs: Vec<(f64, f64)> = points.iter().map(|p| (p.0.ln(), p.1.ln())).collect();
        let n = logs.len() as f64;
        let mx = logs.iter().map(|p| p.0).sum::<f64>() / n;
        let my = logs.iter().map(|p| p.1).sum::<f64>() / n;
        let expected = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum::<f64>()
            / logs.iter().map(|p| (p.0 - mx).powi(2)).sum::<f64>();
        check_slope(&points, expected);
    }

    #[test]
    fn exercise_log_log_slope_leaves_out_what_a_logarithm_cannot_take() {
        let mut points: Vec<(f64, f64)> =
            (1..6).map(|i| (f64::from(i), 1.0 / f64::from(i))).collect();
        points.extend([
            (7.0, 0.0),
            (0.0, 1.0),
            (-2.0, 3.0),
            (f64::INFINITY, 1.0),
            (5.0, f64::NAN),
        ]);
        check_slope(&points, -1.0);
        check_slope(&[(2.0, 1.0)], f64::NAN);
        check_slope(&[(2.0, 1.0), (2.0, 3.0)], f64::NAN);
    }

    /// The records `convergence` should give, worked out here one by one (without the times).
    fn expected_records(
        strategies: &[Strategy],
        counts: &[usize],
        repetitions: usize,
        seed: u64,
    ) -> Vec<(String, u64, f64, f64)> {
        let integrand = x_squared();
        let mut records = Vec::new();
        for strategy in strategies {
            for &n in counts {
                let squared_errors: Vec<f64> = (0..repetitions as u64)
                    .map(|r| {
                        let estimate =
                            strategy.estimate(&integrand, n, &mut repetition_rng(seed, r));
                        (estimate - integrand.value).powi(2)
                    })
                    .collect();
                let mse = squared_errors.iter().sum::<f64>() / repetitions as f64;
                records.push((
                    strategy.name().to_string(),
                    n as u64,
                    mse.sqrt(),
                    mse / integrand.value.powi(2),
                ));
            }
        }
        records
    }

    #[test]
    fn exercise_convergence_measures_every_strategy_and_count() {
        let (counts, repetitions, seed) = ([4, 16, 64], 20, 11);
        let start = Instant::now();
        let records = convergence(&x_squared(), &Strategy::ALL, &counts, repetitions, seed);
        let elapsed = start.elapsed().as_secs_f64();
        let expected = expected_records(&Strategy::ALL, &counts, repetitions, seed);
        let order: Vec<(&str, u64)> = records.iter().map(|r| (&r.technique[..], r.spp)).collect();
        let expected_order: Vec<(&str, u64)> = expected.iter().map(|r| (&r.0[..], r.1)).collect();
        assert!(
            order == expected_order,
            "convergence: the records should come strategy by strategy, each with every count \
             in the order given: {expected_order:?}; yours came as {order:?}"
        );
        let value = x_squared().value;
        for (record, (technique, n, rmse, relmse)) in records.iter().zip(&expected) {
            let near = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs();
            let mistake = if near(record.rmse, *rmse) {
                None
            } else if near(record.rmse, rmse * rmse) {
                Some("that is the mean squared error: the RMSE is its square root".to_string())
            } else if near(
                record.rmse,
                rmse * (repetitions as f64 / (repetitions as f64 - 1.0)).sqrt(),
            ) {
                Some(
                    "the squared errors are divided by repetitions - 1: the errors are measured \
                     against the exact value, not the runs' own mean, so their plain mean is \
                     right"
                        .to_string(),
                )
            } else {
                Some(
                    "each repetition r has its own generator, repetition_rng(seed, r), the \
                     same for every strategy and count; the error is against the integral's \
                     exact value"
                        .to_string(),
                )
            };
            if let Some(mistake) = mistake {
                panic!(
                    "convergence, {technique} with n = {n}: the RMSE is {}, expected {rmse}: \
                     {mistake}",
                    record.rmse
                );
            }
            assert!(
                near(record.relmse, *relmse),
                "convergence, {technique} with n = {n}: relmse is {}, expected {relmse}: the \
                 mean squared error divided by the squared value {value:.4}{}",
                record.relmse,
                if near(record.relmse, rmse / value) {
                    " (yours is the RMSE over the value)"
                } else {
                    ""
                }
            );
            assert!(
                record.seconds > 0.0 && record.seconds.is_finite(),
                "convergence, {technique} with n = {n}: seconds is {}: the mean wall-clock \
                 time of one estimate, measured",
                record.seconds
            );
        }
        let timed: f64 = records.iter().map(|r| r.seconds).sum::<f64>() * repetitions as f64;
        assert!(
            timed <= elapsed * 1.01,
            "convergence: the records' seconds add up to more time than the whole measurement \
             took ({timed:.4} s of {elapsed:.4} s, counting every repetition): seconds is the \
             time of one estimate, the time of all repetitions divided by their number"
        );
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
        let exact = |k: f64| (1..6).map(move |i| (f64::from(i), f64::from(i).powf(k)));
        assert_relative_eq!(log_log_slope(exact(-0.5)), -0.5, max_relative = 1e-12);
    }
}
