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
//! `A` and `b` are integrals too, and the samples the pixel draws anyway estimate them, each
//! sample `x` adding `p_i p_k / (Σ_j p_j)²` to `A_ik` and `f p_i / (Σ_j p_j)²` to `b_i` (the
//! balance heuristic's estimates, from all the samples of both techniques). With `A` and `b`
//! estimated from the very samples the estimate then uses, the left-over sum vanishes exactly,
//! and the pixel's value is just `Σ_i α_i`: the paper's *direct estimator*. It is consistent,
//! not unbiased (`α` and the samples it is applied to are the same), and its bias shrinks with
//! the samples per pixel.
//!
//! A technique whose samples can fail (no light to pick, a direction below the surface, a
//! delta lobe chosen instead) draws from a density that covers less than 1 over the directions
//! it can reach; the share it covers is estimated by its samples that did not fail, so
//! `Σ_i α_i c_i` with `c_i` the share of technique `i`'s samples that gave a direction.

use crate::techniques::{SurfaceDraws, TechniqueSample};
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
    /// Adds one pixel sample's draws: the sample of each technique that gave a direction.
    pub fn add_draws(&mut self, draws: &SurfaceDraws) {
        self.samples += 1;
        for (technique, drawn) in draws.drawn.iter().enumerate() {
            if let Some(sample) = drawn {
                self.drawn[technique] += 1;
                self.add(sample);
            }
        }
    }

    // ANCHOR: add
    /// Adds one technique's sample to the sums: its part of `A`, of `b` and of the balance
    /// heuristic's estimate. A sample that carries nothing (`f` = 0: the light blocked, no
    /// light found) still adds to `A`. A sample no technique could have drawn adds nothing.
    pub fn add(&mut self, sample: &TechniqueSample) {
        let p = sample.pdf.map(f64::from);
        let mixture = p[0] + p[1];
        let usable = mixture > 0.0 && mixture.is_finite() && sample.f.is_finite();
        if !usable {
            return;
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
    pub fn add_draws(&mut self, draws: &SurfaceDraws) {
        self.sums.add_draws(draws);
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
    use crate::techniques::{BSDF, LIGHT};

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
            sums.add_draws(&draws);
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
                    sums.add_draws(&draws);
                    iterations.add_draws(&draws);
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
            sums.add_draws(&SurfaceDraws {
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
            sums.add_draws(&SurfaceDraws {
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
