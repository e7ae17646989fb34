//! Where in its pixel a sample looks: Whitted's two choices.
//!
//! Whitted's tracer shoots one ray through each pixel centre, the regular grid that aliases.
//! Supersampling on a regular `k x k` grid inside each pixel softens edges but keeps the grid's
//! regularity, so fine repeating patterns still alias; chapter 03 replaces both with random and
//! stratified positions.

use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2};

/// Every sample at the centre of its pixel.
#[derive(Clone, Debug)]
pub struct CentreSampler {
    numbers: IndependentSampler,
}

impl CentreSampler {
    /// Centre samples; other dimensions (none in this chapter) come from `seed`.
    pub fn new(seed: u64) -> Self {
        Self {
            numbers: IndependentSampler::new(seed),
        }
    }
}

impl Sampler for CentreSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.numbers.start_pixel_sample(pixel, sample_index);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        Vec2::splat(0.5)
    }

    fn get_1d(&mut self) -> f32 {
        self.numbers.get_1d()
    }
}

// ANCHOR: grid
/// Sample `i` of a pixel at the centre of cell `i` of a regular `k x k` grid over the pixel,
/// row by row; after `k^2` samples the grid repeats.
#[derive(Clone, Debug)]
pub struct GridSampler {
    cells_per_side: u32,
    index: u64,
    numbers: IndependentSampler,
}

impl GridSampler {
    /// A `k x k` grid.
    pub fn new(cells_per_side: u32, seed: u64) -> Self {
        assert!(cells_per_side > 0, "a grid needs at least one cell");
        Self {
            cells_per_side,
            index: 0,
            numbers: IndependentSampler::new(seed),
        }
    }

    /// The grid with exactly `spp` cells, if `spp` is a perfect square.
    pub fn for_spp(spp: u64, seed: u64) -> Option<Self> {
        let k = (spp as f64).sqrt().round() as u64;
        (k > 0 && k * k == spp && k <= u64::from(u32::MAX)).then(|| Self::new(k as u32, seed))
    }
}

impl Sampler for GridSampler {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.index = sample_index;
        self.numbers.start_pixel_sample(pixel, sample_index);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        let k = u64::from(self.cells_per_side);
        let cell = self.index % (k * k);
        let (column, row) = (cell % k, cell / k);
        (Vec2::new(column as f32, row as f32) + 0.5) / k as f32
    }

    fn get_1d(&mut self) -> f32 {
        self.numbers.get_1d()
    }
}
// ANCHOR_END: grid

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_samples_are_cell_centres_in_row_order() {
        let mut grid = GridSampler::for_spp(4, 0).unwrap();
        let positions: Vec<Vec2> = (0..5)
            .map(|i| {
                grid.start_pixel_sample(UVec2::ZERO, i);
                grid.get_pixel_2d()
            })
            .collect();
        let expected = [
            (0.25, 0.25),
            (0.75, 0.25),
            (0.25, 0.75),
            (0.75, 0.75),
            (0.25, 0.25),
        ];
        for (p, (x, y)) in positions.iter().zip(expected) {
            assert_eq!(*p, Vec2::new(x, y));
        }
        assert!(GridSampler::for_spp(8, 0).is_none());
        assert!(GridSampler::for_spp(0, 0).is_none());
    }
}
