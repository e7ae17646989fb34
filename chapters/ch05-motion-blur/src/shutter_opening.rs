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

// ANCHOR: trapezoid_opening_pdf
/// The density over the fraction `s` of the exposure of a shutter that takes the fraction
/// `ramp` (clamped to `[0, 1/2]`) to open fully and as long to close: it rises linearly from 0,
/// stays flat, and falls linearly back to 0, and the area under it is 1. A `ramp` of 0 is the
/// lecture's box; outside `[0, 1]` the shutter is closed.
pub fn trapezoid_opening_pdf(s: f32, ramp: f32) -> f32 {
    // BEGIN SOLUTION
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
    // END SOLUTION
}
// ANCHOR_END: trapezoid_opening_pdf

// ANCHOR: sample_trapezoid_opening
/// The fraction of the exposure drawn from [`trapezoid_opening_pdf`] by a uniform `u` in
/// `[0, 1]`, for the same `ramp` (clamped to `[0, 1/2]`): the inverse of its distribution
/// function, so that the share of the weight before the point drawn is `u`. Never outside
/// `[0, 1]`; a `ramp` of 0 gives `u` back.
pub fn sample_trapezoid_opening(u: f32, ramp: f32) -> f32 {
    // BEGIN SOLUTION
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
    // END SOLUTION
}
// ANCHOR_END: sample_trapezoid_opening

#[cfg(test)]
mod tests {
    use super::*;

    /// The opening's shape, at any height: 0 at the ends of the exposure, 1 on the flat top
    /// from `ramp` to `1 - ramp`, straight lines between (a `ramp` of 0 is the box).
    fn shape(s: f64, ramp: f64) -> f64 {
        if !(0.0..=1.0).contains(&s) {
            0.0
        } else if ramp == 0.0 {
            1.0
        } else {
            (s.min(1.0 - s) / ramp).min(1.0)
        }
    }

    /// The area under [`shape`] over `[a, b]`, by the trapezoid rule on pieces cut at its
    /// corners: exact, up to rounding, since the shape is straight between them.
    fn area_under_shape(a: f64, b: f64, ramp: f64) -> f64 {
        let mut cuts = vec![a];
        cuts.extend([ramp, 1.0 - ramp].into_iter().filter(|&c| a < c && c < b));
        cuts.push(b);
        let steps = 64;
        cuts.windows(2)
            .map(|piece| {
                let h = (piece[1] - piece[0]) / f64::from(steps);
                (0..steps)
                    .map(|i| {
                        let x = piece[0] + f64::from(i) * h;
                        0.5 * (shape(x, ramp) + shape(x + h, ramp)) * h
                    })
                    .sum::<f64>()
            })
            .sum()
    }

    /// The distribution function of the trapezoid, the share of the weight before `s`,
    /// integrated numerically.
    fn cdf(s: f64, ramp: f64) -> f64 {
        area_under_shape(0.0, s.clamp(0.0, 1.0), ramp) / area_under_shape(0.0, 1.0, ramp)
    }

    /// The ramps the checks try, the box and the triangle included.
    const RAMPS: [f32; 5] = [0.0, 0.1, 0.25, 0.4, 0.5];

    /// What is wrong with `trapezoid_opening_pdf` for `ramp`, in words; `None` if it is right.
    fn density_mistake(ramp: f32) -> Option<String> {
        let pdf = |s: f32| trapezoid_opening_pdf(s, ramp);
        for s in [-0.5, -0.01, 1.01, 1.5] {
            if pdf(s) != 0.0 {
                return Some(format!(
                    "at s = {s} it is {}: the shutter is shut outside [0, 1], so no time may \
                     fall there and the density is 0",
                    pdf(s)
                ));
            }
        }
        let top = f64::from(pdf(0.5));
        let at = |s: f32| f64::from(pdf(s)) / top;
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-4;
        if ramp > 0.0 {
            // The shape, measured against the student's own top: the ramps' length and slope.
            let shape = [
                (ramp, 1.0),
                (1.0 - ramp, 1.0),
                (0.5 * ramp, 0.5),
                (1.0 - 0.5 * ramp, 0.5),
                (0.25 * ramp, 0.25),
                (0.0, 0.0),
            ];
            for (s, share) in shape {
                if !close(at(s), share) {
                    let why = if close(at(0.5 * ramp), 1.0) || at(ramp) > 1.0 + 1e-4 {
                        "the ramps are too short"
                    } else if at(ramp) < 1.0 - 1e-4 {
                        "the ramps are too long"
                    } else {
                        "the ramps are not straight lines from 0 to the top"
                    };
                    return Some(format!(
                        "at s = {s} it is {} of its flat top, not {share}: {why}. The shutter \
                         takes the fraction r = {ramp} of the exposure to open, so the density \
                         climbs linearly from 0 at s = 0 to its top at s = r, and falls back \
                         the same way from 1 - r to 1",
                        at(s)
                    ));
                }
            }
        } else if [0.0, 0.3, 1.0].iter().any(|&s| !close(at(s), 1.0)) {
            return Some(
                "a ramp of 0 is the lecture's box: the same height all over [0, 1]".to_string(),
            );
        }
        let n = 20_000;
        let area: f64 = (0..n)
            .map(|i| f64::from(pdf((i as f32 + 0.5) / n as f32)))
            .sum::<f64>()
            / f64::from(n);
        if (area - 1.0).abs() > 1e-3 {
            let why = if close(top, 1.0) {
                "a flat top at height 1 leaves the area short by the two ramps' missing \
                 triangles: the height has to make the area 1 (the density is normalised)"
                    .to_string()
            } else {
                format!(
                    "its flat top is at {top}; the area under the trapezoid is a rectangle and \
                     two triangles, and the height has to make it 1"
                )
            };
            return Some(format!("the area under it is {area:.4}, not 1: {why}"));
        }
        None
    }

    #[test]
    fn exercise_trapezoid_opening_pdf_is_a_normalised_trapezoid() {
        for ramp in RAMPS {
            if let Some(mistake) = density_mistake(ramp) {
                panic!("trapezoid_opening_pdf with ramp {ramp}: {mistake}");
            }
        }
    }

    /// What is wrong with `s = sample_trapezoid_opening(u, ramp)`, in words; `None` if right.
    fn warp_mistake(u: f64, ramp: f64, s: f32) -> Option<String> {
        let expected = inverse_cdf(u, ramp);
        let near = |x: f64| (f64::from(s) - x).abs() <= 2e-6;
        if near(expected) {
            return None;
        }
        // The share of the weight under the rising ramp (and as much under the falling one).
        let share = cdf(ramp, ramp);
        let why = if ramp > 0.0 && near(u) {
            "that is the lecture's box, u itself: the warp has to follow the trapezoid, so \
             that fewer times fall where the shutter is only partly open"
        } else if u < share || u > 1.0 - share {
            "this u falls on a ramp, where the weight up to s grows like the area of a \
             triangle, with the square of s (of 1 - s on the falling ramp): inverting it takes \
             a square root"
        } else {
            "between the ramps the weight grows linearly, so the warp is a straight line there, \
             from where the rising ramp's share of the weight ends to where the falling \
             ramp's begins: check the share you gave one ramp and the line's slope"
        };
        Some(format!(
            "the point should be {expected:.6}, the s before which the share u of the weight \
             lies: {why}"
        ))
    }

    /// The inverse of [`cdf`]: the `s` before which the share `u` of the weight lies, found
    /// by bisection (the distribution function only grows).
    fn inverse_cdf(u: f64, ramp: f64) -> f64 {
        let (mut below, mut above) = (0.0, 1.0);
        for _ in 0..60 {
            let middle = 0.5 * (below + above);
            if cdf(middle, ramp) < u {
                below = middle;
            } else {
                above = middle;
            }
        }
        0.5 * (below + above)
    }

    #[test]
    fn exercise_sample_trapezoid_opening_inverts_the_distribution_function() {
        for ramp in RAMPS {
            let r = f64::from(ramp);
            // The share of the weight under one ramp.
            let share = cdf(r, r);
            // Inside the ramps first, then where they end, then the flat top.
            for u in [
                share / 4.0,
                1.0 - share / 4.0,
                share * 0.81,
                share,
                1.0 - share,
                0.5,
                share + (1.0 - 2.0 * share) / 4.0,
                0.0,
                1.0,
            ] {
                let s = sample_trapezoid_opening(u as f32, ramp);
                if let Some(mistake) = warp_mistake(f64::from(u as f32), r, s) {
                    panic!(
                        "sample_trapezoid_opening: u = {u} with ramp {ramp} gave {s}, but \
                         {mistake}"
                    );
                }
            }
        }
    }

    #[test]
    fn exercise_sample_trapezoid_opening_follows_the_density() {
        // Pearson's chi-square over 20 equal bins of s: with 19 degrees of freedom it stays
        // below 51.1 but for one seed in ten thousand when the points follow the density.
        use common::sampler::{IndependentSampler, Sampler};
        let (n, bins) = (20_000, 20);
        for (seed, ramp) in [(3, 0.25_f32), (7, 0.5)] {
            let mut sampler = IndependentSampler::new(seed);
            sampler.start_pixel_sample(glam::UVec2::ZERO, 0);
            let mut counts = vec![0u32; bins];
            for _ in 0..n {
                let s = sample_trapezoid_opening(sampler.get_1d(), ramp);
                assert!(
                    (0.0..=1.0).contains(&s),
                    "sample_trapezoid_opening: {s} is outside [0, 1] with ramp {ramp}"
                );
                counts[((s * bins as f32) as usize).min(bins - 1)] += 1;
            }
            let chi_square: f64 = counts
                .iter()
                .enumerate()
                .map(|(bin, &count)| {
                    let (a, b) = (bin as f64 / bins as f64, (bin + 1) as f64 / bins as f64);
                    let expected = (cdf(b, ramp.into()) - cdf(a, ramp.into())) * f64::from(n);
                    (f64::from(count) - expected).powi(2) / expected
                })
                .sum();
            assert!(
                chi_square < 51.1,
                "sample_trapezoid_opening with ramp {ramp}: {n} warped uniform numbers fall into \
                 20 bins of s as {counts:?}, which the trapezoid makes unlikely (chi-square \
                 {chi_square:.1} with 19 degrees of freedom, above 51.1): the points do not \
                 follow trapezoid_opening_pdf"
            );
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
