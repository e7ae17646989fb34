//! The three facts about `f32` rounding that robust ray tracing is built on.
//!
//! Every `f32` operation (`+`, `-`, `*`, `/`, `sqrt`) returns the exact result rounded to the
//! nearest float, so its relative error is at most [`MACHINE_EPSILON`]. After `n` operations the
//! accumulated relative error is bounded by [`gamma`]`(n)`. And when a value must be moved to be
//! *certainly* on one side of a bound, we step to the neighbouring float with [`next_float_up`] or
//! [`next_float_down`] instead of adding a guessed epsilon.

/// Half the distance from 1 to the next float: the largest relative error of one rounding.
///
/// (Rust's `f32::EPSILON` is the full distance, so this is `f32::EPSILON / 2`, 2^-24.)
pub const MACHINE_EPSILON: f32 = f32::EPSILON * 0.5;

/// A bound on the relative error after `n` roundings: `n ε / (1 - n ε)`.
///
/// Multiplying `n` values that each carry a factor `(1 ± ε)` gives at most `(1 + ε)^n`, and
/// `(1 + ε)^n - 1 <= n ε / (1 - n ε)` (Higham, *Accuracy and Stability of Numerical
/// Algorithms*, lemma 3.1). The intersection routines count their operations and use this to
/// bound how far a computed hit point can be from the true surface.
pub const fn gamma(n: u32) -> f32 {
    let n_epsilon = n as f32 * MACHINE_EPSILON;
    n_epsilon / (1.0 - n_epsilon)
}

/// The smallest float strictly greater than `v` (`+∞` stays `+∞`, `-0` and `0` both step up to
/// the smallest positive float).
///
/// Rounding a result *up* by one step makes it a guaranteed upper bound of the exact value,
/// because the rounding that produced it moved it by at most half a step.
pub fn next_float_up(v: f32) -> f32 {
    v.next_up()
}

/// The largest float strictly less than `v`; the mirror image of [`next_float_up`].
pub fn next_float_down(v: f32) -> f32 {
    v.next_down()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gamma_grows_slightly_faster_than_n_epsilon() {
        assert_eq!(gamma(0), 0.0);
        for n in 1..10 {
            assert!(gamma(n) > n as f32 * MACHINE_EPSILON);
            assert!(gamma(n) < (n as f32 + 0.01) * MACHINE_EPSILON);
        }
    }

    #[test]
    fn next_float_steps_by_exactly_one_float() {
        for v in [1.0f32, -1.0, 1e-30, -3.5e7, 1e5] {
            let up = next_float_up(v);
            let down = next_float_down(v);
            assert!(up > v && down < v);
            // Nothing fits in between: the midpoint rounds back to one of the ends.
            let mid_up = v + (up - v) * 0.5;
            assert!(mid_up == v || mid_up == up);
            assert_eq!(next_float_down(up), v);
            assert_eq!(next_float_up(down), v);
        }
    }

    #[test]
    fn next_float_handles_zero_and_infinity() {
        assert!(next_float_up(-0.0) > 0.0);
        assert!(next_float_up(0.0) > 0.0);
        assert!(next_float_down(0.0) < 0.0);
        assert_eq!(next_float_up(f32::INFINITY), f32::INFINITY);
        assert_eq!(next_float_down(f32::NEG_INFINITY), f32::NEG_INFINITY);
    }
}
