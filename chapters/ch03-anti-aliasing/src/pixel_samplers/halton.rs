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

use super::ONE_MINUS_EPSILON;

/// The radical inverse of `index` in `base`: its base-`base` digits mirrored around the point,
/// `d0 d1 d2 ...` to `0.d0 d1 d2 ...`. In base 2: 1 to 0.5, 2 to 0.25, 3 to 0.75, 4 to 0.125.
pub fn radical_inverse(base: u32, mut index: u64) -> f64 {
    assert!(base >= 2, "a radical inverse needs a base of at least 2");
    let base = u64::from(base);
    let inverse_base = 1.0 / base as f64;
    let mut reversed = 0.0f64;
    let mut scale = inverse_base;
    while index > 0 {
        reversed += (index % base) as f64 * scale;
        index /= base;
        scale *= inverse_base;
    }
    reversed
}

/// Point `index` of the 2-D Halton sequence (bases 2 and 3), in `[0, 1)^2` as `f32`.
pub fn halton_2d(index: u64) -> Vec2 {
    // A value just below 1 in f64 may round to 1.0 in f32: keep it below.
    let to_unit = |v: f64| (v as f32).min(ONE_MINUS_EPSILON);
    Vec2::new(
        to_unit(radical_inverse(2, index)),
        to_unit(radical_inverse(3, index)),
    )
}

/// Adds `shift` to `p` modulo 1, per coordinate. Both are in `[0, 1)`, so their sum is below
/// 2 and, if at least 1, loses exactly 1 (exact in `f32`): the result stays in `[0, 1)`.
pub fn rotate(p: Vec2, shift: Vec2) -> Vec2 {
    let wrap = |s: f32| if s >= 1.0 { s - 1.0 } else { s };
    Vec2::new(wrap(p.x + shift.x), wrap(p.y + shift.y))
}

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
        rotate(halton_2d(self.index), self.shift)
    }

    fn get_1d(&mut self) -> f32 {
        self.numbers.get_1d()
    }
}
