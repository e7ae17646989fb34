//! Random positions: the simplest cure for aliasing.
//!
//! A uniform position in the pixel turns the aliasing of a regular pattern into noise: the
//! average over `n` samples is an unbiased estimate of the pixel integral, with a standard
//! deviation that falls as `1/sqrt(n)`.

use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2};

// ANCHOR: random_offset
/// The lecture's `prc = pid + 0.5 + (ξ - 0.5)`: a random offset from the pixel centre, in
/// `[-1/2, 1/2)^2`, added to the centre. Returned relative to the pixel's corner, `[0, 1)^2`.
pub fn random_offset(xi: Vec2) -> Vec2 {
    let centre = Vec2::splat(0.5);
    centre + (xi - 0.5)
}
// ANCHOR_END: random_offset

/// Independent uniform positions in the pixel, from the first two numbers of the sample's
/// stream; later dimensions continue the same stream.
#[derive(Clone, Debug)]
pub struct RandomSampler {
    numbers: IndependentSampler,
}

impl RandomSampler {
    /// Every number fixed by `seed`, the pixel and the sample index.
    pub fn new(seed: u64) -> Self {
        Self {
            numbers: IndependentSampler::new(seed),
        }
    }
}

impl Sampler for RandomSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.numbers.start_pixel_sample(pixel, sample_index);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        // For ξ in [1/4, 1) both steps of `0.5 + (ξ - 0.5)` are exact in f32 (Sterbenz), so
        // ξ just below 1 stays below 1: the sample never lands in the next pixel.
        random_offset(self.numbers.get_2d())
    }

    fn get_1d(&mut self) -> f32 {
        self.numbers.get_1d()
    }
}
