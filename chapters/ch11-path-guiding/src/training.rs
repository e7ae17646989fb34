//! Training and rendering: iterations of doubling sample counts, each sampling from the guides
//! the one before it learnt, then a final pass with what they learnt.
//!
//! Müller et al. spend a render's budget this way: iteration `k` renders `2^k` samples per
//! pixel with the guides learnt so far and learns new ones from its own paths; after it, the
//! spatial tree splits its busy leaves, and each quadtree is rebuilt around what it learnt.
//! Training stops when the rest of the budget would be less than twice the next iteration,
//! so that the final pass, guided by the last guides and recording nothing, gets at least as
//! many samples (or as much time) as all the training before it. Every iteration's image is
//! kept: each is unbiased, and the render averages them with the final pass's, the noisy
//! early ones counting for little ([`crate::combine`]).

use crate::combine::PassWeighting;
use crate::path::{GuideRecord, GuidedPathTracer, Learning};
use crate::quadtree::{DirectionTree, SPLIT_FRACTION};
use crate::selection::{self, LearntFraction};
use crate::spatial::SpatialTree;
use crate::target::{GuidingTarget, pixel_estimates};
use ch05_motion_blur::TimeSampler;
use ch08_path_tracing::{Materials, PathTracer};
use common::image::Image;
use common::render::{Budget, PassCost, RenderSettings, render_recorded};
use common::sampler::Sampler;
use glam::{UVec2, Vec2};
use std::time::Instant;

/// How a render is guided.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GuidingOptions {
    /// What the guides follow.
    pub target: GuidingTarget,
    /// The probability of drawing a direction from the BSDF rather than the guide, if fixed;
    /// `None`: each region learns its own ([`crate::selection`]).
    pub bsdf_fraction: Option<f32>,
    /// `c` of the spatial tree's threshold: a leaf is split when it received more than
    /// `c · sqrt(spp)` records in an iteration of `spp` samples per pixel (Müller et al.'s
    /// `c = 12000`, for images of about a million pixels).
    pub spatial_threshold: f64,
    /// The share of a quadtree above which a quadrant is split ([`SPLIT_FRACTION`]).
    pub split_fraction: f32,
    /// How the training's images join the final pass's in the image ([`crate::combine`]): by
    /// their samples and what their guides learnt from (unbiased, the default), by their
    /// samples alone (unbiased), by their measured noise (Müller et al. 2019: consistent
    /// rather than unbiased), or not at all (Müller et al. 2017).
    pub passes: PassWeighting,
}

impl GuidingOptions {
    /// Guiding towards `target` with the papers' settings.
    pub fn new(target: GuidingTarget) -> Self {
        Self {
            target,
            bsdf_fraction: None,
            spatial_threshold: 12000.0,
            split_fraction: SPLIT_FRACTION,
            passes: PassWeighting::ByLearning,
        }
    }

    /// The spatial threshold of Müller et al., scaled to an image of `pixels`: their `c` is
    /// for images of about a million pixels, and a smaller image's iteration has
    /// proportionally fewer records to split its leaves with.
    pub fn for_image(target: GuidingTarget, pixels: u64) -> Self {
        let scale = (pixels as f64 / 1e6).clamp(1e-3, 1.0);
        Self {
            spatial_threshold: 12000.0 * scale.sqrt(),
            ..Self::new(target)
        }
    }
}

/// What one training iteration did and cost.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrainingIteration {
    /// Its samples per pixel.
    pub spp: u64,
    /// Its wall-clock seconds, learning and rebuilding included.
    pub seconds: f64,
    /// Its rays.
    pub rays: u64,
    /// Spatial leaves after it (the guides the next one samples from).
    pub leaves: usize,
    /// Quadtree nodes of those guides, all leaves together.
    pub quadtree_nodes: usize,
    /// The bytes of the whole tree after it.
    pub memory_bytes: usize,
    /// Its samples whose radiance was not finite (a bug upstream), left out of its image.
    pub nonfinite_samples: u64,
    /// The BSDF fraction learnt so far, the leaves' mean weighted by the samples each learnt
    /// from; `None` while nothing has been learnt (or the fraction is fixed).
    pub learnt_fraction: Option<f32>,
}

/// The guides learnt by a training run and what it cost.
#[derive(Clone, Debug)]
pub struct Trained {
    /// The guides, ready to sample from.
    pub guides: SpatialTree,
    /// The iterations, in order.
    pub iterations: Vec<TrainingIteration>,
    /// Each iteration's image (each pixel its samples' mean), in order.
    pub images: Vec<Image>,
    /// Samples per pixel spent.
    pub spp: u64,
    /// Whether a stop ended it.
    pub interrupted: bool,
}

/// How much training a budget allows: the next iteration of `next_spp` is trained when what is
/// left after it would still be at least twice it, the final pass then getting at least as
/// much as all the training. `spent_spp` and `elapsed` are what the training has used, and
/// `seconds_per_spp` its rate.
pub fn trains_next(
    budget: Budget,
    spent_spp: u64,
    next_spp: u64,
    elapsed: f64,
    seconds_per_spp: f64,
) -> bool {
    match budget {
        Budget::Samples(total) => total.saturating_sub(spent_spp) >= 3 * next_spp,
        Budget::Seconds(total) => {
            let next = next_spp as f64 * seconds_per_spp;
            total - elapsed >= 3.0 * next
        }
    }
}

/// Trains guides over `bounds` for a render of `settings`' budget: iterations of 1, 2, 4,
/// ... samples per pixel ([`trains_next`]), each path traced by `tracer` guided by what was
/// learnt so far, with sample indices after the iterations before, its camera ray from
/// `camera_ray`.
pub fn train<S, M, R>(
    settings: &RenderSettings,
    sampler: &S,
    guiding: GuidingOptions,
    bounds: common::geometry::Aabb,
    tracer: &PathTracer<'_, M>,
    camera_ray: R,
) -> Trained
where
    S: TimeSampler,
    M: Materials,
    R: Fn(Vec2, &mut Offset<S>) -> common::Ray + Sync,
{
    let start = Instant::now();
    let mut guides = SpatialTree::new(bounds);
    let mut trained = Trained {
        guides: SpatialTree::new(bounds),
        iterations: Vec::new(),
        images: Vec::new(),
        spp: 0,
        interrupted: false,
    };
    let mut spp = 1u64;
    let mut seconds_per_spp = 0.0;
    while trains_next(
        settings.budget,
        trained.spp,
        spp,
        start.elapsed().as_secs_f64(),
        seconds_per_spp,
    ) {
        let iteration_start = Instant::now();
        // The pixel estimates of the iteration before (1 everywhere for the first: a constant
        // changes no guide, as each guide is a distribution of its own).
        let estimates = trained.images.last().map(pixel_estimates);
        let width = settings.width;
        let estimate_of = |p_film: Vec2| -> f32 {
            let pixel = p_film
                .floor()
                .as_uvec2()
                .min(UVec2::new(settings.width, settings.height) - 1);
            estimates
                .as_ref()
                .map_or(1.0, |e| e[(pixel.y * width + pixel.x) as usize])
        };
        // The quadtrees and fractions being learnt are taken out of the tree for the pass, so
        // that the paths can read the guides while the records are added between slices.
        let mut building: Vec<(DirectionTree, u64, LearntFraction)> = guides
            .guides
            .iter_mut()
            .map(|g| (std::mem::take(&mut g.building), 0, g.fraction))
            .collect();
        let loss = selection::loss_of(guiding.target);
        let offset = Offset {
            inner: sampler.clone(),
            first_index: trained.spp,
        };
        let guided = GuidedPathTracer {
            tracer,
            guides: &guides,
            bsdf_fraction: guiding.bsdf_fraction,
        };
        let pass = render_recorded(
            settings,
            &offset,
            0..spp,
            |p_film, sampler: &mut Offset<S>, records: &mut Vec<GuideRecord>| {
                let ray = camera_ray(p_film, sampler);
                let learning = Learning {
                    target: guiding.target,
                    pixel_estimate: estimate_of(p_film),
                    records,
                };
                guided.radiance(&ray, sampler, Some(learning))
            },
            |records| {
                for r in records {
                    let (tree, count, fraction) = &mut building[r.guide as usize];
                    tree.record(r.point, r.value);
                    *count += 1;
                    if let Some(sample) = &r.fraction {
                        fraction.learn(sample, loss);
                    }
                }
            },
        );
        for (guide, (tree, count, fraction)) in guides.guides.iter_mut().zip(building) {
            guide.building = tree;
            guide.records = count;
            guide.fraction = fraction;
        }
        let Some((image, cost)) = pass else {
            trained.interrupted = true;
            break;
        };
        learn(&mut guides, guiding, spp);
        trained.spp += spp;
        trained.images.push(image);
        let seconds = iteration_start.elapsed().as_secs_f64();
        seconds_per_spp = seconds / spp as f64;
        trained
            .iterations
            .push(iteration_report(&guides, spp, seconds, cost));
        spp *= 2;
    }
    trained.guides = guides;
    trained
}

/// After an iteration of `spp` samples per pixel: each guide's new quadtree is built and
/// becomes the one sampled; busy leaves are split; each guide starts learning a quadtree
/// shaped by what it has learnt. (The book's live demo trains with it too.)
pub fn learn(guides: &mut SpatialTree, guiding: GuidingOptions, spp: u64) {
    for guide in &mut guides.guides {
        let mut built = std::mem::take(&mut guide.building);
        built.build(|sum, area| guiding.target.leaf_weight(sum, area));
        // A guide that learnt nothing this time keeps what it had.
        if built.total() > 0.0 {
            guide.sampling = built;
        }
    }
    guides.refine(guiding.spatial_threshold * (spp as f64).sqrt());
    for guide in &mut guides.guides {
        guide.building = guide.sampling.refined(guiding.split_fraction);
        guide.records = 0;
    }
}

/// What an iteration did, from the tree after it.
fn iteration_report(
    guides: &SpatialTree,
    spp: u64,
    seconds: f64,
    cost: PassCost,
) -> TrainingIteration {
    TrainingIteration {
        spp,
        seconds,
        rays: cost.rays,
        leaves: guides.guides.len(),
        quadtree_nodes: guides.guides.iter().map(|g| g.sampling.nodes.len()).sum(),
        memory_bytes: guides.memory_bytes(),
        nonfinite_samples: cost.nonfinite_samples,
        learnt_fraction: mean_learnt_fraction(guides),
    }
}

/// The leaves' learnt fractions, averaged with the samples each learnt from as weights.
fn mean_learnt_fraction(guides: &SpatialTree) -> Option<f32> {
    let (sum, steps) = guides.guides.iter().fold((0.0f64, 0.0f64), |(sum, n), g| {
        let steps = f64::from(g.fraction.steps());
        (sum + steps * f64::from(g.fraction.fraction()), n + steps)
    });
    (steps > 0.0).then(|| (sum / steps) as f32)
}

/// A sampler whose sample indices start at `first_index`: each pass draws numbers of its own,
/// so that the final pass does not repeat the training's paths. The harness's, not the
/// lecture's.
#[derive(Clone, Debug)]
pub struct Offset<S> {
    /// The sampler.
    pub inner: S,
    /// The index the pass's sample 0 takes.
    pub first_index: u64,
}

impl<S: Sampler> Sampler for Offset<S> {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.inner
            .start_pixel_sample(pixel, self.first_index.saturating_add(sample_index));
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        self.inner.get_pixel_2d()
    }

    fn get_1d(&mut self) -> f32 {
        self.inner.get_1d()
    }

    fn get_2d(&mut self) -> Vec2 {
        self.inner.get_2d()
    }
}

impl<S: TimeSampler> TimeSampler for Offset<S> {
    fn get_time_1d(&mut self) -> f32 {
        self.inner.get_time_1d()
    }
}
