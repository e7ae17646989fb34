//! Stratified (jittered) positions: one random point in each cell of a grid.
//!
//! Split the pixel into `spp` cells, `columns x rows`, and put one uniform point in each. A
//! sample can no longer clump with another: an edge crossing the pixel is crossed by about the
//! right number of cells, and only the cells the edge passes through contribute noise. That
//! is the lecture's "less noise near edges": for a pixel cut by an edge the variance falls as
//! `n^-3/2` instead of `n^-1`.

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

/// Jittered positions for a fixed number of samples per pixel. Sample `i` goes into stratum
/// `i mod spp`, the jitter inside it comes from the first two numbers of the sample's stream.
#[derive(Clone, Debug)]
pub struct StratifiedSampler {
    columns: u32,
    rows: u32,
    index: u64,
    numbers: IndependentSampler,
}

impl StratifiedSampler {
    /// Strata for `spp` samples per pixel; see [`strata_grid`].
    pub fn new(spp: u64, seed: u64) -> Result<Self, String> {
        let (columns, rows) = strata_grid(spp).ok_or_else(|| {
            format!("stratified sampling cannot lay out {spp} samples per pixel as a grid")
        })?;
        Ok(Self {
            columns,
            rows,
            index: 0,
            numbers: IndependentSampler::new(seed),
        })
    }

    /// The grid, `(columns, rows)`.
    pub fn grid(&self) -> (u32, u32) {
        (self.columns, self.rows)
    }
}

impl Sampler for StratifiedSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.index = sample_index;
        self.numbers.start_pixel_sample(pixel, sample_index);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        let xi = self.numbers.get_2d();
        jittered(self.index, self.columns, self.rows, xi)
    }

    fn get_1d(&mut self) -> f32 {
        self.numbers.get_1d()
    }
}
