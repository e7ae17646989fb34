//! Which ray to trace at glass: both, or one picked at random.
//!
//! Glass splits an arriving ray into a reflected and a refracted one, the Fresnel equations
//! saying how the light divides: a share `F` reflected, `1 - F` refracted. Whitted's tracer
//! (chapter 01) follows both. Behind a pane or inside a sphere each of them splits again, so a
//! path of `d` glass surfaces costs `2^d` rays, most of them carrying almost nothing.
//!
//! Picking one of the two at random keeps one ray per bounce. The estimate stays right on
//! average if the chosen ray's light is weighted for the chance of choosing it:
//!
//! - [`GlassStrategy::Half`], the lecture's rule: reflect if `ξ < 1/2`, else refract, each
//!   with the weight the chapter's first exercise finds.
//! - [`GlassStrategy::Fresnel`]: reflect with probability `F`. The chance equals the share,
//!   so no ray is spent on a branch that carries little light (Mitsuba's `dielectric` chooses
//!   this way).
//!
//! Both are unbiased; they differ in noise, which the chapter's figures measure against the
//! run time.

/// How a tracer chooses between the reflected and the refracted ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum GlassStrategy {
    /// Trace both rays (Whitted's method): exponential in the depth.
    Both,
    /// One ray, each with probability 1/2, weighted to stay unbiased.
    Half,
    /// One ray, reflection with probability F, weighted by 1.
    Fresnel,
}

impl GlassStrategy {
    /// Every strategy.
    pub const ALL: [GlassStrategy; 3] = [
        GlassStrategy::Both,
        GlassStrategy::Half,
        GlassStrategy::Fresnel,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            GlassStrategy::Both => "both",
            GlassStrategy::Half => "half",
            GlassStrategy::Fresnel => "fresnel",
        }
    }
}

/// One of the two rays, chosen at random, with the weight that keeps the estimate unbiased.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GlassChoice {
    /// `true` for the reflected ray, `false` for the refracted one.
    pub reflect: bool,
    /// What the chosen ray's radiance is multiplied by, so that the average over the random
    /// choice is Whitted's `F L_r + (1 - F) L_t`.
    pub weight: f32,
}

// ANCHOR: choose_half
/// The lecture's choice: reflection if `u < 1/2`, else refraction, for a surface that
/// reflects the share `reflectance` (the Fresnel `F`) of the light, with the weight that
/// makes the chosen ray's light, on average over `u`, Whitted's `F L_r + (1 - F) L_t`.
pub fn choose_half(u: f32, reflectance: f32) -> GlassChoice {
    // BEGIN SOLUTION
    if u < 0.5 {
        GlassChoice {
            reflect: true,
            weight: 2.0 * reflectance,
        }
    } else {
        GlassChoice {
            reflect: false,
            weight: 2.0 * (1.0 - reflectance),
        }
    }
    // END SOLUTION
}
// ANCHOR_END: choose_half

/// Reflection with probability `reflectance` (the Fresnel `F`), else refraction, each with the
/// weight that keeps the average Whitted's sum. Total internal reflection (`F = 1`) always
/// reflects, and `F = 0` (index-matched glass) always refracts.
pub fn choose_fresnel(u: f32, reflectance: f32) -> GlassChoice {
    GlassChoice {
        reflect: u < reflectance,
        weight: 1.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use common::sampler::{IndependentSampler, Sampler};
    use glam::UVec2;

    /// The mean of `weight * (reflected ? a : b)` over `n` choices, with its standard error.
    fn mean_estimate(choose: fn(f32, f32) -> GlassChoice, f: f32, a: f64, b: f64) -> (f64, f64) {
        let mut sampler = IndependentSampler::new(4);
        let n = 100_000u64;
        let (mut sum, mut sum2) = (0.0f64, 0.0f64);
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            let choice = choose(sampler.get_1d(), f);
            let x = f64::from(choice.weight) * if choice.reflect { a } else { b };
            sum += x;
            sum2 += x * x;
        }
        let mean = sum / n as f64;
        let variance = (sum2 / n as f64 - mean * mean).max(0.0);
        (mean, (variance / n as f64).sqrt())
    }

    #[test]
    fn exercise_choose_half_averages_to_whitteds_sum() {
        // Unbiased: the mean equals Whitted's F a + (1 - F) b within 5 standard errors.
        for f in [0.04f32, 0.5, 0.9, 0.0, 1.0] {
            let (a, b) = (3.0, 0.5);
            let (mean, se) = mean_estimate(choose_half, f, a, b);
            let expected = f64::from(f) * a + (1.0 - f64::from(f)) * b;
            if (mean - expected).abs() <= 5.0 * se + 1e-9 {
                continue;
            }
            let reflected = choose_half(0.25, f);
            let refracted = choose_half(0.75, f);
            let why = if (mean - 0.5 * expected).abs() <= 5.0 * se + 1e-9 {
                "half of it: each branch is taken only half the time, so its share of the light \
                 has to count for more when it is taken"
                    .to_string()
            } else if reflected.weight == 1.0 && refracted.weight == 1.0 {
                "the weights are 1: with a coin of 1/2 the branches are not taken in proportion \
                 to their shares F and 1 - F, so the weight has to make up for it"
                    .to_string()
            } else if reflected.reflect == refracted.reflect {
                "one kind of ray only: the coin has to pick reflection half the time and \
                 refraction the other half"
                    .to_string()
            } else {
                format!(
                    "the branches' weights (reflection {}, refraction {}) do not give back F and \
                     1 - F on average: does each branch carry its own Fresnel share?",
                    if reflected.reflect {
                        reflected.weight
                    } else {
                        refracted.weight
                    },
                    if reflected.reflect {
                        refracted.weight
                    } else {
                        reflected.weight
                    },
                )
            };
            panic!(
                "choose_half: with F = {f}, reflected light {a} and refracted light {b}, Whitted's \
                 sum is {expected}, and the mean of your choices is {mean:.4} (± {se:.4}): {why}"
            );
        }
        // The lecture's convention: reflection below 1/2.
        for (u, reflect) in [(0.25, true), (0.5, false), (0.9, false)] {
            assert!(
                choose_half(u, 0.1).reflect == reflect,
                "choose_half: the lecture reflects for ξ < 1/2 and refracts otherwise; with \
                 ξ = {u} yours {}",
                if reflect { "refracted" } else { "reflected" }
            );
        }
    }

    #[test]
    fn choosing_by_fresnel_is_unbiased_with_weight_one() {
        for f in [0.0f32, 0.04, 0.5, 0.9, 1.0] {
            let (a, b) = (3.0, 0.5);
            let (mean, se) = mean_estimate(choose_fresnel, f, a, b);
            let expected = f64::from(f) * a + (1.0 - f64::from(f)) * b;
            assert!(
                (mean - expected).abs() <= 5.0 * se + 1e-9,
                "F={f}: {mean} vs {expected}"
            );
        }
        assert!(choose_fresnel(0.999_999, 1.0).reflect, "total reflection");
        assert!(!choose_fresnel(0.0, 0.0).reflect, "index-matched glass");
    }

    #[test]
    fn choosing_by_fresnel_has_less_variance_than_half_when_f_is_small() {
        // Glass at normal incidence: F = 0.04. Half wastes half the rays on the reflection.
        let (a, b) = (1.0, 1.0);
        let (_, se_half) = mean_estimate(choose_half, 0.04, a, b);
        let (_, se_fresnel) = mean_estimate(choose_fresnel, 0.04, a, b);
        assert!(se_fresnel < 0.1 * se_half, "{se_fresnel} vs {se_half}");
    }
}
