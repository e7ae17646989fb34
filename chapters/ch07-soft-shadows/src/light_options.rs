//! How many shadow rays a receiver sends to each light, and how their points are chosen.
//!
//! Cook et al. trace one shadow ray per light per *pixel sample*; the pixel's many samples
//! then average the light over its surface. [`LightOptions::samples`] lets a receiver send
//! `N` rays to each light instead: with `S` samples per pixel, a pixel then averages `S x N`
//! points of every light, and the `N` of one receiver can be stratified over the light (a
//! `k x k` jittered grid when `N = k²`, a Latin hypercube otherwise), which a single ray per
//! receiver cannot be. The default is the lecture's, one ray per light per pixel sample.

use crate::disc_warp::DiscWarp;
use crate::light_samples::light_samples;
use crate::sample_stream::SampleStream;
use crate::strategy::{LightSampling, Strategy};
use common::sampler::Sampler;
use glam::Vec2;

/// The largest number of shadow rays per light and receiver `render` accepts.
pub const MAX_LIGHT_SAMPLES: u32 = 4096;

/// Whether one receiver's points on a light are stratified.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum LightStrata {
    /// A jittered `k x k` grid for `N = k²` points, a Latin hypercube for other `N`.
    #[default]
    Stratified,
    /// Independent uniform points.
    Independent,
}

impl LightStrata {
    /// Both ways, stratified first.
    pub const ALL: [LightStrata; 2] = [LightStrata::Stratified, LightStrata::Independent];

    /// The name used on the command line and in figures.
    pub fn name(self) -> &'static str {
        match self {
            LightStrata::Stratified => "stratified",
            LightStrata::Independent => "independent",
        }
    }
}

/// Everything that decides the shadow rays to area lights.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LightOptions {
    /// Shadow rays per light at each matte hit, at least 1.
    pub samples: u32,
    /// Stratified or independent points.
    pub strata: LightStrata,
    /// By area or by solid angle, and the disc warp.
    pub sampling: LightSampling,
}

impl Default for LightOptions {
    /// One stratified (so: plain) point per light, spheres by solid angle, concentric discs.
    fn default() -> Self {
        Self {
            samples: 1,
            strata: LightStrata::Stratified,
            sampling: LightSampling::solid_angle(),
        }
    }
}

impl LightOptions {
    /// `samples` rays per light, otherwise the defaults.
    pub fn with_samples(samples: u32) -> Self {
        Self {
            samples,
            ..Self::default()
        }
    }

    /// The same options with `strategy` for spheres.
    pub fn with_strategy(mut self, strategy: Strategy) -> Self {
        self.sampling.strategy = strategy;
        self
    }

    /// The same options with `warp` for discs.
    pub fn with_disc_warp(mut self, warp: DiscWarp) -> Self {
        self.sampling.disc_warp = warp;
        self
    }

    /// The same options with `strata`.
    pub fn with_strata(mut self, strata: LightStrata) -> Self {
        self.strata = strata;
        self
    }

    /// The points of `[0, 1)²` for one receiver's shadow rays to one light, drawn from the
    /// sample's stream: `2N` dimensions (plus the Latin hypercube's shuffle).
    pub fn points<S: Sampler>(&self, sampler: &mut S) -> Vec<Vec2> {
        let stratified = self.strata == LightStrata::Stratified;
        light_samples(
            self.samples.max(1) as usize,
            stratified,
            &mut SampleStream(sampler),
        )
    }
}
