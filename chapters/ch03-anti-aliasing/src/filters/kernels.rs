//! The filters' one-dimensional profiles. Each 2-D filter of the chapter is separable,
//! `f(x, y) = f(x) f(y)`, as in pbrt and Mitsuba.

// ANCHOR: box_filter
/// The box: 1 on `[-radius, radius)`, 0 outside. Half-open, as pixel `(i, j)` covers
/// `[i, i+1) x [j, j+1)`: with radius 1/2, a sample on the border of two pixels counts for one
/// of them, not for both.
pub fn box_1d(x: f32, radius: f32) -> f32 {
    if -radius <= x && x < radius { 1.0 } else { 0.0 }
}
// ANCHOR_END: box_filter

// ANCHOR: tent_filter
/// The tent (triangle): 1 at the centre, falling linearly to 0 at `radius`, 0 beyond.
pub fn tent_1d(x: f32, radius: f32) -> f32 {
    // BEGIN SOLUTION
    (1.0 - x.abs() / radius).max(0.0)
    // END SOLUTION
}
// ANCHOR_END: tent_filter

// ANCHOR: gaussian_filter
/// A Gaussian of standard deviation `stddev`, lowered by its own value at `radius` so that
/// it reaches 0 there instead of jumping (Mitsuba 3's and pbrt's choice).
pub fn gaussian_1d(x: f32, stddev: f32, radius: f32) -> f32 {
    let gaussian = |x: f32| (-x * x / (2.0 * stddev * stddev)).exp();
    (gaussian(x) - gaussian(radius)).max(0.0)
}
// ANCHOR_END: gaussian_filter

// ANCHOR: mitchell
/// The Mitchell–Netravali cubic of parameters `b` and `c` at `x`, with support `[-2, 2]`.
///
/// Two cubic pieces, `|x| < 1` and `1 <= |x| < 2`, joined so the curve and its slope are
/// continuous. `b = c = 1/3` is the authors' recommended compromise between blurring (large
/// `b`) and ringing (large `c`); between 1 and 2 the curve dips below zero, which sharpens.
pub fn mitchell_1d(x: f32, b: f32, c: f32) -> f32 {
    // BEGIN SOLUTION
    let x = x.abs();
    let (x2, x3) = (x * x, x * x * x);
    if x < 1.0 {
        ((12.0 - 9.0 * b - 6.0 * c) * x3 + (-18.0 + 12.0 * b + 6.0 * c) * x2 + (6.0 - 2.0 * b))
            / 6.0
    } else if x < 2.0 {
        ((-b - 6.0 * c) * x3
            + (6.0 * b + 30.0 * c) * x2
            + (-12.0 * b - 48.0 * c) * x
            + (8.0 * b + 24.0 * c))
            / 6.0
    } else {
        0.0
    }
    // END SOLUTION
}
// ANCHOR_END: mitchell
