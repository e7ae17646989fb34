//! Russian roulette: ending paths at random without bias.
//!
//! A path that carries little light costs as much to extend as one that carries much. From a
//! depth on, continue with probability `q` and divide what survives by `q`: on average the
//! estimate is unchanged, `q · (L / q) + (1 - q) · 0 = L`, and weak paths stop early. Mitsuba
//! 3 takes `q = min(max throughput · eta², 0.95)`: the throughput without the radiance
//! scaling of refractions (which says nothing about how much the path still matters), and
//! never 1, so even a white furnace ends.

/// The highest continuation probability: every path ends eventually.
pub const MAX_SURVIVAL: f32 = 0.95;

// ANCHOR: russian_roulette
/// The roulette for a path whose throughput (radiance scaling removed) has the largest
/// channel `throughput_max`, with the uniform number `u`: `Some(1 / q)`, the factor the
/// surviving throughput is multiplied by, or `None` when the path ends.
/// `q = min(throughput_max, MAX_SURVIVAL)`; a path with nothing left (`q` below the smallest
/// normal float, whose inverse would be infinite, or NaN) ends.
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
        assert_eq!(russian_roulette(0.5, 0.49), Some(2.0));
        assert_eq!(russian_roulette(0.5, 0.5), None);
        assert_eq!(russian_roulette(3.0, 0.9), Some(1.0 / 0.95));
        assert_eq!(russian_roulette(3.0, 0.96), None);
        assert_eq!(russian_roulette(0.0, 0.0), None);
        assert_eq!(russian_roulette(f32::NAN, 0.0), None);
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
            assert!((mean - 1.0).abs() < 1e-3, "throughput {t}: {mean}");
        }
    }
}
