//! The sRGB transfer curve: from linear radiance to the numbers a PNG stores, and back.
//!
//! A renderer computes *linear* values: twice the light is twice the number. Screens and PNG
//! files expect *sRGB-encoded* values, which spend more of their 256 steps on dark tones, where
//! the eye is most sensitive. Writing linear values straight into a PNG makes every image look
//! too dark and its shadows banded; the curve below is the standard fix (IEC 61966-2-1): a short
//! straight segment near black, then a power of 1/2.4.

/// Linear values at or below this lie on the straight segment of the curve.
const LINEAR_KNEE: f32 = 0.003_130_8;
/// The same knee, measured in encoded values (`12.92 * LINEAR_KNEE`).
const ENCODED_KNEE: f32 = 0.040_45;

/// Encodes a linear value in `[0, 1]` with the sRGB curve (the "OETF").
pub fn linear_to_srgb(linear: f32) -> f32 {
    if linear <= LINEAR_KNEE {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    }
}

/// Decodes an sRGB value in `[0, 1]` back to linear; the inverse of [`linear_to_srgb`].
pub fn srgb_to_linear(encoded: f32) -> f32 {
    if encoded <= ENCODED_KNEE {
        encoded / 12.92
    } else {
        ((encoded + 0.055) / 1.055).powf(2.4)
    }
}

/// A linear value as the 8-bit sRGB number a PNG stores.
///
/// Values outside `[0, 1]` are clamped first: a highlight brighter than white shows as white and
/// a (buggy) negative value as black. NaN, which only a bug produces, also shows as black.
pub fn to_srgb8(linear: f32) -> u8 {
    if linear.is_nan() {
        return 0;
    }
    (linear_to_srgb(linear.clamp(0.0, 1.0)) * 255.0).round() as u8
}

/// An 8-bit sRGB number (as read from a PNG) as a linear value in `[0, 1]`.
pub fn srgb8_to_linear(value: u8) -> f32 {
    srgb_to_linear(f32::from(value) / 255.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn black_and_white_are_fixed_points() {
        assert_eq!(to_srgb8(0.0), 0);
        assert_eq!(to_srgb8(1.0), 255);
        assert_eq!(srgb8_to_linear(0), 0.0);
        assert_eq!(srgb8_to_linear(255), 1.0);
    }

    #[test]
    fn half_the_light_is_stored_as_188_not_128() {
        // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354, and 0.7354 * 255 = 187.5.
        assert_eq!(to_srgb8(0.5), 188);
        // The common mistake of a plain 1/2.2 gamma would give 186.
        assert_ne!(to_srgb8(0.5), 186);
    }

    #[test]
    fn the_two_pieces_meet_at_the_knee() {
        let below = 12.92 * LINEAR_KNEE;
        let above = 1.055 * LINEAR_KNEE.powf(1.0 / 2.4) - 0.055;
        assert!((below - above).abs() < 1e-6, "{below} vs {above}");
        assert_eq!(to_srgb8(LINEAR_KNEE), 10); // 0.04045 * 255 = 10.3
        assert!((srgb_to_linear(ENCODED_KNEE) - LINEAR_KNEE).abs() < 1e-7);
    }

    #[test]
    fn out_of_range_values_are_clamped() {
        assert_eq!(to_srgb8(7.5), 255);
        assert_eq!(to_srgb8(f32::INFINITY), 255);
        assert_eq!(to_srgb8(-0.25), 0);
        assert_eq!(to_srgb8(f32::NAN), 0);
    }

    #[test]
    fn decoding_is_the_inverse_of_encoding() {
        for value in 0..=255u8 {
            assert_eq!(to_srgb8(srgb8_to_linear(value)), value);
        }
    }

    #[test]
    fn a_round_trip_through_8_bits_loses_at_most_half_a_step() {
        for i in 0..=1000 {
            let linear = i as f32 / 1000.0;
            let decoded = srgb8_to_linear(to_srgb8(linear));
            let step_error = (linear_to_srgb(decoded) - linear_to_srgb(linear)).abs() * 255.0;
            assert!(
                step_error <= 0.5 + 1e-3,
                "{linear}: off by {step_error} steps"
            );
        }
    }
}
