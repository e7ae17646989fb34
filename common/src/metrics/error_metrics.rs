//! How far is a render from the reference? One number per image.
//!
//! Both metrics average over every pixel and every colour channel, accumulating in f64: a
//! million f32 squares summed in f32 would lose the very digits that tell two good renders apart.

use glam::DVec3;

use crate::image::Image;

/// Added to the squared reference value in [`relmse`], so that black pixels (where the reference
/// is 0) do not divide by zero or dominate the average.
///
/// With `0.01`, a pixel of brightness 0.1 or more is measured essentially relative to itself,
/// while errors in darker pixels count roughly as absolute errors scaled by 100. The constant
/// must stay the same across a chapter for its numbers to be comparable.
pub const RELMSE_EPSILON: f64 = 1e-2;

/// Root-mean-square error: `sqrt(mean((x - r)^2))` over all pixels and channels.
///
/// Monte Carlo noise makes this fall as `1 / sqrt(samples)`; it is in the image's own units,
/// so bright regions weigh more than dark ones. Two images without pixels have error 0. A NaN
/// pixel in either image makes the error NaN, and an infinite one infinite (or NaN): a check
/// that compares the error with a bound then fails, as it must, and can say why.
///
/// # Panics
///
/// If the sizes differ: comparing images of different sizes is a bug in the caller (a wrong
/// reference or resolution), not a condition to handle.
pub fn rmse(image: &Image, reference: &Image) -> f64 {
    mean_over_channels(image, reference, |x, r| (x - r).powi(2)).sqrt()
}

/// Relative mean squared error: the mean of `(x - r)^2 / (r^2 + 0.01)` over all pixels and
/// channels ([`RELMSE_EPSILON`] is the `0.01`).
///
/// Dividing by the reference's own brightness makes an error of 0.1 in a dark shadow count as
/// much as an error of 1 in a bright highlight, roughly as the eye sees it: it shows noise in the
/// shadows that RMSE would hide. Note that it is *not* square-rooted, by convention. NaN and
/// infinite pixels count as in [`rmse`].
///
/// # Panics
///
/// If the sizes differ, as [`rmse`].
pub fn relmse(image: &Image, reference: &Image) -> f64 {
    mean_over_channels(image, reference, |x, r| {
        (x - r).powi(2) / (r * r + RELMSE_EPSILON)
    })
}

/// The average colour of the image, accumulated in f64. Zero for an image without pixels; a
/// channel with a NaN pixel is NaN, and one with an infinite pixel infinite (or NaN).
///
/// A quick check on a renderer: noise averages out, so an unbiased render's mean approaches the
/// reference's as samples grow, while a biased one settles on the wrong value.
pub fn mean(image: &Image) -> DVec3 {
    let sum: DVec3 = image.pixels.iter().map(|p| p.as_dvec3()).sum();
    if image.pixels.is_empty() {
        DVec3::ZERO
    } else {
        sum / image.pixels.len() as f64
    }
}

/// The mean of `error(x, r)` over all channels of all pixel pairs.
fn mean_over_channels(image: &Image, reference: &Image, error: impl Fn(f64, f64) -> f64) -> f64 {
    assert!(
        image.width == reference.width && image.height == reference.height,
        "cannot compare a {} x {} image with a {} x {} reference",
        image.width,
        image.height,
        reference.width,
        reference.height
    );
    let mut sum = 0.0;
    for (pixel, reference_pixel) in image.pixels.iter().zip(&reference.pixels) {
        for channel in 0..3 {
            sum += error(
                f64::from(pixel[channel]),
                f64::from(reference_pixel[channel]),
            );
        }
    }
    let count = image.pixels.len() * 3;
    if count == 0 { 0.0 } else { sum / count as f64 }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use glam::Vec3;

    fn two_pixels(a: Vec3, b: Vec3) -> Image {
        Image {
            width: 2,
            height: 1,
            pixels: vec![a, b],
        }
    }

    #[test]
    fn identical_images_have_no_error() {
        let image = two_pixels(Vec3::new(0.1, 2.0, 0.0), Vec3::new(5.0, 0.5, 0.25));
        assert_eq!(rmse(&image, &image), 0.0);
        assert_eq!(relmse(&image, &image), 0.0);
    }

    #[test]
    fn rmse_of_a_known_difference() {
        let reference = two_pixels(Vec3::ZERO, Vec3::ZERO);
        // Squared errors 9, 0, 0 and 16, 0, 11: mean 36 / 6 = 6.
        let image = two_pixels(Vec3::new(3.0, 0.0, 0.0), Vec3::new(4.0, 0.0, 11f32.sqrt()));
        assert_relative_eq!(rmse(&image, &reference), 6f64.sqrt(), max_relative = 1e-6);
        // RMSE is symmetric.
        assert_relative_eq!(rmse(&reference, &image), 6f64.sqrt(), max_relative = 1e-6);
    }

    #[test]
    fn relmse_of_a_known_difference() {
        let reference = two_pixels(Vec3::splat(1.0), Vec3::splat(0.0));
        let image = two_pixels(Vec3::splat(1.5), Vec3::splat(0.0));
        // Three channels of 0.25 / 1.01, three of 0: mean (0.75 / 1.01) / 6.
        assert_relative_eq!(
            relmse(&image, &reference),
            0.125 / 1.01,
            max_relative = 1e-12
        );
    }

    #[test]
    fn relmse_weighs_errors_relative_to_the_reference() {
        // The same relative error, 10 %, in a bright and a dim pixel gives about the same
        // relMSE, while RMSE differs by the brightness ratio.
        let bright = (
            Image::filled(1, 1, Vec3::splat(10.0)),
            Image::filled(1, 1, Vec3::splat(11.0)),
        );
        let dim = (
            Image::filled(1, 1, Vec3::splat(1.0)),
            Image::filled(1, 1, Vec3::splat(1.1)),
        );
        let bright_relmse = relmse(&bright.1, &bright.0);
        let dim_relmse = relmse(&dim.1, &dim.0);
        assert!((bright_relmse / dim_relmse - 1.0).abs() < 0.02);
        assert_relative_eq!(
            rmse(&bright.1, &bright.0) / rmse(&dim.1, &dim.0),
            10.0,
            max_relative = 1e-5
        );
    }

    #[test]
    fn the_epsilon_keeps_black_pixels_finite() {
        // Against a black reference, relMSE is the squared error divided by the epsilon.
        let black = Image::new(1, 1);
        let grey = Image::filled(1, 1, Vec3::splat(0.1));
        let value = relmse(&grey, &black);
        assert!(value.is_finite());
        assert_relative_eq!(value, 0.01 / RELMSE_EPSILON, max_relative = 1e-6);
    }

    #[test]
    fn mean_averages_every_pixel() {
        let image = two_pixels(Vec3::new(1.0, 2.0, 3.0), Vec3::new(3.0, 2.0, 1.0));
        assert_eq!(mean(&image), DVec3::splat(2.0));
        assert_eq!(mean(&Image::new(0, 0)), DVec3::ZERO);
    }

    #[test]
    fn a_pixel_that_is_not_a_number_shows_in_every_metric() {
        let good = two_pixels(Vec3::ONE, Vec3::ONE);
        for (bad, infinite) in [(f32::NAN, false), (f32::INFINITY, true)] {
            let broken = two_pixels(Vec3::new(1.0, bad, 1.0), Vec3::ONE);
            for (image, reference) in [(&broken, &good), (&good, &broken)] {
                let error = rmse(image, reference);
                assert!(if infinite {
                    error == f64::INFINITY
                } else {
                    error.is_nan()
                });
                let relative = relmse(image, reference);
                assert!(relative.is_nan() || relative == f64::INFINITY, "{relative}");
            }
            assert!(!mean(&broken).is_finite() && mean(&broken).x == 1.0);
        }
    }

    #[test]
    #[should_panic(expected = "cannot compare a 2 x 1 image with a 1 x 2 reference")]
    fn different_sizes_are_a_bug() {
        let reference = Image::new(1, 2);
        rmse(&Image::new(2, 1), &reference);
    }
}
