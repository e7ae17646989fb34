//! Gauss–Legendre quadrature: `n` nodes and weights on `[-1, 1]` that integrate every
//! polynomial of degree below `2n` exactly. Mitsuba tabulates the rough coating of
//! `roughplastic` with it, so this workbook does too.

/// The `(node, weight)` pairs of the `n`-point rule, nodes ascending; the weights sum to 2.
///
/// The nodes are the roots of the Legendre polynomial `P_n`, found by Newton's method from
/// Tricomi's estimate `cos(π (i + 3/4) / (n + 1/2))`, with `P_n` and its derivative from the
/// three-term recurrence; the weight of a root `x` is `2 / ((1 - x²) P_n'(x)²)`.
pub fn nodes_and_weights(n: usize) -> Vec<(f64, f64)> {
    let mut rule = Vec::with_capacity(n);
    for i in 0..n {
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut derivative = 1.0;
        for _ in 0..100 {
            let (p, dp) = legendre(n, x);
            derivative = dp;
            let step = p / dp;
            x -= step;
            if step.abs() < 1e-16 {
                break;
            }
        }
        let (_, dp) = legendre(n, x);
        if dp.is_finite() {
            derivative = dp;
        }
        rule.push((-x, 2.0 / ((1.0 - x * x) * derivative * derivative)));
    }
    rule
}

/// `(P_n(x), P_n'(x))` by Bonnet's recurrence `(k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1}`.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let (mut previous, mut current) = (1.0, x);
    if n == 0 {
        return (1.0, 0.0);
    }
    for k in 1..n {
        let k = k as f64;
        let next = ((2.0 * k + 1.0) * x * current - k * previous) / (k + 1.0);
        previous = current;
        current = next;
    }
    let derivative = n as f64 * (x * current - previous) / (x * x - 1.0);
    (current, derivative)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `∫_{-1}^{1} x^k dx` is `2 / (k + 1)` for even `k` and 0 for odd: exact up to `2n - 1`.
    #[test]
    fn integrates_polynomials_up_to_degree_2n_minus_1() {
        for n in [1, 2, 5, 32, 128] {
            let rule = nodes_and_weights(n);
            assert!(
                rule.windows(2).all(|w| w[0].0 < w[1].0),
                "n = {n}: not ascending"
            );
            for k in 0..2 * n.min(20) {
                let sum: f64 = rule.iter().map(|&(x, w)| w * x.powi(k as i32)).sum();
                let exact = if k % 2 == 0 {
                    2.0 / (k as f64 + 1.0)
                } else {
                    0.0
                };
                assert!(
                    (sum - exact).abs() < 1e-12,
                    "n = {n}, x^{k}: {sum} vs {exact}"
                );
            }
        }
    }
}
