//! Multi-jittered samples: stratified in the grid's cells and in each axis on its own.
//!
//! A jittered grid of `columns x rows` cells stratifies the square, but projected on the `x`
//! axis its points fall only into `columns` intervals, several in each: an integrand that
//! varies along `x` alone (an edge straight up the pixel, a light wide in one direction) sees
//! `columns` strata, not `n`. Chiu, Shirley and Wang's multi-jittering puts each point, inside
//! its cell, into one of `rows` sub-columns and one of `columns` sub-rows chosen so that the
//! `n` points also fall into `n` different intervals of each axis: a Latin hypercube and a
//! jittered grid at once. Kensler's *correlated* variant chooses the sub-columns by one
//! permutation for every column and the sub-rows by one for every row, which keeps both
//! properties and spreads the points more evenly still.

use super::ONE_MINUS_EPSILON;
use super::permutation::permutation_element;
use super::stratified::{Strata, shuffled_stratum};
use common::sampler::Sampler;
use glam::{UVec2, Vec2};

// ANCHOR: multi_jittered
/// The point, in `[0, 1)^2`, of cell `cell` (counted row by row) of a `columns x rows` grid,
/// multi-jittered with the permutations of `key`: inside its cell, in sub-column number
/// `permutation(row)` of `rows` and sub-row number `permutation(column)` of `columns`, jittered
/// there by `xi`. The `columns * rows` cells then cover every one of the `columns * rows`
/// intervals of each axis exactly once.
pub fn multi_jittered(cell: u32, columns: u32, rows: u32, key: u32, xi: Vec2) -> Vec2 {
    let column = cell % columns;
    let row = (cell / columns) % rows;
    // One permutation for all columns, one for all rows: Kensler's correlated choice.
    let sub_column = permutation_element(row, rows, key.wrapping_mul(0x68bc_21eb));
    let sub_row = permutation_element(column, columns, key.wrapping_mul(0x02e5_be93));
    let x = (column as f32 + (sub_column as f32 + xi.x) / rows as f32) / columns as f32;
    let y = (row as f32 + (sub_row as f32 + xi.y) / columns as f32) / rows as f32;
    Vec2::new(x, y).min(Vec2::splat(ONE_MINUS_EPSILON))
}
// ANCHOR_END: multi_jittered

/// Multi-jittered samples for a fixed number of samples per pixel, in every dimension (Mitsuba
/// 3's `multijitter`): the pixel position and every 2D draw multi-jittered on the grid of
/// [`strata_grid`](super::strata_grid), every 1D draw stratified into `spp` intervals, each dimension with its own
/// order of cells and its own permutations.
#[derive(Clone, Debug)]
pub struct MultiJitterSampler {
    strata: Strata,
}

impl MultiJitterSampler {
    /// The grid for `spp` samples per pixel; see [`strata_grid`](super::strata_grid). At most `u32::MAX` samples.
    pub fn new(spp: u64, seed: u64) -> Result<Self, String> {
        Strata::new(spp, seed, "multi-jittered sampling").map(|strata| Self { strata })
    }

    /// The grid, `(columns, rows)`.
    pub fn grid(&self) -> (u32, u32) {
        (self.strata.columns, self.strata.rows)
    }
}

impl Sampler for MultiJitterSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.strata.start(pixel, sample_index);
    }

    /// Cell `i mod spp` for sample `i`, as the stratified sampler's, multi-jittered.
    fn get_pixel_2d(&mut self) -> Vec2 {
        let s = &mut self.strata;
        let cell = (s.index % u64::from(s.count())) as u32;
        let key = s.keys.next_key();
        multi_jittered(cell, s.columns, s.rows, key, s.numbers.get_2d())
    }

    /// As the stratified sampler's: one of `spp` equal intervals.
    fn get_1d(&mut self) -> f32 {
        self.strata.next_1d()
    }

    fn get_2d(&mut self) -> Vec2 {
        let s = &mut self.strata;
        let key = s.keys.next_key();
        let cell = shuffled_stratum(s.index, s.count(), key);
        multi_jittered(cell, s.columns, s.rows, key, s.numbers.get_2d())
    }
}
