//! How many dimensions a path draws: a [`Sampler`] that counts, for `render --stats`.
//!
//! A sample's dimensions are the numbers it draws: the pixel position (2), the time (1, only
//! if something moves), the lens point (2, only for an aperture), then per bounce the light
//! pick, the light point and the BSDF's numbers. Counting them shows that a scene pays only
//! for what it uses: a static pinhole scene draws no time and no lens numbers, a scene lit by
//! point lights alone no light numbers at all.
//!
//! [`CountingSampler`] hands every call on to the sampler it wraps, unchanged and in the same
//! order, so the image is the same bit for bit; it only adds up how many numbers were asked
//! for. The sums live in the wrapper (one per tile, as the render loop clones the sampler per
//! tile) and reach the shared [`DimensionTally`] once, when the tile's copy is dropped: no
//! atomic operation per sample. A render without `--stats` does not use the wrapper at all.

use crate::bsdf::Materials;
use crate::{Method, render_with_materials};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch05_motion_blur::TimeSampler;
use common::film::Filter;
use common::render::{RenderOutput, RenderSettings};
use common::sampler::Sampler;
use glam::{UVec2, Vec2};
use std::sync::atomic::{AtomicU64, Ordering};

/// Dimensions per path over a whole render, shared by the tiles' samplers.
#[derive(Debug, Default)]
pub struct DimensionTally {
    paths: AtomicU64,
    total: AtomicU64,
    max: AtomicU64,
}

/// The dimensions drawn per path, as `--stats` writes them (`dimensions_per_path`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DimensionStats {
    /// The mean over the render's samples.
    pub mean: f64,
    /// The most any one sample drew.
    pub max: u64,
    /// How many samples were counted.
    pub paths: u64,
}

impl DimensionTally {
    /// The mean and maximum so far (0 and 0 before any sample).
    pub fn stats(&self) -> DimensionStats {
        let paths = self.paths.load(Ordering::Relaxed);
        let total = self.total.load(Ordering::Relaxed);
        DimensionStats {
            mean: if paths > 0 {
                total as f64 / paths as f64
            } else {
                0.0
            },
            max: self.max.load(Ordering::Relaxed),
            paths,
        }
    }

    fn add(&self, local: &Local) {
        if local.paths > 0 {
            self.paths.fetch_add(local.paths, Ordering::Relaxed);
            self.total.fetch_add(local.total, Ordering::Relaxed);
            self.max.fetch_max(local.max, Ordering::Relaxed);
        }
    }
}

/// The sums of one copy of the sampler: finished samples, and the one being drawn.
#[derive(Clone, Copy, Debug, Default)]
struct Local {
    paths: u64,
    total: u64,
    max: u64,
    current: Option<u64>,
}

impl Local {
    /// Closes the sample being drawn, if any.
    fn finish_sample(&mut self) {
        if let Some(n) = self.current.take() {
            self.paths += 1;
            self.total += n;
            self.max = self.max.max(n);
        }
    }
}

// ANCHOR: counting_sampler
/// `inner`, counting the dimensions of each sample: a 1D draw counts 1, a 2D draw (the pixel
/// position among them) counts 2.
#[derive(Debug)]
pub struct CountingSampler<'a, S> {
    inner: S,
    tally: &'a DimensionTally,
    local: Local,
}

impl<'a, S: Sampler> CountingSampler<'a, S> {
    /// `inner`, reporting to `tally`.
    pub fn new(inner: S, tally: &'a DimensionTally) -> Self {
        Self {
            inner,
            tally,
            local: Local::default(),
        }
    }

    /// The dimensions drawn so far by the current sample.
    pub fn drawn(&self) -> u64 {
        self.local.current.unwrap_or(0)
    }

    fn count(&mut self, n: u64) {
        *self.local.current.get_or_insert(0) += n;
    }
}

impl<S: Sampler> Sampler for CountingSampler<'_, S> {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.local.finish_sample();
        self.local.current = Some(0);
        self.inner.start_pixel_sample(pixel, sample_index);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        self.count(2);
        self.inner.get_pixel_2d()
    }

    fn get_1d(&mut self) -> f32 {
        self.count(1);
        self.inner.get_1d()
    }

    // Handed on as a 2D draw, not as two 1D draws: a sampler may place its pairs differently.
    fn get_2d(&mut self) -> Vec2 {
        self.count(2);
        self.inner.get_2d()
    }
}

impl<S: TimeSampler> TimeSampler for CountingSampler<'_, S> {
    fn get_time_1d(&mut self) -> f32 {
        self.count(1);
        self.inner.get_time_1d()
    }
}
// ANCHOR_END: counting_sampler

/// A copy starts with nothing counted: the render loop's copies count their own tiles.
impl<S: Clone> Clone for CountingSampler<'_, S> {
    fn clone(&self) -> Self {
        Self {
            inner: self.inner.clone(),
            tally: self.tally,
            local: Local::default(),
        }
    }
}

/// A copy hands its sums to the tally when the render loop is done with it.
impl<S> Drop for CountingSampler<'_, S> {
    fn drop(&mut self) {
        self.local.finish_sample();
        self.tally.add(&self.local);
    }
}

/// [`render_with_materials`], and with `count` also the dimensions per path. Without `count`
/// this is exactly `render_with_materials` with `sampler`; with it, the same image, through a
/// [`CountingSampler`].
#[allow(clippy::too_many_arguments)]
pub fn render_counted<S: TimeSampler, M: Materials>(
    count: bool,
    scene: &MotionScene,
    method: Method,
    materials: M,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> (RenderOutput, Option<DimensionStats>) {
    if !count {
        return (
            render_with_materials(scene, method, materials, lens, settings, sampler, filter),
            None,
        );
    }
    let tally = DimensionTally::default();
    let counting = CountingSampler::new(sampler.clone(), &tally);
    let output = render_with_materials(scene, method, materials, lens, settings, &counting, filter);
    drop(counting);
    (output, Some(tally.stats()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use common::sampler::IndependentSampler;

    #[test]
    fn counts_one_per_1d_two_per_2d_and_hands_on_the_same_numbers() {
        let tally = DimensionTally::default();
        let mut plain = IndependentSampler::new(5);
        {
            let mut counting = CountingSampler::new(IndependentSampler::new(5), &tally);
            for (index, draws) in [(0u64, 1usize), (1, 3)] {
                plain.start_pixel_sample(UVec2::new(2, 3), index);
                counting.start_pixel_sample(UVec2::new(2, 3), index);
                assert_eq!(counting.get_pixel_2d(), plain.get_pixel_2d());
                for _ in 0..draws {
                    assert_eq!(counting.get_1d(), plain.get_1d());
                    assert_eq!(counting.get_2d(), plain.get_2d());
                }
                assert_eq!(counting.drawn(), 2 + 3 * draws as u64);
            }
        }
        let stats = tally.stats();
        assert_eq!((stats.paths, stats.max), (2, 11));
        assert_eq!(stats.mean, (5.0 + 11.0) / 2.0);
    }
}
