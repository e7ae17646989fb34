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

use super::unit_f64;

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

// ANCHOR: triples_chi2
/// How evenly consecutive triples of `numbers` fill the unit cube: Pearson's statistic of
/// their counts in the `k³` equal cubic cells, `k = cells_per_axis`.
///
/// The numbers are read as a renderer hands them out: the first three are the coordinates
/// `(x, y, z)` of the first point, the next three those of the second point, and so on. Each
/// number belongs to one point only, and a last incomplete triple is left out. Each axis of
/// `[0, 1]` is cut into `k` equal parts, and a number equal to 1 (rounding to a float can make
/// one) counts in the last part. The statistic is the plain sum over all cells, not divided by
/// the number of points, of cells or of degrees of freedom.
///
/// # Panics
///
/// If `cells_per_axis` is 0 or `numbers` hold no complete triple.
pub fn triples_chi2(numbers: &[f64], cells_per_axis: usize) -> f64 {
    assert!(
        cells_per_axis > 0 && numbers.len() >= 3,
        "triples_chi2 needs at least one cell and one triple"
    );
    // BEGIN SOLUTION
    let k = cells_per_axis;
    let part = |u: f64| ((u * k as f64) as usize).min(k - 1);
    let mut counts = vec![0u64; k.pow(3)];
    let points = numbers.chunks_exact(3);
    let point_count = points.len();
    for point in points {
        counts[(part(point[0]) * k + part(point[1])) * k + part(point[2])] += 1;
    }
    let expected = point_count as f64 / counts.len() as f64;
    counts
        .iter()
        .map(|&observed| (observed as f64 - expected).powi(2) / expected)
        .sum()
    // END SOLUTION
}
// ANCHOR_END: triples_chi2

/// Pearson's test that `triples` consecutive non-overlapping triples `(x, y, z)` from `source`
/// fall evenly into the `k^3` cells of the unit cube, `k = cells_per_axis`: the statistic of
/// [`triples_chi2`] with its p-value, `k^3 - 1` degrees of freedom.
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
    // Every number word / 2^32 is exact in an f64, and so is its product with a cell count:
    // the cells are the same as those of exact integer arithmetic.
    let numbers: Vec<f64> = (0..3 * triples)
        .map(|_| unit_f64(source.next_u32()))
        .collect();
    outcome(triples_chi2(&numbers, cells_per_axis), cells - 1)
}

/// The largest statistic [`serial_chi2_3d`] accepts at `significance`: the value a perfect
/// generator exceeds with probability `significance`, from the chi-square distribution with
/// `cells_per_axis^3 - 1` degrees of freedom.
pub fn serial_threshold(cells_per_axis: usize, significance: f64) -> f64 {
    let degrees_of_freedom = cells_per_axis.pow(3) - 1;
    ChiSquared::new(degrees_of_freedom as f64)
        .expect("at least one degree of freedom")
        .inverse_cdf(1.0 - significance)
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
    outcome(statistic, counts.len() - 1)
}

/// A statistic with its degrees of freedom and p-value.
fn outcome(statistic: f64, degrees_of_freedom: usize) -> ChiSquareOutcome {
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

    use rand::{Rng, TryRng};

    const RANDU_RECORDED: f64 = 72.52053333333335;
    const MT_RECORDED: f64 = 54.387200000000014;
    const PCG_RECORDED: f64 = 79.62453333333335;

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

    /// What is wrong with `answer`, the student's statistic for a hand-made sequence whose
    /// points fall into the cells of `k` per axis with the `right` counts, in words; `None` if
    /// it is right to rounding. `overlapping` are the counts of the sequence's overlapping
    /// triples `(u₀, u₁, u₂), (u₁, u₂, u₃), ...`, when they tell that mistake apart.
    fn triples_mistake(
        answer: f64,
        right: &[u64],
        k: usize,
        overlapping: Option<&[u64]>,
    ) -> Option<String> {
        let points = right.iter().sum::<u64>() as f64;
        let cells = right.len() as f64;
        let sum_with = |counts: &[u64], expected: f64, divide: bool| -> f64 {
            counts
                .iter()
                .map(|&observed| {
                    let squared = (observed as f64 - expected).powi(2);
                    if divide { squared / expected } else { squared }
                })
                .sum()
        };
        let expected = sum_with(right, points / cells, true);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs().max(1.0);
        if close(answer, expected) {
            return None;
        }
        let mistake = if !answer.is_finite() {
            "it is not a finite number: does a cell expect no points?".to_string()
        } else if close(answer, sum_with(right, points / k as f64, true)) {
            format!(
                "that is the statistic with {points} / {k} points expected in each cell: the \
                 expected count is per cell, and a point lands in one of the {k}³ cells, not \
                 in one part of one axis"
            )
        } else if overlapping.is_some_and(|counts| {
            let triples = counts.iter().sum::<u64>() as f64;
            close(answer, sum_with(counts, triples / cells, true))
        }) {
            "the triples overlap: (u₁, u₂, u₃) is not a point, because each number is a \
             coordinate of one point only; read the numbers three at a time"
                .to_string()
        } else if close(answer, expected / (cells - 1.0)) {
            "that is the statistic divided by its degrees of freedom; the statistic is not \
             divided or normalised by anything, as documented"
                .to_string()
        } else if close(answer, expected / points) || close(answer, expected / cells) {
            "that is the statistic divided by the number of points or of cells; the statistic \
             is not divided or normalised by anything, as documented"
                .to_string()
        } else if close(answer, sum_with(right, points / cells, false)) {
            "the squared differences are not divided by the expected count".to_string()
        } else if right.iter().all(|&count| count == right[0]) {
            format!(
                "every cell holds the same number of points, so the statistic is 0: a point is \
                 counted in the wrong cell (which of the {k} parts holds u = i / {k}, and u = 1?)"
            )
        } else {
            format!("the statistic should be {expected}")
        };
        Some(format!(
            "{mistake}; yours gave {answer}, expected {expected}"
        ))
    }

    /// The student's statistic, with a panic turned into words.
    fn students_triples_chi2(numbers: &[f64], k: usize, what: &str) -> f64 {
        workbench::test_support::catch_panic(|| triples_chi2(numbers, k)).unwrap_or_else(
            |message| {
                panic!(
                    "triples_chi2 on {what} ({k} parts per axis) panicked ({message}). Every \
                     number of [0, 1] is in one of the {k} parts of its axis: a number equal \
                     to 1 counts in the last part, not in a part {k} that does not exist"
                )
            },
        )
    }

    #[test]
    fn exercise_triples_chi2_all_points_in_one_cell() {
        // Ten points at (0.3, 0.3, 0.3): one cell of the 2³ holds all ten, seven hold none.
        let numbers = [0.3; 30];
        let answer = students_triples_chi2(&numbers, 2, "ten points in one cell");
        let mut right = [0; 8];
        right[0] = 10;
        let mut overlapping = [0; 8];
        overlapping[0] = 28;
        if let Some(mistake) = triples_mistake(answer, &right, 2, Some(&overlapping)) {
            panic!("triples_chi2: ten points in one of the 2³ cells: {mistake}");
        }
        // A last incomplete triple is left out.
        let with_leftover: Vec<f64> = numbers.iter().copied().chain([0.9, 0.9]).collect();
        let leftover = students_triples_chi2(&with_leftover, 2, "ten points and two numbers");
        assert!(
            leftover == answer,
            "triples_chi2: two numbers after the last complete triple are not a point and must \
             be left out; with them the statistic went from {answer} to {leftover}"
        );
    }

    /// The points of the perfect lattice of `k` per axis with coordinates `coordinate(i)`,
    /// `i < k`, each cell `repeat` times, in a scrambled order.
    fn lattice(k: usize, repeat: usize, coordinate: impl Fn(usize) -> f64) -> Vec<f64> {
        let mut points = Vec::new();
        for copy in 0..repeat {
            for cell in 0..k.pow(3) {
                // A stride coprime with k³ visits every cell once, not in the counting order.
                let cell = (cell * 7 + copy) % k.pow(3);
                points.extend([cell / (k * k), cell / k % k, cell % k].map(&coordinate));
            }
        }
        points
    }

    #[test]
    fn exercise_triples_chi2_perfect_lattices() {
        for (what, k, coordinate) in [
            (
                "the lattice of cell corners i / 4",
                4,
                &(|i: usize| i as f64 / 4.0) as &dyn Fn(usize) -> f64,
            ),
            (
                "the lattice of cell centres (i + 1/2) / 3, with 1 in place of the last",
                3,
                &|i: usize| if i == 2 { 1.0 } else { (i as f64 + 0.5) / 3.0 },
            ),
        ] {
            let numbers = lattice(k, 2, coordinate);
            let answer = students_triples_chi2(&numbers, k, what);
            if let Some(mistake) = triples_mistake(answer, &vec![2; k.pow(3)], k, None) {
                panic!("triples_chi2: {what}, two points in every cell: {mistake}");
            }
        }
    }

    #[test]
    fn exercise_triples_chi2_of_generators() {
        // Recorded from the lecture's solution, and equal to the statistics of the same cells
        // counted from the 32-bit words in exact integer arithmetic: 30 000 triples in 4³
        // cells, seed 7. RANDU passes at this coarse resolution (63 degrees of freedom).
        for (generator, recorded) in [
            (Generator::Randu, RANDU_RECORDED),
            (Generator::Mt19937, MT_RECORDED),
            (Generator::Pcg32, PCG_RECORDED),
        ] {
            let mut source = generator.new_source(7);
            let numbers: Vec<f64> = (0..90_000)
                .map(|_| crate::rng::unit_f64(source.next_u32()))
                .collect();
            let answer = students_triples_chi2(&numbers, 4, generator.name());
            assert!(
                (answer - recorded).abs() <= 1e-9 * recorded,
                "triples_chi2: the first 30 000 triples of {generator} (seed 7) in 4³ cells \
                 give the statistic {recorded}; yours gave {answer}"
            );
        }
    }

    #[test]
    fn exercise_triples_chi2_refuses_randu_and_passes_pcg() {
        // 8³ = 512 cells: a perfect generator's statistic follows the chi-square distribution
        // with 511 degrees of freedom, and exceeds this once in a thousand runs.
        let threshold = serial_threshold(8, 1e-3);
        assert!((threshold - 615.5).abs() < 0.1, "threshold {threshold}");
        let randu = serial_chi2_3d(&mut Generator::Randu.new_source(7), 100_000, 8);
        let pcg = serial_chi2_3d(&mut Generator::Pcg32.new_source(7), 100_000, 8);
        assert_eq!(randu.degrees_of_freedom, 511);
        assert!(
            randu.statistic > threshold,
            "triples_chi2: RANDU's triples lie on 15 planes and leave most of the 8³ cells \
             empty, but your statistic {} stays below the threshold {threshold} (511 degrees \
             of freedom, significance 0.001)",
            randu.statistic
        );
        assert!(
            pcg.statistic <= threshold,
            "triples_chi2: PCG32's triples fill the 8³ cells evenly, but your statistic {} is \
             above the threshold {threshold} (511 degrees of freedom, significance 0.001)",
            pcg.statistic
        );
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
