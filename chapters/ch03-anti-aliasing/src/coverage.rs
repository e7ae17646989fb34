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

    /// The exact area of the unit square below the edge: `∫ clamp(slope x + intercept, 0, 1) dx`
    /// over `[0, 1]`, integrated piece by piece (each piece is linear, so the trapezoid rule is
    /// exact on it).
    pub fn coverage(&self) -> f64 {
        let (m, b) = (f64::from(self.slope), f64::from(self.intercept));
        let height = |x: f64| (m * x + b).clamp(0.0, 1.0);
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
    }
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

    #[test]
    fn coverage_is_the_exact_area() {
        let cases = [
            (0.0, 0.3, 0.3),   // horizontal
            (1.0, 0.0, 0.5),   // the diagonal
            (2.0, 0.0, 0.75),  // steep, through a corner
            (0.5, 0.25, 0.5),  // crosses both sides
            (0.0, 1.5, 1.0),   // above the pixel
            (-1.0, -0.1, 0.0), // below it
            (-0.2, 0.9, 0.8),  // falling
        ];
        for (slope, intercept, area) in cases {
            let edge = HalfPlane { slope, intercept };
            assert!((edge.coverage() - area).abs() < 1e-7, "{edge:?}");
        }
    }
}
