//! One pixel's value from its own samples, the two techniques combined by a heuristic weight
//! (chapter 08's, sample by sample) or optimally (per pixel, [`OptimalSums`]).
//!
//! The optimal weights are solved from the pixel's samples, so a pixel must own its samples:
//! each sample counts in the pixel it lies in and in no other, with weight 1, as under a box
//! filter. (A wider filter shares a sample among pixels with different weights; each pixel
//! would then solve a weighted system of the samples it reaches. The chapter keeps to the box.)

use crate::optimal::{OptimalSums, ProgressiveOptimal};
use crate::path::draw_path;
use crate::techniques::{BSDF, LIGHT, SurfaceDraws, draw_techniques};
use ch05_motion_blur::{CameraRays, TimeSampler};
use ch08_path_tracing::{Materials, MisHeuristic, PathTracer};
use common::Ray;
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
    pixel_from(
        camera_rays,
        tracer,
        pixel,
        spp,
        sampler,
        combination,
        |ray, sampler, add| add(1, draw_techniques(tracer, ray, sampler)),
    )
}

/// The value of `pixel` as [`pixel_value`] makes it, but from whole paths ([`draw_path`]): the
/// two techniques are combined at every vertex, each depth from its own sums, since the light
/// found after `d` bounces is an integrand of its own.
pub fn path_pixel_value<M: Materials, S: TimeSampler>(
    tracer: &PathTracer<'_, M>,
    camera_rays: &CameraRays,
    pixel: UVec2,
    spp: u64,
    sampler: &mut S,
    combination: Combination,
) -> Vec3 {
    pixel_from(
        camera_rays,
        tracer,
        pixel,
        spp,
        sampler,
        combination,
        |ray, sampler, add| draw_path(tracer, ray, sampler, add),
    )
}

/// The pixel's samples, each a camera ray that `draw` turns into draws per depth, combined
/// depth by depth as `combination` says.
fn pixel_from<M: Materials, S: TimeSampler>(
    camera_rays: &CameraRays,
    tracer: &PathTracer<'_, M>,
    pixel: UVec2,
    spp: u64,
    sampler: &mut S,
    combination: Combination,
    mut draw: impl FnMut(&Ray, &mut S, &mut dyn FnMut(usize, SurfaceDraws)),
) -> Vec3 {
    let mut sums = DepthSums::new(combination);
    for index in 0..spp {
        sampler.start_pixel_sample(pixel, index);
        let p_film = pixel.as_vec2() + sampler.get_pixel_2d();
        let ray = camera_rays.generate(tracer.world, p_film, sampler);
        draw(&ray, sampler, &mut |depth, draws| sums.add(depth, &draws));
        sums.end_sample(ends_iteration(index, spp));
    }
    sums.estimate()
}

/// Samples in the progressive variant's first iteration, which has no weights yet (the
/// balance heuristic); each later iteration has twice as many as the one before.
pub const FIRST_ITERATION: u64 = 4;

/// Whether the sample `index` of `spp` ends one of the progressive variant's iterations: 4
/// samples, then 8, 16, ..., the last cut at `spp`.
fn ends_iteration(index: u64, spp: u64) -> bool {
    let done = index + 1;
    done == spp
        || (done.is_multiple_of(FIRST_ITERATION) && (done / FIRST_ITERATION + 1).is_power_of_two())
}

/// A pixel's sums, one set per depth: the light seen directly at depth 0, the light found at
/// the `d`-th surface at depth `d`. Every pixel sample counts at every depth, including those
/// whose path ended before it (a sample that drew nothing there).
struct DepthSums {
    combination: Combination,
    /// Pixel samples finished.
    samples: u64,
    /// The pixel's iterations ended so far (for a depth first reached late).
    iterations: Vec<u64>,
    /// The sum of what needs no combining, over every depth and sample.
    certain: Vec3,
    /// The heuristic's weighted sum, over every depth and sample.
    weighted: Vec3,
    /// Per depth: its sums, its progressive estimate, and whether this sample reached it.
    optimal: Vec<OptimalSums>,
    progressive: Vec<ProgressiveOptimal>,
    reached: Vec<bool>,
}

impl DepthSums {
    fn new(combination: Combination) -> Self {
        Self {
            combination,
            samples: 0,
            iterations: Vec::new(),
            certain: Vec3::ZERO,
            weighted: Vec3::ZERO,
            optimal: Vec::new(),
            progressive: Vec::new(),
            reached: Vec::new(),
        }
    }

    /// Adds what the current sample drew at `depth`.
    fn add(&mut self, depth: usize, draws: &SurfaceDraws) {
        self.certain += draws.certain;
        match self.combination {
            Combination::Heuristic(heuristic) => {
                self.weighted += heuristic_estimate(draws, heuristic);
            }
            Combination::Optimal | Combination::Progressive => {
                while self.reached.len() <= depth {
                    self.first_reached();
                }
                self.reached[depth] = true;
                self.add_at(depth, draws);
            }
        }
    }

    /// Adds `draws` to the sums of `depth` that the combination uses.
    fn add_at(&mut self, depth: usize, draws: &SurfaceDraws) {
        match self.combination {
            Combination::Heuristic(_) => {}
            Combination::Optimal => self.optimal[depth].add(draws),
            Combination::Progressive => self.progressive[depth].add(draws),
        }
    }

    /// A depth no sample reached before: it has had every earlier sample, none of which drew.
    fn first_reached(&mut self) {
        let depth = self.reached.len();
        self.optimal.push(OptimalSums::default());
        self.progressive.push(ProgressiveOptimal::default());
        self.reached.push(false);
        let iterations = self.iterations.clone();
        let mut ends = iterations.iter().peekable();
        for sample in 1..=self.samples {
            self.add_at(depth, &SurfaceDraws::default());
            if ends.next_if_eq(&&sample).is_some() {
                self.progressive[depth].end_iteration();
            }
        }
    }

    /// Ends the current sample: the depths it did not reach count it as a sample that drew
    /// nothing; at an iteration's end, every depth's progressive estimate ends it too.
    fn end_sample(&mut self, ends_iteration: bool) {
        self.samples += 1;
        let nothing = SurfaceDraws::default();
        for depth in 0..self.reached.len() {
            if !std::mem::take(&mut self.reached[depth]) {
                self.add_at(depth, &nothing);
            }
            if ends_iteration {
                self.progressive[depth].end_iteration();
            }
        }
        if ends_iteration {
            self.iterations.push(self.samples);
        }
    }

    /// The pixel's value: the certain part averaged, plus each depth's combination.
    fn estimate(&self) -> Vec3 {
        let n = self.samples.max(1) as f32;
        let certain = self.certain / n;
        match self.combination {
            Combination::Heuristic(_) => (self.certain + self.weighted) / n,
            Combination::Optimal => {
                certain + self.optimal.iter().map(OptimalSums::estimate).sum::<Vec3>()
            }
            Combination::Progressive => {
                certain
                    + self
                        .progressive
                        .iter()
                        .map(ProgressiveOptimal::estimate)
                        .sum::<Vec3>()
            }
        }
    }
}

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::techniques::TechniqueSample;

    /// Four pixel samples; only the last reaches depth 1, where its light sample finds
    /// `f = 2` with density 1 (and the BSDF could not have drawn it). The light at depth 1 is
    /// then `(f / p) / 4 = 0.5`, as for any depth that every sample counts, drawn or not.
    #[test]
    fn a_depth_first_reached_late_counts_the_samples_before() {
        for combination in [Combination::Optimal, Combination::Progressive] {
            let mut sums = DepthSums::new(combination);
            for index in 0..4 {
                sums.add(0, &SurfaceDraws::default());
                if index == 3 {
                    let light = TechniqueSample {
                        f: Vec3::splat(2.0),
                        pdf: [1.0, 0.0],
                    };
                    let draws = SurfaceDraws {
                        certain: Vec3::ZERO,
                        drawn: [Some(light), None],
                    };
                    sums.add(1, &draws);
                }
                sums.end_sample(ends_iteration(index, 4));
            }
            let estimate = sums.estimate();
            assert!(
                (estimate - Vec3::splat(0.5)).abs().max_element() < 1e-6,
                "{}: the depth reached by the fourth sample only estimates {estimate}, not 0.5: \
                 does a depth first reached late count the samples before it as samples that \
                 drew nothing there?",
                combination.name()
            );
        }
    }

    #[test]
    fn iterations_end_after_4_12_28_samples_and_at_the_last() {
        let ends: Vec<u64> = (0..40)
            .filter(|&i| ends_iteration(i, 40))
            .map(|i| i + 1)
            .collect();
        assert_eq!(ends, [4, 12, 28, 40]);
    }
}
