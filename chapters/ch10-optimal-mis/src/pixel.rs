//! One pixel's value from its own samples, the two techniques combined by a heuristic weight
//! (chapter 08's, sample by sample) or optimally (per pixel, [`OptimalSums`]).
//!
//! The optimal weights are solved from the pixel's samples, so a pixel must own its samples:
//! each sample counts in the pixel it lies in and in no other, with weight 1, as under a box
//! filter. (A wider filter shares a sample among pixels with different weights; each pixel
//! would then solve a weighted system of the samples it reaches. The chapter keeps to the box.)

use crate::optimal::{OptimalSums, ProgressiveOptimal};
use crate::techniques::{BSDF, LIGHT, SurfaceDraws, draw_techniques};
use ch05_motion_blur::{CameraRays, TimeSampler};
use ch08_path_tracing::{Materials, MisHeuristic, PathTracer};
use glam::{UVec2, Vec3};

/// How a pixel combines its light and BSDF samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Combination {
    /// Chapter 08's weights, fixed in advance, sample by sample.
    Heuristic(MisHeuristic),
    /// The weights that minimise the variance, solved per pixel ([`OptimalSums`]).
    Optimal,
    /// The same weights, each iteration of the pixel's samples weighted with those solved
    /// from the iterations before it: unbiased ([`ProgressiveOptimal`]).
    Progressive,
}

impl Combination {
    /// Every combination, by its name on the command line: `balance`, `power`, `optimal`,
    /// `progressive`.
    pub const ALL: [Combination; 4] = [
        Combination::Heuristic(MisHeuristic::Balance),
        Combination::Heuristic(MisHeuristic::Power),
        Combination::Optimal,
        Combination::Progressive,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Combination::Heuristic(heuristic) => heuristic.name(),
            Combination::Optimal => "optimal",
            Combination::Progressive => "progressive",
        }
    }
}

/// The value of `pixel` from its `spp` samples: each sample a camera ray through the pixel
/// (the position in it drawn first, then the time and the lens as chapter 05 draws them),
/// and at the surface it meets one light sample and one BSDF sample ([`draw_techniques`]),
/// combined as `combination` says.
pub fn pixel_value<M: Materials, S: TimeSampler>(
    tracer: &PathTracer<'_, M>,
    camera_rays: &CameraRays,
    pixel: UVec2,
    spp: u64,
    sampler: &mut S,
    combination: Combination,
) -> Vec3 {
    let mut certain = Vec3::ZERO;
    let mut weighted = Vec3::ZERO;
    let mut sums = OptimalSums::default();
    let mut progressive = ProgressiveOptimal::default();
    // The progressive variant's iterations: 4 samples, then 8, 16, ..., the last cut at `spp`.
    let (mut iteration_size, mut iteration_end) = (FIRST_ITERATION, FIRST_ITERATION);
    for index in 0..spp {
        sampler.start_pixel_sample(pixel, index);
        let p_film = pixel.as_vec2() + sampler.get_pixel_2d();
        let ray = camera_rays.generate(tracer.world, p_film, sampler);
        let draws = draw_techniques(tracer, &ray, sampler);
        certain += draws.certain;
        match combination {
            Combination::Heuristic(heuristic) => weighted += heuristic_estimate(&draws, heuristic),
            Combination::Optimal => sums.add(&draws),
            Combination::Progressive => {
                progressive.add(&draws);
                if index + 1 == iteration_end || index + 1 == spp {
                    progressive.end_iteration();
                    iteration_size *= 2;
                    iteration_end += iteration_size;
                }
            }
        }
    }
    let n = spp.max(1) as f32;
    match combination {
        Combination::Heuristic(_) => (certain + weighted) / n,
        Combination::Optimal => certain / n + sums.estimate(),
        Combination::Progressive => certain / n + progressive.estimate(),
    }
}

/// Samples in the progressive variant's first iteration, which has no weights yet (the
/// balance heuristic); each later iteration has twice as many as the one before.
pub const FIRST_ITERATION: u64 = 4;

/// The two samples of `draws` weighted by `heuristic`, as chapter 08 weighs them: each
/// sample's `f / p` times its weight against the other technique's density.
pub fn heuristic_estimate(draws: &SurfaceDraws, heuristic: MisHeuristic) -> Vec3 {
    let mut sum = Vec3::ZERO;
    for (technique, other) in [(LIGHT, BSDF), (BSDF, LIGHT)] {
        let Some(sample) = draws.drawn[technique] else {
            continue;
        };
        let (own, theirs) = (sample.pdf[technique], sample.pdf[other]);
        let drawable = own > 0.0;
        if !drawable || sample.f == Vec3::ZERO {
            continue;
        }
        let weight = if technique == LIGHT {
            heuristic.weight(own, theirs)
        } else {
            heuristic.bsdf_sample_weight(own, theirs)
        };
        let term = sample.f * (weight / own);
        if term.is_finite() {
            sum += term;
        }
    }
    sum
}
