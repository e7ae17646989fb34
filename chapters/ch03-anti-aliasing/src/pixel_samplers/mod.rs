//! Where in its pixel each sample looks: the four strategies of the chapter.
//!
//! A pixel is not a point but a small square, and its value is the integral of the image over
//! that square (weighted by a filter, see [`crate::filters`]). Chapter 01 evaluated the image
//! at the centre only; here the samples spread over the square:
//!
//! | kind | position of sample `i` | error |
//! |---|---|---|
//! | [`Centre`](PixelSamplerKind::Centre) | the centre, always (chapter 01) | aliasing: does not shrink with more samples |
//! | [`Random`](PixelSamplerKind::Random) | uniform in the pixel | noise, `O(n^-1/2)` |
//! | [`Stratified`](PixelSamplerKind::Stratified) | uniform in stratum `i` of an `x` by `y` grid | less noise at edges, `O(n^-3/4)` |
//! | [`Halton`](PixelSamplerKind::Halton) | point `i` of the Halton sequence (bases 2, 3), shifted per pixel | low discrepancy, close to `O(n^-1)` at edges |
//!
//! Only the *pixel position* differs. Every other dimension a sample asks for (`get_1d`: the
//! lens in chapter 04, the time in chapter 05, ...) comes from chapter 01's
//! `IndependentSampler` keyed by `(seed, pixel, sample index)`, so an image does not depend
//! on the number of threads, and the strategies can be compared fairly. The pixel position is
//! always the first dimension drawn.

mod halton;
mod random;
mod stratified;

pub use halton::{HaltonSampler, halton_position, radical_inverse};
pub use random::{RandomSampler, random_offset};
pub use stratified::{StratifiedSampler, jittered, strata_grid};

use ch01_whitted::pixel::CentreSampler;
use common::sampler::Sampler;
use glam::{UVec2, Vec2};

/// The largest `f32` below 1. A position computed as `(k + ξ) / n` can round up to exactly 1 in
/// `f32` even though it is below 1 in exact arithmetic; 1 would put the sample in the next
/// pixel, so such positions are kept at this value instead (pbrt-v4's `OneMinusEpsilon`).
pub const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

/// The command-line names of the strategies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum PixelSamplerKind {
    /// Every sample at the pixel centre (chapter 01): aliasing that more samples cannot fix.
    Centre,
    /// Independent uniform positions in the pixel.
    Random,
    /// Jittered: one uniform position in each cell of a grid of `spp` cells.
    Stratified,
    /// The Halton sequence in bases 2 and 3, rotated by a random shift per pixel.
    Halton,
}

impl PixelSamplerKind {
    /// Every strategy, in the order of the enum.
    pub const ALL: [PixelSamplerKind; 4] = [
        PixelSamplerKind::Centre,
        PixelSamplerKind::Random,
        PixelSamplerKind::Stratified,
        PixelSamplerKind::Halton,
    ];

    /// The name used on the command line and in figures.
    pub fn name(self) -> &'static str {
        match self {
            PixelSamplerKind::Centre => "centre",
            PixelSamplerKind::Random => "random",
            PixelSamplerKind::Stratified => "stratified",
            PixelSamplerKind::Halton => "halton",
        }
    }
}

/// One of the four strategies, as a single type implementing [`Sampler`].
///
/// [`Sampler`] is `Clone`, hence not object-safe: a `Box<dyn Sampler>` cannot exist, so the
/// choice made on the command line is carried by this enum, which delegates every call.
#[derive(Clone, Debug)]
pub enum PixelSampler {
    /// See [`PixelSamplerKind::Centre`].
    Centre(CentreSampler),
    /// See [`PixelSamplerKind::Random`].
    Random(RandomSampler),
    /// See [`PixelSamplerKind::Stratified`].
    Stratified(StratifiedSampler),
    /// See [`PixelSamplerKind::Halton`].
    Halton(HaltonSampler),
}

impl PixelSampler {
    /// The strategy `kind` for `spp` samples per pixel, every random number fixed by `seed`.
    ///
    /// Only the stratified sampler uses `spp` (to lay out its grid); the others accept any
    /// number of samples. Errors: `spp == 0`, or a count too large for a grid of strata.
    pub fn new(kind: PixelSamplerKind, spp: u64, seed: u64) -> Result<Self, String> {
        if spp == 0 {
            return Err("a pixel needs at least one sample, got spp 0".to_string());
        }
        Ok(match kind {
            PixelSamplerKind::Centre => PixelSampler::Centre(CentreSampler::new(seed)),
            PixelSamplerKind::Random => PixelSampler::Random(RandomSampler::new(seed)),
            PixelSamplerKind::Stratified => {
                PixelSampler::Stratified(StratifiedSampler::new(spp, seed)?)
            }
            PixelSamplerKind::Halton => PixelSampler::Halton(HaltonSampler::new(seed)),
        })
    }

    /// Which strategy this is.
    pub fn kind(&self) -> PixelSamplerKind {
        match self {
            PixelSampler::Centre(_) => PixelSamplerKind::Centre,
            PixelSampler::Random(_) => PixelSamplerKind::Random,
            PixelSampler::Stratified(_) => PixelSamplerKind::Stratified,
            PixelSampler::Halton(_) => PixelSamplerKind::Halton,
        }
    }

    /// The positions of samples `0..spp` of `pixel`, in `[0, 1)^2`: for plots and tests.
    pub fn positions(&mut self, pixel: UVec2, spp: u64) -> Vec<Vec2> {
        (0..spp)
            .map(|index| {
                self.start_pixel_sample(pixel, index);
                self.get_pixel_2d()
            })
            .collect()
    }
}

impl Sampler for PixelSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        match self {
            PixelSampler::Centre(s) => s.start_pixel_sample(pixel, sample_index),
            PixelSampler::Random(s) => s.start_pixel_sample(pixel, sample_index),
            PixelSampler::Stratified(s) => s.start_pixel_sample(pixel, sample_index),
            PixelSampler::Halton(s) => s.start_pixel_sample(pixel, sample_index),
        }
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        match self {
            PixelSampler::Centre(s) => s.get_pixel_2d(),
            PixelSampler::Random(s) => s.get_pixel_2d(),
            PixelSampler::Stratified(s) => s.get_pixel_2d(),
            PixelSampler::Halton(s) => s.get_pixel_2d(),
        }
    }

    fn get_1d(&mut self) -> f32 {
        match self {
            PixelSampler::Centre(s) => s.get_1d(),
            PixelSampler::Random(s) => s.get_1d(),
            PixelSampler::Stratified(s) => s.get_1d(),
            PixelSampler::Halton(s) => s.get_1d(),
        }
    }
}

#[cfg(test)]
mod radical_inverse_values;
#[cfg(test)]
mod tests;
