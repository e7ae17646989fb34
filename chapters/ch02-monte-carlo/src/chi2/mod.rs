//! The chi-square goodness-of-fit test: does a warp deliver the density it claims?
//!
//! A warp and its density are written separately, and nothing forces them to agree: a missing
//! square root, a forgotten fold or a density off by a constant factor all compile and give
//! plausible-looking pictures, and then bias every estimator that divides by the density.
//! Nori's `warptest` and Mitsuba's `chi2` test catch such mistakes the way a statistician
//! would, and this module follows them:
//!
//! 1. Draw many samples of the warp from a fixed-seed generator and count how many land in
//!    each bin of a grid laid over the domain: the *observed* counts `O_i`.
//! 2. Integrate the claimed density over each bin and multiply by the number of samples: the
//!    *expected* counts `E_i`.
//! 3. Pearson's statistic `X² = Σ (O_i - E_i)² / E_i` measures the mismatch. If the density
//!    is right, each `O_i` scatters around `E_i` by about `√E_i`, each term is about 1, and
//!    `X²` follows the chi-square distribution with `k - 1` degrees of freedom for `k` bins
//!    (one fewer, since the counts must add up to the number of samples). A wrong density
//!    makes `X²` grow in proportion to the number of samples.
//! 4. The p-value is the chance that a correct warp would give an `X²` at least this large. A
//!    tiny p-value rejects the warp.
//!
//! The chi-square approximation needs every `E_i` to be at least about 5, so bins expecting
//! fewer are pooled into one, as Mitsuba does. A sample in a bin that expects *nothing* needs
//! no statistics at all: the warp produced a point its density calls impossible, and the test
//! fails outright with `p = 0`.
//!
//! Planar domains are binned on a grid over their bounding rectangle. Directions are binned
//! on a grid over `(φ, cos θ)` in `[0, 2π) x [-1, 1]`, where the solid-angle element is exactly
//! `dφ dcos θ`: in both cases the grid's coordinates measure the domain without distortion,
//! every bin of the sphere has the same solid angle, and integrating a density over a bin is a
//! plain double integral.
//!
//! [`chi2_test_density`] takes any sampling function and density, so chapter 07 can test its
//! light sampling with it; [`chi2_test`] is the shortcut for the chapter's [`Warp`]s.
//!
//! The pieces, one file each: `bins` (the grid), `expected` (integrating the density over the
//! bins), `simpson` (the adaptive integration rule it uses) and `pearson` (the statistic with
//! its pooling).

mod bins;
mod expected;
mod pearson;
mod simpson;
#[cfg(test)]
mod tests;

use common::sampler::unit_f32;
use glam::Vec2;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;
use statrs::distribution::{ChiSquared, ContinuousCDF};

use crate::warps::{Domain, Warp, WarpPoint};
use bins::BinGrid;
use expected::expected_counts;
use pearson::pearson_with_pooling;

/// Bins expecting fewer samples than this are pooled into one bin: below it, the counts are
/// too far from normally distributed for the chi-square distribution to describe `X²`.
pub const MIN_EXPECTED_COUNT: f64 = 5.0;

/// The outcome of one chi-square test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Chi2Result {
    /// Pearson's `X² = Σ (observed - expected)² / expected` over the bins kept.
    pub statistic: f64,
    /// The degrees of freedom: bins kept (after pooling) minus 1.
    pub dof: usize,
    /// The chance that a warp delivering its claimed density gives a statistic at least this
    /// large; 0 when a sample was impossible.
    pub p_value: f64,
    /// How many bins expected fewer than [`MIN_EXPECTED_COUNT`] samples and were pooled.
    pub pooled_bins: usize,
    /// Samples the claimed density calls impossible: in a bin expecting nothing, outside the
    /// grid, not finite, or a "direction" that is not of unit length. One is enough to fail.
    pub impossible_samples: usize,
}

/// Tests `warp` against the density it claims ([`Warp::pdf`]) with `samples` samples drawn
/// from a PCG generator seeded by `seed`, on a grid of `resolution = (columns, rows)` bins.
///
/// For a planar warp the columns divide `x` and the rows `y`; for directions the columns
/// divide `φ` and the rows `cos θ`.
pub fn chi2_test(warp: &Warp, samples: usize, seed: u64, resolution: (usize, usize)) -> Chi2Result {
    chi2_test_density(
        warp.domain(),
        samples,
        seed,
        resolution,
        |u| warp.sample(u),
        |point| warp.pdf(point),
    )
}

/// Tests a sampling function against a claimed density over `domain`: `sample` turns a
/// uniform `u` in `[0, 1)^2` into a point, and `pdf` is the density it claims, per unit area
/// for planar domains and per unit solid angle for directions. `samples`, `seed` and
/// `resolution` are as for [`chi2_test`].
pub fn chi2_test_density(
    domain: Domain,
    samples: usize,
    seed: u64,
    resolution: (usize, usize),
    sample: impl FnMut(Vec2) -> WarpPoint,
    pdf: impl Fn(WarpPoint) -> f32,
) -> Chi2Result {
    chi2_tables(domain, samples, seed, resolution, sample, pdf).result
}

/// What the test compares, bin by bin, with its verdict: the tables Nori's `warptest` draws
/// side by side.
#[derive(Clone, Debug, PartialEq)]
pub struct Chi2Tables {
    /// The samples counted in each bin, row by row (`columns` per row); an impossible sample
    /// is in none.
    pub observed: Vec<u64>,
    /// The samples the claimed density expects in each bin, in the same order.
    pub expected: Vec<f64>,
    /// Bins per row.
    pub columns: usize,
    /// The verdict.
    pub result: Chi2Result,
}

/// [`chi2_test_density`], keeping the observed and expected counts of every bin.
pub fn chi2_tables(
    domain: Domain,
    samples: usize,
    seed: u64,
    resolution: (usize, usize),
    mut sample: impl FnMut(Vec2) -> WarpPoint,
    pdf: impl Fn(WarpPoint) -> f32,
) -> Chi2Tables {
    let grid = BinGrid::new(domain, resolution);
    let expected = expected_counts(&grid, &pdf, samples);

    let mut observed = vec![0u64; grid.len()];
    let mut impossible_samples = 0;
    let mut rng = Pcg32::seed_from_u64(seed);
    for _ in 0..samples {
        let u = Vec2::new(unit_f32(rng.next_u32()), unit_f32(rng.next_u32()));
        match grid.bin_of(sample(u)) {
            Some(bin) if expected[bin] > 0.0 => observed[bin] += 1,
            _ => impossible_samples += 1,
        }
    }

    let pearson = pearson_with_pooling(&observed, &expected);
    let dof = pearson.kept_bins.saturating_sub(1);
    let p_value = if impossible_samples > 0 {
        0.0
    } else if dof == 0 {
        // A single bin holds every sample: there is nothing to compare.
        1.0
    } else {
        let distribution = ChiSquared::new(dof as f64).expect("dof is positive");
        // The survival function 1 - CDF, computed directly: for large X² the CDF rounds to 1
        // and the subtraction would give 0 instead of, say, 1e-40.
        distribution.sf(pearson.statistic)
    };
    let result = Chi2Result {
        statistic: pearson.statistic,
        dof,
        p_value,
        pooled_bins: pearson.pooled_bins,
        impossible_samples,
    };
    Chi2Tables {
        observed,
        expected,
        columns: resolution.0,
        result,
    }
}

/// The significance level for each of `tests` tests so that, if every warp is correct, the
/// chance that *any* of them fails is `alpha` (Šidák's correction): `1 - (1 - alpha)^(1/tests)`.
///
/// Run twenty correct warps at `alpha = 0.01` each and one of them fails with probability
/// `1 - 0.99^20 ≈ 18%`; a test suite that fails that often is ignored. Each test gets the
/// stricter level instead, about `alpha / tests`. It is computed through `ln_1p` and `expm1`
/// so that tiny levels do not lose their digits in `1 - (...)`.
pub fn significance_level(tests: usize, alpha: f64) -> f64 {
    -((-alpha).ln_1p() / tests as f64).exp_m1()
}
