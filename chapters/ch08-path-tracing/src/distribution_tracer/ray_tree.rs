//! Measuring the ray tree: how many rays one camera ray costs, and how much of the pixel the
//! rays of each depth carry.
//!
//! Both numbers come from renders, not formulas: the tree's real size depends on the scene
//! (a ray that leaves it, or meets a black surface, does not branch), and so does the light
//! each depth adds. A depth's share is measured by rendering with `max_depth = d` and
//! `d - 1` with the **same seed** and differencing the mean radiance: the two renders draw
//! the same numbers for the shallow part of every tree, so their difference is the light of
//! depth `d` alone, with little noise.

use super::{DistributionOptions, render_distribution};
use ch03_anti_aliasing::{FilterKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use common::render::{RenderOutput, RenderSettings};
use common::sampler::IndependentSampler;

/// A render of `scene` at `size` and `spp`, pinhole, box filter, independent samples.
pub fn render_small(
    scene: &MotionScene,
    options: DistributionOptions,
    size: (u32, u32),
    spp: u64,
    seed: u64,
) -> RenderOutput {
    let settings = RenderSettings::new(size.0, size.1, spp);
    let filter = ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter");
    render_distribution(
        scene,
        options,
        &Lens::PINHOLE,
        &settings,
        &IndependentSampler::new(seed),
        &filter,
    )
}

/// Rays of every kind (secondary and shadow rays, the camera ray itself) per camera ray.
pub fn rays_per_camera_ray(output: &RenderOutput) -> f64 {
    let stats = &output.stats;
    let camera_rays = u64::from(stats.width) * u64::from(stats.height) * stats.spp;
    stats.rays as f64 / camera_rays.max(1) as f64
}

/// The mean radiance (all channels averaged) of a render: what a depth's share is of.
pub fn mean_radiance(output: &RenderOutput) -> f64 {
    let mean = common::metrics::mean(&output.image);
    (mean.x + mean.y + mean.z) / 3.0
}

/// For `d = 1 ..= max_depth`: the share of the image's mean radiance carried by rays of depth
/// `d` (segment `d` of their branch), from renders that differ only in `max_depth`.
pub fn depth_shares(
    scene: &MotionScene,
    options: DistributionOptions,
    size: (u32, u32),
    spp: u64,
    seed: u64,
) -> Vec<(u32, f64)> {
    let means: Vec<f64> = (1..=options.max_depth)
        .map(|d| {
            let at_depth = DistributionOptions {
                max_depth: d,
                ..options
            };
            mean_radiance(&render_small(scene, at_depth, size, spp, seed))
        })
        .collect();
    let total = means.last().copied().unwrap_or(0.0).max(f64::MIN_POSITIVE);
    means
        .iter()
        .enumerate()
        .map(|(i, &mean)| {
            let previous = if i == 0 { 0.0 } else { means[i - 1] };
            (i as u32 + 1, (mean - previous) / total)
        })
        .collect()
}
