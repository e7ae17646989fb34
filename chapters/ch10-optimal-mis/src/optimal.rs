//! The optimal combination of two techniques, estimated from a pixel's own samples.
//!
//! Two techniques draw directions with densities `p_1` and `p_2`, one sample each per pixel
//! sample. Any weights `w_1 + w_2 = 1` give an unbiased estimator; Kondapaneni et al. (2019)
//! show that the variance is smallest for
//!
//! `w_i(x) = α_i p_i(x) / f(x) + p_i(x) / Σ_k p_k(x) · (1 − Σ_k α_k p_k(x) / f(x))`,
//!
//! where the vector `α` solves the 2 × 2 system `A α = b` with
//! `A_ik = ∫ p_i p_k / Σ_j p_j` and `b_i = ∫ f p_i / Σ_j p_j`. With these weights the estimator
//! is `Σ_i α_i + Σ_samples (f − Σ_k α_k p_k) / Σ_j p_j`: the balance heuristic's estimate of
//! what the densities, scaled by `α`, leave of `f`, plus what they cover exactly (each density
//! integrates to 1). Where `f` is a combination of the densities, nothing is left, and the
//! estimate has no noise at all.
//!
//! `A` and `b` are integrals too, and the samples the pixel draws anyway estimate them
//! ([`OptimalSums::add`], the balance heuristic's estimates, from all the samples of both
//! techniques). With `A` and `b`
//! estimated from the very samples the estimate then uses, the left-over sum vanishes exactly,
//! and the pixel's value is just `Σ_i α_i`: the paper's *direct estimator*. It is consistent,
//! not unbiased (`α` and the samples it is applied to are the same), and its bias shrinks with
//! the samples per pixel.
//!
//! A technique whose samples can fail (no light to pick, a direction below the surface, a
//! delta lobe chosen instead) draws from a density that covers less than 1 over the directions
//! it can reach; the share it covers is estimated by its samples that did not fail, so
//! `Σ_i α_i c_i` with `c_i` the share of technique `i`'s samples that gave a direction.

use crate::techniques::SurfaceDraws;
use glam::{DVec3, Vec3};

/// The sums of one pixel's samples from which the optimal combination is solved.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OptimalSums {
    /// `A_ik`, the second moments of the densities (symmetric: `a[0][1] == a[1][0]`).
    pub a: [[f64; 2]; 2],
    /// `b_i`, per colour channel.
    pub b: [DVec3; 2],
    /// `Σ f / Σ_j p_j`: the balance heuristic's estimate, to fall back on.
    pub balance: DVec3,
    /// Pixel samples taken.
    pub samples: u64,
    /// Samples of each technique that gave a direction.
    pub drawn: [u64; 2],
}

/// How nearly singular the system may be before the balance heuristic is trusted instead:
/// the smallest `det A / (A_11 A_22)` (which lies in `[0, 1]`). Where the two densities are
/// nearly proportional over every sample the system cannot tell the techniques apart, and
/// nothing is lost by balancing them.
pub const SMALLEST_RELATIVE_DETERMINANT: f64 = 1e-9;

impl OptimalSums {
    // ANCHOR: add
    /// Adds one pixel sample's draws to the sums: the sample of each technique that gave a
    /// direction, to `A`, to `b` and to the balance heuristic's estimate; and the pixel sample
    /// to the counts.
    ///
    /// `A_ik` and `b_i` are integrals over the directions, and the pixel's samples, of both
    /// techniques, are their estimate: from which density, all told, does a sample come, and
    /// what does the integral's estimate take from each sample? A light sample whose shadow ray
    /// was blocked carries `f` = 0: does it add to `A`? Which count does a technique that drew
    /// nothing change, and which does it leave alone? Which sample can add nothing at all
    /// without a NaN getting into the sums, and in which precision are the terms worked out?
    pub fn add(&mut self, draws: &SurfaceDraws) {
        // BEGIN SOLUTION
        self.samples += 1;
        for (technique, drawn) in draws.drawn.iter().enumerate() {
            let Some(sample) = drawn else {
                continue;
            };
            self.drawn[technique] += 1;
            let p = sample.pdf.map(f64::from);
            let mixture = p[0] + p[1];
            // No technique could have drawn it, or its value is not a number: nothing to add.
            let usable = mixture > 0.0 && mixture.is_finite() && sample.f.is_finite();
            if !usable {
                continue;
            }
            let f = sample.f.as_dvec3();
            let scale = 1.0 / (mixture * mixture);
            for i in 0..2 {
                for k in 0..2 {
                    self.a[i][k] += p[i] * p[k] * scale;
                }
                self.b[i] += f * (p[i] * scale);
            }
            self.balance += f / mixture;
        }
        // END SOLUTION
    }
    // ANCHOR_END: add

    // ANCHOR: solve
    /// `α`, per colour channel, solving `A α = b`; `None` when the system is too nearly
    /// singular ([`SMALLEST_RELATIVE_DETERMINANT`]). A technique that never gave a density
    /// (`A_ii` = 0) takes no part: the other one alone is solved.
    ///
    /// Which two cases leave nothing to solve, and which one the other technique alone? How
    /// nearly singular may `A` be before its solution means nothing?
    pub fn solve(&self) -> Option<[DVec3; 2]> {
        // BEGIN SOLUTION
        let [[a11, a12], [_, a22]] = self.a;
        let [b1, b2] = self.b;
        match (a11 > 0.0, a22 > 0.0) {
            (false, false) => Some([DVec3::ZERO; 2]),
            (true, false) => Some([b1 / a11, DVec3::ZERO]),
            (false, true) => Some([DVec3::ZERO, b2 / a22]),
            (true, true) => {
                let det = a11 * a22 - a12 * a12;
                // NaN sums (which `add` keeps out) would fail this test too.
                let solvable = det > SMALLEST_RELATIVE_DETERMINANT * a11 * a22;
                if !solvable {
                    return None;
                }
                Some([(a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det])
            }
        }
        // END SOLUTION
    }
    // ANCHOR_END: solve

    /// The pixel's estimate of the combined integral: `Σ_i α_i c_i`, each technique's `α`
    /// times the share of its samples that gave a direction; the balance heuristic's estimate
    /// where the system cannot be solved.
    pub fn estimate(&self) -> Vec3 {
        if self.samples == 0 {
            return Vec3::ZERO;
        }
        let n = self.samples as f64;
        match self.solve() {
            Some(alpha) => {
                let share = self.drawn.map(|drawn| drawn as f64 / n);
                (alpha[0] * share[0] + alpha[1] * share[1]).as_vec3()
            }
            None => (self.balance / n).as_vec3(),
        }
    }

    /// The balance heuristic's estimate from the same samples: what the optimal weights are
    /// compared with, and fallen back on.
    pub fn balance_estimate(&self) -> Vec3 {
        if self.samples == 0 {
            return Vec3::ZERO;
        }
        (self.balance / self.samples as f64).as_vec3()
    }
}

/// The progressive, unbiased variant of the optimal combination (the paper's Section 5): the
/// pixel's samples come in iterations, and each iteration is estimated with the weights
/// solved from the iterations *before* it, which its own samples then cannot bias:
/// `Σ_i α_i c_i + Σ_samples (f − Σ_k α_k p_k) / Σ_j p_j` with `α` fixed, unbiased for any `α`.
/// The first iteration has no `α` yet and is the balance heuristic (`α` = 0). The pixel's
/// estimate is the iterations' estimates weighted by their samples.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ProgressiveOptimal {
    /// The sums of every sample so far, from which the next iteration's `α` is solved.
    pub sums: OptimalSums,
    /// The weights of the current iteration, from the iterations before it.
    pub alpha: [DVec3; 2],
    /// The current iteration's sum of `(f − Σ_k α_k p_k) / Σ_j p_j`.
    residual: DVec3,
    /// The current iteration's pixel samples, and its samples of each technique that drew.
    iteration_samples: u64,
    iteration_drawn: [u64; 2],
    /// The finished iterations' estimates, each times its samples, and their samples.
    finished: DVec3,
    finished_samples: u64,
}

impl ProgressiveOptimal {
    /// Adds one pixel sample's draws to the current iteration and to the sums.
    pub fn add(&mut self, draws: &SurfaceDraws) {
        self.sums.add(draws);
        self.iteration_samples += 1;
        for (technique, drawn) in draws.drawn.iter().enumerate() {
            let Some(sample) = drawn else {
                continue;
            };
            self.iteration_drawn[technique] += 1;
            let p = sample.pdf.map(f64::from);
            let mixture = p[0] + p[1];
            let usable = mixture > 0.0 && mixture.is_finite() && sample.f.is_finite();
            if usable {
                let covered = self.alpha[0] * p[0] + self.alpha[1] * p[1];
                self.residual += (sample.f.as_dvec3() - covered) / mixture;
            }
        }
    }

    /// Ends the current iteration: its estimate joins the finished ones, and the next
    /// iteration's `α` is solved from every sample so far (kept as it was where the system
    /// cannot be solved).
    pub fn end_iteration(&mut self) {
        if self.iteration_samples > 0 {
            let n = self.iteration_samples as f64;
            let share = self.iteration_drawn.map(|drawn| drawn as f64 / n);
            let estimate = self.alpha[0] * share[0] + self.alpha[1] * share[1] + self.residual / n;
            self.finished += estimate * n;
            self.finished_samples += self.iteration_samples;
        }
        if let Some(alpha) = self.sums.solve() {
            self.alpha = alpha;
        }
        self.residual = DVec3::ZERO;
        self.iteration_samples = 0;
        self.iteration_drawn = [0; 2];
    }

    /// The estimate of the finished iterations, weighted by their samples (the current one,
    /// unfinished, left out).
    pub fn estimate(&self) -> Vec3 {
        if self.finished_samples == 0 {
            return Vec3::ZERO;
        }
        (self.finished / self.finished_samples as f64).as_vec3()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::techniques::{BSDF, LIGHT, TechniqueSample};

    fn sample(f: f32, light: f32, bsdf: f32) -> TechniqueSample {
        TechniqueSample {
            f: Vec3::splat(f),
            pdf: [light, bsdf],
        }
    }

    /// Draws `n` pixel samples of `f` on [0, 1] with two techniques: uniform (p = 1) and
    /// linear (p = 2x), by inversion, from a fixed sequence.
    fn two_techniques(f: impl Fn(f32) -> f32, n: u64) -> OptimalSums {
        let mut sums = OptimalSums::default();
        for k in 0..n {
            let u = (k as f32 + 0.5) / n as f32;
            let v = ((k * 7919) % n) as f32 / n as f32 + 0.5 / n as f32;
            let uniform = u;
            let linear = v.sqrt();
            let draws = SurfaceDraws {
                certain: Vec3::ZERO,
                drawn: [
                    Some(sample(f(uniform), 1.0, 2.0 * uniform)),
                    Some(sample(f(linear), 1.0, 2.0 * linear)),
                ],
            };
            sums.add(&draws);
        }
        sums
    }

    /// Where `f` is a combination of the densities, the solve finds it, and the estimate is
    /// exact from a handful of samples: the zero-variance case.
    #[test]
    fn an_integrand_made_of_the_densities_is_integrated_exactly() {
        // f = 0.3 · 1 + 0.7 · 2x integrates to 1.
        let sums = two_techniques(|x| 0.3 + 1.4 * x, 5);
        let alpha = sums.solve().unwrap();
        assert!((alpha[LIGHT].x - 0.3).abs() < 1e-6, "{alpha:?}");
        assert!((alpha[BSDF].x - 0.7).abs() < 1e-6, "{alpha:?}");
        assert!((sums.estimate().x - 1.0).abs() < 1e-6);
        // The balance heuristic is unbiased but not exact from five samples.
        assert!((sums.balance_estimate().x - 1.0).abs() > 1e-4);
    }

    /// On an integrand that is no combination of the densities, the estimate converges to the
    /// integral (consistency), with the pixel's samples alone.
    #[test]
    fn the_estimate_converges_to_the_integral() {
        // ∫ x² = 1/3.
        for n in [64, 1024] {
            let sums = two_techniques(|x| x * x, n);
            let error = (sums.estimate().x - 1.0 / 3.0).abs();
            assert!(error < 4.0 / n as f32, "{n} samples: error {error}");
        }
    }

    /// Trials of `∫ x² = 1/3` from 2 samples of each technique per iteration, 4 iterations: the
    /// direct estimator's mean over many trials is off (its α is fitted to the very samples it
    /// is applied to), the progressive one's is not.
    #[test]
    fn the_progressive_estimate_is_unbiased_where_the_direct_one_is_not() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg32::seed_from_u64(7);
        let trials = 40_000;
        let (mut direct, mut progressive) = (Vec::new(), Vec::new());
        for _ in 0..trials {
            let mut sums = OptimalSums::default();
            let mut iterations = ProgressiveOptimal::default();
            for _ in 0..4 {
                for _ in 0..2 {
                    let uniform: f32 = rng.random();
                    let linear = rng.random::<f32>().sqrt();
                    let draws = SurfaceDraws {
                        certain: Vec3::ZERO,
                        drawn: [
                            Some(sample(uniform * uniform, 1.0, 2.0 * uniform)),
                            Some(sample(linear * linear, 1.0, 2.0 * linear)),
                        ],
                    };
                    sums.add(&draws);
                    iterations.add(&draws);
                }
                iterations.end_iteration();
            }
            direct.push(f64::from(sums.estimate().x));
            progressive.push(f64::from(iterations.estimate().x));
        }
        let mean_and_error = |values: &[f64]| {
            let n = values.len() as f64;
            let mean = values.iter().sum::<f64>() / n;
            let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
            (mean, (variance / n).sqrt())
        };
        let (direct, direct_se) = mean_and_error(&direct);
        let (progressive, progressive_se) = mean_and_error(&progressive);
        assert!(
            (progressive - 1.0 / 3.0).abs() < 4.0 * progressive_se,
            "progressive: {progressive} ± {progressive_se}, expected 1/3"
        );
        assert!(
            (direct - 1.0 / 3.0).abs() > 4.0 * direct_se,
            "the direct estimator from 8 samples should be visibly biased: {direct} ± {direct_se}"
        );
    }

    /// The sums after the given pixel samples, each the draws of the two techniques.
    fn sums_after(pixel_samples: &[[Option<TechniqueSample>; 2]]) -> OptimalSums {
        let mut sums = OptimalSums::default();
        for &drawn in pixel_samples {
            sums.add(&SurfaceDraws {
                certain: Vec3::ZERO,
                drawn,
            });
        }
        sums
    }

    /// How a sum `got` compares with the value worked out by hand.
    #[derive(Debug, PartialEq)]
    enum Agreement {
        Exact,
        /// Off by about what rounding every term to `f32` gives.
        SinglePrecision,
        Off,
    }

    fn agreement(got: f64, expected: f64) -> Agreement {
        let error = (got - expected).abs();
        let scale = expected.abs().max(1e-30);
        if error <= 1e-13 * scale {
            Agreement::Exact
        } else if error <= 1e-6 * scale {
            Agreement::SinglePrecision
        } else {
            Agreement::Off
        }
    }

    /// Panics, naming the likely mistake, unless `got` is `expected` to `f64`'s precision.
    fn expect_sum(what: &str, got: f64, expected: f64, otherwise: &str) {
        match agreement(got, expected) {
            Agreement::Exact => {}
            Agreement::SinglePrecision => panic!(
                "{what} is {got:.17} where it should be {expected:.17}: right to about 7 digits \
                 only, which is f32's rounding. The densities and f arrive as f32; turn them \
                 into f64 before multiplying and dividing, so that thousands of terms added \
                 up keep their precision"
            ),
            Agreement::Off => panic!("{what} is {got} where it should be {expected}: {otherwise}"),
        }
    }

    /// The check of exercise `ch10-optimal-add`: the counts of pixel samples and of draws, what
    /// a light sample and a BSDF sample add to `A`, `b` and the balance heuristic's sum
    /// (against values worked out by hand), a blocked sample, and samples that must add
    /// nothing.
    #[test]
    fn exercise_optimal_add() {
        // Neither technique drew: one pixel sample, no draw, nothing summed.
        let failed = sums_after(&[[None, None]]);
        assert!(
            failed.samples != 0,
            "after one pixel sample in which neither technique drew, samples is still 0: every \
             pixel sample counts, even one that found nothing, since the shares of samples that \
             drew (and the balance heuristic's average) divide by it"
        );
        assert!(
            failed.drawn == [0, 0],
            "after one pixel sample in which neither technique drew, drawn is {:?} where it \
             should be [0, 0]: a failed sample (no direction) counts as a pixel sample, not as \
             a draw of its technique",
            failed.drawn
        );
        assert!(
            failed
                == OptimalSums {
                    samples: 1,
                    ..OptimalSums::default()
                },
            "one pixel sample in which neither technique drew should count as one sample and \
             add nothing else; the sums are {failed:?}"
        );

        // A light sample, f = (3, 6, 12) with densities 1 (light) and 2 (BSDF), and a BSDF
        // sample that found no light (f = 0) with densities 0.5 and 1.5: worked out by hand,
        // the light sample adds 1/9, 2/9 and 4/9 to A, f/9 to b_1, 2f/9 to b_2 and f/3 to the
        // balance sum; the BSDF sample adds 1/16, 3/16 and 9/16 to A and nothing else.
        let f = Vec3::new(3.0, 6.0, 12.0);
        let light = Some(TechniqueSample { f, pdf: [1.0, 2.0] });
        let blocked = Some(TechniqueSample {
            f: Vec3::ZERO,
            pdf: [0.5, 1.5],
        });
        let both = sums_after(&[[light, blocked]]);
        assert!(
            both.samples == 1,
            "after one pixel sample in which both techniques drew, samples is {} where it \
             should be 1: it counts pixel samples, not the techniques' draws (those are drawn)",
            both.samples
        );
        assert!(
            both.drawn == [1, 1],
            "after one pixel sample in which both techniques drew, drawn is {:?} where it \
             should be [1, 1]",
            both.drawn
        );

        let alone = sums_after(&[[light, None]]);
        let a11 = alone.a[0][0];
        let ratio = a11 * 9.0;
        if (ratio - 3.0).abs() < 1e-5 {
            panic!(
                "A_11 after one light sample with densities 1 and 2 is {a11}, 3 times too \
                 large, and 3 is the sum of the densities: is the mixture density squared? \
                 It appears once in the integral's integrand, and once more as the density the \
                 sample was drawn from"
            );
        }
        if (ratio - 1.0 / 3.0).abs() < 1e-5 {
            panic!(
                "A_11 after one light sample with densities 1 and 2 is {a11}, 3 times too \
                 small: the mixture density divides one time too many"
            );
        }
        let a_light = [[1.0 / 9.0, 2.0 / 9.0], [2.0 / 9.0, 4.0 / 9.0]];
        for (i, k) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            expect_sum(
                &format!("A_{}{} after one light sample", i + 1, k + 1),
                alone.a[i][k],
                a_light[i][k],
                "with densities p_1 = 1 and p_2 = 2 it should be the hand-worked value; \
                 check which densities multiply in A_ik and what divides them",
            );
        }
        let b1 = alone.b[0];
        let b2 = alone.b[1];
        let b_swapped = (b1 - f.as_dvec3() * (2.0 / 9.0)).abs().max_element() < 1e-6
            || (b2 - f.as_dvec3() / 9.0).abs().max_element() < 1e-6;
        if b_swapped {
            panic!(
                "after one light sample with densities p_1 = 1 and p_2 = 2, b_1 = {b1} and \
                 b_2 = {b2}: b uses the wrong technique's density. b_i is weighted by technique \
                 i's density at the sample, whichever technique drew it, as A_ik is by p_i and \
                 p_k"
            );
        }
        let channels = ["red", "green", "blue"];
        for (channel, name) in channels.iter().enumerate() {
            let fc = f64::from(f[channel]);
            let what = format!("b_1 ({name}) after one light sample");
            expect_sum(
                &what,
                b1[channel],
                fc / 9.0,
                "with f = (3, 6, 12) and densities 1 and 2 it should be the hand-worked value; \
                 check what multiplies f and what divides it",
            );
            let what = format!("b_2 ({name}) after one light sample");
            expect_sum(&what, b2[channel], 2.0 * fc / 9.0, "check as for b_1");
            let what = format!("the balance sum ({name}) after one light sample");
            expect_sum(
                &what,
                alone.balance[channel],
                fc / 3.0,
                "it is the balance heuristic's term of the sample, f over the densities' sum, \
                 unsquared",
            );
        }

        let dark = sums_after(&[[None, blocked]]);
        assert!(
            dark.a != [[0.0; 2]; 2],
            "a BSDF sample that found no light (f = 0, densities 0.5 and 1.5) left A at zero: a \
             sample that carries nothing still adds to A (its densities were there, only f was \
             0); leaving it out makes the densities look as if they covered less than they do"
        );
        let a_dark = [[1.0 / 16.0, 3.0 / 16.0], [3.0 / 16.0, 9.0 / 16.0]];
        for (i, k) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            expect_sum(
                &format!("A_{}{} after one BSDF sample with f = 0", i + 1, k + 1),
                dark.a[i][k],
                a_dark[i][k],
                "with densities 0.5 and 1.5 it should be the hand-worked value",
            );
        }
        assert!(
            dark.b == [DVec3::ZERO; 2] && dark.balance == DVec3::ZERO,
            "a sample with f = 0 should add nothing to b or to the balance sum; they are {:?} \
             and {}",
            dark.b,
            dark.balance
        );
        // Both together: the sums of the two.
        let expected_both = [[25.0 / 144.0, 59.0 / 144.0], [59.0 / 144.0, 145.0 / 144.0]];
        for (i, k) in [(0, 0), (0, 1), (1, 1)] {
            expect_sum(
                &format!("A_{}{} after a light and a BSDF sample", i + 1, k + 1),
                both.a[i][k],
                expected_both[i][k],
                "each sample of the pixel adds its own terms, whichever technique drew it",
            );
        }

        // A sample that no technique could have drawn (both densities 0), and one whose value
        // is not a number: each was drawn, and adds nothing to the sums.
        let nowhere = Some(TechniqueSample {
            f: Vec3::ONE,
            pdf: [0.0, 0.0],
        });
        let not_a_number = Some(TechniqueSample {
            f: Vec3::new(f32::NAN, 1.0, 1.0),
            pdf: [1.0, 1.0],
        });
        let nothing = sums_after(&[[nowhere, not_a_number]]);
        let finite = nothing.a.iter().flatten().all(|a| a.is_finite())
            && nothing.b.iter().all(|b| b.is_finite())
            && nothing.balance.is_finite();
        assert!(
            finite,
            "after a sample whose densities are both 0 and one whose f is NaN, the sums hold \
             something that is not a number ({nothing:?}): such samples count as drawn but add \
             nothing to the sums, or one NaN spoils the pixel for good"
        );
        assert!(
            nothing
                == OptimalSums {
                    samples: 1,
                    drawn: [1, 1],
                    ..OptimalSums::default()
                },
            "a sample whose densities are both 0, and one whose f is NaN, should count as a \
             pixel sample and as draws, and add nothing else; the sums are {nothing:?}"
        );
    }

    /// Sums with the given `A` (symmetric) and `b` (the same in every channel).
    fn sums_of(a: [[f64; 2]; 2], b: [f64; 2]) -> OptimalSums {
        OptimalSums {
            a,
            b: b.map(DVec3::splat),
            ..OptimalSums::default()
        }
    }

    /// The check of exercise `ch10-optimal-solve`: `α` of a known system, the two techniques
    /// told apart; a technique that never drew; none that drew; a system too nearly singular.
    #[test]
    fn exercise_optimal_solve() {
        let close =
            |a: DVec3, expected: f64| (a - DVec3::splat(expected)).abs().max_element() < 1e-9;
        // A = [[2, 1], [1, 3]], b = [5, 10]: α = (1, 3).
        let Some(alpha) = sums_of([[2.0, 1.0], [1.0, 3.0]], [5.0, 10.0]).solve() else {
            panic!(
                "solve gave None for A = [[2, 1], [1, 3]], b = [5, 10], whose determinant is 5: \
                 is the test for a singular system against the right quantity?"
            );
        };
        if close(alpha[0], 3.0) && close(alpha[1], 1.0) {
            panic!(
                "α came out as (3, 1) where it is (1, 3): the two techniques' values are swapped \
                 (in Cramer's rule, the numerator of α_1 puts b in the first column of A)"
            );
        }
        assert!(
            close(alpha[0], 1.0) && close(alpha[1], 3.0),
            "for A = [[2, 1], [1, 3]] and b = [5, 10], α should be (1, 3), and is ({}, {}): \
             check the determinant A_11 A_22 - A_12² and the sign of each A_12 term",
            alpha[0].x,
            alpha[1].x
        );
        // The light technique never drew: A_11 = A_12 = b_1 = 0.
        let alone = sums_of([[0.0, 0.0], [0.0, 4.0]], [0.0, 2.0]).solve();
        let Some(alone) = alone else {
            panic!(
                "solve gave None when only the BSDF technique drew (A_11 = 0): that technique \
                 alone is solved, α_2 = b_2 / A_22, and the other α is 0"
            );
        };
        assert!(
            alone[0] == DVec3::ZERO && close(alone[1], 0.5),
            "when only the BSDF technique drew (A = [[0, 0], [0, 4]], b = [0, 2]) α should be \
             (0, 0.5), and is ({}, {}): a technique that never drew takes no part",
            alone[0].x,
            alone[1].x
        );
        let only_light = sums_of([[4.0, 0.0], [0.0, 0.0]], [2.0, 0.0]).solve();
        assert!(
            only_light.is_some_and(|a| close(a[0], 0.5) && a[1] == DVec3::ZERO),
            "when only the light technique drew (A = [[4, 0], [0, 0]], b = [2, 0]) α should be \
             (0.5, 0), and is {only_light:?}"
        );
        let none = OptimalSums::default().solve();
        assert!(
            none == Some([DVec3::ZERO; 2]),
            "with no samples at all α should be (0, 0), nothing to add, and is {none:?}"
        );
        // Proportional densities: A = [[1, 2], [2, 4]] is singular, and so is anything within
        // rounding of it.
        for nudge in [0.0, 1e-13] {
            let singular = sums_of([[1.0, 2.0], [2.0, 4.0 + nudge]], [1.0, 2.0]).solve();
            assert!(
                singular.is_none(),
                "A = [[1, 2], [2, {}]] is singular to within rounding (det / (A_11 A_22) below \
                 SMALLEST_RELATIVE_DETERMINANT), so solve should give None and let the balance \
                 heuristic stand in; it gave {singular:?}",
                4.0 + nudge
            );
        }
    }

    /// Equal densities everywhere cannot be told apart: the system is singular, and the
    /// estimate is the balance heuristic's.
    #[test]
    fn proportional_densities_fall_back_to_the_balance_heuristic() {
        let mut sums = OptimalSums::default();
        for (k, x) in [0.1f32, 0.5, 0.9].into_iter().enumerate() {
            sums.add(&SurfaceDraws {
                certain: Vec3::ZERO,
                drawn: [
                    Some(sample(x, 1.0, 1.0)),
                    Some(sample(x * (k as f32), 1.0, 1.0)),
                ],
            });
        }
        assert!(sums.solve().is_none());
        assert_eq!(sums.estimate(), sums.balance_estimate());
    }

    /// A technique that never drew is left out; one whose samples fail half the time covers
    /// half of what it would, and its α is scaled by that share.
    #[test]
    fn failed_samples_count_and_a_technique_that_never_drew_is_left_out() {
        let mut sums = OptimalSums::default();
        for k in 0..4 {
            let x = (k as f32 + 0.5) / 4.0;
            sums.add(&SurfaceDraws {
                certain: Vec3::ZERO,
                // The light technique fails every time; the BSDF one every other time.
                drawn: [None, (k % 2 == 0).then(|| sample(2.0 * x, 0.0, 2.0 * x))],
            });
        }
        assert_eq!(sums.drawn, [0, 2]);
        // f = p_BSDF: α = 1, and the share 1/2 of successes gives 1/2.
        let alpha = sums.solve().unwrap();
        assert_eq!(alpha[LIGHT], DVec3::ZERO);
        assert!((alpha[BSDF].x - 1.0).abs() < 1e-12);
        assert!((sums.estimate().x - 0.5).abs() < 1e-6);
    }
}
