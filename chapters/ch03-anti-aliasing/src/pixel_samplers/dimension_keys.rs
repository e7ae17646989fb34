//! One key per dimension of a pixel's samples: what makes each dimension's order its own.
//!
//! The samplers that place every dimension (stratified, multi-jittered, Sobol) shuffle or
//! scramble each dimension with a key of its own, fixed by the seed, the pixel and the
//! dimension's number within the sample. The same dimension of all the samples of a pixel
//! shares a key, so that together they cover its strata; another dimension or another pixel
//! gets an unrelated one. Counting calls, not numbers: a 2D draw is one dimension of the
//! sampler, as in Mitsuba 3 and pbrt-v4.

use common::sampler::mix;
use glam::UVec2;

/// The keys of the dimensions of the current sample, handed out in the order they are drawn.
#[derive(Clone, Debug)]
pub struct DimensionKeys {
    seed: u64,
    pixel_key: u64,
    next: u64,
}

impl DimensionKeys {
    /// Keys under `seed`; [`DimensionKeys::start`] before each sample.
    pub fn new(seed: u64) -> Self {
        Self {
            seed,
            pixel_key: 0,
            next: 0,
        }
    }

    /// Starts a sample of `pixel`: its next dimension is dimension 0 again.
    pub fn start(&mut self, pixel: UVec2) {
        self.pixel_key = mix((u64::from(pixel.y) << 32) | u64::from(pixel.x));
        self.next = 0;
    }

    /// The key of the next dimension.
    pub fn next_key(&mut self) -> u32 {
        // A salt of its own, so the keys are unrelated to the independent numbers of the same
        // pixel (which hash the same seed and pixel).
        let key = mix(mix(self.seed ^ 0x3c6e_f372_fe94_f82b) ^ self.pixel_key ^ mix(self.next));
        self.next += 1;
        key as u32
    }
}
