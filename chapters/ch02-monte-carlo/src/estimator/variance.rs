//! Measuring an estimator's noise: the variance of its estimates over independent runs.
//!
//! Theory says the variance of a Monte Carlo estimate is `σ² / n`. To *see* it, run the
//! estimator many times with independent random numbers and compute the sample variance of
//! the results. Halving the noise should cost four times the samples, and a good importance
//! density should lower `σ²` itself.

use common::sampler::mix;
use rand::SeedableRng;
use rand_pcg::Pcg32;

// ANCHOR: sample_variance
/// The mean and the unbiased sample variance of `values`, in one pass by Welford's method.
///
/// The deviations are taken from the sample's own mean, which sits closer to the values than
/// the true mean does, so the plain mean of their squares comes out too small on average; the
/// unbiased variance makes up for it.
///
/// Why not the textbook shortcut through `Σ x² - n mean²`? It subtracts two huge,
/// nearly equal numbers: for values around `10⁹` with a spread of 10, both terms are about
/// `10¹⁸` and their difference is below the rounding error of either, so the result is
/// garbage (even negative). Welford's method updates the mean and the sum of squared
/// deviations one value at a time, and only ever adds small, positive quantities.
///
/// One value has no spread to measure: its variance is returned as 0 (strictly it is
/// undefined, `0 / 0`). With no values at all both results are `NaN`.
pub fn sample_mean_and_variance(values: &[f64]) -> (f64, f64) {
    // BEGIN SOLUTION
    if values.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let mut mean = 0.0;
    let mut sum_of_squared_deviations = 0.0;
    for (index, &value) in values.iter().enumerate() {
        let deviation = value - mean;
        mean += deviation / (index + 1) as f64;
        // The old deviation times the new one: exactly the growth of M₂.
        sum_of_squared_deviations += deviation * (value - mean);
    }
    let variance = if values.len() < 2 {
        0.0
    } else {
        sum_of_squared_deviations / (values.len() - 1) as f64
    };
    (mean, variance)
    // END SOLUTION
}
// ANCHOR_END: sample_variance

/// The random number generator of repetition number `repetition` of an experiment with
/// `seed`: a PCG32 whose state and stream are both derived from the two numbers.
///
/// Mixing the numbers first makes repetitions 0, 1, 2, ... statistically independent, as if
/// each had a seed of its own, and the whole experiment reproducible from one `seed`.
pub fn repetition_rng(seed: u64, repetition: u64) -> Pcg32 {
    Pcg32::seed_from_u64(mix(seed ^ mix(repetition)))
}

/// Runs `estimator` once per repetition, each time with its own generator from
/// [`repetition_rng`], and returns the `repetitions` estimates.
pub fn repeated_estimates(
    repetitions: usize,
    seed: u64,
    mut estimator: impl FnMut(&mut Pcg32) -> f64,
) -> Vec<f64> {
    (0..repetitions as u64)
        .map(|repetition| estimator(&mut repetition_rng(seed, repetition)))
        .collect()
}

/// The empirical variance of `estimator`'s estimate: the sample variance of
/// [`repeated_estimates`] over `repetitions` independent runs.
///
/// For an estimator with `n` samples it should come out near `σ² / n`. Its own relative
/// error is about `√(2 / repetitions)`: a few hundred repetitions measure it to 10 %.
pub fn estimator_variance(
    repetitions: usize,
    seed: u64,
    estimator: impl FnMut(&mut Pcg32) -> f64,
) -> f64 {
    sample_mean_and_variance(&repeated_estimates(repetitions, seed, estimator)).1
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use rand::Rng;

    /// What is wrong with `(mean, variance)`, an answer for `values` whose mean and unbiased
    /// variance are `expected`, in words; `None` if it is right to `tolerance` (relative).
    fn variance_mistake(
        values: &[f64],
        (mean, variance): (f64, f64),
        expected: (f64, f64),
        tolerance: f64,
    ) -> Option<String> {
        let close = |a: f64, b: f64| (a - b).abs() <= tolerance * b.abs().max(1e-300);
        if close(mean, expected.0) && close(variance, expected.1) {
            return None;
        }
        let n = values.len() as f64;
        let mistake = if !close(mean, expected.0) {
            format!("the mean should be {}", expected.0)
        } else if close(variance, expected.1 * (n - 1.0) / n) {
            "that is the squared deviations divided by n: measured from the sample's own mean \
             they come out too small on average, and dividing by n - 1 makes up for it"
                .to_string()
        } else if variance < 0.0 {
            "a variance is never negative: the formula loses the spread in the rounding of two \
             huge, nearly equal numbers"
                .to_string()
        } else if values.iter().all(|x| x.abs() > 1e6) && (variance - expected.1).abs() < 1e4 {
            "far from zero the formula loses the spread in the rounding: is anything subtracted \
             from something of nearly the same, huge size?"
                .to_string()
        } else {
            format!("the unbiased sample variance is {}", expected.1)
        };
        Some(format!(
            "{mistake}.\n  values {values:?}: your sample_mean_and_variance gave mean {mean}, \
             variance {variance}; expected mean {}, variance {}",
            expected.0, expected.1
        ))
    }

    #[test]
    fn exercise_sample_variance_known_values() {
        // Mean 5; squared deviations 9, 1, 1, 1, 0, 0, 4, 16 sum to 32; 32 / 7.
        let values = [2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0];
        let answer = sample_mean_and_variance(&values);
        if let Some(mistake) = variance_mistake(&values, answer, (5.0, 32.0 / 7.0), 1e-15) {
            panic!("sample_mean_and_variance: {mistake}");
        }
        // Two values: (a - b)² / 2.
        let answer = sample_mean_and_variance(&[1.0, 4.0]);
        if let Some(mistake) = variance_mistake(&[1.0, 4.0], answer, (2.5, 4.5), 1e-15) {
            panic!("sample_mean_and_variance: {mistake}");
        }
    }

    #[test]
    fn exercise_sample_variance_is_stable_far_from_zero() {
        // 10⁹ + {4, 7, 13, 16}: mean 10⁹ + 10, deviations ±3, ±6, variance 90 / 3 = 30.
        let values = [4.0, 7.0, 13.0, 16.0].map(|x| 1e9 + x);
        let answer = sample_mean_and_variance(&values);
        if let Some(mistake) = variance_mistake(&values, answer, (1e9 + 10.0, 30.0), 1e-9) {
            panic!("sample_mean_and_variance: {mistake}");
        }
        // The shortcut formula fails on the same values: the reason for Welford's method.
        let n = values.len() as f64;
        let sum: f64 = values.iter().sum();
        let sum_of_squares: f64 = values.iter().map(|x| x * x).sum();
        let shortcut = (sum_of_squares - sum * sum / n) / (n - 1.0);
        assert!((shortcut - 30.0).abs() > 10.0, "shortcut gave {shortcut}");
    }

    #[test]
    fn exercise_sample_variance_of_one_value_is_zero() {
        for values in [&[7.5][..], &[3.0; 10]] {
            let (mean, variance) =
                workbench::test_support::catch_panic(|| sample_mean_and_variance(values))
                    .unwrap_or_else(|message| {
                        panic!(
                            "sample_mean_and_variance: values {values:?} made it panic \
                             ({message}): they do not spread at all, so the variance is 0"
                        )
                    });
            assert!(
                mean == values[0] && variance == 0.0,
                "sample_mean_and_variance: values {values:?} do not spread at all, so the \
                 variance is 0 (one value: 0 by convention, not 0 / 0); yours gave mean {mean}, \
                 variance {variance}"
            );
        }
    }

    #[test]
    fn exercise_sample_variance_of_nothing_is_nan() {
        let (mean, variance) =
            workbench::test_support::catch_panic(|| sample_mean_and_variance(&[])).unwrap_or_else(
                |message| {
                    panic!(
                        "sample_mean_and_variance: no values made it panic ({message}): no values \
                     have no mean and no variance, and both are NaN"
                    )
                },
            );
        assert!(
            mean.is_nan() && variance.is_nan(),
            "sample_mean_and_variance: no values have no mean and no variance: both are NaN, \
             not mean {mean}, variance {variance}"
        );
    }

    #[test]
    fn repetitions_are_reproducible_and_distinct() {
        let draw = |rng: &mut Pcg32| f64::from(rng.next_u32());
        let first = repeated_estimates(50, 1, draw);
        assert_eq!(first, repeated_estimates(50, 1, draw));
        assert_ne!(first, repeated_estimates(50, 2, draw));
        let mut sorted = first.clone();
        sorted.sort_by(f64::total_cmp);
        sorted.dedup();
        assert_eq!(sorted.len(), 50, "every repetition has its own numbers");
    }

    #[test]
    fn the_variance_of_a_uniform_number_is_one_twelfth() {
        let variance = estimator_variance(20_000, 5, |rng| {
            f64::from(common::sampler::unit_f32(rng.next_u32()))
        });
        // Relative error of a variance from 20 000 values: about sqrt(2 / 20 000) = 1 %.
        assert_relative_eq!(variance, 1.0 / 12.0, max_relative = 0.05);
    }
}
