//! Where each sample of a pixel looks, and where its other dimensions land: the chapter's
//! samplers.
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
//! | [`MultiJitter`](PixelSamplerKind::MultiJitter) | stratified, and in `n` intervals of each axis too | as stratified, better for edges along an axis |
//! | [`Sobol`](PixelSamplerKind::Sobol) | point `i` of Sobol's sequence, Owen-scrambled per pixel | low discrepancy at every power of two |
//!
//! The pixel position is a sample's first dimension; the later chapters draw more of them (the
//! lens in chapter 04, the time in chapter 05, the light and the bounces after). The centre,
//! random and Halton samplers draw those from chapter 01's `IndependentSampler`, keyed by
//! `(seed, pixel, sample index)`. The stratified, multi-jittered and Sobol samplers place them
//! as they place the pixel position, each dimension with an order of its own
//! ([`dimension_keys`], [`permutation`]), as Mitsuba 3's `stratified`, `multijitter` and
//! `ldsampler` do. Every number still depends on the seed, the pixel and the sample index
//! only, so an image does not depend on the number of threads.

pub mod dimension_keys;
mod halton;
mod multi_jitter;
pub mod permutation;
mod random;
mod sobol;
mod stratified;

pub use halton::{HaltonSampler, halton_position, radical_inverse};
pub use multi_jitter::{MultiJitterSampler, multi_jittered};
pub use permutation::permutation_element;
pub use random::{RandomSampler, random_offset};
pub use sobol::{SobolSampler, owen_scramble, scrambled_sobol_2d, sobol_2d};
pub use stratified::{StratifiedSampler, jittered, shuffled_stratum, strata_grid};

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
    /// Independent uniform numbers, the position in the pixel among them (Mitsuba's
    /// `independent`).
    #[cfg_attr(feature = "lab", value(alias = "independent"))]
    Random,
    /// Jittered: one uniform position in each cell of a grid of `spp` cells, and every other
    /// dimension stratified too, in an order of its own.
    Stratified,
    /// The Halton sequence in bases 2 and 3 for the position, rotated by a random shift per
    /// pixel; the other dimensions independent.
    Halton,
    /// Multi-jittered (Kensler's correlated form) in every dimension.
    #[cfg_attr(feature = "lab", value(name = "multijitter"))]
    MultiJitter,
    /// Owen-scrambled Sobol points in every dimension (Mitsuba's `ldsampler` draws from the
    /// same sequence).
    #[cfg_attr(feature = "lab", value(alias = "ldsampler"))]
    Sobol,
}

impl PixelSamplerKind {
    /// Every strategy, in the order of the enum.
    pub const ALL: [PixelSamplerKind; 6] = [
        PixelSamplerKind::Centre,
        PixelSamplerKind::Random,
        PixelSamplerKind::Stratified,
        PixelSamplerKind::Halton,
        PixelSamplerKind::MultiJitter,
        PixelSamplerKind::Sobol,
    ];

    /// The name used on the command line and in figures.
    pub fn name(self) -> &'static str {
        match self {
            PixelSamplerKind::Centre => "centre",
            PixelSamplerKind::Random => "random",
            PixelSamplerKind::Stratified => "stratified",
            PixelSamplerKind::Halton => "halton",
            PixelSamplerKind::MultiJitter => "multijitter",
            PixelSamplerKind::Sobol => "sobol",
        }
    }

    /// Whether the sampler lays out its strata for a sample count known in advance (and so
    /// cannot render to a time budget).
    pub fn needs_sample_count(self) -> bool {
        matches!(
            self,
            PixelSamplerKind::Stratified | PixelSamplerKind::MultiJitter
        )
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
    /// See [`PixelSamplerKind::MultiJitter`].
    MultiJitter(MultiJitterSampler),
    /// See [`PixelSamplerKind::Sobol`].
    Sobol(SobolSampler),
}

impl PixelSampler {
    /// The strategy `kind` for `spp` samples per pixel, every random number fixed by `seed`.
    ///
    /// Only the stratified and multi-jittered samplers use `spp` (to lay out their grid); the
    /// others accept any number of samples. Errors: `spp == 0`, or a count too large for a grid of strata.
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
            PixelSamplerKind::MultiJitter => {
                PixelSampler::MultiJitter(MultiJitterSampler::new(spp, seed)?)
            }
            PixelSamplerKind::Sobol => PixelSampler::Sobol(SobolSampler::new(seed)),
        })
    }

    /// Which strategy this is.
    pub fn kind(&self) -> PixelSamplerKind {
        match self {
            PixelSampler::Centre(_) => PixelSamplerKind::Centre,
            PixelSampler::Random(_) => PixelSamplerKind::Random,
            PixelSampler::Stratified(_) => PixelSamplerKind::Stratified,
            PixelSampler::Halton(_) => PixelSamplerKind::Halton,
            PixelSampler::MultiJitter(_) => PixelSamplerKind::MultiJitter,
            PixelSampler::Sobol(_) => PixelSamplerKind::Sobol,
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

/// Hands a call to the sampler inside.
macro_rules! each {
    ($self:ident, $s:ident => $call:expr) => {
        match $self {
            PixelSampler::Centre($s) => $call,
            PixelSampler::Random($s) => $call,
            PixelSampler::Stratified($s) => $call,
            PixelSampler::Halton($s) => $call,
            PixelSampler::MultiJitter($s) => $call,
            PixelSampler::Sobol($s) => $call,
        }
    };
}

impl Sampler for PixelSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        each!(self, s => s.start_pixel_sample(pixel, sample_index))
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        each!(self, s => s.get_pixel_2d())
    }

    fn get_1d(&mut self) -> f32 {
        each!(self, s => s.get_1d())
    }

    fn get_2d(&mut self) -> Vec2 {
        each!(self, s => s.get_2d())
    }
}

#[cfg(test)]
mod every_dimension_tests;
#[cfg(test)]
mod radical_inverse_values;
#[cfg(test)]
mod tests;
