//! Are the numbers spread evenly? Pearson's chi-square test, in one and in three dimensions.
//!
//! Cut `[0, 1)` into `bins` equal bins and count where `samples` numbers land. A perfect
//! generator puts `E = samples / bins` in each on average, with Poisson-like scatter, and
//! Pearson's statistic `X^2 = Σ (O - E)^2 / E` then follows a chi-square distribution with
//! `bins - 1` degrees of freedom. The p-value is the chance that a perfect generator scatters
//! at least this much: a tiny p-value (say below 0.001) means "not uniform".
//!
//! The 3D *serial* test does the same with consecutive non-overlapping triples and `k^3` cubic
//! cells, so it also checks that neighbouring numbers are independent. How well does it catch
//! RANDU, whose triples lie on 15 planes? It depends on the resolution. With 2 cells per axis
//! (the 8 octants) RANDU *passes*: every octant is cut by planes of the same total area, so
//! each gets its fair share. With 4 cells per axis and 100 000 triples it fails (p-values of
//! 1e-5 to 1e-9 depending on the seed), with 8 per axis overwhelmingly. A cell test needs fine
//! cells and many samples to see structure; the lattice test of [`super::randu_plane_index`]
//! shows RANDU's flaw directly, with a handful of triples.

use rand::Rng;
use statrs::distribution::{ChiSquared, ContinuousCDF};

/// The result of a chi-square test against the uniform distribution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChiSquareOutcome {
    /// Pearson's statistic `Σ (observed - expected)^2 / expected` over all cells.
    pub statistic: f64,
    /// Number of cells minus one (the counts must add up to the total, which fixes one).
    pub degrees_of_freedom: usize,
    /// Chance that a truly uniform generator gives a statistic at least this large.
    pub p_value: f64,
}

/// Pearson's test that `samples` numbers from `source` fall evenly into `bins` equal bins of
/// `[0, 1)`.
///
/// # Panics
///
/// If `bins < 2`, or if fewer than 5 samples are expected per bin: below that the statistic no
/// longer follows the chi-square distribution and the p-value would mislead.
pub fn uniformity_chi2<R: Rng + ?Sized>(
    source: &mut R,
    samples: usize,
    bins: usize,
) -> ChiSquareOutcome {
    check_expected_counts(samples, bins);
    let mut counts = vec![0u64; bins];
    for _ in 0..samples {
        counts[cell_of(source.next_u32(), bins)] += 1;
    }
    chi_square_against_uniform(&counts)
}

/// Pearson's test that `triples` consecutive non-overlapping triples `(x, y, z)` from `source`
/// fall evenly into the `k^3` cells of the unit cube, `k = cells_per_axis`.
///
/// # Panics
///
/// If `cells_per_axis < 2`, or if fewer than 5 triples are expected per cell.
pub fn serial_chi2_3d<R: Rng + ?Sized>(
    source: &mut R,
    triples: usize,
    cells_per_axis: usize,
) -> ChiSquareOutcome {
    let cells = cells_per_axis.pow(3);
    check_expected_counts(triples, cells);
    let mut counts = vec![0u64; cells];
    for _ in 0..triples {
        let x = cell_of(source.next_u32(), cells_per_axis);
        let y = cell_of(source.next_u32(), cells_per_axis);
        let z = cell_of(source.next_u32(), cells_per_axis);
        counts[(x * cells_per_axis + y) * cells_per_axis + z] += 1;
    }
    chi_square_against_uniform(&counts)
}

/// Which of `cells` equal parts of `[0, 1)` the number `word / 2^32` falls in.
///
/// This is `floor(u * cells)` computed exactly in integers: no float rounding can put the
/// largest number into a cell `cells` that does not exist.
fn cell_of(word: u32, cells: usize) -> usize {
    ((u64::from(word) * cells as u64) >> 32) as usize
}

/// Asserts the conditions under which Pearson's statistic is chi-square distributed.
fn check_expected_counts(samples: usize, cells: usize) {
    assert!(cells >= 2, "a chi-square test needs at least 2 cells");
    assert!(
        samples >= 5 * cells,
        "{samples} samples in {cells} cells: expect at least 5 per cell"
    );
}

/// Pearson's statistic for `counts` against equal expected counts, with its p-value.
fn chi_square_against_uniform(counts: &[u64]) -> ChiSquareOutcome {
    let total: u64 = counts.iter().sum();
    let expected = total as f64 / counts.len() as f64;
    let statistic = counts
        .iter()
        .map(|&observed| (observed as f64 - expected).powi(2) / expected)
        .sum();
    let degrees_of_freedom = counts.len() - 1;
    let distribution =
        ChiSquared::new(degrees_of_freedom as f64).expect("at least one degree of freedom");
    ChiSquareOutcome {
        statistic,
        degrees_of_freedom,
        p_value: distribution.sf(statistic),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Generator;
    use std::convert::Infallible;

    use rand::TryRng;

    /// Reject uniformity below this p-value. With fixed seeds each test is deterministic; the
    /// threshold only says how surprised a perfect generator would have to be to fail.
    const SIGNIFICANCE: f64 = 1e-3;

    #[test]
    fn every_generator_is_even_in_one_dimension() {
        // Including RANDU: its flaw is not in how evenly single numbers spread.
        for generator in Generator::ALL {
            let outcome = uniformity_chi2(&mut generator.new_source(2024), 200_000, 100);
            assert_eq!(outcome.degrees_of_freedom, 99);
            assert!(outcome.p_value > SIGNIFICANCE, "{generator}: {outcome:?}");
        }
    }

    /// A deliberately bad source: `u^2` piles numbers up near 0.
    struct Squared(Generator, crate::rng::Source);

    impl TryRng for Squared {
        type Error = Infallible;
        fn try_next_u32(&mut self) -> Result<u32, Infallible> {
            let u = crate::rng::unit_f64(self.1.next_u32());
            Ok((u * u * 4_294_967_296.0) as u32)
        }
        fn try_next_u64(&mut self) -> Result<u64, Infallible> {
            rand::rand_core::utils::next_u64_via_u32(self)
        }
        fn try_fill_bytes(&mut self, destination: &mut [u8]) -> Result<(), Infallible> {
            rand::rand_core::utils::fill_bytes_via_next_word(destination, || self.try_next_u32())
        }
    }

    #[test]
    fn the_test_rejects_a_skewed_source() {
        let mut skewed = Squared(Generator::Pcg32, Generator::Pcg32.new_source(1));
        let outcome = uniformity_chi2(&mut skewed, 10_000, 20);
        assert!(outcome.p_value < 1e-10, "{:?}: {outcome:?}", skewed.0);
    }

    #[test]
    fn good_generators_pass_the_serial_test() {
        for generator in [Generator::Minstd, Generator::Mt19937, Generator::Pcg32] {
            for cells_per_axis in [4, 32] {
                let outcome = serial_chi2_3d(&mut generator.new_source(7), 500_000, cells_per_axis);
                assert!(
                    outcome.p_value > SIGNIFICANCE,
                    "{generator}, {cells_per_axis}: {outcome:?}"
                );
            }
        }
    }

    #[test]
    fn randu_passes_the_coarsest_serial_test_and_fails_finer_ones() {
        let outcome = serial_chi2_3d(&mut Generator::Randu.new_source(7), 100_000, 2);
        assert!(outcome.p_value > SIGNIFICANCE, "octants: {outcome:?}");
        for cells_per_axis in [4, 8] {
            let outcome =
                serial_chi2_3d(&mut Generator::Randu.new_source(7), 100_000, cells_per_axis);
            assert!(
                outcome.p_value < 1e-4,
                "{cells_per_axis} per axis: {outcome:?}"
            );
        }
    }

    #[test]
    fn cells_are_exact_at_the_ends() {
        assert_eq!(cell_of(0, 7), 0);
        assert_eq!(cell_of(u32::MAX, 7), 6);
        assert_eq!(cell_of(1 << 31, 2), 1);
        assert_eq!(cell_of((1 << 31) - 1, 2), 0);
    }

    #[test]
    #[should_panic(expected = "at least 5 per cell")]
    fn too_few_samples_are_refused() {
        uniformity_chi2(&mut Generator::Pcg32.new_source(1), 99, 20);
    }
}
