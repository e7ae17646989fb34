//! How sharp a picture is: the root mean square difference between neighbouring pixels, the
//! measure the claims of the blurring controls compare (a wider filter, a wider aperture).
//!
//! Blur spreads each pixel's light over its neighbours, so neighbours grow alike. The mean
//! *absolute* difference would not see it on a lone edge (a step of 1 spread over three pixels
//! is still a total rise of 1), but the mean *square* does: one step of 1 weighs 1, three of
//! 1/3 weigh 1/3. Noise raises the measure too, so the claims that use it render with enough
//! samples for noise not to decide the comparison.

use common::image::Image;

/// The root mean square, over every pixel `(x, y)` that `counts` accepts and its right and
/// lower neighbours, of the difference of their values (the mean of the three channels); 0 if
/// no pixel counts.
pub fn rms_neighbour_difference(image: &Image, counts: impl Fn(u32, u32) -> bool) -> f64 {
    let mut sum = 0.0;
    let mut pairs = 0u64;
    for y in 0..image.height {
        for x in 0..image.width {
            if !counts(x, y) {
                continue;
            }
            let here = image.get(x, y);
            for (nx, ny) in [(x + 1, y), (x, y + 1)] {
                if nx < image.width && ny < image.height {
                    let difference = f64::from((here - image.get(nx, ny)).element_sum()) / 3.0;
                    sum += difference * difference;
                    pairs += 1;
                }
            }
        }
    }
    if pairs == 0 {
        0.0
    } else {
        (sum / pairs as f64).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// A 4 x 1 image of these grey values.
    fn row(values: [f32; 4]) -> Image {
        let mut image = Image::new(4, 1);
        for (x, value) in (0..).zip(values) {
            image.set(x, 0, Vec3::splat(value));
        }
        image
    }

    #[test]
    fn a_blurred_edge_is_less_sharp_than_a_hard_one() {
        let hard = rms_neighbour_difference(&row([0.0, 0.0, 1.0, 1.0]), |_, _| true);
        let ramp = rms_neighbour_difference(&row([0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]), |_, _| true);
        // One step of 1 among three pairs, against three steps of 1/3.
        assert!((hard - (1.0f64 / 3.0).sqrt()).abs() < 1e-6, "{hard}");
        assert!((ramp - 1.0 / 3.0).abs() < 1e-6, "{ramp}");
    }

    #[test]
    fn only_the_pixels_that_count_are_measured() {
        let edge = row([0.0, 0.0, 1.0, 1.0]);
        assert!((rms_neighbour_difference(&edge, |x, _| x == 1) - 1.0).abs() < 1e-6);
        assert_eq!(rms_neighbour_difference(&edge, |x, _| x == 3), 0.0);
        assert_eq!(
            rms_neighbour_difference(&Image::new(3, 3), |_, _| true),
            0.0
        );
    }
}
