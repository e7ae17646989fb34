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

/// An absolute allowance for rounding near zero, added to error bounds that are otherwise
/// relative: there a rounding or a widening moves by a subnormal float (`2^-149`), not by a
/// fraction of the value, and a few dozen such steps are far below this.
pub const TINY: f32 = f32::MIN_POSITIVE;

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
///
/// The same as [`f32::next_up`], written so that the sign of `v` needs no branch: in interval
/// arithmetic the signs of the values are as good as random, a branch on them is mispredicted
/// half the time, and a misprediction costs more than the whole step. Positive floats are
/// ordered like their bit patterns, negative ones in reverse, so the step is `+1` or `-1` on
/// the bits, with the sign bit choosing which.
#[inline]
pub fn next_float_up(v: f32) -> f32 {
    if v.is_nan() || v == f32::INFINITY {
        return v;
    }
    let bits = v.to_bits();
    if bits & !SIGN_BIT == 0 {
        return f32::from_bits(1); // from either zero to the smallest positive float
    }
    let negative = bits >> 31;
    f32::from_bits(bits.wrapping_add(1).wrapping_sub(negative << 1))
}

/// The largest float strictly less than `v`; the mirror image of [`next_float_up`] (and the
/// same as [`f32::next_down`]).
#[inline]
pub fn next_float_down(v: f32) -> f32 {
    if v.is_nan() || v == f32::NEG_INFINITY {
        return v;
    }
    let bits = v.to_bits();
    if bits & !SIGN_BIT == 0 {
        return -f32::from_bits(1);
    }
    let negative = bits >> 31;
    f32::from_bits(bits.wrapping_sub(1).wrapping_add(negative << 1))
}

/// The sign bit of an `f32`.
const SIGN_BIT: u32 = 1 << 31;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_steps_are_those_of_the_standard_library() {
        let special = [
            0.0f32,
            -0.0,
            f32::MIN_POSITIVE,
            -f32::MIN_POSITIVE,
            f32::from_bits(1),
            -f32::from_bits(1),
            f32::MAX,
            f32::MIN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            1.0,
            -1.0,
        ];
        // Every 65 521st bit pattern (a prime stride) covers all exponents, signs and NaNs.
        let spread = (0..=u32::MAX).step_by(65_521).map(f32::from_bits);
        for v in special.into_iter().chain(spread) {
            let (up, down) = (next_float_up(v), next_float_down(v));
            if v.is_nan() {
                assert!(up.is_nan() && down.is_nan());
            } else {
                assert_eq!(up.to_bits(), v.next_up().to_bits(), "{v:e}");
                assert_eq!(down.to_bits(), v.next_down().to_bits(), "{v:e}");
            }
        }
    }

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
