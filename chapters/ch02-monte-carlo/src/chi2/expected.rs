//! The expected counts: how many samples each bin should receive if the density is right.

use glam::DVec2;

use super::bins::BinGrid;
use super::simpson::{adaptive_simpson_2d, simpson_2d};
use crate::warps::WarpPoint;

/// The expected count of every bin: `samples` times the claimed density integrated over it.
///
/// How exact must these be? A bin's observed count scatters by `√E` around its expectation
/// `E`, so an error `ε` in `E` adds only about `ε² / E` to that bin's term of `X²`, whose own
/// randomness is of order 1. Each bin is therefore integrated to within a tenth of `√E`
/// counts, with `E` first estimated by a plain Simpson's rule on a coarse mesh. That is loose
/// where counts are large and tight where they are small, and it lets the adaptive rule (in
/// `simpson`) stop refining a jump of the density (the disc's rim, the triangle's diagonal)
/// once the remaining error no longer matters.
pub(super) fn expected_counts(
    grid: &BinGrid,
    pdf: &impl Fn(WarpPoint) -> f32,
    samples: usize,
) -> Vec<f64> {
    let n = samples as f64;
    (0..grid.len())
        .map(|bin| {
            let (lower, upper) = grid.bin_bounds(bin);
            let density = |x: f64, y: f64| pdf(grid.point_at(DVec2::new(x, y))) as f64;
            let rough = n * simpson_2d(&density, lower, upper);
            let tolerance = 0.1 * rough.max(1.0).sqrt() / n;
            (n * adaptive_simpson_2d(&density, lower, upper, tolerance)).max(0.0)
        })
        .collect()
}
