//! Image files for `bitmap` textures and `envmap` emitters: PNG, JPEG, BMP, OpenEXR and
//! Radiance HDR, decoded into linear RGB as Mitsuba 3 does.
//!
//! An 8- or 16-bit image (PNG, JPEG, BMP) stores sRGB-encoded values, which Mitsuba turns into
//! linear ones unless the texture says `raw` (for data that is not a colour); a floating-point
//! image (EXR, Radiance HDR) is linear already. Alpha is dropped; a grey image gives three equal channels.

use super::bounded_read::{IMAGE_FILE_LIMIT, read_bytes};
use glam::Vec3;

use crate::output::srgb_to_linear;
use image::{DynamicImage, ImageDecoder, ImageReader};
use std::io::Cursor;
use std::path::Path;
use std::sync::Arc;

/// The pixels of one image file, decoded, in linear RGB (sRGB decoded unless read `raw`).
#[derive(Clone, Debug, PartialEq)]
pub struct DecodedImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Row by row from the top, each row from the left.
    pub pixels: Arc<[Vec3]>,
}

/// Reads and decodes the image file at `path`; errors name it.
pub fn load_bitmap(path: &Path, raw: bool) -> Result<DecodedImage, String> {
    let bytes = read_bytes(path, "image", IMAGE_FILE_LIMIT)?;
    parse_bitmap(&bytes, raw).map_err(|e| format!("the image {}: {e}", path.display()))
}

/// The most pixels an image may have: 2^25, such as 8192 x 4096 (about 400 MB once decoded).
/// A header that claims more is refused before anything is allocated for it.
pub const MAX_BITMAP_PIXELS: u64 = 1 << 25;

/// Decodes the bytes of a PNG, JPEG, BMP, EXR or Radiance HDR file (the format is told by its
/// first bytes).
pub fn parse_bitmap(bytes: &[u8], raw: bool) -> Result<DecodedImage, String> {
    let bytes = radiance_signature(bytes);
    let decoder = ImageReader::new(Cursor::new(&*bytes))
        .with_guessed_format()
        .map_err(|e| format!("cannot tell its format: {e}"))?
        .into_decoder()
        .map_err(|e| {
            format!("not a PNG, JPEG, BMP, EXR or HDR image the workbook can read: {e}")
        })?;
    // What the decoder will allocate, asked before it does: a header may claim anything.
    let (width, height) = decoder.dimensions();
    let pixels = u64::from(width) * u64::from(height);
    if pixels > MAX_BITMAP_PIXELS || decoder.total_bytes() > MAX_BITMAP_PIXELS * 16 {
        return Err(format!(
            "the image is {width} x {height} pixels, more than the {MAX_BITMAP_PIXELS} a texture \
             may have"
        ));
    }
    let image = DynamicImage::from_decoder(decoder).map_err(|e| {
        format!("not a PNG, JPEG, BMP, EXR or HDR image the workbook can read: {e}")
    })?;
    let (width, height) = (image.width(), image.height());
    if u64::from(width) * u64::from(height) > MAX_BITMAP_PIXELS || width == 0 || height == 0 {
        return Err(format!(
            "the image is {width} x {height} pixels: none, or too many"
        ));
    }
    let is_float = matches!(
        image,
        DynamicImage::ImageRgb32F(_) | DynamicImage::ImageRgba32F(_)
    );
    let decode = !is_float && !raw;
    let pixels = image
        .into_rgb32f()
        .pixels()
        .map(|p| {
            let colour = Vec3::from(p.0);
            if decode {
                colour.map(srgb_to_linear)
            } else {
                colour
            }
        })
        .collect();
    Ok(DecodedImage {
        width,
        height,
        pixels,
    })
}

/// A Radiance HDR file starts with `#?` and the name of the program that wrote it: `#?RADIANCE`
/// usually, `#?RGBE` from Mitsuba. The decoder knows only the first, so any other first line
/// of that form is replaced by it; other files are left as they are.
fn radiance_signature(bytes: &[u8]) -> std::borrow::Cow<'_, [u8]> {
    const RADIANCE: &[u8] = b"#?RADIANCE";
    let end_of_line = bytes.iter().take(64).position(|&b| b == b'\n');
    match end_of_line {
        Some(end) if bytes.starts_with(b"#?") && !bytes.starts_with(RADIANCE) => {
            let mut fixed = RADIANCE.to_vec();
            fixed.extend_from_slice(&bytes[end..]);
            std::borrow::Cow::Owned(fixed)
        }
        _ => std::borrow::Cow::Borrowed(bytes),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::{ImageFormat, Rgb, RgbImage};

    fn png(pixels: &[[u8; 3]], width: u32) -> Vec<u8> {
        let height = pixels.len() as u32 / width;
        let image = RgbImage::from_fn(width, height, |x, y| Rgb(pixels[(y * width + x) as usize]));
        let mut bytes = Vec::new();
        image
            .write_to(&mut Cursor::new(&mut bytes), ImageFormat::Png)
            .unwrap();
        bytes
    }

    #[test]
    fn an_srgb_png_is_decoded_as_mitsuba_decodes_it() {
        // Mitsuba 3.9.1 reads the 8-bit pixel (187, 123, 243) as (0.496933, 0.198069, 0.896269),
        // and with `raw` as (0.733333, 0.482353, 0.952941).
        let bytes = png(&[[187, 123, 243]], 1);
        let decoded = parse_bitmap(&bytes, false).unwrap();
        let mitsuba = Vec3::new(0.496933, 0.198069, 0.896269);
        assert!(
            decoded.pixels[0].abs_diff_eq(mitsuba, 1e-5),
            "{}",
            decoded.pixels[0]
        );
        let raw = parse_bitmap(&bytes, true).unwrap();
        let mitsuba_raw = Vec3::new(0.733333, 0.482353, 0.952941);
        assert!(
            raw.pixels[0].abs_diff_eq(mitsuba_raw, 1e-5),
            "{}",
            raw.pixels[0]
        );
    }

    #[test]
    fn a_radiance_file_signed_by_mitsuba_is_read() {
        let mut bytes = Vec::new();
        image::Rgb32FImage::from_pixel(9, 2, image::Rgb([2.0, 0.5, 1.0]))
            .write_to(&mut Cursor::new(&mut bytes), ImageFormat::Hdr)
            .unwrap();
        assert!(bytes.starts_with(b"#?RADIANCE\n"));
        let mitsuba = [b"#?RGBE".as_slice(), &bytes[10..]].concat();
        for bytes in [bytes, mitsuba] {
            let image = parse_bitmap(&bytes, false).unwrap();
            assert_eq!((image.width, image.height), (9, 2));
            assert_eq!(image.pixels[17], Vec3::new(2.0, 0.5, 1.0));
        }
    }

    #[test]
    fn a_bmp_is_decoded_like_a_png() {
        // Mitsuba reads BMP files too (its documentation's flower texture is one): 8-bit sRGB.
        let image = RgbImage::from_fn(2, 1, |x, _| {
            Rgb(if x == 0 { [187, 123, 243] } else { [0, 0, 0] })
        });
        let mut bmp = Vec::new();
        image
            .write_to(&mut Cursor::new(&mut bmp), ImageFormat::Bmp)
            .unwrap();
        assert!(bmp.starts_with(b"BM"));
        let from_bmp = parse_bitmap(&bmp, false).unwrap();
        let from_png = parse_bitmap(&png(&[[187, 123, 243], [0, 0, 0]], 2), false).unwrap();
        assert_eq!(from_bmp, from_png);
    }

    #[test]
    fn rows_start_at_the_top() {
        let decoded = parse_bitmap(&png(&[[255, 0, 0], [0, 0, 255]], 1), true).unwrap();
        assert_eq!((decoded.width, decoded.height), (1, 2));
        assert_eq!(decoded.pixels[0], Vec3::X);
        assert_eq!(decoded.pixels[1], Vec3::Z);
    }

    #[test]
    fn bytes_that_are_no_image_are_refused_in_words() {
        let message = parse_bitmap(b"not an image", false).unwrap_err();
        assert!(message.contains("PNG, JPEG, BMP, EXR or HDR"), "{message}");
        let mut truncated = png(&[[1, 2, 3]; 16], 4);
        truncated.truncate(truncated.len() / 2);
        assert!(parse_bitmap(&truncated, false).is_err());
    }

    /// A valid 4 x 4 PNG, to be broken by the property below.
    fn small_png() -> Vec<u8> {
        png(&[[200, 100, 50]; 16], 4)
    }

    proptest::proptest! {
        #![proptest_config(crate::scene_file::tests::property_config())]

        /// Any bytes: an error, or an image with one finite pixel per place.
        #[test]
        fn random_bytes_never_panic(bytes in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..512), raw: bool) {
            if let Ok(image) = parse_bitmap(&bytes, raw) {
                proptest::prop_assert_eq!(image.pixels.len(), (image.width * image.height) as usize);
            }
        }

        /// A PNG with some bytes changed (past the signature, so the decoder is reached).
        #[test]
        fn a_damaged_png_never_panics(
            changes in proptest::collection::vec((proptest::prelude::any::<proptest::sample::Index>(), proptest::prelude::any::<u8>()), 1..8),
        ) {
            let mut bytes = small_png();
            for (at, byte) in changes {
                let i = at.index(bytes.len());
                bytes[i] = byte;
            }
            if let Ok(image) = parse_bitmap(&bytes, false) {
                proptest::prop_assert_eq!(image.pixels.len(), (image.width * image.height) as usize);
            }
        }
    }

    /// A valid 16 x 3 Radiance HDR file signed as Mitsuba signs it, to be broken below.
    fn small_hdr() -> Vec<u8> {
        let mut bytes = Vec::new();
        image::Rgb32FImage::from_fn(16, 3, |x, y| image::Rgb([x as f32, y as f32 * 0.3, 2.0]))
            .write_to(&mut Cursor::new(&mut bytes), ImageFormat::Hdr)
            .unwrap();
        [b"#?RGBE".as_slice(), &bytes[10..]].concat()
    }

    proptest::proptest! {
        #![proptest_config(crate::scene_file::tests::property_config())]

        /// A Radiance HDR file with some bytes changed, or cut short: an error or an image.
        #[test]
        fn a_damaged_radiance_file_never_panics(
            changes in proptest::collection::vec((proptest::prelude::any::<proptest::sample::Index>(), proptest::prelude::any::<u8>()), 0..8),
            keep in 0.0..=1.0f64,
        ) {
            let mut bytes = small_hdr();
            for (at, byte) in changes {
                let i = at.index(bytes.len());
                bytes[i] = byte;
            }
            bytes.truncate((bytes.len() as f64 * keep) as usize);
            if let Ok(image) = parse_bitmap(&bytes, false) {
                proptest::prop_assert_eq!(image.pixels.len(), (image.width * image.height) as usize);
            }
        }
    }

    /// The CRC-32 of a PNG chunk's type and data.
    fn crc32(bytes: &[u8]) -> u32 {
        let mut crc = !0u32;
        for &byte in bytes {
            crc ^= u32::from(byte);
            for _ in 0..8 {
                crc = if crc & 1 == 1 {
                    (crc >> 1) ^ 0xEDB8_8320
                } else {
                    crc >> 1
                };
            }
        }
        !crc
    }

    #[test]
    fn an_image_claiming_too_many_pixels_is_refused_before_decoding() {
        // `cargo fuzz run bitmap` found an EXR whose header claimed so many pixels that decoding
        // it ran out of memory. Here a PNG header claims 65536 x 65536 pixels and no data
        // follows: the size alone must refuse it.
        let mut ihdr = b"IHDR".to_vec();
        ihdr.extend_from_slice(&65536u32.to_be_bytes());
        ihdr.extend_from_slice(&65536u32.to_be_bytes());
        ihdr.extend_from_slice(&[8, 2, 0, 0, 0]); // 8-bit RGB, no interlacing
        let mut bytes = b"\x89PNG\r\n\x1a\n".to_vec();
        bytes.extend_from_slice(&13u32.to_be_bytes());
        bytes.extend_from_slice(&ihdr);
        bytes.extend_from_slice(&crc32(&ihdr).to_be_bytes());
        // An empty IDAT chunk: where the header ends and the pixels would begin.
        bytes.extend_from_slice(&0u32.to_be_bytes());
        bytes.extend_from_slice(b"IDAT");
        bytes.extend_from_slice(&crc32(b"IDAT").to_be_bytes());
        let message = parse_bitmap(&bytes, false).unwrap_err();
        assert!(message.contains("more than"), "{message}");
    }

    #[test]
    fn a_missing_file_is_named() {
        let message = load_bitmap(Path::new("/nowhere/wood.png"), false).unwrap_err();
        assert!(message.contains("/nowhere/wood.png"), "{message}");
    }
}
