//! PFM, the simplest floating-point image format: a three-line text header, then raw floats.
//!
//! ```text
//! PF            "PF" for RGB, "Pf" for grey
//! 640 480       width and height
//! -1.0          the sign gives the byte order: negative = little-endian
//! <bytes>       width * height * channels f32 values, BOTTOM row first
//! ```
//!
//! The rows run bottom to top, the opposite of our [`Image`] and of PNG; forgetting this is the
//! classic PFM bug and shows up as an upside-down reference image. The magnitude of the scale is
//! meant as a brightness factor that almost every tool ignores; so do we.

use glam::Vec3;

use common::image::Image;

/// Encodes `image` as a little-endian RGB PFM, bottom row first.
pub(super) fn encode(image: &Image) -> Vec<u8> {
    let header = format!("PF\n{} {}\n-1.0\n", image.width, image.height);
    let mut bytes = Vec::with_capacity(header.len() + image.pixels.len() * 12);
    bytes.extend_from_slice(header.as_bytes());
    for y in (0..image.height).rev() {
        for x in 0..image.width {
            for channel in image.get(x, y).to_array() {
                bytes.extend_from_slice(&channel.to_le_bytes());
            }
        }
    }
    bytes
}

/// Decodes a PFM file (RGB or grey, either byte order). The error says what was expected.
pub(super) fn decode(bytes: &[u8]) -> Result<Image, String> {
    let mut header = HeaderReader { bytes, position: 0 };
    let channels = match header.token()? {
        b"PF" => 3,
        b"Pf" => 1,
        _ => return Err("the magic word `PF` (colour) or `Pf` (grey) at the start".into()),
    };
    let width: u32 = header.number("the image width")?;
    let height: u32 = header.number("the image height")?;
    let scale: f32 = header.number("the scale (negative for little-endian)")?;
    // Exactly one whitespace byte separates the header from the data; the data may well begin
    // with bytes that look like whitespace, so we must not skip more.
    header.single_whitespace()?;

    let data = &bytes[header.position..];
    let expected_len = width as usize * height as usize * channels * 4;
    if data.len() != expected_len {
        return Err(format!(
            "{expected_len} bytes of pixel data for {width} x {height} x {channels} floats, \
             found {}",
            data.len()
        ));
    }

    let little_endian = scale < 0.0;
    let floats: Vec<f32> = data
        .chunks_exact(4)
        .map(|four| {
            let four = [four[0], four[1], four[2], four[3]];
            if little_endian {
                f32::from_le_bytes(four)
            } else {
                f32::from_be_bytes(four)
            }
        })
        .collect();

    let mut image = Image::new(width, height);
    for (stored_row, row) in floats
        .chunks_exact(width.max(1) as usize * channels)
        .enumerate()
    {
        let y = height - 1 - stored_row as u32;
        for (x, pixel) in row.chunks_exact(channels).enumerate() {
            let colour = match pixel {
                [r, g, b] => Vec3::new(*r, *g, *b),
                [grey] => Vec3::splat(*grey),
                _ => unreachable!("a pixel has 1 or 3 channels"),
            };
            image.set(x as u32, y, colour);
        }
    }
    Ok(image)
}

/// Reads the whitespace-separated words of the text header.
struct HeaderReader<'a> {
    bytes: &'a [u8],
    position: usize,
}

impl<'a> HeaderReader<'a> {
    fn token(&mut self) -> Result<&'a [u8], String> {
        while self
            .bytes
            .get(self.position)
            .is_some_and(u8::is_ascii_whitespace)
        {
            self.position += 1;
        }
        let start = self.position;
        while self
            .bytes
            .get(self.position)
            .is_some_and(|byte| !byte.is_ascii_whitespace())
        {
            self.position += 1;
        }
        if start == self.position {
            return Err("a complete header, but the file ended".into());
        }
        Ok(&self.bytes[start..self.position])
    }

    fn number<T: std::str::FromStr>(&mut self, what: &str) -> Result<T, String> {
        let token = self.token()?;
        std::str::from_utf8(token)
            .ok()
            .and_then(|text| text.parse().ok())
            .ok_or_else(|| format!("{what}, found `{}`", String::from_utf8_lossy(token)))
    }

    fn single_whitespace(&mut self) -> Result<(), String> {
        match self.bytes.get(self.position) {
            Some(byte) if byte.is_ascii_whitespace() => {
                self.position += 1;
                Ok(())
            }
            _ => Err("a newline after the scale".into()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn two_by_two() -> Image {
        let mut image = Image::new(2, 2);
        image.set(0, 0, Vec3::new(1.0, 2.0, 3.0)); // top left
        image.set(1, 0, Vec3::new(4.0, 5.0, 6.0)); // top right
        image.set(0, 1, Vec3::new(7.0, 8.0, 9.0)); // bottom left
        image.set(1, 1, Vec3::new(10.0, 11.0, 12.0)); // bottom right
        image
    }

    fn floats_le(values: &[f32]) -> Vec<u8> {
        values.iter().flat_map(|v| v.to_le_bytes()).collect()
    }

    #[test]
    fn header_then_bottom_row_first() {
        let bytes = encode(&two_by_two());
        let header = b"PF\n2 2\n-1.0\n";
        assert_eq!(&bytes[..header.len()], header);
        let expected_data = floats_le(&[
            7.0, 8.0, 9.0, 10.0, 11.0, 12.0, // bottom row first
            1.0, 2.0, 3.0, 4.0, 5.0, 6.0, // then the top row
        ]);
        assert_eq!(&bytes[header.len()..], expected_data.as_slice());
    }

    #[test]
    fn round_trip_is_bit_exact() {
        let mut image = two_by_two();
        image.set(1, 0, Vec3::new(f32::MIN_POSITIVE, 1.0e30, -0.0));
        image.set(0, 1, Vec3::new(0.1, 1.0 / 3.0, f32::INFINITY));
        let decoded = decode(&encode(&image)).unwrap();
        let bits = |image: &Image| -> Vec<u32> {
            image
                .pixels
                .iter()
                .flat_map(|p| p.to_array().map(f32::to_bits))
                .collect()
        };
        assert_eq!((decoded.width, decoded.height), (2, 2));
        assert_eq!(bits(&decoded), bits(&image));
    }

    #[test]
    fn reads_big_endian_grey() {
        // A 2 x 1 grey image written by a big-endian tool, with a data byte that looks like
        // whitespace (0x20) right after the header.
        let mut bytes = b"Pf 2 1\n1.0\n".to_vec();
        for value in [2.0f32.powi(-62), 0.5] {
            bytes.extend_from_slice(&value.to_be_bytes());
        }
        assert_eq!(bytes[11], 0x20);
        let image = decode(&bytes).unwrap();
        assert_eq!(
            image.pixels,
            [Vec3::splat(2.0f32.powi(-62)), Vec3::splat(0.5)]
        );
    }

    #[test]
    fn malformed_files_say_what_was_expected() {
        assert!(decode(b"P6\n2 2\n255\n").unwrap_err().contains("PF"));
        assert!(decode(b"PF\ntwo 2\n-1.0\n").unwrap_err().contains("width"));
        assert!(decode(b"PF\n2 2\n").unwrap_err().contains("ended"));
        let short = decode(b"PF\n1 1\n-1.0\n\0\0\0\0").unwrap_err();
        assert!(short.contains("12 bytes"), "{short}");
    }
}
