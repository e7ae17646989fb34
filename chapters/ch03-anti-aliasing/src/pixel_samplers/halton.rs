//! The Halton sequence: deterministic points that fill the square evenly at every count.
//!
//! Point `i` of the Halton sequence in bases `(2, 3)` mirrors the digits of `i` in each base
//! around the decimal point (the *radical inverse*). Every prefix of the sequence is spread
//! almost as evenly as a grid, without fixing the count in advance as stratification must:
//! its *discrepancy* is `O((log n)^2 / n)`, so the error of a pixel integral with a few edges
//! falls close to `1/n`.
//!
//! Used as is, every pixel would get the same points, and the image would inherit their
//! pattern. A *Cranley–Patterson rotation* shifts the whole point set by a random offset per
//! pixel (modulo 1): the points keep their even spacing on the torus, and neighbouring pixels
//! no longer share a pattern.

use common::sampler::{IndependentSampler, Sampler, mix, unit_f32};
use glam::{UVec2, Vec2};

// ANCHOR: radical_inverse
/// The radical inverse of `index` in `base`: the digits of `index` written in `base`, mirrored
/// around the point, so that the index's last digit becomes the first digit of a fraction in
/// `[0, 1)`. Every `u64` index has one, `u64::MAX` included. What are 1, 2 and 3 in base 2,
/// mirrored?
pub fn radical_inverse(base: u32, index: u64) -> f64 {
    assert!(base >= 2, "a radical inverse needs a base of at least 2");
    // BEGIN SOLUTION
    let base = u64::from(base);
    let inverse_base = 1.0 / base as f64;
    let mut index = index;
    let mut reversed = 0.0f64;
    let mut scale = inverse_base;
    while index > 0 {
        reversed += (index % base) as f64 * scale;
        index /= base;
        scale *= inverse_base;
    }
    reversed
    // END SOLUTION
}
// ANCHOR_END: radical_inverse

// ANCHOR: halton_position
/// The position, in `[0, 1)^2`, of sample `index` of a pixel whose Cranley–Patterson shift is
/// `shift` (in `[0, 1)^2`): point `index` of the Halton sequence in bases 2 (for `x`) and 3
/// (for `y`), moved by `shift` and wrapped around the pixel, as on a torus.
///
/// Which base belongs to which coordinate, and what can the conversion to `f32`, or the shift,
/// do to a value just below 1?
pub fn halton_position(index: u64, shift: Vec2) -> Vec2 {
    // BEGIN SOLUTION
    use super::ONE_MINUS_EPSILON;
    // A value just below 1 in f64 may round to 1.0 in f32: keep it below.
    let to_unit = |v: f64| (v as f32).min(ONE_MINUS_EPSILON);
    let point = Vec2::new(
        to_unit(radical_inverse(2, index)),
        to_unit(radical_inverse(3, index)),
    );
    // Both are in [0, 1), so their sum is below 2 and, if at least 1, loses exactly 1 (exact
    // in f32): the result stays in [0, 1).
    let wrap = |s: f32| if s >= 1.0 { s - 1.0 } else { s };
    Vec2::new(wrap(point.x + shift.x), wrap(point.y + shift.y))
    // END SOLUTION
}
// ANCHOR_END: halton_position

/// Halton points, rotated by a random shift per pixel (Cranley–Patterson).
#[derive(Clone, Debug)]
pub struct HaltonSampler {
    seed: u64,
    index: u64,
    shift: Vec2,
    numbers: IndependentSampler,
}

impl HaltonSampler {
    /// The shift of each pixel is fixed by `seed` and the pixel.
    pub fn new(seed: u64) -> Self {
        Self {
            seed,
            index: 0,
            shift: Vec2::ZERO,
            numbers: IndependentSampler::new(seed),
        }
    }

    /// The Cranley–Patterson shift of `pixel`: a hash of `(seed, pixel)`, the same for every
    /// sample of the pixel (otherwise the points would lose their even spacing).
    pub fn pixel_shift(seed: u64, pixel: UVec2) -> Vec2 {
        let pixel_key = (u64::from(pixel.y) << 32) | u64::from(pixel.x);
        // A different salt from the independent sampler's, so the shift is not correlated
        // with the numbers of the pixel's samples.
        let bits = mix(mix(seed ^ 0x6a09_e667_f3bc_c909) ^ mix(pixel_key));
        Vec2::new(unit_f32(bits as u32), unit_f32((bits >> 32) as u32))
    }
}

impl Sampler for HaltonSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.index = sample_index;
        self.shift = Self::pixel_shift(self.seed, pixel);
        self.numbers.start_pixel_sample(pixel, sample_index);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        halton_position(self.index, self.shift)
    }

    fn get_1d(&mut self) -> f32 {
        self.numbers.get_1d()
    }
}
