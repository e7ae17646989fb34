//! PNG: 8-bit sRGB, what every browser, book and image viewer shows.
//!
//! A PNG cannot hold radiance above 1 and has only 256 levels per channel, so it is for looking
//! at, never for measuring: errors are computed on the floats, and the EXR or PFM twin of an
//! image is what a later comparison should read.

use glam::Vec3;
use image::{ExtendedColorType, ImageEncoder, ImageError, ImageFormat};

use common::image::Image;
use common::srgb::{srgb_to_linear, srgb8_to_linear, to_srgb8};

/// Encodes linear `image` as an 8-bit sRGB PNG in memory.
pub(super) fn encode(image: &Image) -> Result<Vec<u8>, ImageError> {
    let rgb: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(|pixel| pixel.to_array().map(to_srgb8))
        .collect();
    encode_rgb8(image.width, image.height, &rgb)
}

/// Encodes bytes that are already 8-bit sRGB, three per pixel, top row first: the pixels a
/// plot is drawn into.
pub(crate) fn encode_rgb8(width: u32, height: u32, rgb: &[u8]) -> Result<Vec<u8>, ImageError> {
    let mut bytes = Vec::new();
    image::codecs::png::PngEncoder::new(&mut bytes).write_image(
        rgb,
        width,
        height,
        ExtendedColorType::Rgb8,
    )?;
    Ok(bytes)
}

/// Decodes a PNG and undoes its sRGB encoding; an alpha channel, if any, is dropped.
///
/// 16-bit PNGs are decoded through the same curve at full precision.
pub(super) fn decode(bytes: &[u8]) -> Result<Image, ImageError> {
    let decoded = image::load_from_memory_with_format(bytes, ImageFormat::Png)?;
    let (width, height) = (decoded.width(), decoded.height());
    let colour = decoded.color();
    let eight_bit = colour.bytes_per_pixel() == colour.channel_count();
    let pixels = if eight_bit {
        decoded
            .to_rgb8()
            .into_raw()
            .chunks_exact(3)
            .map(|rgb| Vec3::from_array([rgb[0], rgb[1], rgb[2]].map(srgb8_to_linear)))
            .collect()
    } else {
        decoded
            .to_rgb32f()
            .into_raw()
            .chunks_exact(3)
            .map(|rgb| Vec3::from_slice(rgb).map(srgb_to_linear))
            .collect()
    };
    Ok(Image {
        width,
        height,
        pixels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use common::srgb::linear_to_srgb;

    #[test]
    fn stores_srgb_bytes() {
        let mut image = Image::new(2, 1);
        image.set(0, 0, Vec3::new(0.0, 0.5, 1.0));
        image.set(1, 0, Vec3::new(3.0, -1.0, 0.003_130_8));
        let stored =
            image::load_from_memory_with_format(&encode(&image).unwrap(), ImageFormat::Png)
                .unwrap()
                .to_rgb8()
                .into_raw();
        // Over-bright clamps to white, negative to black.
        assert_eq!(stored, [0, 188, 255, 255, 0, 10]);
    }

    #[test]
    fn round_trip_is_within_half_an_8_bit_step() {
        let mut image = Image::new(64, 1);
        for x in 0..64 {
            let t = x as f32 / 63.0;
            image.set(x, 0, Vec3::new(t, t * t, t.sqrt() * 0.9));
        }
        let decoded = decode(&encode(&image).unwrap()).unwrap();
        assert_eq!((decoded.width, decoded.height), (64, 1));
        for (original, decoded) in image.pixels.iter().zip(&decoded.pixels) {
            let steps = (original.map(linear_to_srgb) - decoded.map(linear_to_srgb)).abs() * 255.0;
            assert!(
                steps.max_element() <= 0.5 + 1e-3,
                "{original} came back as {decoded}"
            );
        }
    }

    #[test]
    fn sixteen_bit_files_are_decoded_too() {
        let mut raw = Vec::new();
        for value in [0u16, 32768, 65535] {
            raw.extend_from_slice(&value.to_ne_bytes());
        }
        let mut bytes = Vec::new();
        image::codecs::png::PngEncoder::new(&mut bytes)
            .write_image(&raw, 1, 1, ExtendedColorType::Rgb16)
            .unwrap();
        let pixel = decode(&bytes).unwrap().pixels[0];
        assert_eq!(pixel.x, 0.0);
        assert!((pixel.y - srgb_to_linear(32768.0 / 65535.0)).abs() < 1e-6);
        assert_eq!(pixel.z, 1.0);
    }
}
