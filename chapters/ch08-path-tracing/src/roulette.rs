//! Russian roulette: ending paths at random without bias.
//!
//! A path that carries little light costs as much to extend as one that carries much. From a
//! depth on, continue with probability `q` and scale what survives so that on average the
//! estimate is unchanged, and weak paths stop early. Mitsuba 3 takes `q` from the throughput
//! without the radiance scaling of refractions (which says nothing about how much the path
//! still matters), and never 1, so even a white furnace ends.

/// The highest continuation probability: every path ends eventually.
pub const MAX_SURVIVAL: f32 = 0.95;

// ANCHOR: russian_roulette
/// The roulette for a path whose throughput (radiance scaling removed) has the largest
/// channel `throughput_max`, with the uniform number `u`: `Some(factor)`, what the surviving
/// throughput is multiplied by (always finite), or `None` when the path ends. The path survives
/// when `u` falls below its chance of surviving. A dim path is likely to end, a bright one
/// survives at most with probability [`MAX_SURVIVAL`]; a path with nothing left, or a NaN,
/// ends.
pub fn russian_roulette(throughput_max: f32, u: f32) -> Option<f32> {
    // BEGIN SOLUTION
    // `f32::min` ignores NaN, so a NaN throughput is refused before it can become 0.95; and
    // below the smallest normal float, 1 / q would overflow to infinity.
    if throughput_max.is_nan() || throughput_max < f32::MIN_POSITIVE {
        return None;
    }
    let q = throughput_max.min(MAX_SURVIVAL);
    if u >= q {
        return None;
    }
    Some(1.0 / q)
    // END SOLUTION
}
// ANCHOR_END: russian_roulette

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exercise_russian_roulette_is_unbiased() {
        let cases: [(f32, f32, Option<f32>, &str); 6] = [
            (
                0.5,
                0.49,
                Some(2.0),
                "a path with throughput 0.5 survives for u below 0.5, and the survivor has to carry more, so that the mean over u stays what it was",
            ),
            (
                0.5,
                0.5,
                None,
                "a path with throughput 0.5 survives only for u below 0.5",
            ),
            (
                3.0,
                0.9,
                // Worked out beforehand for the cap 0.95, to f32's precision.
                Some(1.052_631_6),
                "a bright path survives with probability MAX_SURVIVAL, not 1 (every path must have a chance to end), and its survivor carries what keeps the mean at 1",
            ),
            (
                3.0,
                0.96,
                None,
                "even a bright path ends when u is above MAX_SURVIVAL",
            ),
            (
                0.0,
                0.0,
                None,
                "a path that carries nothing ends: it could only be kept fair by an infinite factor",
            ),
            (
                f32::NAN,
                0.0,
                None,
                "a NaN throughput ends the path (f32::min ignores a NaN, so min(NaN, 0.95) is 0.95)",
            ),
        ];
        for (t, u, expected, why) in cases {
            let got = russian_roulette(t, u);
            let agrees = match (got, expected) {
                (Some(got), Some(expected)) => (got - expected).abs() <= 1e-6 * expected,
                (got, expected) => got == expected,
            };
            assert!(
                agrees,
                "russian_roulette: {why}.\n  russian_roulette({t}, {u}) gave {got:?}, expected {expected:?}"
            );
        }
        let tiny = russian_roulette(1e-39, 0.0);
        assert!(
            tiny.is_none_or(f32::is_finite),
            "russian_roulette: a throughput below the smallest normal float (1e-39) would survive \
             with a factor of {tiny:?}: a survivor's factor overflows to infinity there, so the \
             path ends"
        );
        // The mean of the factor over u is exactly 1 for any throughput.
        for t in [1e-4f32, 0.1, 0.7, 0.95, 1.0, 20.0] {
            let n = 100_000;
            let mean: f64 = (0..n)
                .map(|i| {
                    let u = (i as f32 + 0.5) / n as f32;
                    f64::from(russian_roulette(t, u).unwrap_or(0.0))
                })
                .sum::<f64>()
                / f64::from(n);
            assert!(
                (mean - 1.0).abs() < 1e-3,
                "russian_roulette: over all u the factor of a path with throughput {t} averages \
                 {mean:.4}, not 1: the roulette has to leave the expected throughput unchanged"
            );
        }
    }
}
