//! How far the shutter is open over the exposure: the lecture's instantaneous shutter, and a
//! real one that takes a while to open and to close.
//!
//! The lecture assumes the shutter opens and closes at once, so every instant of `[t0, t1]`
//! counts the same and the time is uniform ([`Shutter::time_at`](crate::Shutter::time_at)).
//! A leaf or focal-plane shutter needs a fraction of the exposure to open fully and as long to
//! close: how much light it lets through, over the exposure, is a trapezoid instead of a box.
//! The pixel integral then weights each instant by that opening, normalised to integrate to 1,
//! and drawing the time from that weight is the generalisation the lecture mentions.
//!
//! The functions work on the fraction `s` of the exposure, in `[0, 1]`; `Shutter::time_at(s)`
//! turns it into a time. They come in pairs, as chapter 02's warps do: a warp of a uniform `u`
//! and the density of the points it makes.

// ANCHOR: trapezoid_opening
/// The density over the fraction `s` of the exposure of a shutter that takes the fraction
/// `ramp` (clamped to `[0, 1/2]`) to open fully and as long to close: it rises linearly, stays
/// flat, and falls linearly, with the height `1 / (1 - ramp)` that makes its area 1. A `ramp`
/// of 0 is the lecture's box; outside `[0, 1]` the shutter is closed.
pub fn trapezoid_opening_pdf(s: f32, ramp: f32) -> f32 {
    let ramp = ramp.clamp(0.0, 0.5);
    if !(0.0..=1.0).contains(&s) {
        return 0.0;
    }
    let height = 1.0 / (1.0 - ramp);
    let edge = s.min(1.0 - s);
    if edge < ramp {
        height * edge / ramp
    } else {
        height
    }
}

/// The fraction of the exposure drawn from [`trapezoid_opening_pdf`] by a uniform `u` in
/// `[0, 1]`: the inverse of its distribution function. Each ramp holds `ramp / (2 (1 - ramp))`
/// of the weight; a `u` that falls in a ramp is turned into a point by a square root (the
/// weight up to `s` grows like `s²` there), one in the middle linearly.
pub fn sample_trapezoid_opening(u: f32, ramp: f32) -> f32 {
    let ramp = ramp.clamp(0.0, 0.5);
    let u = u.clamp(0.0, 1.0);
    let in_ramp = 0.5 * ramp / (1.0 - ramp); // the weight of one ramp
    let s = if u < in_ramp {
        (2.0 * ramp * (1.0 - ramp) * u).sqrt()
    } else if u > 1.0 - in_ramp {
        1.0 - (2.0 * ramp * (1.0 - ramp) * (1.0 - u)).sqrt()
    } else {
        ramp + (u - in_ramp) * (1.0 - ramp)
    };
    s.clamp(0.0, 1.0)
}
// ANCHOR_END: trapezoid_opening

#[cfg(test)]
mod tests {
    use super::*;

    /// The distribution function of the trapezoid, integrated in closed form.
    fn cdf(s: f64, ramp: f64) -> f64 {
        let height = 1.0 / (1.0 - ramp);
        let rising = |s: f64| height * s * s / (2.0 * ramp);
        if s <= ramp {
            rising(s)
        } else if s <= 1.0 - ramp {
            rising(ramp) + height * (s - ramp)
        } else {
            1.0 - rising(1.0 - s)
        }
    }

    #[test]
    fn a_ramp_of_zero_is_the_lecture_s_uniform_time() {
        for u in [0.0, 0.1, 0.37, 0.5, 0.9, 1.0] {
            assert_eq!(sample_trapezoid_opening(u, 0.0), u);
            assert_eq!(trapezoid_opening_pdf(u, 0.0), 1.0);
        }
    }

    #[test]
    fn the_density_integrates_to_one_and_is_zero_outside() {
        for ramp in [0.0, 0.1, 0.25, 0.5] {
            let n = 100_000;
            let integral: f64 = (0..n)
                .map(|i| f64::from(trapezoid_opening_pdf((i as f32 + 0.5) / n as f32, ramp)))
                .sum::<f64>()
                / n as f64;
            assert!((integral - 1.0).abs() < 1e-4, "ramp {ramp}: {integral}");
            assert_eq!(trapezoid_opening_pdf(-0.01, ramp), 0.0);
            assert_eq!(trapezoid_opening_pdf(1.01, ramp), 0.0);
        }
    }

    #[test]
    fn the_warp_inverts_the_distribution_function() {
        // u = F(s): the share of the weight before the point drawn is u itself.
        for ramp in [0.05, 0.25, 0.5] {
            let mut previous = 0.0;
            for i in 0..=1000 {
                let u = i as f32 / 1000.0;
                let s = sample_trapezoid_opening(u, ramp);
                assert!((0.0..=1.0).contains(&s), "ramp {ramp}, u {u}: {s}");
                assert!(s >= previous, "ramp {ramp}: not increasing at u {u}");
                previous = s;
                let back = cdf(f64::from(s), f64::from(ramp));
                assert!(
                    (back - f64::from(u)).abs() < 1e-5,
                    "ramp {ramp}, u {u}: s {s} holds {back} of the weight before it"
                );
            }
        }
    }

    #[test]
    fn the_ends_of_the_exposure_get_fewer_samples() {
        // A histogram of the warped points follows the density: thin at the ends, flat between.
        let ramp = 0.25;
        let (n, bins) = (200_000, 20);
        let mut counts = vec![0usize; bins];
        for i in 0..n {
            let s = sample_trapezoid_opening((i as f32 + 0.5) / n as f32, ramp);
            counts[((s * bins as f32) as usize).min(bins - 1)] += 1;
        }
        for (bin, &count) in counts.iter().enumerate() {
            let (a, b) = (bin as f64 / bins as f64, (bin + 1) as f64 / bins as f64);
            let expected = (cdf(b, ramp.into()) - cdf(a, ramp.into())) * n as f64;
            assert!(
                (count as f64 - expected).abs() <= 2.0 + 1e-3 * expected,
                "bin {bin}: {count} points, expected {expected}"
            );
        }
        assert!(counts[0] < counts[bins / 2] / 4);
    }
}
