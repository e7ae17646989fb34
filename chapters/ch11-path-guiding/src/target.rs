//! What the guide learns: the value a path's vertex records for the direction it took.
//!
//! Müller et al. guide towards the light arriving at a point, `L_i(ω)`: each vertex records
//! the radiance its path brought back along the direction it sampled, over the density of
//! that direction, so that a quadtree cell sums an estimate of the light arriving through it
//! ([`GuidingTarget::Radiance`]). That is the best density only when what follows is
//! noiseless and the BSDF is flat. Rath, Grittmann, Herholz, Vévoda, Slusallek and Křivánek
//! (*Variance-Aware Path Guiding*, SIGGRAPH 2020) asked which density makes the *pixel's*
//! variance smallest, and found the square root of the second moment of the pixel's
//! estimate: the whole integrand (what the path carried to the vertex, the BSDF, the light),
//! with the noise of the rest of the path in it, measured relative to the pixel it ends in
//! ([`GuidingTarget::Variance`]). A direction whose light is dim but noisy is then worth
//! drawing, and a bright pixel no longer takes the guide from a dark one.
//!
//! The pixel's value is not known while it renders; the paper takes it from the iteration
//! before, smoothed by a few box filters ([`pixel_estimates`]).

use common::image::Image;
use glam::Vec3;

/// What a guide is taught to follow.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum GuidingTarget {
    /// The light arriving from each direction (Müller et al. 2017).
    Radiance,
    /// The square root of the second moment of the pixel's estimate (Rath et al. 2020).
    Variance,
}

impl GuidingTarget {
    /// Its name on the command line and in the figures.
    pub fn name(self) -> &'static str {
        match self {
            GuidingTarget::Radiance => "radiance",
            GuidingTarget::Variance => "variance",
        }
    }

    /// A leaf's weight in the built quadtree from the sum of its records and its share `area`
    /// of the square. Sampling picks leaves in proportion to their weights and spreads each
    /// over its area, so the density in a leaf is its weight over its area: for radiance the
    /// records' mean per area; for variance the square root of it, since the records are
    /// second moments (`sqrt(sum / area) · area`).
    pub fn leaf_weight(self, sum: f32, area: f32) -> f32 {
        match self {
            GuidingTarget::Radiance => sum,
            GuidingTarget::Variance => (sum * area).max(0.0).sqrt(),
        }
    }
}

/// What a path knows at one of its vertices once it has ended: the numbers a guide learns
/// from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VertexRecord {
    /// The estimate of the radiance arriving along the sampled direction: all the path
    /// brought back after this vertex, divided by what it carried from the vertex on.
    pub incident: Vec3,
    /// What the path carried to the camera from the vertex, before its BSDF: the product of
    /// the weights of the bounces before it.
    pub throughput: Vec3,
    /// `f cos θ` of the sampled direction at the vertex.
    pub f_cos: Vec3,
    /// The density with which the direction was drawn (the mixture's, per unit solid angle).
    pub pdf: f32,
    /// The estimate of the pixel the path belongs to (its channels' mean), from the
    /// iteration before.
    pub pixel_estimate: f32,
}

impl GuidingTarget {
    // ANCHOR: recorded_value
    /// The value `vertex` adds to the cell of its direction in the quadtree being learnt.
    /// A cell's sum estimates the integral, over its directions, of the function the target
    /// follows: one sample of a direction drawn with density `pdf` is worth its value over the
    /// density. Channels are averaged into one number.
    ///
    /// For [`Radiance`](Self::Radiance) the function is the light arriving. For
    /// [`Variance`](Self::Variance) it is the second moment of the vertex's part of its pixel:
    /// which product of the record's fields is what the vertex adds to the pixel, how is it
    /// made relative, and what makes it a second moment? A record that cannot say (an estimate
    /// of the pixel that is not positive) adds nothing.
    pub fn recorded_value(self, vertex: &VertexRecord) -> f32 {
        // BEGIN SOLUTION
        if vertex.pdf.is_nan() || vertex.pdf <= 0.0 {
            return 0.0;
        }
        match self {
            GuidingTarget::Radiance => mean(vertex.incident) / vertex.pdf,
            GuidingTarget::Variance => {
                if vertex.pixel_estimate.is_nan() || vertex.pixel_estimate <= 0.0 {
                    return 0.0;
                }
                let integrand = vertex.throughput * vertex.f_cos * vertex.incident;
                let relative = mean(integrand) / vertex.pixel_estimate;
                relative * relative / vertex.pdf
            }
        }
        // END SOLUTION
    }
    // ANCHOR_END: recorded_value
}

/// The mean of the three channels.
pub fn mean(v: Vec3) -> f32 {
    (v.x + v.y + v.z) / 3.0
}

/// Box filters in a row on each axis, as the paper's estimate runs them.
const BOX_PASSES: usize = 3;

/// The pixels a box filter reaches on each side.
const BOX_RADIUS: i64 = 1;

/// Each pixel's estimate for the variance-aware target, from an iteration's `image`: its
/// channels' mean, smoothed by [`BOX_PASSES`] box filters of radius [`BOX_RADIUS`] along each
/// axis (one iteration's pixel is noisy, and a noisy estimate below the pixel's true value
/// would make its paths count for too much), no lower than a thousandth of the image's mean,
/// so that a black pixel's paths are not divided by 0. Row by row.
pub fn pixel_estimates(image: &Image) -> Vec<f32> {
    let (w, h) = (image.width as usize, image.height as usize);
    let mut values: Vec<f32> = image.pixels.iter().map(|&p| mean(p).max(0.0)).collect();
    let finite_mean = {
        let finite: Vec<f64> = values
            .iter()
            .filter(|v| v.is_finite())
            .map(|&v| f64::from(v))
            .collect();
        if finite.is_empty() {
            0.0
        } else {
            finite.iter().sum::<f64>() / finite.len() as f64
        }
    };
    for v in &mut values {
        if !v.is_finite() {
            *v = finite_mean as f32;
        }
    }
    let blur = |values: &[f32], along_x: bool| -> Vec<f32> {
        let mut out = vec![0.0; values.len()];
        for y in 0..h {
            for x in 0..w {
                let (mut sum, mut n) = (0.0f32, 0.0f32);
                for d in -BOX_RADIUS..=BOX_RADIUS {
                    let (xx, yy) = if along_x {
                        (x as i64 + d, y as i64)
                    } else {
                        (x as i64, y as i64 + d)
                    };
                    if xx >= 0 && yy >= 0 && (xx as usize) < w && (yy as usize) < h {
                        sum += values[yy as usize * w + xx as usize];
                        n += 1.0;
                    }
                }
                out[y * w + x] = sum / n;
            }
        }
        out
    };
    for _ in 0..BOX_PASSES {
        values = blur(&values, true);
        values = blur(&values, false);
    }
    let floor = 1e-3 * finite_mean as f32;
    values.iter().map(|&v| v.max(floor)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A vertex whose numbers are easy to follow: the path carried 0.5 to it, the BSDF's
    /// `f cos θ` is 0.4, the light arriving 3, the density 0.4, the pixel 0.3. Chosen so that
    /// no two of the usual mistakes give the same number.
    fn vertex() -> VertexRecord {
        VertexRecord {
            incident: Vec3::splat(3.0),
            throughput: Vec3::splat(0.5),
            f_cos: Vec3::splat(0.4),
            pdf: 0.4,
            pixel_estimate: 0.3,
        }
    }

    /// The first of `candidates` (a number a mistake gives, and its words) that `got` equals,
    /// or `otherwise`.
    fn mistake<'a>(got: f32, candidates: &[(f32, &'a str)], otherwise: &'a str) -> &'a str {
        candidates
            .iter()
            .find(|(wrong, _)| (got - wrong).abs() < 1e-3 * wrong.abs().max(1.0))
            .map_or(otherwise, |(_, words)| words)
    }

    #[test]
    fn exercise_recorded_value_follows_the_light_for_radiance() {
        let got = GuidingTarget::Radiance.recorded_value(&vertex());
        let why = mistake(
            got,
            &[
                (
                    3.0,
                    "the light was not divided by the density of its direction",
                ),
                (
                    1.2,
                    "the light was multiplied by the density: a sample drawn often is worth less",
                ),
                (
                    1.5,
                    "the radiance target follows the light alone, not the BSDF or the path",
                ),
                (
                    22.5,
                    "the light was squared: only the variance-aware target records a second moment",
                ),
            ],
            "which of the record's fields does the radiance target follow?",
        );
        assert!(
            (got - 7.5).abs() < 1e-3,
            "recorded_value: light 3 arriving along a direction drawn with density 0.4 records \
             {got}, expected 7.5: {why}"
        );
    }

    #[test]
    fn exercise_recorded_value_is_the_second_moment_relative_to_the_pixel() {
        let got = GuidingTarget::Variance.recorded_value(&vertex());
        // What the vertex adds to its pixel: 0.5 · 0.4 · 3 = 0.6; relative to the pixel's 0.3,
        // 2; its second moment 4; one sample of density 0.4 of it is worth 10.
        let why = mistake(
            got,
            &[
                (
                    7.5,
                    "that is the radiance target's value: the variance-aware target records what \
                     the vertex adds to its pixel, not the light arriving",
                ),
                (
                    22.5,
                    "the light arriving was squared, not what the vertex adds to its pixel",
                ),
                (
                    5.0,
                    "the value is not squared: the target is a second moment",
                ),
                (
                    0.9,
                    "the value was not made relative to the pixel's estimate",
                ),
                (
                    3.0,
                    "the pixel's estimate divides the value before it is squared, not after",
                ),
                (
                    4.0,
                    "the square was not divided by the density of the direction",
                ),
                (
                    25.0,
                    "the density was squared with the value: one sample is worth its value over \
                     the density once",
                ),
                (
                    0.36 / 0.09 / 0.09 / 0.4,
                    "the pixel's estimate was divided twice",
                ),
                (
                    40.0,
                    "the path's throughput before the vertex was left out of what the vertex adds",
                ),
                (
                    62.5,
                    "the BSDF's f cos θ was left out of what the vertex adds",
                ),
            ],
            "what does the vertex add to its pixel, relative to the pixel?",
        );
        assert!(
            (got - 10.0).abs() < 1e-3,
            "recorded_value: a vertex adding 0.6 to a pixel of 0.3, its direction drawn with \
             density 0.4, records {got} for the variance-aware target, expected 10: {why}"
        );
        for pixel_estimate in [0.0, -1.0, f32::NAN] {
            let dark = VertexRecord {
                pixel_estimate,
                ..vertex()
            };
            let got = GuidingTarget::Variance.recorded_value(&dark);
            assert!(
                got == 0.0,
                "recorded_value: with an estimate of its pixel of {pixel_estimate} a vertex \
                 cannot say how much it adds relative to it, so it records nothing, not {got}"
            );
        }
        for target in [GuidingTarget::Radiance, GuidingTarget::Variance] {
            for pdf in [0.0, f32::NAN] {
                let none = VertexRecord { pdf, ..vertex() };
                let got = target.recorded_value(&none);
                assert!(
                    got == 0.0,
                    "recorded_value: a direction of density {pdf} was never drawn, and records \
                     nothing for the {} target, not {got}",
                    target.name()
                );
            }
        }
    }

    #[test]
    fn pixel_estimates_are_smoothed_and_never_zero() {
        // A bright pixel far enough from the edges for the filters not to reach them.
        let mut image = Image::new(15, 13);
        image.set(7, 6, Vec3::splat(63.0));
        let estimates = pixel_estimates(&image);
        let total: f32 = estimates.iter().sum();
        assert!(
            (total - 63.0).abs() < 0.5,
            "the box filters keep the image's sum: {total}"
        );
        assert!(estimates[6 * 15 + 7] < 63.0 && estimates[6 * 15 + 8] > 0.2);
        assert!(estimates.iter().all(|&e| e > 0.0));
    }
}
