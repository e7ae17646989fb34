//! `∫ pdf dω` to about `10⁻⁶`, although the density jumps to 0 at the horizon, where a fixed
//! grid would err by a part in a thousand.
//!
//! Along `v`, where the jumps cut across, adaptive Simpson's rule: a panel is halved while its
//! two halves disagree with the whole. Across a jump they always disagree, so the panel that
//! holds it is halved down to `2^-MAX_DEPTH`, where what the jump can still hide is
//! negligible; everywhere else the rule stops early. Around the azimuth, where the integral
//! is periodic and only bends, the trapezoid rule, at two resolutions to estimate its error.

/// Every panel is halved at least this often, so that no feature hides between the first
/// few nodes.
const MIN_DEPTH: u32 = 4;
/// ... and at most this often.
const MAX_DEPTH: u32 = 30;

/// `∫_a^b f` to within about `tolerance`.
pub fn simpson(f: &impl Fn(f64) -> f64, a: f64, b: f64, tolerance: f64) -> f64 {
    let (fa, fm, fb) = (f(a), f((a + b) / 2.0), f(b));
    let whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    refine(f, [a, b], [fa, fm, fb], whole, tolerance, 0)
}

fn refine(
    f: &impl Fn(f64) -> f64,
    [a, b]: [f64; 2],
    [fa, fm, fb]: [f64; 3],
    whole: f64,
    tolerance: f64,
    depth: u32,
) -> f64 {
    let m = (a + b) / 2.0;
    let (fl, fr) = (f((a + m) / 2.0), f((m + b) / 2.0));
    let left = (m - a) / 6.0 * (fa + 4.0 * fl + fm);
    let right = (b - m) / 6.0 * (fm + 4.0 * fr + fb);
    let delta = left + right - whole;
    if depth >= MAX_DEPTH || (depth >= MIN_DEPTH && delta.abs() <= 15.0 * tolerance) {
        // Richardson's correction: the halves' error is about a fifteenth of the change.
        return left + right + delta / 15.0;
    }
    let half = tolerance / 2.0;
    refine(f, [a, m], [fa, fl, fm], left, half, depth + 1)
        + refine(f, [m, b], [fm, fr, fb], right, half, depth + 1)
}

/// `∫_0^{2π} g(φ) dφ` of a periodic `g` by the trapezoid rule at `n` and `2n` points, and
/// the difference of the two as the error of the finer.
pub fn around(g: &impl Fn(f64) -> f64, n: usize) -> (f64, f64) {
    let step = std::f64::consts::TAU / (2 * n) as f64;
    let (mut even, mut odd) = (0.0, 0.0);
    for i in 0..2 * n {
        let value = g(i as f64 * step);
        if i % 2 == 0 {
            even += value;
        } else {
            odd += value;
        }
    }
    let coarse = 2.0 * step * even;
    let fine = step * (even + odd);
    (fine, (fine - coarse).abs())
}
