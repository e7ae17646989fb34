//! A density over the unit square that is constant on each cell of a grid: where a light whose
//! radiance is a texture sends its light samples (more often where the texture is bright).
//!
//! A cell is chosen with a chance proportional to its weight, its row first (by the rows'
//! sums) and then its column within the row; the point is uniform inside the cell. The number
//! that chose the row, and the one that chose the column, are stretched back over `[0, 1)`
//! inside the chosen interval and give the point's place in the cell, so neighbouring numbers
//! give neighbouring points and no number is wasted.

use glam::Vec2;

/// A piecewise-constant density on `[0, 1]²` over `columns × rows` cells.
#[derive(Clone, Debug, PartialEq)]
pub struct GridDistribution {
    columns: usize,
    rows: usize,
    /// The chance of each row and those before it: `rows + 1` values from 0 to 1.
    row_cdf: Vec<f64>,
    /// In each row, the chance of each cell and those before it: `columns + 1` values per row
    /// from 0 to 1 (a row of weight 0, never chosen, is uniform).
    column_cdf: Vec<f64>,
    /// Each cell's density per unit area of the square: its chance times the cell count.
    density: Vec<f32>,
}

impl GridDistribution {
    /// The density of `weights`, row by row from `v = 0`, each row `columns` cells from `u = 0`.
    /// `None` when there are no cells, when `weights` does not fill the grid, or when no
    /// weight is positive; a weight that is negative or not finite counts as 0.
    pub fn new(columns: usize, rows: usize, weights: &[f32]) -> Option<Self> {
        if columns == 0 || rows == 0 || weights.len() != columns * rows {
            return None;
        }
        let weight = |w: f32| {
            if w.is_finite() && w > 0.0 {
                w as f64
            } else {
                0.0
            }
        };
        let mut row_cdf = Vec::with_capacity(rows + 1);
        let mut column_cdf = Vec::with_capacity(rows * (columns + 1));
        row_cdf.push(0.0);
        let mut total = 0.0;
        for row in weights.chunks(columns) {
            let start = column_cdf.len();
            column_cdf.push(0.0);
            let mut sum = 0.0;
            for &w in row {
                sum += weight(w);
                column_cdf.push(sum);
            }
            for (k, c) in column_cdf[start..].iter_mut().enumerate() {
                *c = if sum > 0.0 {
                    *c / sum
                } else {
                    k as f64 / columns as f64
                };
            }
            total += sum;
            row_cdf.push(total);
        }
        if !(total > 0.0 && total.is_finite()) {
            return None;
        }
        for c in &mut row_cdf {
            *c /= total;
        }
        let cells = (columns * rows) as f64;
        let density = weights
            .iter()
            .map(|&w| (weight(w) / total * cells) as f32)
            .collect();
        Some(Self {
            columns,
            rows,
            row_cdf,
            column_cdf,
            density,
        })
    }

    /// A point of the square drawn with this density from the numbers `u` in `[0, 1)²`, and
    /// the density there (per unit area of the square, always positive). Numbers outside
    /// `[0, 1)`, NaN too, give the point of the nearest number inside (NaN that of 0).
    pub fn sample(&self, u: Vec2) -> (Vec2, f32) {
        let (row, v) = pick(&self.row_cdf, u.y as f64);
        let in_row = &self.column_cdf[row * (self.columns + 1)..(row + 1) * (self.columns + 1)];
        let (column, x) = pick(in_row, u.x as f64);
        let point = Vec2::new(
            ((column as f64 + x) / self.columns as f64) as f32,
            ((row as f64 + v) / self.rows as f64) as f32,
        )
        .clamp(Vec2::ZERO, Vec2::ONE);
        (point, self.density[row * self.columns + column])
    }

    /// The density at the point `p` of the square (0 outside it).
    pub fn density(&self, p: Vec2) -> f32 {
        if !(p.x >= 0.0 && p.x <= 1.0 && p.y >= 0.0 && p.y <= 1.0) {
            return 0.0;
        }
        let column = ((p.x * self.columns as f32) as usize).min(self.columns - 1);
        let row = ((p.y * self.rows as f32) as usize).min(self.rows - 1);
        self.density[row * self.columns + column]
    }
}

/// The interval of `cdf` (ascending, from 0 to 1) that `u` falls in, never one of zero width,
/// and where in it `u` lies, in `[0, 1)`. A number below 0, or NaN, picks as 0 does, and one
/// of 1 or more as the last interval of weight: any number picks an interval a sample can be in.
fn pick(cdf: &[f64], u: f64) -> (usize, f64) {
    let u = if u > 0.0 { u } else { 0.0 };
    let count = cdf.len() - 1;
    // The first interval whose upper end is above u; intervals of zero width are skipped.
    let index = cdf[1..].partition_point(|&c| c <= u).min(count - 1);
    // Rounding may leave u at the very top: step back to the last interval with width.
    let index = (0..=index)
        .rev()
        .find(|&i| cdf[i + 1] > cdf[i])
        .unwrap_or(index);
    let width = cdf[index + 1] - cdf[index];
    let offset = if width > 0.0 {
        ((u - cdf[index]) / width).clamp(0.0, 1.0 - f64::EPSILON)
    } else {
        0.5
    };
    (index, offset)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    #[test]
    fn cells_are_chosen_in_proportion_to_their_weights() {
        // 3 x 2 cells; one of weight 0 must never be chosen.
        let weights = [1.0, 0.0, 3.0, 2.0, 2.0, 0.5];
        let grid = GridDistribution::new(3, 2, &weights).unwrap();
        let total: f32 = weights.iter().sum();
        let mut rng = rand_pcg::Pcg32::seed_from_u64(5);
        let n = 200_000;
        let mut counts = [0usize; 6];
        for _ in 0..n {
            let u = Vec2::new(rng.random(), rng.random());
            let (p, density) = grid.sample(u);
            let cell = (p.y * 2.0).min(1.0) as usize * 3 + (p.x * 3.0).min(2.0) as usize;
            counts[cell] += 1;
            assert_eq!(density, grid.density(p), "at {p}");
            assert!(density > 0.0);
        }
        for (cell, &w) in weights.iter().enumerate() {
            let expected = n as f32 * w / total;
            // Four standard deviations of a binomial count.
            let sigma = (expected * (1.0 - w / total)).sqrt().max(1.0);
            let count = counts[cell] as f32;
            assert!(
                (count - expected).abs() < 4.0 * sigma,
                "cell {cell}: {count} samples, expected {expected}"
            );
        }
    }

    #[test]
    fn the_density_integrates_to_one() {
        let weights: Vec<f32> = (0..12).map(|i| (i % 5) as f32).collect();
        let grid = GridDistribution::new(4, 3, &weights).unwrap();
        let cell_area = 1.0 / 12.0;
        let mut integral = 0.0;
        for row in 0..3 {
            for column in 0..4 {
                let centre = Vec2::new((column as f32 + 0.5) / 4.0, (row as f32 + 0.5) / 3.0);
                integral += grid.density(centre) * cell_area;
            }
        }
        assert!((integral - 1.0).abs() < 1e-5, "{integral}");
    }

    #[test]
    fn numbers_at_the_ends_stay_in_the_square_and_in_cells_of_weight() {
        let grid = GridDistribution::new(3, 1, &[0.0, 1.0, 0.0]).unwrap();
        for u in [0.0, 1e-9, 0.5, 1.0 - f32::EPSILON, 1.0] {
            let (p, density) = grid.sample(Vec2::new(u, u));
            assert!((1.0 / 3.0..=2.0 / 3.0).contains(&p.x), "u {u}: {p}");
            assert_eq!(density, 3.0);
        }
    }

    proptest::proptest! {
        #![proptest_config(crate::geometry::awkward::config(256))]

        /// Numbers outside `[0, 1)`, NaN among them, still give a point of the square in a
        /// cell of weight, never one of density 0 that a light sample would divide by.
        #[test]
        fn any_numbers_give_a_point_of_weight(u in crate::geometry::awkward::vec2()) {
            let grid = GridDistribution::new(3, 3, &[0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 0.0, 0.0, 0.0])
                .unwrap();
            let (p, density) = grid.sample(u);
            proptest::prop_assert!(p.cmpge(Vec2::ZERO).all() && p.cmple(Vec2::ONE).all(), "{p}");
            proptest::prop_assert!(density > 0.0 && density.is_finite(), "{density} at {p}");
            proptest::prop_assert!(grid.density(u).is_finite());
        }
    }

    #[test]
    fn nothing_to_sample_is_none() {
        assert!(GridDistribution::new(2, 2, &[0.0; 4]).is_none());
        assert!(GridDistribution::new(2, 2, &[1.0; 3]).is_none());
        assert!(GridDistribution::new(0, 2, &[]).is_none());
        assert!(GridDistribution::new(1, 1, &[f32::NAN]).is_none());
    }
}
