//! Where in the shutter interval the samples of a pixel go.
//!
//! The time is the sample's second dimension, after the pixel position and before the lens
//! (pbrt-v4's order). *Independent* time samples are uniform numbers, each on its own; they
//! clump and leave gaps, and a pixel that a moving edge crosses sees the edge's time share
//! with the noise of a coin tossed `n` times. *Stratified* time samples cut the interval into
//! `n` equal strata, one per sample, each sample jittered inside its own: the share of time
//! is then right to within one stratum.
//!
//! Which sample gets which stratum is a permutation, different for every pixel (fixed by the
//! seed and the pixel, so renders stay deterministic): with the same order everywhere, sample
//! `i` would see the same instant in every pixel, and the time would correlate with the pixel
//! position and the lens, which other samplers stratify by sample index too.

use ch03_anti_aliasing::PixelSampler;
use ch03_anti_aliasing::pixel_samplers::permutation_element;
use common::render::Budget;
use common::sampler::{IndependentSampler, Sampler, mix};
use glam::{UVec2, Vec2};

/// A sampler that can hand out the time dimension.
pub trait TimeSampler: Sampler {
    /// The number in `[0, 1)` that picks the sample's time. By default the next dimension.
    fn get_time_1d(&mut self) -> f32 {
        self.get_1d()
    }
}

impl TimeSampler for IndependentSampler {}
impl TimeSampler for PixelSampler {}

/// The two ways of drawing time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum TimeSampling {
    /// Each sample's time on its own.
    Independent,
    /// One sample per stratum of the shutter interval, in a per-pixel random order.
    Stratified,
}

impl TimeSampling {
    /// What a render that offers no choice uses: stratified time when something moves and the
    /// budget is a sample count (the strata are laid out for it), else independent time (and
    /// a scene that does not move draws no time at all, so the choice changes nothing).
    pub fn by_default(moves: bool, budget: &Budget) -> Self {
        match budget {
            Budget::Samples(_) if moves => TimeSampling::Stratified,
            _ => TimeSampling::Independent,
        }
    }

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            TimeSampling::Independent => "independent",
            TimeSampling::Stratified => "stratified",
        }
    }

    /// `inner` drawing its times this way in a render of `budget`: stratified over the `spp`
    /// samples of a pixel, or independent, which is stratified time with one stratum, the
    /// whole shutter. Stratified time needs a sample count to lay out its strata.
    pub fn sampler<S: Sampler>(
        self,
        inner: S,
        budget: &Budget,
        seed: u64,
    ) -> Result<StratifiedTime<S>, String> {
        match (self, budget) {
            (TimeSampling::Independent, _) => Ok(StratifiedTime::new(inner, 1, seed)),
            (TimeSampling::Stratified, Budget::Samples(spp)) => {
                Ok(StratifiedTime::new(inner, *spp, seed))
            }
            (TimeSampling::Stratified, Budget::Seconds(_)) => Err(
                "stratified time cuts the shutter into one stratum per sample, so it needs a sample count (--spp), not --time".to_string(),
            ),
        }
    }
}

/// The largest `f32` below 1.
pub const ONE_MINUS_EPSILON: f32 = 1.0 - f32::EPSILON / 2.0;

// ANCHOR: stratified_time_sample
/// The time sample of stratum `stratum` out of `strata` equal parts of `[0, 1)`, jittered by
/// `jitter` in `[0, 1)`: a uniform number inside that part, `jitter` saying where. Always
/// below 1, even where `f32` rounding of the last part's top would give exactly 1
/// (`ONE_MINUS_EPSILON` is the largest `f32` below 1).
pub fn stratified_time_sample(stratum: u64, strata: u64, jitter: f32) -> f32 {
    // BEGIN SOLUTION
    let u = (stratum as f64 + f64::from(jitter)) / strata.max(1) as f64;
    (u as f32).min(ONE_MINUS_EPSILON)
    // END SOLUTION
}
// ANCHOR_END: stratified_time_sample

/// Wraps a sampler and stratifies its time dimension over the `strata` samples of a pixel;
/// every other dimension comes from the inner sampler unchanged. With one stratum the time is
/// the inner sampler's own number, as independent time draws it.
///
/// Samples `strata .. 2 strata` (a longer render) get a fresh permutation, so every run of
/// `strata` consecutive samples covers every stratum once.
#[derive(Clone, Debug)]
pub struct StratifiedTime<S> {
    inner: S,
    strata: u64,
    seed: u64,
    stratum: u64,
}

impl<S: Sampler> StratifiedTime<S> {
    /// `inner` with its time stratified over `strata` samples (at least 1).
    pub fn new(inner: S, strata: u64, seed: u64) -> Self {
        Self {
            inner,
            strata: strata.clamp(1, u64::from(u32::MAX)),
            seed,
            stratum: 0,
        }
    }

    /// The stratum of the current sample.
    pub fn stratum(&self) -> u64 {
        self.stratum
    }
}

impl<S: Sampler> Sampler for StratifiedTime<S> {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.inner.start_pixel_sample(pixel, sample_index);
        if self.strata == 1 {
            // One stratum: every sample's, with no permutation to draw.
            self.stratum = 0;
            return;
        }
        let pixel_key = (u64::from(pixel.y) << 32) | u64::from(pixel.x);
        let round = sample_index / self.strata;
        let key = mix(mix(self.seed ^ 0x7469_6d65) ^ mix(pixel_key) ^ round) as u32;
        let i = (sample_index % self.strata) as u32;
        self.stratum = u64::from(permutation_element(i, self.strata as u32, key));
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

impl<S: Sampler> TimeSampler for StratifiedTime<S> {
    fn get_time_1d(&mut self) -> f32 {
        // The jitter is the inner sampler's next number: the same dimension an independent
        // time would use, so the lens and later dimensions are unchanged.
        stratified_time_sample(self.stratum, self.strata, self.inner.get_1d())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exercise_stratified_time_sample_lands_in_its_stratum() {
        for strata in [1u64, 2, 7, 64] {
            for stratum in 0..strata {
                for jitter in [0.0, 0.25, 0.5, 0.999] {
                    let u = stratified_time_sample(stratum, strata, jitter);
                    let low = stratum as f32 / strata as f32;
                    let high = (stratum + 1) as f32 / strata as f32;
                    assert!(
                        u >= low && u < high,
                        "stratified_time_sample: stratum {stratum} of {strata} is the stretch \
                         [{low}, {high}) of the shutter, and the jitter ({jitter}) only moves \
                         the sample within it; yours gave {u}"
                    );
                }
            }
        }
        let u = stratified_time_sample(3, 8, 0.5);
        assert!(
            u == 3.5 / 8.0,
            "stratified_time_sample: the jitter 0.5 puts the sample in the middle of stratum 3 of \
             8, at {}; yours gave {u}{}",
            3.5 / 8.0,
            if u == 3.0 / 8.0 {
                ": the jitter is left out, so every sample of a stratum falls at its start"
            } else {
                ""
            }
        );
    }

    #[test]
    fn exercise_stratified_time_sample_stays_below_one() {
        let strata = 1u64 << 30;
        let u = stratified_time_sample(strata - 1, strata, ONE_MINUS_EPSILON);
        assert!(
            u < 1.0,
            "stratified_time_sample: the last of 2^30 strata with the largest jitter gave {u}: \
             in f32, the largest jitter in the last stratum can round up to 1, which is outside \
             the shutter interval [0, 1)"
        );
        let u = stratified_time_sample(0, 1, ONE_MINUS_EPSILON);
        assert!(
            u == ONE_MINUS_EPSILON,
            "stratified_time_sample: one stratum and the largest jitter below 1 give that jitter \
             back, {ONE_MINUS_EPSILON}; yours gave {u}{}",
            if u < ONE_MINUS_EPSILON && u > 0.999 {
                ": the bound that keeps the sample below 1 is lower than it needs to be (1 - \
                 f32::EPSILON is two steps below 1; ONE_MINUS_EPSILON is the largest f32 below 1)"
            } else {
                ""
            }
        );
    }

    #[test]
    fn every_pixel_covers_every_stratum_once_in_a_different_order() {
        let n = 8;
        let mut sampler = StratifiedTime::new(IndependentSampler::new(3), n, 3);
        let mut orders = Vec::new();
        for pixel in [UVec2::new(0, 0), UVec2::new(1, 0), UVec2::new(5, 9)] {
            let mut strata = Vec::new();
            for index in 0..2 * n {
                sampler.start_pixel_sample(pixel, index);
                sampler.get_pixel_2d();
                let u = sampler.get_time_1d();
                strata.push((u * n as f32) as u64);
                assert_eq!(strata[index as usize], sampler.stratum());
            }
            for round in strata.chunks(n as usize) {
                let mut sorted = round.to_vec();
                sorted.sort();
                assert_eq!(sorted, (0..n).collect::<Vec<_>>(), "{pixel}");
            }
            orders.push(strata);
        }
        assert_ne!(orders[0], orders[1]);
        assert_ne!(orders[1], orders[2]);
    }

    #[test]
    fn one_stratum_is_independent_time() {
        let budget = Budget::Samples(16);
        let mut one = TimeSampling::Independent
            .sampler(IndependentSampler::new(5), &budget, 5)
            .unwrap();
        let mut inner = IndependentSampler::new(5);
        for (pixel, index) in [(UVec2::new(0, 0), 0), (UVec2::new(7, 3), 11)] {
            one.start_pixel_sample(pixel, index);
            inner.start_pixel_sample(pixel, index);
            assert_eq!(one.get_pixel_2d(), inner.get_pixel_2d());
            assert_eq!(one.get_time_1d(), inner.get_1d());
            assert_eq!(one.get_2d(), inner.get_2d());
        }
        let stratified = TimeSampling::Stratified.sampler(IndependentSampler::new(5), &budget, 5);
        assert_eq!(stratified.unwrap().strata, 16);
        let timed =
            TimeSampling::Stratified.sampler(IndependentSampler::new(5), &Budget::Seconds(1.0), 5);
        assert!(timed.unwrap_err().contains("--spp"));
    }
}
