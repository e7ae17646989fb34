//! Stratified (jittered) positions: one random point in each cell of a grid.
//!
//! Split the pixel into `spp` cells, `columns x rows`, and put one uniform point in each. A
//! sample can no longer clump with another: an edge crossing the pixel is crossed by about the
//! right number of cells, and only the cells the edge passes through contribute noise. That
//! is the lecture's "less noise near edges": for a pixel cut by an edge the variance falls as
//! `n^-3/2` instead of `n^-1`.

use super::dimension_keys::DimensionKeys;
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2};

// ANCHOR: strata_grid
/// The grid of strata for `spp` samples: `(columns, rows)`, with exactly `spp` cells, at least
/// as many columns as rows, and as close to square as `spp` allows; `None` for no samples, or
/// for a grid too large to count in `u32`. A prime count can only be a single row of thin
/// strata: still stratified in `x`.
///
/// Which divisors of `spp` could be the number of rows, and which of them makes the squarest
/// grid?
pub fn strata_grid(spp: u64) -> Option<(u32, u32)> {
    // BEGIN SOLUTION
    if spp == 0 {
        return None;
    }
    // The rows: the largest divisor of spp not above its square root.
    let mut rows = (spp as f64).sqrt().floor() as u64;
    // The float square root can be one off for huge counts; nudge it to the true floor.
    while rows * rows > spp {
        rows -= 1;
    }
    while (rows + 1) * (rows + 1) <= spp {
        rows += 1;
    }
    while !spp.is_multiple_of(rows) {
        rows -= 1;
    }
    let columns = spp / rows;
    Some((u32::try_from(columns).ok()?, u32::try_from(rows).ok()?))
    // END SOLUTION
}
// ANCHOR_END: strata_grid

// ANCHOR: jittered
/// The position, in `[0, 1)^2` like every position in a pixel, of sample `sample_index` of a
/// pixel divided into `columns x rows` strata: a uniform point, given by `xi` in `[0, 1)^2`,
/// inside stratum number `sample_index` (counted row by row from the top left; after the last
/// stratum the order starts again), `xi = (0, 0)` at the stratum's top left corner.
pub fn jittered(sample_index: u64, columns: u32, rows: u32, xi: Vec2) -> Vec2 {
    // BEGIN SOLUTION
    let strata = u64::from(columns) * u64::from(rows);
    let stratum = sample_index % strata;
    let column = (stratum % u64::from(columns)) as f32;
    let row = (stratum / u64::from(columns)) as f32;
    let p = Vec2::new((column + xi.x) / columns as f32, (row + xi.y) / rows as f32);
    // (k + ξ) / n can round up to 1 in f32 for the last stratum; 1 is the next pixel.
    p.min(Vec2::splat(super::ONE_MINUS_EPSILON))
    // END SOLUTION
}
// ANCHOR_END: jittered

// ANCHOR: shuffled_stratum
/// The stratum, out of `strata` (at least 1), that sample `sample_index` of a pixel takes in a
/// dimension whose order is chosen by `key`: the pixel's first `strata` samples take every
/// stratum once, in a random order, and each further round of `strata` samples again, in a new
/// order. [`permutation_element`](super::permutation_element)`(i, n, key)` is element `i` of a
/// random order of `0..n`, and [`mix`](common::sampler::mix) hashes 64 bits.
///
/// Which place within its round does a sample have, and what must the key of each round mix
/// in so that rounds differ?
pub fn shuffled_stratum(sample_index: u64, strata: u32, key: u32) -> u32 {
    // BEGIN SOLUTION
    use super::permutation_element;
    use common::sampler::mix;
    let strata = strata.max(1);
    let round = sample_index / u64::from(strata);
    let round_key = key ^ (mix(round) as u32);
    permutation_element((sample_index % u64::from(strata)) as u32, strata, round_key)
    // END SOLUTION
}
// ANCHOR_END: shuffled_stratum

/// The strata a sampler lays out for the samples of a pixel, and where the current sample is
/// among them: the grid of `spp` cells, the sample's index, the keys of its dimensions, and
/// its own stream for the jitter. The stratified and the multi-jittered samplers share it.
#[derive(Clone, Debug)]
pub(super) struct Strata {
    /// The grid's columns.
    pub(super) columns: u32,
    /// The grid's rows.
    pub(super) rows: u32,
    /// The current sample's index.
    pub(super) index: u64,
    /// The keys of the current sample's dimensions.
    pub(super) keys: DimensionKeys,
    /// The current sample's own numbers.
    pub(super) numbers: IndependentSampler,
}

impl Strata {
    /// The grid of [`strata_grid`] for `spp` samples per pixel (at most `u32::MAX`); `what`
    /// names the sampler in the error.
    pub(super) fn new(spp: u64, seed: u64, what: &str) -> Result<Self, String> {
        let (columns, rows) = strata_grid(spp)
            .filter(|_| spp <= u64::from(u32::MAX))
            .ok_or_else(|| format!("{what} cannot lay out {spp} samples per pixel as a grid"))?;
        Ok(Self {
            columns,
            rows,
            index: 0,
            keys: DimensionKeys::new(seed),
            numbers: IndependentSampler::new(seed),
        })
    }

    /// How many strata: the samples per pixel.
    pub(super) fn count(&self) -> u32 {
        self.columns * self.rows
    }

    /// Starts sample `sample_index` of `pixel`.
    pub(super) fn start(&mut self, pixel: UVec2, sample_index: u64) {
        self.index = sample_index;
        self.keys.start(pixel);
        self.numbers.start_pixel_sample(pixel, sample_index);
    }

    // ANCHOR: strata_next_1d
    /// A 1D dimension: one of `spp` equal intervals, a grid of `spp` columns and one row.
    pub(super) fn next_1d(&mut self) -> f32 {
        let stratum = shuffled_stratum(self.index, self.count(), self.keys.next_key());
        let xi = Vec2::new(self.numbers.get_1d(), 0.0);
        jittered(u64::from(stratum), self.count(), 1, xi).x
    }
    // ANCHOR_END: strata_next_1d
}

/// Jittered samples for a fixed number of samples per pixel, in every dimension.
///
/// The pixel position of sample `i` goes into cell `i mod spp` of the pixel's grid. Every
/// further dimension is stratified too: a 1D draw into one of `spp` equal intervals, a 2D draw
/// into one cell of the same grid, each dimension dealing out its strata in an order of its
/// own ([`shuffled_stratum`]). Where in its stratum a number lands comes from the sample's
/// own stream, as in Mitsuba 3's `stratified` sampler.
#[derive(Clone, Debug)]
pub struct StratifiedSampler {
    strata: Strata,
}

impl StratifiedSampler {
    /// Strata for `spp` samples per pixel; see [`strata_grid`]. At most `u32::MAX` strata.
    pub fn new(spp: u64, seed: u64) -> Result<Self, String> {
        Strata::new(spp, seed, "stratified sampling").map(|strata| Self { strata })
    }

    /// The grid, `(columns, rows)`.
    pub fn grid(&self) -> (u32, u32) {
        (self.strata.columns, self.strata.rows)
    }
}

// ANCHOR: stratified_every_dimension
impl Sampler for StratifiedSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.strata.start(pixel, sample_index);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        let s = &mut self.strata;
        jittered(s.index, s.columns, s.rows, s.numbers.get_2d())
    }

    /// One of `spp` equal intervals, in the dimension's own order (`Strata::next_1d`).
    fn get_1d(&mut self) -> f32 {
        self.strata.next_1d()
    }

    fn get_2d(&mut self) -> Vec2 {
        let s = &mut self.strata;
        let cell = shuffled_stratum(s.index, s.count(), s.keys.next_key());
        jittered(u64::from(cell), s.columns, s.rows, s.numbers.get_2d())
    }
}
// ANCHOR_END: stratified_every_dimension
