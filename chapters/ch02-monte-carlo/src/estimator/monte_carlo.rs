//! The Monte Carlo estimator itself, in its two forms.
//!
//! To integrate `f` over a domain `D`, draw points `x_1, ..., x_n` independently with a
//! density `p` and average `f(x_i) / p(x_i)`:
//!
//! ```text
//! I = ∫_D f(x) dx  ≈  F_n = (1/n) Σ f(x_i) / p(x_i).
//! ```
//!
//! **Why it is right (unbiased).** One term has expectation
//! `E[f(X) / p(X)] = ∫ (f(x) / p(x)) p(x) dx = ∫ f(x) dx = I`: the density we sample with
//! cancels the density we divide by. The mean of `n` terms has the same expectation, for
//! every `n`, so `E[F_n] = I`. This needs `p(x) > 0` wherever `f(x) ≠ 0`: where `p` is zero
//! no point is ever drawn, and that part of the integral is silently missed.
//!
//! **Why it converges.** The terms are independent, so the variance of their mean is
//! `Var[F_n] = σ² / n` with `σ² = Var[f(X) / p(X)]`: the error, a standard deviation, falls as
//! `σ / √n`. Four times the samples for half the noise, in any dimension.
//!
//! **How to do better.** Lower `σ²`. Choosing `p` similar in shape to `f` makes `f / p` nearly
//! constant (*importance sampling*); if `p` is exactly proportional to `f` every term equals
//! `I` and the variance is zero. Uniform sampling is the special case `p = 1 / |D|`, where the
//! estimator becomes `|D|` times the average of `f`.

// ANCHOR: estimate
/// The lecture's estimator of `∫ f`: `n` points, each a fresh one from `sample`, whose density
/// is `pdf`; each point's share of the estimate is weighted by how likely it was to be drawn.
///
/// `pdf` must be the density that `sample` actually draws from: any other function biases the
/// result. A point whose density is 0 (it can only appear through rounding at the edge of a
/// domain, where `f` vanishes too in our integrands) contributes 0 rather than `0 / 0`.
///
/// With `n = 0` there is nothing to average, and the estimate is `NaN`.
pub fn estimate<X: Copy>(
    n: usize,
    sample: &mut impl FnMut() -> X,
    f: impl Fn(X) -> f64,
    pdf: impl Fn(X) -> f64,
) -> f64 {
    // BEGIN SOLUTION
    let mut sum = 0.0;
    for _ in 0..n {
        let x = sample();
        let density = pdf(x);
        if density > 0.0 {
            sum += f(x) / density;
        }
    }
    sum / n as f64
    // END SOLUTION
}
// ANCHOR_END: estimate

/// The uniform estimator `(|D| / n) Σ f(x_i)`, with `x_i` uniform points of a domain of
/// measure `|D|` = `domain_measure` (its length, area or solid angle).
///
/// It is [`estimate`] with the constant density `p = 1 / |D|`, written the way it is usually
/// first met: the average value of `f` times the size of the domain.
///
/// With `n = 0` the estimate is `NaN`.
pub fn estimate_uniform<X: Copy>(
    domain_measure: f64,
    n: usize,
    mut sample: impl FnMut() -> X,
    f: impl Fn(X) -> f64,
) -> f64 {
    let mut sum = 0.0;
    for _ in 0..n {
        sum += f(sample());
    }
    domain_measure * sum / n as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    /// The points `0.05, 0.15, ..., 0.95` of `[0, 1]`, in order: a deterministic stand-in for
    /// random points, so the sums can be checked by hand.
    fn midpoints(n: usize) -> impl FnMut() -> f64 {
        let mut i = 0;
        move || {
            i += 1;
            (i as f64 - 0.5) / n as f64
        }
    }

    /// Runs `estimate` on the points `xs` with `f` and `pdf`, and fails, naming the mistake, if
    /// it is not the lecture's estimator.
    fn check_estimate(xs: &[f64], f: impl Fn(f64) -> f64, pdf: impl Fn(f64) -> f64, case: &str) {
        let mut points = xs.iter().copied();
        let mut drawn = 0;
        let value = estimate(
            xs.len(),
            &mut || {
                drawn += 1;
                points.next().unwrap_or(f64::NAN)
            },
            &f,
            &pdf,
        );
        let n = xs.len() as f64;
        let terms = |g: &dyn Fn(f64) -> f64| -> f64 {
            xs.iter()
                .filter(|&&x| pdf(x) > 0.0)
                .map(|&x| g(x))
                .sum::<f64>()
        };
        let sum = terms(&|x| f(x) / pdf(x));
        let expected = sum / n;
        let near = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs().max(1e-300);
        if drawn != xs.len() {
            panic!(
                "estimate ({case}): it drew {drawn} points where n = {}: one fresh point per \
                 term, n terms",
                xs.len()
            );
        }
        if near(value, expected) {
            return;
        }
        let mistake = if value.is_nan() && xs.iter().any(|&x| pdf(x) == 0.0) {
            "it is NaN: a point of density 0 gives 0 / 0; such a point contributes nothing"
                .to_string()
        } else if near(value, terms(&f) / n) {
            "each f(x) is averaged as it is, without dividing by its density: that is only \
             right for the uniform density 1 on a domain of size 1. A point that was likely to \
             be drawn must count for less"
                .to_string()
        } else if near(value, terms(&|x| f(x) * pdf(x)) / n) {
            "each f(x) is multiplied by its density, where it must be divided by it".to_string()
        } else if near(value, sum) {
            "that is the sum of the terms, not their mean".to_string()
        } else if near(value, sum / (n - 1.0)) || near(value, sum / (n + 1.0)) {
            "the sum of the terms is divided by the wrong count: the estimate is their mean"
                .to_string()
        } else {
            format!("the mean of f(x_i) / p(x_i) here is {expected}")
        };
        panic!("estimate ({case}): {mistake}.\n  Your estimate gave {value}, expected {expected}");
    }

    #[test]
    fn exercise_estimate_integrates_a_constant_exactly() {
        let points: Vec<f64> = std::iter::repeat_with(midpoints(7)).take(7).collect();
        check_estimate(
            &points,
            |_| 4.0,
            |_| 1.0 / 2.5,
            "f = 4 on a domain of size 2.5",
        );
        assert_relative_eq!(estimate(7, &mut midpoints(7), |_| 4.0, |_| 1.0 / 2.5), 10.0);
    }

    #[test]
    fn exercise_estimate_divides_each_term_by_its_own_density() {
        // Two points with densities 1/2 and 2: terms 2 * 3 = 6 and 5 / 2 = 2.5, mean 4.25.
        check_estimate(
            &[0.0, 1.0],
            |x| if x == 0.0 { 3.0 } else { 5.0 },
            |x| if x == 0.0 { 0.5 } else { 2.0 },
            "two points of densities 1/2 and 2",
        );
        let f = |x: f64| x * x + 1.0;
        let points: Vec<f64> = std::iter::repeat_with(midpoints(10)).take(10).collect();
        check_estimate(&points, f, |x| 0.5 + x, "a density that grows with x");
    }

    #[test]
    fn exercise_estimate_of_points_of_zero_density() {
        check_estimate(&[0.0, 1.0, 0.5], |x| x, |x| x, "a point of density 0");
    }

    #[test]
    fn exercise_estimate_of_no_samples_is_nan() {
        let value = workbench::test_support::catch_panic(|| {
            estimate(0, &mut || 0.0, |x| x, |_| 1.0)
        })
        .unwrap_or_else(|message| {
            panic!(
                "estimate: with n = 0 it panicked ({message}): there is nothing to average, \
                     and the estimate is NaN"
            )
        });
        assert!(
            value.is_nan(),
            "estimate: with n = 0 there is nothing to average, and the estimate is NaN, not \
             {value}"
        );
    }

    #[test]
    fn the_uniform_form_is_the_general_form_with_a_constant_density() {
        let f = |x: f64| x * x + 1.0;
        let uniform = estimate_uniform(3.0, 10, midpoints(10), f);
        let general = estimate(10, &mut midpoints(10), f, |_| 1.0 / 3.0);
        assert_relative_eq!(uniform, general, max_relative = 1e-14);
        // The midpoint rule's value for ∫ (x² + 1) dx over [0, 1], times 3.
        assert_relative_eq!(
            uniform,
            3.0 * (1.0 + 1.0 / 3.0 - 0.1 * 0.1 / 12.0),
            max_relative = 1e-12
        );
        assert!(estimate_uniform(1.0, 0, || 0.0, |x| x).is_nan());
    }
}
