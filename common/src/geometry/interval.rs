//! Interval arithmetic: let the computer keep track of rounding error.
//!
//! An [`Interval`] is a pair `[lo, hi]` that is guaranteed to contain the exact real value of a
//! computation. Each operation computes its result in ordinary `f32` and then steps the lower
//! end one float down and the upper end one float up: the true result of the operation on any
//! values inside the operands lies inside that widened interval, because `f32` rounding moves
//! a value by at most half a step.
//!
//! The spheres, parallelograms and discs compute their hit distance `t` this way whenever it is close to
//! 0 or otherwise delicate. They accept a hit only if the *whole* interval is positive, so a
//! secondary ray that starts on the surface can never re-hit it at a `t` that is only positive
//! because of rounding. (Most crossings are far from 0; for them, plain floats with an error
//! bound worked out by hand give the same certainty at a fraction of the cost, and the
//! intervals are not computed at all.)

use std::ops::{Add, Div, Mul, Neg, Sub};

use glam::Vec3;

use super::float::{next_float_down, next_float_up};

/// A closed interval `[lo, hi]` of reals, known to contain the exact value of a computation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Interval {
    /// A lower bound of the exact value.
    pub lo: f32,
    /// An upper bound of the exact value.
    pub hi: f32,
}

/// Three intervals: a vector whose exact value is only known to lie in a box.
pub(crate) type IntervalVec3 = [Interval; 3];

impl Interval {
    /// A value known exactly (an input such as a ray origin or a radius).
    #[inline]
    pub fn exact(v: f32) -> Self {
        Self { lo: v, hi: v }
    }

    /// `[lo, hi]` widened by one float on each side, to cover the rounding that produced them.
    #[inline]
    fn widened(lo: f32, hi: f32) -> Self {
        Self {
            lo: next_float_down(lo),
            hi: next_float_up(hi),
        }
    }

    /// The whole real line: what is known about `x / y` when `y` might be zero.
    const EVERYTHING: Self = Self {
        lo: f32::NEG_INFINITY,
        hi: f32::INFINITY,
    };

    /// The best single-float estimate of the exact value.
    #[inline]
    pub fn midpoint(self) -> f32 {
        0.5 * (self.lo + self.hi)
    }

    /// Whether zero lies inside.
    #[inline]
    pub fn contains_zero(self) -> bool {
        self.lo <= 0.0 && self.hi >= 0.0
    }

    /// `x²`, which unlike `x * x` knows that both factors are the same and so is never negative.
    #[inline]
    pub fn squared(self) -> Self {
        let lo_sq = self.lo * self.lo;
        let hi_sq = self.hi * self.hi;
        if self.contains_zero() {
            Self {
                lo: 0.0,
                hi: next_float_up(lo_sq.max(hi_sq)),
            }
        } else {
            Self::widened(lo_sq.min(hi_sq), lo_sq.max(hi_sq))
        }
    }

    /// `√x`, treating any negative part of the interval as zero.
    #[inline]
    pub fn sqrt(self) -> Self {
        Self {
            lo: next_float_down(self.lo.max(0.0).sqrt()).max(0.0),
            hi: next_float_up(self.hi.max(0.0).sqrt()),
        }
    }

    /// `self × a` for an exactly known `a`. The same interval as `self * Interval::exact(a)`,
    /// whose four candidate products are these two, each twice.
    #[inline]
    pub fn scaled(self, a: f32) -> Self {
        let (p, q) = (self.lo * a, self.hi * a);
        Self::widened(f32::INFINITY.min(p).min(q), f32::NEG_INFINITY.max(p).max(q))
    }

    /// The interval of four candidate end points (products or quotients of the ends).
    #[inline]
    fn spanning(candidates: [f32; 4]) -> Self {
        let lo = candidates.iter().copied().fold(f32::INFINITY, f32::min);
        let hi = candidates.iter().copied().fold(f32::NEG_INFINITY, f32::max);
        Self::widened(lo, hi)
    }
}

impl Add for Interval {
    type Output = Self;
    #[inline]
    fn add(self, rhs: Self) -> Self {
        Self::widened(self.lo + rhs.lo, self.hi + rhs.hi)
    }
}

impl Sub for Interval {
    type Output = Self;
    #[inline]
    fn sub(self, rhs: Self) -> Self {
        Self::widened(self.lo - rhs.hi, self.hi - rhs.lo)
    }
}

impl Neg for Interval {
    type Output = Self;
    /// Negation is exact, so no widening.
    #[inline]
    fn neg(self) -> Self {
        Self {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Self;
    #[inline]
    fn mul(self, rhs: Self) -> Self {
        Self::spanning([
            self.lo * rhs.lo,
            self.lo * rhs.hi,
            self.hi * rhs.lo,
            self.hi * rhs.hi,
        ])
    }
}

impl Div for Interval {
    type Output = Self;
    #[inline]
    fn div(self, rhs: Self) -> Self {
        if rhs.contains_zero() {
            return Self::EVERYTHING;
        }
        Self::spanning([
            self.lo / rhs.lo,
            self.lo / rhs.hi,
            self.hi / rhs.lo,
            self.hi / rhs.hi,
        ])
    }
}

/// The exact vector `v`.
#[inline]
pub(crate) fn exact_vec(v: Vec3) -> IntervalVec3 {
    // Written out rather than `to_array().map(..)`, which the optimiser does not always unroll
    // on this hot path (the same below).
    [
        Interval::exact(v.x),
        Interval::exact(v.y),
        Interval::exact(v.z),
    ]
}

/// `a - b` for exactly known `a` and `b`, with the rounding of the subtraction accounted for.
#[inline]
pub(crate) fn difference(a: Vec3, b: Vec3) -> IntervalVec3 {
    [
        Interval::exact(a.x) - Interval::exact(b.x),
        Interval::exact(a.y) - Interval::exact(b.y),
        Interval::exact(a.z) - Interval::exact(b.z),
    ]
}

/// The dot product of two interval vectors.
#[inline]
pub(crate) fn dot(a: IntervalVec3, b: IntervalVec3) -> Interval {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The cross product of two interval vectors.
/// The dot product of an exactly known vector with an interval vector: the same result as
/// [`dot`] with [`exact_vec`]`(a)`, in half the products.
#[inline]
pub(crate) fn dot_exact(a: Vec3, b: IntervalVec3) -> Interval {
    b[0].scaled(a.x) + b[1].scaled(a.y) + b[2].scaled(a.z)
}

#[inline]
pub(crate) fn cross(a: IntervalVec3, b: IntervalVec3) -> IntervalVec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The squared length of an interval vector.
#[inline]
pub(crate) fn length_squared(a: IntervalVec3) -> Interval {
    a[0].squared() + a[1].squared() + a[2].squared()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contains(interval: Interval, exact: f64) -> bool {
        interval.lo as f64 <= exact && exact <= interval.hi as f64
    }

    #[test]
    fn every_operation_contains_the_exact_result() {
        // 0.1 and 0.2 are not representable, so every operation on them rounds; f64 is
        // accurate enough to stand in for the exact result.
        let values = [0.1f32, -0.2, 3.0, 1e-7, -1e5, 7.25];
        for &x in &values {
            for &y in &values {
                let (ix, iy) = (Interval::exact(x), Interval::exact(y));
                let (fx, fy) = (x as f64, y as f64);
                assert!(contains(ix + iy, fx + fy));
                assert!(contains(ix - iy, fx - fy));
                assert!(contains(ix * iy, fx * fy));
                assert!(contains(ix / iy, fx / fy));
                assert!(contains(ix.squared(), fx * fx));
            }
            assert!(contains(
                Interval::exact(x.abs()).sqrt(),
                (x.abs() as f64).sqrt()
            ));
        }
    }

    #[test]
    fn products_with_exact_values_are_the_general_ones() {
        let values = [
            0.1f32,
            -0.2,
            3.0,
            1e-7,
            -1e5,
            0.0,
            -0.0,
            f32::INFINITY,
            f32::NAN,
        ];
        for &a in &values {
            for &lo in &values {
                for &hi in &values {
                    let x = Interval { lo, hi };
                    let general = Interval::exact(a) * x;
                    let scaled = x.scaled(a);
                    assert_eq!(scaled.lo.to_bits(), general.lo.to_bits(), "{a} {x:?}");
                    assert_eq!(scaled.hi.to_bits(), general.hi.to_bits(), "{a} {x:?}");
                    assert_eq!((x * Interval::exact(a)).lo.to_bits(), general.lo.to_bits());
                }
            }
        }
        let v = Vec3::new(0.3, -2.0, 7.0);
        let w = difference(Vec3::new(1.0, 0.5, -3.0), Vec3::new(0.25, 1e-3, 2.0));
        assert_eq!(dot_exact(v, w), dot(exact_vec(v), w));
    }

    #[test]
    fn squares_are_never_negative_and_division_by_maybe_zero_knows_nothing() {
        let straddling = Interval { lo: -1.0, hi: 2.0 };
        assert_eq!(straddling.squared().lo, 0.0);
        assert!((straddling * straddling).lo < 0.0);
        let quotient = Interval::exact(1.0) / straddling;
        assert_eq!(quotient.lo, f32::NEG_INFINITY);
        assert_eq!(quotient.hi, f32::INFINITY);
    }
}
