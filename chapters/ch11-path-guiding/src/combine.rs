//! Keeping the training's images: every pass's image in the render's, with a weight.
//!
//! Each training iteration renders the whole image with guides it does not change while it
//! renders, so its image is an unbiased estimate of the same picture as the final pass's,
//! only noisier: its guides had learnt less, and it has fewer samples. Throwing it away
//! wastes the half of the budget the training took.
//!
//! Any weights fixed before the passes are drawn, summing to 1, keep the average unbiased.
//! The simplest weighs each pass by its samples ([`sample_count_weights`]): every sample
//! counts alike, as if the whole budget were one pass. With `n_k` samples of per-sample
//! variance `σ_k²` in pass `k`, the average's variance is `Σ n_k σ_k² / N²`: below the final
//! pass's alone as long as the training's samples are, on average, less than three times as
//! noisy as the final pass's (the training is about as long as the final pass).
//!
//! But a pass's samples are as good as its guides, and its guides learnt from every sample
//! before it: on the door-gap room a sample of the first passes is about as noisy as an
//! unguided one, a sample of the final pass a fifth of that. The weights that make the
//! average's variance smallest are `n_k / σ_k²`. The render's default takes `σ_k²` as falling
//! with the square root of `m_k`, the training samples pass `k`'s guides learnt from, and so
//! weighs each pass by `n_k √m_k` ([`learning_weights`]): still fixed before anything is drawn,
//! so still unbiased. (Two seeds' passes measured on three scenes, 1024 samples per pixel,
//! the average's variance over the one by samples: door gap 0.80 and 0.84, against 0.78 and
//! 0.84 for the inverse of each pass's measured variance, the best any weights can do; glossy
//! floor 1.01, Cornell box 1.04, where the guides gain little and the samples' own weights were
//! already near the best. With `n_k m_k`, as if the guides' noise fell as one over what they
//! learnt from, 0.83 and 0.89 on the door gap, but 1.15 and 1.17 on the other two.)
//!
//! Müller, Evans, Keller and Novák (*Practical Path Guiding in Production*, 2019) weigh each
//! pass by the inverse of its variance instead ([`inverse_variance_weights`]), the weights
//! that make the variance of a weighted mean of independent estimates smallest. The
//! variances are not known; they are measured on the images themselves. Two passes
//! estimate the same picture, so the mean squared difference of their pixels is the sum of
//! their variances. The final pass is compared with each earlier one; its own variance is
//! taken as that of the last training pass (guided almost alike) scaled by their samples. The
//! weights are one number per pass measured over the whole image: a pixel's value moves its
//! pass's weight by a share of one pixel among all, so the bias the measured weights bring is
//! of that order, far below the noise of any pixel.
//!
//! Either way the passes must be means of the same kind: per-pixel means (the box filter of one pixel)
//! all of them, as training passes are.

use common::film::Filter;
use common::image::Image;
use glam::{Vec2, Vec3};

/// Whether `filter` makes each pixel the plain mean of its own samples (a box of one pixel),
/// as a training pass's image is: only then are the final pass's image and the training's
/// alike, and averaged. Another filter's final image is kept alone.
pub fn makes_pixel_means(filter: &dyn Filter) -> bool {
    let centre = filter.evaluate(Vec2::ZERO);
    filter.radius() == Vec2::splat(0.5)
        && centre > 0.0
        && [
            Vec2::new(0.49, 0.49),
            Vec2::new(-0.49, 0.0),
            Vec2::new(0.0, -0.49),
        ]
        .iter()
        .all(|&o| filter.evaluate(o) == centre)
}

/// One pass's image and its samples per pixel.
pub struct Pass<'a> {
    /// The image, each pixel the mean of its samples.
    pub image: &'a Image,
    /// Its samples per pixel.
    pub spp: u64,
}

/// How the passes' images make the render's image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PassWeighting {
    /// The final pass alone (Müller et al. 2017): the training's images are thrown away.
    FinalOnly,
    /// Every pass, weighed by its samples ([`sample_count_weights`]): unbiased.
    BySamples,
    /// Every pass, weighed by its samples and by what its guides learnt from
    /// ([`learning_weights`]): unbiased.
    ByLearning,
    /// Every pass, weighed by its measured noise ([`inverse_variance_weights`]): consistent.
    ByMeasuredNoise,
}

/// Each pass's share of all the samples: weights that depend on nothing the passes drew, so
/// the average of unbiased images stays unbiased.
pub fn sample_count_weights(passes: &[Pass<'_>]) -> Vec<f64> {
    let total: f64 = passes.iter().map(|p| p.spp as f64).sum();
    passes
        .iter()
        .map(|p| {
            if total > 0.0 {
                p.spp as f64 / total
            } else {
                0.0
            }
        })
        .collect()
}

/// Each pass's samples times the square root of the samples of the passes before it (what its
/// guides learnt from), over their sum: weights that depend on nothing the passes drew. The
/// first pass, guided by nothing, weighs nothing; a lone pass weighs all.
pub fn learning_weights(passes: &[Pass<'_>]) -> Vec<f64> {
    let mut learnt_from = 0.0;
    let raw: Vec<f64> = passes
        .iter()
        .map(|p| {
            let weight = p.spp as f64 * f64::sqrt(learnt_from);
            learnt_from += p.spp as f64;
            weight
        })
        .collect();
    let total: f64 = raw.iter().sum();
    if total > 0.0 {
        raw.iter().map(|w| w / total).collect()
    } else {
        sample_count_weights(passes)
    }
}

/// The mean over the pixels of the squared difference of two images (channels averaged).
fn mean_squared_difference(a: &Image, b: &Image) -> f64 {
    let n = a.pixels.len().max(1) as f64;
    a.pixels
        .iter()
        .zip(&b.pixels)
        .map(|(&x, &y)| {
            let d = f64::from(crate::target::mean(x - y));
            if d.is_finite() { d * d } else { 0.0 }
        })
        .sum::<f64>()
        / n
}

/// The weights of `passes` (the final pass last), summing to 1: each the inverse of its
/// variance measured against the final pass (see the module's opening), and in proportion to
/// samples where nothing can be measured (one pass, or images that do not differ). No pass
/// is taken as less noisy per sample than the final one.
pub fn inverse_variance_weights(passes: &[Pass<'_>]) -> Vec<f64> {
    let Some((last, earlier)) = passes.split_last() else {
        return Vec::new();
    };
    let by_samples = || sample_count_weights(passes);
    let Some(before) = earlier.last() else {
        return by_samples();
    };
    let (spp_final, spp_before) = (last.spp.max(1) as f64, before.spp.max(1) as f64);
    // The last two passes differ by the variance of both; the final pass's is the one before's
    // times its samples over the final pass's.
    let var_before =
        mean_squared_difference(before.image, last.image) / (1.0 + spp_before / spp_final);
    let var_final = var_before * spp_before / spp_final;
    if !var_final.is_finite() || var_final <= 0.0 {
        return by_samples();
    }
    let inverse: Vec<f64> = earlier
        .iter()
        .map(|p| {
            let at_best = var_final * spp_final / p.spp.max(1) as f64;
            let var = mean_squared_difference(p.image, last.image) - var_final;
            1.0 / var.max(at_best)
        })
        .chain(std::iter::once(1.0 / var_final))
        .collect();
    let total: f64 = inverse.iter().sum();
    inverse.iter().map(|w| w / total).collect()
}

/// The images of `passes` averaged with `weights`.
pub fn combine(passes: &[Pass<'_>], weights: &[f64]) -> Image {
    let first = passes[0].image;
    let mut image = Image::new(first.width, first.height);
    for (pass, &weight) in passes.iter().zip(weights) {
        for (sum, &p) in image.pixels.iter_mut().zip(&pass.image.pixels) {
            *sum += p * weight as f32;
        }
    }
    image.pixels.iter_mut().for_each(|p| {
        if !p.is_finite() {
            *p = Vec3::ZERO;
        }
    });
    image
}

#[cfg(test)]
mod tests {
    use super::*;

    fn noisy(value: f32, noise: f32, seed: u32) -> Image {
        let mut image = Image::new(64, 64);
        for (i, p) in image.pixels.iter_mut().enumerate() {
            // A fixed pattern of ±noise, different for each seed.
            let mut h = (i as u64) << 32 | u64::from(seed);
            for _ in 0..2 {
                h ^= h >> 31;
                h = h.wrapping_mul(0x9e37_79b9_7f4a_7c15);
            }
            let sign = if (h >> 40) & 1 == 0 { 1.0 } else { -1.0 };
            *p = Vec3::splat(value + sign * noise);
        }
        image
    }

    #[test]
    fn a_noisier_pass_counts_for_less_and_the_weights_sum_to_one() {
        // Variances 4, 1 and 1/4 (spp 1, 2, 4: the last two alike per sample).
        let (a, b, c) = (noisy(1.0, 2.0, 1), noisy(1.0, 1.0, 2), noisy(1.0, 0.5, 3));
        let passes = [
            Pass { image: &a, spp: 1 },
            Pass { image: &b, spp: 2 },
            Pass { image: &c, spp: 8 },
        ];
        let w = inverse_variance_weights(&passes);
        assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-9);
        assert!(w[0] < w[1] && w[1] < w[2], "{w:?}");
        // Inverse variances 1/4 : 1 : 4, within the measurement's noise.
        assert!((w[2] / w[1] - 4.0).abs() < 0.6, "{w:?}");
        assert!((w[1] / w[0] - 4.0).abs() < 1.2, "{w:?}");
        let image = combine(&passes, &w);
        let mean: f32 = image.pixels.iter().map(|p| p.x).sum::<f32>() / 4096.0;
        assert!((mean - 1.0).abs() < 0.02, "{mean}");
    }

    #[test]
    fn sample_count_weights_are_each_pass_share_of_the_samples() {
        let (a, b) = (noisy(1.0, 2.0, 1), noisy(1.0, 0.1, 2));
        let passes = [Pass { image: &a, spp: 1 }, Pass { image: &b, spp: 3 }];
        // Whatever the images hold: the weights are fixed by the samples alone.
        assert_eq!(sample_count_weights(&passes), vec![0.25, 0.75]);
        assert_eq!(sample_count_weights(&passes[..1]), vec![1.0]);
    }

    #[test]
    fn learning_weights_grow_with_what_each_pass_learnt_from() {
        let (a, b, c) = (noisy(1.0, 2.0, 1), noisy(1.0, 0.1, 2), noisy(1.0, 0.1, 3));
        let passes = [
            Pass { image: &a, spp: 1 },
            Pass { image: &b, spp: 3 },
            Pass { image: &c, spp: 12 },
        ];
        // 1 x √0, 3 x √1, 12 x √4: 0, 3 and 24 of 27.
        let w = learning_weights(&passes);
        let expected = [0.0, 3.0 / 27.0, 24.0 / 27.0];
        assert!(
            w.iter().zip(expected).all(|(w, e)| (w - e).abs() < 1e-12),
            "{w:?}"
        );
        assert_eq!(learning_weights(&passes[..1]), vec![1.0]);
    }

    #[test]
    fn only_a_box_of_one_pixel_makes_pixel_means() {
        assert!(makes_pixel_means(&common::film::PixelBoxFilter));
        struct Tent(f32);
        impl Filter for Tent {
            fn radius(&self) -> Vec2 {
                Vec2::splat(self.0)
            }
            fn evaluate(&self, o: Vec2) -> f32 {
                ((1.0 - o.x.abs() / self.0) * (1.0 - o.y.abs() / self.0)).max(0.0)
            }
        }
        assert!(!makes_pixel_means(&Tent(0.5)));
        assert!(!makes_pixel_means(&Tent(1.0)));
    }

    #[test]
    fn with_nothing_to_measure_the_weights_follow_the_samples() {
        let flat = Image::filled(4, 4, Vec3::ONE);
        let passes = [
            Pass {
                image: &flat,
                spp: 1,
            },
            Pass {
                image: &flat,
                spp: 3,
            },
        ];
        assert_eq!(inverse_variance_weights(&passes), vec![0.25, 0.75]);
        assert_eq!(inverse_variance_weights(&passes[..1]), vec![1.0]);
    }
}
