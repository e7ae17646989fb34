//! Handing out the random numbers of one sample, dimension by dimension.
//!
//! Every random decision of a sample draws from the same stream in a fixed order, as in
//! pbrt-v4: first the position inside the pixel, then the shutter time, then the lens, then
//! the numbers of each bounce. A feature the scene does not use asks for nothing, so a pinhole
//! camera draws no lens numbers and a static scene no time.
//!
//! The stream of a sample depends only on `(seed, pixel, sample index)`. Tiles can therefore
//! be rendered by any thread in any order and the image comes out the same, bit for bit.

// ANCHOR: sampler_trait
use glam::{UVec2, Vec2};
use rand::Rng;
use rand_pcg::Pcg32;

/// A source of sample dimensions for one pixel sample at a time.
///
/// `start_pixel_sample` must be called before each sample; it resets the dimension counter.
/// Implementations differ in *where* the pixel position lands (chapter 01 uses the pixel
/// centre, chapter 03 jitters and stratifies it) and in how the other dimensions spread over
/// a pixel's samples (independent, or stratified like the pixel position: chapter 03); each
/// number is uniform in `[0, 1)`.
pub trait Sampler: Clone + Send + Sync {
    /// Starts sample number `sample_index` of `pixel`.
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64);

    /// The position of the sample inside its pixel, in `[0, 1)^2`. Always the first dimension.
    fn get_pixel_2d(&mut self) -> Vec2;

    /// The next dimension: a number in `[0, 1)`.
    fn get_1d(&mut self) -> f32;

    /// The next dimension as a point of the unit square. By default two 1D draws; a sampler
    /// that places its 2D points jointly (a grid of strata, a 2D sequence) says so here, and
    /// a sampler that wraps another must hand this call on as it is, or the pairs would lose
    /// their joint placement.
    fn get_2d(&mut self) -> Vec2 {
        let x = self.get_1d();
        let y = self.get_1d();
        Vec2::new(x, y)
    }
}
// ANCHOR_END: sampler_trait

/// Independent uniform numbers from a PCG generator seeded by `(seed, pixel, sample index)`.
///
/// The pixel position it hands out is uniform over the pixel too; chapters that place pixel
/// samples differently wrap it and override [`Sampler::get_pixel_2d`].
#[derive(Clone, Debug)]
pub struct IndependentSampler {
    seed: u64,
    rng: Pcg32,
}

impl IndependentSampler {
    /// A sampler whose every number is fixed by `seed` and the sample it belongs to.
    pub fn new(seed: u64) -> Self {
        Self {
            seed,
            rng: Pcg32::new(seed, 0),
        }
    }
}

impl Sampler for IndependentSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        let pixel_key = (u64::from(pixel.y) << 32) | u64::from(pixel.x);
        let state = mix(mix(self.seed ^ mix(pixel_key)) ^ sample_index);
        // The stream selects one of PCG's 2^63 independent sequences; keying it by the pixel
        // as well keeps neighbouring pixels from sharing a sequence at shifted positions.
        self.rng = Pcg32::new(state, mix(pixel_key ^ 0x9e37_79b9_7f4a_7c15));
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        self.get_2d()
    }

    fn get_1d(&mut self) -> f32 {
        unit_f32(self.rng.next_u32())
    }
}

/// Maps 32 random bits to a float in `[0, 1)`.
///
/// Only the top 24 bits are used: every such value is exactly representable as an `f32`, so
/// the result can never round up to 1.0 (a value of 1 would put a pixel sample into the next
/// pixel, or a disc sample onto its rim).
pub fn unit_f32(bits: u32) -> f32 {
    (bits >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
}

/// SplitMix64's finaliser: a cheap bijective mixing of 64 bits, so that nearby keys (pixel 3
/// and pixel 4, sample 0 and sample 1) give unrelated generator states.
pub fn mix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn first_numbers(sampler: &mut IndependentSampler, pixel: UVec2, index: u64) -> Vec<f32> {
        sampler.start_pixel_sample(pixel, index);
        (0..8).map(|_| sampler.get_1d()).collect()
    }

    #[test]
    fn same_pixel_and_index_give_the_same_numbers() {
        let mut a = IndependentSampler::new(7);
        let mut b = IndependentSampler::new(7);
        // Draw something else in between: the stream must depend on the key only.
        b.start_pixel_sample(UVec2::new(1, 1), 3);
        b.get_2d();
        let pixel = UVec2::new(5, 9);
        assert_eq!(
            first_numbers(&mut a, pixel, 11),
            first_numbers(&mut b, pixel, 11)
        );
    }

    #[test]
    fn pixels_indices_and_seeds_give_different_numbers() {
        let mut s = IndependentSampler::new(7);
        let base = first_numbers(&mut s, UVec2::new(5, 9), 11);
        assert_ne!(base, first_numbers(&mut s, UVec2::new(6, 9), 11));
        assert_ne!(base, first_numbers(&mut s, UVec2::new(5, 10), 11));
        assert_ne!(base, first_numbers(&mut s, UVec2::new(9, 5), 11));
        assert_ne!(base, first_numbers(&mut s, UVec2::new(5, 9), 12));
        let mut other_seed = IndependentSampler::new(8);
        assert_ne!(base, first_numbers(&mut other_seed, UVec2::new(5, 9), 11));
    }

    #[test]
    fn unit_f32_stays_below_one() {
        assert_eq!(unit_f32(0), 0.0);
        assert!(unit_f32(u32::MAX) < 1.0);
        assert_eq!(unit_f32(u32::MAX), 1.0 - 1.0 / 16_777_216.0);
    }

    #[test]
    fn numbers_are_uniform_enough() {
        // Mean of n uniforms is 1/2 with standard deviation sqrt(1/12/n); allow 5 sigma.
        let mut s = IndependentSampler::new(1);
        let n = 100_000;
        let mut sum = 0.0f64;
        for i in 0..n {
            s.start_pixel_sample(UVec2::new(i as u32 % 317, i as u32 / 317), i);
            sum += f64::from(s.get_1d());
        }
        let mean = sum / n as f64;
        let sigma = (1.0 / 12.0 / n as f64).sqrt();
        assert!((mean - 0.5).abs() < 5.0 * sigma, "mean {mean}");
    }
}
