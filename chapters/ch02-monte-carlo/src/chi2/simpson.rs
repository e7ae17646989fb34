//! Adaptive Simpson's rule, in one dimension and nested into two.
//!
//! Simpson's rule integrates a parabola through three points exactly, and so any cubic; on a
//! smooth integrand its error shrinks like the fifth power of the panel width. The adaptive
//! version spends its points where they are needed: it halves a panel only while the two halves
//! disagree with the whole, which happens near peaks and jumps of the integrand, and nowhere
//! else.

use glam::DVec2;

/// Adaptive Simpson refines every panel at least this many times, so that a feature between
/// the first few nodes (a sliver of the disc in a corner of its bin) is not missed.
const MIN_DEPTH: u32 = 3;
/// ... and at most this many times, where a jump of the density never converges.
const MAX_DEPTH: u32 = 16;

/// `∫∫ f(x, y) dx dy` over the rectangle `[lower, upper]` to within about `tolerance`: an
/// adaptive Simpson's rule over `y` of adaptive Simpson's rules over `x` (as Nori does).
///
/// The inner integrals are asked for `tolerance / height`, so that their errors, summed over
/// the height, stay within the outer tolerance and do not look like structure to the outer
/// rule.
pub(super) fn adaptive_simpson_2d(
    f: &impl Fn(f64, f64) -> f64,
    lower: DVec2,
    upper: DVec2,
    tolerance: f64,
) -> f64 {
    let inner_tolerance = tolerance / (upper.y - lower.y);
    let row = |y: f64| adaptive_simpson(&|x: f64| f(x, y), lower.x, upper.x, inner_tolerance);
    adaptive_simpson(&row, lower.y, upper.y, tolerance)
}

/// A plain composite Simpson's rule with `2^MIN_DEPTH` panels a side (17 x 17 nodes): a rough
/// first estimate of a bin's integral, to set the adaptive rule's tolerance by.
pub(super) fn simpson_2d(f: &impl Fn(f64, f64) -> f64, lower: DVec2, upper: DVec2) -> f64 {
    let panels = 1usize << MIN_DEPTH;
    let nodes = 2 * panels + 1;
    let step = (upper - lower) / (2 * panels) as f64;
    let weight = |i: usize| match i {
        0 => 1.0,
        i if i == nodes - 1 => 1.0,
        i if i % 2 == 1 => 4.0,
        _ => 2.0,
    };
    let mut sum = 0.0;
    for j in 0..nodes {
        for i in 0..nodes {
            let (x, y) = (lower.x + i as f64 * step.x, lower.y + j as f64 * step.y);
            sum += weight(i) * weight(j) * f(x, y);
        }
    }
    sum * step.x * step.y / 9.0
}

/// One panel `[a, b]` of adaptive Simpson's rule: its ends, its middle, the integrand there,
/// and Simpson's estimate `(b - a) / 6 (f(a) + 4 f(m) + f(b))`.
#[derive(Clone, Copy)]
struct Panel {
    a: f64,
    b: f64,
    fa: f64,
    fm: f64,
    fb: f64,
    estimate: f64,
}

impl Panel {
    fn new(a: f64, b: f64, fa: f64, fm: f64, fb: f64) -> Self {
        let estimate = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
        Self {
            a,
            b,
            fa,
            fm,
            fb,
            estimate,
        }
    }
}

/// `∫_a^b f(x) dx` to within about `tolerance`, by adaptive Simpson's rule: split a panel in
/// two, and accept the halves when they agree with the whole.
pub(super) fn adaptive_simpson(f: &impl Fn(f64) -> f64, a: f64, b: f64, tolerance: f64) -> f64 {
    let m = 0.5 * (a + b);
    let whole = Panel::new(a, b, f(a), f(m), f(b));
    refine(f, whole, tolerance, 0)
}

/// Simpson's rule has error `O(h^5)` per panel, so halving the panel divides the error by 16:
/// the difference `left + right - whole` is then about 15 times the error of `left + right`,
/// which gives both the stopping test and the correction term (Richardson extrapolation).
fn refine(f: &impl Fn(f64) -> f64, whole: Panel, tolerance: f64, depth: u32) -> f64 {
    let m = 0.5 * (whole.a + whole.b);
    let (left_middle, right_middle) = (0.5 * (whole.a + m), 0.5 * (m + whole.b));
    let left = Panel::new(whole.a, m, whole.fa, f(left_middle), whole.fm);
    let right = Panel::new(m, whole.b, whole.fm, f(right_middle), whole.fb);
    let difference = left.estimate + right.estimate - whole.estimate;
    // A density that is not finite somewhere never converges: refining it to the deepest level
    // everywhere would take billions of evaluations, and the answer is not a number anyway.
    if depth >= MAX_DEPTH || !difference.is_finite() {
        return left.estimate + right.estimate;
    }
    if depth >= MIN_DEPTH && difference.abs() <= 15.0 * tolerance {
        return left.estimate + right.estimate + difference / 15.0;
    }
    refine(f, left, tolerance / 2.0, depth + 1) + refine(f, right, tolerance / 2.0, depth + 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn a_density_that_is_not_a_number_gives_up_at_once() {
        let calls = std::cell::Cell::new(0u64);
        let nan = |_: f64, _: f64| {
            calls.set(calls.get() + 1);
            f64::NAN
        };
        let integral = adaptive_simpson_2d(&nan, DVec2::ZERO, DVec2::ONE, 1e-9);
        assert!(integral.is_nan());
        // Without the early exit: about 2^16 rows of 2^16 points each.
        assert!(calls.get() < 1000, "{} evaluations", calls.get());
    }

    #[test]
    fn cubics_are_exact() {
        let cubic = |x: f64| 4.0 * x * x * x - x + 2.0;
        // ∫_0^2 = [x⁴ - x²/2 + 2x]_0^2 = 16 - 2 + 4.
        assert_relative_eq!(
            adaptive_simpson(&cubic, 0.0, 2.0, 1e-12),
            18.0,
            epsilon = 1e-12
        );
        let plane = |x: f64, y: f64| x * x * y;
        let (lower, upper) = (DVec2::ZERO, DVec2::new(3.0, 2.0));
        // ∫_0^3 x² dx ∫_0^2 y dy = 9 · 2.
        assert_relative_eq!(simpson_2d(&plane, lower, upper), 18.0, epsilon = 1e-12);
        assert_relative_eq!(
            adaptive_simpson_2d(&plane, lower, upper, 1e-9),
            18.0,
            epsilon = 1e-9
        );
    }

    #[test]
    fn a_narrow_peak_seen_by_one_node_is_resolved() {
        // A Gaussian of width 1e-3 centred on a node of the starting mesh (5/16), which sees
        // it there and nowhere else. (Centred between nodes, it would be missed altogether:
        // adaptive rules only refine what their nodes show them.)
        let width = 1e-3;
        let peak = |x: f64| (-0.5 * ((x - 0.3125) / width).powi(2)).exp();
        let exact = width * (2.0 * std::f64::consts::PI).sqrt();
        assert_relative_eq!(
            adaptive_simpson(&peak, 0.0, 1.0, 1e-9),
            exact,
            max_relative = 1e-5
        );
    }

    #[test]
    fn a_jump_is_integrated_to_the_finest_panel() {
        // The quarter disc's indicator: the jump never converges, and the depth limit bounds
        // the error by about the width of the finest panel.
        let disc = |x: f64, y: f64| if x * x + y * y <= 1.0 { 1.0 } else { 0.0 };
        let area = adaptive_simpson_2d(&disc, DVec2::ZERO, DVec2::ONE, 1e-6);
        assert_relative_eq!(area, std::f64::consts::FRAC_PI_4, epsilon = 1e-4);
    }
}
