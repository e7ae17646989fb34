//! Is a render biased, or only noisy? A block test.
//!
//! RMSE mixes two very different faults: noise, which more samples remove, and bias, which they
//! do not. To tell them apart, cut both images into 8x8 blocks and compare the block means: a
//! block mean of an unbiased render lies within a few standard errors of the reference's, so
//! almost no block differs by more than 3 of them. A systematic error (a wrong Fresnel factor, a
//! missing `1/pi`) shifts every block of the affected region by the same amount and, once the
//! noise is low enough, pushes many blocks past 3 standard errors.
//!
//! The definition is the one used by the comparison script that accompanies Mitsuba-based
//! checks, so that numbers from either side can be set next to each other.

use crate::image::Image;

/// Side of a block in pixels.
pub const BIAS_BLOCK_SIZE: u32 = 8;

/// A block mean counts as off when it is more than this many standard errors away.
pub const BIAS_THRESHOLD: f64 = 3.0;

/// The share (in `[0, 1]`) of `(8x8 block, colour channel)` pairs whose mean in `image` differs
/// from the mean in `reference` by more than [`BIAS_THRESHOLD`] standard errors.
///
/// The standard error of a block mean is estimated from the spread of `image`'s own 64 pixels
/// in that block (`std / sqrt(64)`), plus `1e-4 (1 + |reference mean|)` so that a flat, noiseless
/// block does not demand exact equality of floating-point sums. Pixels beyond the last whole
/// block on the right and bottom are left out. For an unbiased render the score is close to the
/// chance of a 3-sigma excursion, about 0.003; a biased one scores far more.
///
/// # Panics
///
/// If the sizes differ (a caller bug, as for [`rmse`](super::rmse)).
pub fn bias_blocks(image: &Image, reference: &Image) -> f64 {
    assert_eq!(
        (image.width, image.height),
        (reference.width, reference.height),
        "bias_blocks compares images of the same size"
    );
    let b = BIAS_BLOCK_SIZE;
    let (blocks_x, blocks_y) = (image.width / b, image.height / b);
    if blocks_x == 0 || blocks_y == 0 {
        return 0.0;
    }
    let n = f64::from(b * b);
    let mut off = 0usize;
    for by in 0..blocks_y {
        for bx in 0..blocks_x {
            for channel in 0..3 {
                let values = |img: &Image| -> Vec<f64> {
                    (0..b * b)
                        .map(|i| f64::from(img.get(bx * b + i % b, by * b + i / b)[channel]))
                        .collect()
                };
                let (values_image, values_reference) = (values(image), values(reference));
                let mean_image = values_image.iter().sum::<f64>() / n;
                let mean_reference = values_reference.iter().sum::<f64>() / n;
                let variance = values_image
                    .iter()
                    .map(|v| (v - mean_image).powi(2))
                    .sum::<f64>()
                    / n;
                let standard_error =
                    variance.sqrt() / n.sqrt() + 1e-4 * (1.0 + mean_reference.abs());
                let within = (mean_image - mean_reference).abs() <= BIAS_THRESHOLD * standard_error;
                // NaN compares false: a NaN block is counted as off, never as fine.
                if !within {
                    off += 1;
                }
            }
        }
    }
    off as f64 / f64::from(blocks_x * blocks_y * 3)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;
    use rand::RngExt;
    use rand::SeedableRng;
    use rand_pcg::Pcg32;

    /// A smooth reference with independent uniform noise of half-width `noise` added.
    fn noisy(reference: &Image, noise: f32, offset: f32, seed: u64) -> Image {
        let mut rng = Pcg32::seed_from_u64(seed);
        let mut image = reference.clone();
        for p in &mut image.pixels {
            let n = Vec3::new(
                rng.random_range(-noise..noise),
                rng.random_range(-noise..noise),
                rng.random_range(-noise..noise),
            );
            *p += n + Vec3::splat(offset);
        }
        image
    }

    fn gradient(width: u32, height: u32) -> Image {
        let mut image = Image::new(width, height);
        for y in 0..height {
            for x in 0..width {
                image.set(
                    x,
                    y,
                    Vec3::new(x as f32 / width as f32, 0.5, y as f32 / 64.0),
                );
            }
        }
        image
    }

    #[test]
    fn unbiased_noise_scores_near_the_chance_level() {
        let reference = gradient(128, 128);
        let score = bias_blocks(&noisy(&reference, 0.2, 0.0, 1), &reference);
        // 256 blocks x 3 channels; the chance of a 3-sigma excursion is 0.27 %, so a handful at
        // most. (The gradient inside a block adds spread, making the test more lenient still.)
        assert!(score < 0.02, "score {score}");
    }

    #[test]
    fn an_offset_well_above_the_standard_error_is_caught() {
        let reference = gradient(128, 128);
        // Uniform noise of half-width 0.2 has std 0.115; over 64 pixels the standard error is
        // 0.0144, so an offset of 0.06 is about 4 standard errors.
        let score = bias_blocks(&noisy(&reference, 0.2, 0.06, 2), &reference);
        assert!(score > 0.5, "score {score}");
    }

    #[test]
    fn identical_images_score_zero_and_nan_counts_as_off() {
        let reference = gradient(16, 8);
        assert_eq!(bias_blocks(&reference, &reference), 0.0);
        let mut broken = reference.clone();
        broken.set(3, 3, Vec3::NAN);
        // One block of two, all three channels.
        assert_eq!(bias_blocks(&broken, &reference), 0.5);
    }

    #[test]
    fn images_smaller_than_a_block_have_no_blocks() {
        let tiny = Image::new(7, 7);
        assert_eq!(bias_blocks(&tiny, &tiny), 0.0);
    }
}
