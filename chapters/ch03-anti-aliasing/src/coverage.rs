//! The simplest anti-aliasing problem: how much of a pixel does an edge cover?
//!
//! A pixel cut by a straight edge, dark on one side and bright on the other, has the value
//! "fraction of the pixel on the bright side". Estimating that fraction with `n` samples shows
//! the difference between the samplers in its purest form: random samples give a variance of
//! `c (1 - c) / n`; stratified samples only err in the strata the edge crosses, about `sqrt(n)`
//! of them, for a variance of order `n^-3/2`; Halton points do better still.

use crate::pixel_samplers::{PixelSampler, PixelSamplerKind};
use glam::{UVec2, Vec2};

/// The part of the plane below the line `y = slope * x + intercept`, in pixel coordinates
/// (`[0, 1)^2` is the pixel).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfPlane {
    /// Rise of the edge per unit of `x`.
    pub slope: f32,
    /// Height of the edge at `x = 0`.
    pub intercept: f32,
}

impl HalfPlane {
    /// Whether `p` lies below the edge.
    pub fn contains(&self, p: Vec2) -> bool {
        p.y < self.slope * p.x + self.intercept
    }

    // ANCHOR: edge_coverage
    /// The exact area of the unit square below the edge: the true value of a pixel that is 1
    /// below the edge and 0 above it, against which the samplers' estimates are measured.
    ///
    /// Over each `x` of the square, how much of the column `[0, 1]` lies below the edge? Where
    /// does that height stop being a straight line, and what integrates a straight line exactly?
    pub fn coverage(&self) -> f64 {
        // BEGIN SOLUTION
        let (m, b) = (f64::from(self.slope), f64::from(self.intercept));
        // The height below the edge within the square: the line, clamped to [0, 1].
        let height = |x: f64| (m * x + b).clamp(0.0, 1.0);
        // It bends where the line crosses the bottom or the top of the square; between those
        // points it is linear, and the trapezoid rule is exact on each piece.
        let mut breaks = vec![0.0, 1.0];
        if m != 0.0 {
            for level in [0.0, 1.0] {
                let x = (level - b) / m;
                if x > 0.0 && x < 1.0 {
                    breaks.push(x);
                }
            }
        }
        breaks.sort_by(f64::total_cmp);
        breaks
            .windows(2)
            .map(|w| 0.5 * (height(w[0]) + height(w[1])) * (w[1] - w[0]))
            .sum()
        // END SOLUTION
    }
    // ANCHOR_END: edge_coverage
}

/// The fraction of `spp` samples of `kind` (with seed `seed`, in `pixel`) that fall below
/// the edge: the Monte Carlo estimate of [`HalfPlane::coverage`].
pub fn estimate_coverage(
    kind: PixelSamplerKind,
    spp: u64,
    seed: u64,
    pixel: UVec2,
    edge: HalfPlane,
) -> f64 {
    let mut sampler = PixelSampler::new(kind, spp, seed).expect("spp is at least 1");
    let inside = sampler
        .positions(pixel, spp)
        .into_iter()
        .filter(|&p| edge.contains(p))
        .count();
    inside as f64 / spp as f64
}

/// The mean squared error of [`estimate_coverage`] over `repetitions` seeds: the variance of
/// the estimator plus its squared bias (zero for every sampler but the centre).
pub fn coverage_mse(kind: PixelSamplerKind, spp: u64, repetitions: u64, edge: HalfPlane) -> f64 {
    let exact = edge.coverage();
    let squared_errors: f64 = (0..repetitions)
        .map(|seed| {
            let e = estimate_coverage(kind, spp, seed, UVec2::new(3, 5), edge) - exact;
            e * e
        })
        .sum();
    squared_errors / repetitions as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The share of a 100 x 100 grid of points, one in the middle of each cell, that lies
    /// below the edge: the area to about 1/100 of the pixel's width along the edge, a rough
    /// check only.
    fn area_by_grid(edge: HalfPlane) -> f64 {
        let n = 100;
        let below = (0..n * n)
            .filter(|&i| {
                let cell = Vec2::new((i % n) as f32, (i / n) as f32);
                edge.contains((cell + Vec2::splat(0.5)) / n as f32)
            })
            .count();
        below as f64 / (n * n) as f64
    }

    /// What is wrong with `got = edge.coverage()`, which should be `expected` within
    /// `tolerance`, in words; `None` if right.
    fn coverage_mistake(
        edge: HalfPlane,
        expected: f64,
        tolerance: f64,
        got: f64,
    ) -> Option<String> {
        if (got - expected).abs() <= tolerance {
            return None;
        }
        let (m, b) = (f64::from(edge.slope), f64::from(edge.intercept));
        let unclamped = b + 0.5 * m;
        let ends_only = 0.5 * (b.clamp(0.0, 1.0) + (m + b).clamp(0.0, 1.0));
        let mistake = if !got.is_finite() {
            "the area is not a number".to_string()
        } else if !(0.0..=1.0).contains(&got) || (got - unclamped).abs() <= 1e-9 {
            "the area of a part of the pixel lies between 0 and 1: where the edge passes above \
             or below the pixel, only the pixel's own column counts"
                .to_string()
        } else if (got - ends_only).abs() <= 1e-9 {
            "the edge leaves the pixel through its top or bottom, so the height under it bends \
             there: one trapezoid over the whole pixel is no longer exact, but one per straight \
             piece is"
                .to_string()
        } else {
            "the area below the edge is the integral, over x in [0, 1], of the height of the \
             column under the edge inside the pixel"
                .to_string()
        };
        Some(format!(
            "{mistake}.\n  slope {}, intercept {}: coverage() gave {got}, expected {expected}",
            edge.slope, edge.intercept
        ))
    }

    #[test]
    fn exercise_edge_coverage_is_the_exact_area() {
        // Horizontal, the diagonal, through a corner, across both sides, above and below the
        // pixel, falling, in at the bottom and out at the top, out through top and bottom:
        // (slope, intercept, area), the areas worked out beforehand in f64 from the f32 slope
        // and intercept.
        let cases = [
            (0.0, 0.3, 0.30000001192092896),
            (1.0, 0.0, 0.5),
            (2.0, 0.0, 0.75),
            (0.5, 0.25, 0.5),
            (0.0, 1.5, 1.0),
            (-1.0, -0.1, 0.0),
            (-0.2, 0.9, 0.799999974668026),
            (3.0, -1.0, 0.5),
            (-4.0, 2.5, 0.5),
        ];
        for (slope, intercept, expected) in cases {
            let edge = HalfPlane { slope, intercept };
            if let Some(mistake) = coverage_mistake(edge, expected, 1e-9, edge.coverage()) {
                panic!("coverage: {mistake}");
            }
        }
    }

    #[test]
    fn exercise_edge_coverage_of_random_edges() {
        use common::sampler::{IndependentSampler, Sampler};
        let mut numbers = IndependentSampler::new(3);
        numbers.start_pixel_sample(UVec2::ZERO, 0);
        for _ in 0..200 {
            let edge = HalfPlane {
                slope: 8.0 * numbers.get_1d() - 4.0,
                intercept: 3.0 * numbers.get_1d() - 1.0,
            };
            // Roughly the share of a fine grid of points below the edge ...
            let rough = area_by_grid(edge);
            if let Some(mistake) = coverage_mistake(edge, rough, 0.02, edge.coverage()) {
                panic!("coverage: {mistake} (roughly: counted on a 100 x 100 grid)");
            }
            // ... and exactly what the pixel turned half round about its centre leaves above
            // the same edge: the two areas make the whole pixel.
            let (m, b) = (edge.slope, edge.intercept);
            let turned = HalfPlane {
                slope: m,
                intercept: 1.0 - m - b,
            };
            let (area, other) = (edge.coverage(), turned.coverage());
            assert!(
                (area + other - 1.0).abs() <= 1e-6,
                "coverage: the part of the pixel below the edge of slope {m}, intercept {b} \
                 ({area}) and the part below the edge turned half round about the pixel's \
                 centre (slope {m}, intercept {}: {other}) make the whole pixel, but they add \
                 up to {}",
                turned.intercept,
                area + other
            );
        }
    }
}
