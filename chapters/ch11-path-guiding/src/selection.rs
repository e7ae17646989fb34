//! The BSDF fraction, learnt: how often each region should ask the BSDF rather than its guide.
//!
//! Half and half is a guess. Where the guide has learnt the light well (a door gap seen from
//! a dull floor) most directions should come from it; where the surface is glossy, or the
//! guide has learnt little, from the BSDF. Müller, Evans, Keller and Novák (*Practical Path
//! Guiding in Production*, 2019) learn the fraction `α` of each spatial leaf while training,
//! by gradient descent on how far the mixture `α p_bsdf + (1 - α) p_guide` is from the
//! integrand `F`: the Kullback-Leibler divergence from `F`, or the second moment `∫ F² / p`,
//! the variance of the estimate. The crate descends the second moment whatever the guide
//! follows ([`loss_of`]): the fraction's only business is the estimate's noise.
//!
//! Every vertex that drew its direction from a mixture gives one sample of the gradient. For a
//! loss `∫ F^k / p^(k-1)` (`k` 1 or 2, up to a constant for `k` 1), the derivative in `α` is
//! `-∫ (F / p)^k (p_bsdf - p_guide) / p`, estimated with the direction drawn by density
//! `p_drawn` as `-(F / p)^k (p_bsdf - p_guide) / p_drawn`. The fraction is kept as the logistic
//! function of a free number `θ`, so that any step leaves it a probability, and `θ` is moved
//! by Adam (Kingma and Ba 2015), whose steps are of the learning rate's size whatever the
//! scale of `F`.
//!
//! The fraction is kept between [`LOWEST_FRACTION`] and one minus it: the guide gives no
//! density to directions it has seen no light from, and the BSDF must still draw them, with
//! weights at most `1 / LOWEST_FRACTION` times the BSDF's own. The floor is a fifth, not the
//! twentieth we first tried: on the door-gap room, where a learnt fraction of a twentieth met
//! light its guide had not learnt, the rare BSDF samples that found it made fireflies that
//! cost more than the learning gained (radiance-guided, with the divergence as the loss, the
//! error at equal time was 2.3 to 2.7 times the unguided render's, against 1.2 to 1.3 with
//! the floor at a fifth; measured on one core, two seeds, 20 seconds). (Müller
//! et al. also pull `θ` towards 0 by a fixed amount; against gradients whose size is the
//! scene's brightness, that pull holds a dim room's fraction near a half, and the bounds on
//! `θ` are enough to keep it from wandering off.)

use crate::target::GuidingTarget;
use glam::Vec3;

/// The least probability of either technique.
pub const LOWEST_FRACTION: f32 = 0.2;

/// Adam's step size, its two moments' decay, and the small number keeping it finite.
///
/// The step is a fifth of Müller et al.'s 0.01. Taken once per record, their step let each
/// leaf's fraction wander with the noise of its few records, and leaves at the bounds drew
/// badly: on the door-gap room (two seeds, 20 seconds on one core, the error at equal time
/// over chapter 08's) the learnt fraction gave 0.61 (variance) and 0.68 (radiance) against
/// 0.55 for both with the fraction fixed at a half; with this step, 0.55 and 0.56. On the
/// glossy floor and the Cornell box the two steps measured alike (0.95 and 0.98; 1.58 and
/// 1.60), within the measurement's noise.
const LEARNING_RATE: f32 = 0.002;
const BETA_1: f32 = 0.9;
const BETA_2: f32 = 0.999;
const EPSILON: f32 = 1e-8;

/// One vertex's say on the fraction: the integrand at the direction it drew, the BSDF's and the
/// guide's densities there, and the fraction it was drawn with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FractionSample {
    /// The integrand `F` the loss compares with (one channel).
    pub integrand: f32,
    /// The BSDF's density of the direction, per unit solid angle.
    pub bsdf_pdf: f32,
    /// The guide's.
    pub guide_pdf: f32,
    /// The BSDF fraction with which it was drawn.
    pub drawn_with: f32,
}

/// The loss the fraction descends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FractionLoss {
    /// The Kullback-Leibler divergence of the mixture from the integrand.
    Divergence,
    /// The second moment of the estimate, `∫ F² / p`.
    SecondMoment,
}

/// A spatial leaf's BSDF fraction and the state of the descent learning it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LearntFraction {
    /// The free number whose logistic function is the fraction.
    theta: f32,
    /// The fraction, [`fraction_of`] `theta`, kept beside it: every vertex of the region
    /// reads it, and only a step of the descent changes it.
    fraction: f32,
    /// Adam's running means of the gradient and of its square, and its step count.
    first_moment: f32,
    second_moment: f32,
    steps: u32,
    /// The two decays to the power of the step count: what of the moments' zero start is
    /// left in them.
    decay_1: f32,
    decay_2: f32,
}

impl Default for LearntFraction {
    /// Half and half, nothing learnt.
    fn default() -> Self {
        Self {
            theta: 0.0,
            fraction: fraction_of(0.0),
            first_moment: 0.0,
            second_moment: 0.0,
            steps: 0,
            decay_1: 1.0,
            decay_2: 1.0,
        }
    }
}

/// The logistic function, kept within [`LOWEST_FRACTION`] of 0 and 1.
fn fraction_of(theta: f32) -> f32 {
    (1.0 / (1.0 + (-theta).exp())).clamp(LOWEST_FRACTION, 1.0 - LOWEST_FRACTION)
}

impl LearntFraction {
    /// The probability of drawing from the BSDF.
    pub fn fraction(&self) -> f32 {
        self.fraction
    }

    /// How many samples it has learnt from.
    pub fn steps(&self) -> u32 {
        self.steps
    }

    /// One step of descent on `loss` from `sample`. A sample that cannot say (a density or
    /// integrand not finite, nothing drawn) changes nothing.
    pub fn learn(&mut self, sample: &FractionSample, loss: FractionLoss) {
        let FractionSample {
            integrand,
            bsdf_pdf,
            guide_pdf,
            drawn_with,
        } = *sample;
        let drawn = drawn_with * bsdf_pdf + (1.0 - drawn_with) * guide_pdf;
        let alpha = self.fraction();
        let mixture = alpha * bsdf_pdf + (1.0 - alpha) * guide_pdf;
        if !(integrand.is_finite() && bsdf_pdf.is_finite() && guide_pdf.is_finite())
            || drawn.is_nan()
            || drawn <= 0.0
            || mixture.is_nan()
            || mixture <= 0.0
        {
            return;
        }
        let ratio = integrand.max(0.0) / mixture;
        let weight = match loss {
            FractionLoss::Divergence => ratio,
            FractionLoss::SecondMoment => ratio * ratio,
        };
        let d_alpha = -weight * (bsdf_pdf - guide_pdf) / drawn;
        // The logistic's derivative (of the unclamped fraction: at the bounds the pull back
        // inwards still moves θ).
        let logistic = 1.0 / (1.0 + (-self.theta).exp());
        let gradient = d_alpha * logistic * (1.0 - logistic);
        if !gradient.is_finite() {
            return;
        }
        self.adam_step(gradient);
    }

    /// Adam's step on `θ` for `gradient`.
    fn adam_step(&mut self, gradient: f32) {
        self.steps += 1;
        self.decay_1 *= BETA_1;
        self.decay_2 *= BETA_2;
        self.first_moment = BETA_1 * self.first_moment + (1.0 - BETA_1) * gradient;
        self.second_moment = BETA_2 * self.second_moment + (1.0 - BETA_2) * gradient * gradient;
        // The moments start at 0: divided by what the decay has let through so far, they
        // are unbiased means from the first step.
        let mean = self.first_moment / (1.0 - self.decay_1);
        let mean_square = self.second_moment / (1.0 - self.decay_2);
        self.theta -= LEARNING_RATE * mean / (mean_square.sqrt() + EPSILON);
        // Beyond the clamp's reach θ would only grow a debt to pay back before it moves the
        // fraction again.
        let bound = ((1.0 - LOWEST_FRACTION) / LOWEST_FRACTION).ln() + 1.0;
        self.theta = self.theta.clamp(-bound, bound);
        self.fraction = fraction_of(self.theta);
    }
}

/// The loss the fraction descends for a guide that follows `target`: the estimate's second
/// moment for both. Müller et al. descend the divergence for a guide of the light arriving;
/// measured here (two seeds, 20 seconds on one core, the error at equal time over chapter
/// 08's), the divergence gave 1.31 on the door-gap room, 1.11 on the glossy floor and 1.69 on
/// the Cornell box, the second moment 0.77, 1.05 and 1.58.
pub fn loss_of(_target: GuidingTarget) -> FractionLoss {
    FractionLoss::SecondMoment
}

/// The integrand of `loss`'s comparison as a vertex knows it: `f cos θ L_i`, the light
/// scattered along the direction, for the divergence (guiding towards the light); for the
/// second moment, that times what the path carried to the vertex, over the pixel's estimate,
/// as the variance-aware target measures a vertex's part of its pixel.
pub fn integrand(
    loss: FractionLoss,
    throughput: Vec3,
    f_cos: Vec3,
    incident: Vec3,
    pixel_estimate: f32,
) -> f32 {
    let mean = |v: Vec3| (v.x + v.y + v.z) / 3.0;
    match loss {
        FractionLoss::Divergence => mean(f_cos * incident),
        FractionLoss::SecondMoment if pixel_estimate > 0.0 => {
            mean(throughput * f_cos * incident) / pixel_estimate
        }
        FractionLoss::SecondMoment => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Directions on [0, 1): the BSDF uniform, the guide all on [0, 0.1), the integrand
    /// `light` on [0, 0.1) and `elsewhere` beyond; `n` samples drawn from the mixture.
    fn learn_on(light: f32, elsewhere: f32, n: u32, loss: FractionLoss) -> LearntFraction {
        let mut learnt = LearntFraction::default();
        let mut state = 12345u32;
        let mut uniform = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1u32 << 24) as f32
        };
        for _ in 0..n {
            let alpha = learnt.fraction();
            let x = if uniform() < alpha {
                uniform()
            } else {
                0.1 * uniform()
            };
            let in_gap = x < 0.1;
            learnt.learn(
                &FractionSample {
                    integrand: if in_gap { light } else { elsewhere },
                    bsdf_pdf: 1.0,
                    guide_pdf: if in_gap { 10.0 } else { 0.0 },
                    drawn_with: alpha,
                },
                loss,
            );
        }
        learnt
    }

    #[test]
    fn the_fraction_follows_the_better_technique_and_stays_a_probability() {
        for loss in [FractionLoss::Divergence, FractionLoss::SecondMoment] {
            // All the light where the guide looks: the guide should draw all it may, the
            // fraction down at its floor.
            let guide_wins = learn_on(1.0, 0.0, 20_000, loss);
            assert!(
                guide_wins.fraction() < LOWEST_FRACTION + 0.05,
                "{loss:?}: {guide_wins:?}"
            );
            // The light everywhere alike: the BSDF (uniform) is the integrand's shape.
            let bsdf_wins = learn_on(1.0, 1.0, 20_000, loss);
            assert!(
                bsdf_wins.fraction() > 1.0 - LOWEST_FRACTION - 0.05,
                "{loss:?}: {bsdf_wins:?}"
            );
            for learnt in [guide_wins, bsdf_wins] {
                let f = learnt.fraction();
                assert!((LOWEST_FRACTION..=1.0 - LOWEST_FRACTION).contains(&f));
            }
        }
    }

    #[test]
    fn samples_that_cannot_say_change_nothing() {
        let mut learnt = LearntFraction::default();
        for sample in [
            (f32::NAN, 1.0, 1.0),
            (1.0, f32::INFINITY, 1.0),
            (1.0, 0.0, 0.0),
            (1.0, -1.0, 0.0),
        ] {
            learnt.learn(
                &FractionSample {
                    integrand: sample.0,
                    bsdf_pdf: sample.1,
                    guide_pdf: sample.2,
                    drawn_with: 0.5,
                },
                FractionLoss::Divergence,
            );
        }
        assert_eq!(learnt, LearntFraction::default());
        assert_eq!(learnt.fraction(), 0.5);
    }
}
