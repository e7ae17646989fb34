//! OpenEXR: the floating-point format of film studios, which every HDR viewer opens.
//!
//! We store three f32 channels, linear and unclamped, so an EXR keeps exactly what the renderer
//! computed. The `image` crate does the encoding; our only job is to lay the floats out.

use std::io::Cursor;

use glam::Vec3;
use image::{ExtendedColorType, ImageEncoder, ImageError, ImageFormat};

use common::image::Image;

/// Encodes `image` as an RGB f32 EXR file in memory.
pub(super) fn encode(image: &Image) -> Result<Vec<u8>, ImageError> {
    // The encoder takes raw bytes in native order: three f32 per pixel, top row first.
    let raw: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(|pixel| pixel.to_array())
        .flat_map(f32::to_ne_bytes)
        .collect();
    let mut bytes = Vec::new();
    image::codecs::openexr::OpenExrEncoder::new(Cursor::new(&mut bytes)).write_image(
        &raw,
        image.width,
        image.height,
        ExtendedColorType::Rgb32F,
    )?;
    Ok(bytes)
}

/// Decodes an EXR file; an alpha channel, if any, is dropped.
pub(super) fn decode(bytes: &[u8]) -> Result<Image, ImageError> {
    let decoded = image::load_from_memory_with_format(bytes, ImageFormat::OpenExr)?.to_rgb32f();
    let (width, height) = decoded.dimensions();
    let pixels = decoded
        .into_raw()
        .chunks_exact(3)
        .map(Vec3::from_slice)
        .collect();
    Ok(Image {
        width,
        height,
        pixels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_keeps_every_float() {
        let mut image = Image::new(3, 2);
        image.set(0, 0, Vec3::new(0.1, 1.0 / 3.0, 12345.678));
        image.set(2, 1, Vec3::new(1.0e-20, 65504.5, 3.0e30));
        image.set(1, 1, Vec3::new(0.0, 0.5, 2.0));
        let decoded = decode(&encode(&image).unwrap()).unwrap();
        assert_eq!(decoded, image);
    }
}
