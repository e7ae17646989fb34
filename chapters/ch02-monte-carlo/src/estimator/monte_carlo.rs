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
/// The general (importance-sampling) estimator `(1/n) Σ f(x_i) / p(x_i)`, with each `x_i` a
/// fresh point from `sample` and `pdf` its density.
///
/// `pdf` must be the density that `sample` actually draws from: any other function biases the
/// result. A point whose density is 0 (it can only appear through rounding at the edge of a
/// domain, where `f` vanishes too in our integrands) contributes 0 rather than `0 / 0`.
///
/// With `n = 0` there is nothing to average, and the estimate is `NaN`.
pub fn estimate<X: Copy>(
    n: usize,
    mut sample: impl FnMut() -> X,
    f: impl Fn(X) -> f64,
    pdf: impl Fn(X) -> f64,
) -> f64 {
    let mut sum = 0.0;
    for _ in 0..n {
        let x = sample();
        let density = pdf(x);
        if density > 0.0 {
            sum += f(x) / density;
        }
    }
    sum / n as f64
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

    #[test]
    fn a_constant_is_integrated_exactly() {
        assert_relative_eq!(estimate_uniform(2.5, 7, midpoints(7), |_| 4.0), 10.0);
        assert_relative_eq!(estimate(7, midpoints(7), |_| 4.0, |_| 1.0 / 2.5), 10.0);
    }

    #[test]
    fn the_uniform_form_is_the_general_form_with_a_constant_density() {
        let f = |x: f64| x * x + 1.0;
        let uniform = estimate_uniform(3.0, 10, midpoints(10), f);
        let general = estimate(10, midpoints(10), f, |_| 1.0 / 3.0);
        assert_relative_eq!(uniform, general, max_relative = 1e-14);
        // The midpoint rule's value for ∫ (x² + 1) dx over [0, 1], times 3.
        assert_relative_eq!(
            uniform,
            3.0 * (1.0 + 1.0 / 3.0 - 0.1 * 0.1 / 12.0),
            max_relative = 1e-12
        );
    }

    #[test]
    fn each_term_is_divided_by_its_own_density() {
        // Two points with densities 1/2 and 2: terms 2 * 3 = 6 and 5 / 2 = 2.5, mean 4.25.
        let mut points = [0.0, 1.0].into_iter();
        let value = estimate(
            2,
            || points.next().unwrap(),
            |x| if x == 0.0 { 3.0 } else { 5.0 },
            |x| if x == 0.0 { 0.5 } else { 2.0 },
        );
        assert_eq!(value, 4.25);
    }

    #[test]
    fn points_of_zero_density_contribute_nothing() {
        let mut points = [0.0, 1.0].into_iter();
        let value = estimate(2, || points.next().unwrap(), |x| x, |x| x);
        assert_eq!(value, 0.5);
    }

    #[test]
    fn no_samples_give_nan() {
        assert!(estimate(0, || 0.0, |x| x, |_| 1.0).is_nan());
        assert!(estimate_uniform(1.0, 0, || 0.0, |x| x).is_nan());
    }
}
