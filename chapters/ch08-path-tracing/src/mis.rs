//! Multiple importance sampling: two ways of finding the same light, each weighted where it is
//! good.
//!
//! A light reaches a surface along a direction that two strategies can produce: the light
//! sample (good for small lights, bad for a sharp glossy lobe) and the BSDF sample (the
//! reverse). Counting both would count the light twice; counting one throws the other's
//! strength away. Veach's answer: weight each sample by `w_a(x)`, with `w_a + w_b = 1` at
//! every `x`, and the sum stays unbiased whatever the weights. The *balance heuristic*
//! `p_a / (p_a + p_b)` is provably close to the best; the *power heuristic* (squares) is
//! better still when one density is much larger, and is what Mitsuba 3 and pbrt use.

/// How the two estimators of the same light are combined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum MisHeuristic {
    /// No combination: light found by BSDF rays at non-delta surfaces is ignored, the light
    /// sample alone counts (plain next-event estimation).
    None,
    /// `p_a / (p_a + p_b)`.
    Balance,
    /// Veach's power heuristic with exponent 2 ([`power_heuristic`]).
    Power,
}

impl MisHeuristic {
    /// Every heuristic.
    pub const ALL: [MisHeuristic; 3] = [
        MisHeuristic::None,
        MisHeuristic::Balance,
        MisHeuristic::Power,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            MisHeuristic::None => "none",
            MisHeuristic::Balance => "balance",
            MisHeuristic::Power => "power",
        }
    }

    /// The weight of a sample drawn with density `pdf_a` that the other strategy would have
    /// drawn with density `pdf_b`. With [`MisHeuristic::None`] the light sample (the caller's
    /// `a`) takes everything: 1.
    pub fn weight(self, pdf_a: f32, pdf_b: f32) -> f32 {
        match self {
            MisHeuristic::None => 1.0,
            MisHeuristic::Balance => balance_heuristic(pdf_a, pdf_b),
            MisHeuristic::Power => power_heuristic(pdf_a, pdf_b),
        }
    }

    /// The weight of light that a BSDF sample drawn with density `bsdf_pdf` found, which a
    /// light sample would have drawn with density `light_pdf`: the heuristic's
    /// `weight(bsdf_pdf, light_pdf)`, but 0 with [`MisHeuristic::None`], where the light sample
    /// counts such light in full.
    pub fn bsdf_sample_weight(self, bsdf_pdf: f32, light_pdf: f32) -> f32 {
        match self {
            MisHeuristic::None => 0.0,
            mis => mis.weight(bsdf_pdf, light_pdf),
        }
    }
}

/// `p_a / (p_a + p_b)`, 0 when `p_a` is 0 (the sample could not have been drawn).
pub fn balance_heuristic(pdf_a: f32, pdf_b: f32) -> f32 {
    if pdf_a <= 0.0 {
        return 0.0;
    }
    if pdf_a.is_infinite() {
        return 1.0;
    }
    pdf_a / (pdf_a + pdf_b)
}

// ANCHOR: power_heuristic
/// Veach's power heuristic with exponent 2: the weight of a sample drawn by strategy `a`
/// (density `pdf_a`) that strategy `b` could also have drawn (density `pdf_b`).
///
/// 0 when `p_a` is 0 (strategy `a` could not have drawn the sample), 1 when `p_a` is infinite
/// (a delta, which the other strategy can never draw); finite for any two densities that
/// `f32` holds, however large or small.
pub fn power_heuristic(pdf_a: f32, pdf_b: f32) -> f32 {
    // BEGIN SOLUTION
    if pdf_a <= 0.0 {
        return 0.0;
    }
    if pdf_a.is_infinite() {
        return 1.0;
    }
    let ratio = pdf_b / pdf_a;
    1.0 / (1.0 + ratio * ratio)
    // END SOLUTION
}
// ANCHOR_END: power_heuristic

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exercise_power_heuristic_squares_the_densities() {
        let cases: [(f32, f32, f32, &str); 8] = [
            (
                1.0,
                1.0,
                0.5,
                "two equally likely strategies share the sample evenly",
            ),
            (3.0, 1.0, 0.9, "densities 3 and 1 square to 9 and 1"),
            (1.0, 3.0, 0.1, "densities 1 and 3 square to 1 and 9"),
            (
                0.0,
                5.0,
                0.0,
                "a strategy that could not have drawn the sample gets weight 0",
            ),
            (
                2.0,
                0.0,
                1.0,
                "when the other strategy could not have drawn it, the weight is 1",
            ),
            (
                f32::INFINITY,
                1.0,
                1.0,
                "a delta (infinite density) can only come from its own strategy: weight 1",
            ),
            (
                1e30,
                1e30,
                0.5,
                "equal huge densities (a sharp lobe) still share evenly; 1e30² overflows f32 to infinity, and inf / inf is NaN",
            ),
            (
                1e-30,
                1e-30,
                0.5,
                "equal tiny densities still share evenly; 1e-30² underflows f32 to 0, and 0 / 0 is NaN",
            ),
        ];
        for (a, b, expected, why) in cases {
            let w = power_heuristic(a, b);
            if (w - expected).abs() <= 1e-6 {
                continue;
            }
            let balance = balance_heuristic(a, b);
            let mistake = if (w - balance).abs() <= 1e-6 && a.is_finite() {
                "that is the balance heuristic, p_a / (p_a + p_b): the power heuristic squares the \
                 densities first"
                    .to_string()
            } else if (w - balance * balance).abs() <= 1e-6 && a.is_finite() {
                "that is the balance heuristic's weight squared: the power heuristic squares the \
                 densities before it shares the sample out, so its two weights still add up to 1"
                    .to_string()
            } else {
                why.to_string()
            };
            panic!(
                "power_heuristic: {mistake}.\n  power_heuristic({a}, {b}) gave {w}, expected {expected}"
            );
        }
        // The two weights of one sample add up to 1: the combination is unbiased.
        for (a, b) in [(0.3f32, 7.0f32), (1e-3, 1e3), (2.0, 2.5)] {
            let sum = power_heuristic(a, b) + power_heuristic(b, a);
            assert!(
                (sum - 1.0).abs() < 1e-6,
                "power_heuristic: the weights of one sample under the two strategies add up to \
                 {sum}, not 1 (densities {a} and {b}): the combined estimator would be biased"
            );
        }
    }

    #[test]
    fn balance_weights_add_up_to_one() {
        for (a, b) in [(0.3f32, 7.0f32), (1e-3, 1e3), (2.0, 2.5)] {
            let sum = balance_heuristic(a, b) + balance_heuristic(b, a);
            assert!((sum - 1.0).abs() < 1e-6);
        }
        assert_eq!(MisHeuristic::None.weight(0.1, 10.0), 1.0);
    }
}
