//! How many shadow rays a receiver sends to each light, and how their points are chosen.
//!
//! Cook et al. trace one shadow ray per light per *pixel sample*; the pixel's many samples
//! then average the light over its surface. [`LightOptions::samples`] lets a receiver send
//! `N` rays to each light instead: with `S` samples per pixel, a pixel then averages `S x N`
//! points of every light, and the `N` of one receiver can be stratified over the light (a
//! `k x k` jittered grid when `N = k²`, a Latin hypercube otherwise), which a single ray per
//! receiver cannot be. The default is the lecture's, one ray per light per pixel sample.
//!
//! `N` shadow rays per light and pixel find the visible fraction of the light with an error
//! that falls as `1 / √N` when their points are independent. Independent points clump, and a
//! clump means that one part of the light is tested twice while another is not tested at
//! all. Stratifying the square of `u` (chapter 02) spreads the points over the whole light,
//! the way Cook et al. jitter their pixel samples, and in a penumbra it visibly reduces the
//! noise, never increasing it.
//!
//! The choice of stratification: for `N = k²` a `k x k` jittered grid (chapter 02's
//! [`jittered_2d`]), which stratifies both coordinates and the square jointly; for other `N`
//! a Latin hypercube (one point in each of `N` columns and in each of `N` rows, the rows
//! shuffled), which stratifies each coordinate on its own. A grid that is not square, such as
//! 2 x 3 for 6, would favour one direction of the light over the other.

use crate::disc_warp::DiscWarp;
use crate::sample_stream::SampleStream;
use crate::strategy::{LightSampling, Strategy};
use ch02_monte_carlo::stratified::{independent_2d, jittered_2d, stratified_1d};
use common::sampler::Sampler;
use glam::Vec2;
use rand::Rng;
use rand::seq::SliceRandom;

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

/// `n` points of `[0, 1)^2` for one receiver's shadow rays to one light: independent when
/// `stratified` is false; otherwise jittered on a `k x k` grid when `n = k²`, a Latin
/// hypercube when `n` is not a square.
pub fn light_samples<R: Rng + ?Sized>(n: usize, stratified: bool, rng: &mut R) -> Vec<Vec2> {
    if !stratified {
        return independent_2d(n, rng);
    }
    let k = n.isqrt();
    if k * k == n {
        jittered_2d(k, rng)
    } else {
        latin_hypercube_2d(n, rng)
    }
}

/// `n` points of `[0, 1)^2` with exactly one in each column `[i/n, (i+1)/n) x [0, 1)` and one
/// in each row: stratified `x` paired with shuffled stratified `y`.
pub fn latin_hypercube_2d<R: Rng + ?Sized>(n: usize, rng: &mut R) -> Vec<Vec2> {
    let xs = stratified_1d(n, rng);
    let mut ys = stratified_1d(n, rng);
    ys.shuffle(rng);
    xs.into_iter()
        .zip(ys)
        .map(|(x, y)| Vec2::new(x, y))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_pcg::Pcg32;

    fn cells(points: &[Vec2], columns: usize, rows: usize) -> Vec<usize> {
        let mut count = vec![0; columns * rows];
        for p in points {
            assert!(
                (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y),
                "{p}"
            );
            let column = (p.x * columns as f32) as usize;
            let row = (p.y * rows as f32) as usize;
            count[row * columns + column] += 1;
        }
        count
    }

    #[test]
    fn a_square_number_gives_a_jittered_grid() {
        let points = light_samples(16, true, &mut Pcg32::seed_from_u64(1));
        assert_eq!(points.len(), 16);
        assert!(cells(&points, 4, 4).iter().all(|&c| c == 1));
    }

    #[test]
    fn other_numbers_give_a_latin_hypercube() {
        for n in [2, 7, 12] {
            let points = light_samples(n, true, &mut Pcg32::seed_from_u64(n as u64));
            assert_eq!(points.len(), n);
            assert!(
                cells(&points, n, 1).iter().all(|&c| c == 1),
                "columns, n = {n}"
            );
            assert!(
                cells(&points, 1, n).iter().all(|&c| c == 1),
                "rows, n = {n}"
            );
        }
    }

    #[test]
    fn independent_points_are_in_range_and_repeatable() {
        let a = light_samples(50, false, &mut Pcg32::seed_from_u64(5));
        assert_eq!(a, light_samples(50, false, &mut Pcg32::seed_from_u64(5)));
        assert_eq!(cells(&a, 1, 1), vec![50]);
        assert!(light_samples(0, true, &mut Pcg32::seed_from_u64(5)).is_empty());
    }
}
