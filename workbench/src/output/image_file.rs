//! Writing and reading whole images, the format chosen by the file's extension.

use std::path::Path;

use image::ImageError;
use image::error::{ParameterError, ParameterErrorKind};

use super::{OutputError, exr, pfm, png, write_atomic};
use common::image::Image;

/// The extensions [`write_image`] and [`read_image`] understand, for error messages.
const IMAGE_EXTENSIONS: &str = ".png, .exr or .pfm";

/// The file formats we write, each with its reason to exist.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    /// 8-bit sRGB, for looking at.
    Png,
    /// Linear f32, for measuring, opened by every HDR viewer.
    Exr,
    /// Linear f32 in the simplest possible layout, for measuring and for other renderers.
    Pfm,
}

impl Format {
    /// The format named by the extension of `path`, ignoring case (`.PNG` is a PNG too).
    fn of(path: &Path) -> Result<Self, OutputError> {
        let extension = path
            .extension()
            .map(|extension| extension.to_string_lossy().to_ascii_lowercase());
        match extension.as_deref() {
            Some("png") => Ok(Self::Png),
            Some("exr") => Ok(Self::Exr),
            Some("pfm") => Ok(Self::Pfm),
            _ => Err(OutputError::UnknownExtension {
                path: path.to_owned(),
                expected: IMAGE_EXTENSIONS,
            }),
        }
    }
}

/// Checks that `path` names an image format [`write_image`] can write, without writing
/// anything: call it before a long render, so that a typo in the extension costs a second, not
/// the render.
pub fn check_image_path(path: &Path) -> Result<(), OutputError> {
    Format::of(path).map(|_| ())
}

/// Writes `image` to `path`, atomically, in the format its extension names:
///
/// - `.png`: sRGB-encoded 8-bit, clamped to `[0, 1]`, for looking at;
/// - `.exr`: linear f32 RGB, exact;
/// - `.pfm`: linear f32 RGB, little-endian, rows stored bottom to top (as the format demands).
///
/// The extension is checked, and the whole file encoded in memory, before anything touches the
/// disk: a bad extension or an unencodable image (one whose pixels do not fill its size, which
/// an image put together by hand can be) leaves the disk as it was. A NaN or infinite pixel is
/// written as it is to the float formats and clamped in a PNG (NaN as black).
pub fn write_image(path: &Path, image: &Image) -> Result<(), OutputError> {
    let format = Format::of(path)?;
    let encode_error = |source| OutputError::Encode {
        path: path.to_owned(),
        source,
    };
    let size = u64::from(image.width) * u64::from(image.height);
    if image.pixels.len() as u64 != size {
        let problem = format!(
            "the image has {} pixels, not {} x {}",
            image.pixels.len(),
            image.width,
            image.height
        );
        return Err(encode_error(ImageError::Parameter(
            ParameterError::from_kind(ParameterErrorKind::Generic(problem)),
        )));
    }
    let bytes = match format {
        Format::Png => png::encode(image).map_err(encode_error)?,
        Format::Exr => exr::encode(image).map_err(encode_error)?,
        Format::Pfm => pfm::encode(image),
    };
    write_atomic(path, |out| out.write_all(&bytes))
}

/// Reads a linear image from a `.pfm` (RGB or grey, either byte order), `.exr` or `.png` file
/// (whose sRGB encoding is undone): for example a reference rendered by another program.
pub fn read_image(path: &Path) -> Result<Image, OutputError> {
    let format = Format::of(path)?;
    let bytes = std::fs::read(path).map_err(|source| OutputError::Read {
        path: path.to_owned(),
        source,
    })?;
    let malformed = |expected: String| OutputError::Malformed {
        path: path.to_owned(),
        expected,
    };
    match format {
        Format::Pfm => pfm::decode(&bytes).map_err(malformed),
        Format::Exr => exr::decode(&bytes)
            .map_err(|error| malformed(format!("an OpenEXR image; the decoder said: {error}"))),
        Format::Png => png::decode(&bytes)
            .map_err(|error| malformed(format!("a PNG image; the decoder said: {error}"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    fn gradient() -> Image {
        let mut image = Image::new(5, 3);
        for y in 0..3 {
            for x in 0..5 {
                image.set(x, y, Vec3::new(x as f32 / 4.0, y as f32 / 2.0, 0.25));
            }
        }
        image
    }

    #[test]
    fn float_formats_round_trip_exactly_through_files() {
        let directory = tempfile::tempdir().unwrap();
        let mut image = gradient();
        image.set(4, 2, Vec3::new(17.5, 1.0e-7, 0.1)); // beyond what a PNG can hold
        for name in ["image.pfm", "image.exr", "IMAGE.PFM", "Image.Exr"] {
            let path = directory.path().join(name);
            check_image_path(&path).unwrap();
            write_image(&path, &image).unwrap();
            assert_eq!(read_image(&path).unwrap(), image, "{name}");
        }
    }

    #[test]
    fn png_round_trips_through_a_file_within_8_bit_precision() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("image.png");
        let image = gradient();
        write_image(&path, &image).unwrap();
        let decoded = read_image(&path).unwrap();
        assert_eq!((decoded.width, decoded.height), (5, 3));
        for (original, decoded) in image.pixels.iter().zip(&decoded.pixels) {
            assert!((*original - *decoded).abs().max_element() < 0.01);
        }
    }

    #[test]
    fn an_unknown_extension_is_refused_before_anything_is_written() {
        let directory = tempfile::tempdir().unwrap();
        for name in ["image.jpg", "image"] {
            let path = directory.path().join(name);
            assert!(check_image_path(&path).is_err());
            let error = write_image(&path, &gradient()).unwrap_err();
            let message = error.to_string();
            assert!(matches!(error, OutputError::UnknownExtension { .. }));
            assert!(message.contains(name), "{message}");
            assert!(message.contains(".png, .exr or .pfm"), "{message}");
        }
        assert_eq!(std::fs::read_dir(directory.path()).unwrap().count(), 0);
    }

    #[test]
    fn reading_reports_missing_and_malformed_files_by_name() {
        let directory = tempfile::tempdir().unwrap();
        let missing = directory.path().join("missing.exr");
        let error = read_image(&missing).unwrap_err();
        assert!(matches!(error, OutputError::Read { .. }));
        assert!(error.to_string().contains("missing.exr"));

        for name in ["broken.pfm", "broken.exr", "broken.png"] {
            let path = directory.path().join(name);
            std::fs::write(&path, b"not an image").unwrap();
            let error = read_image(&path).unwrap_err();
            assert!(
                matches!(error, OutputError::Malformed { .. }),
                "{name}: {error}"
            );
            assert!(error.to_string().contains(name));
        }
    }

    #[test]
    fn pixels_that_are_not_numbers_are_written_and_clamped_in_a_png() {
        let directory = tempfile::tempdir().unwrap();
        let mut image = gradient();
        image.set(0, 0, Vec3::new(f32::NAN, f32::INFINITY, f32::NEG_INFINITY));
        image.set(1, 0, Vec3::new(f32::MAX, -0.0, 1e-40));
        for name in ["image.pfm", "image.exr"] {
            let path = directory.path().join(name);
            write_image(&path, &image).unwrap();
            let read = read_image(&path).unwrap();
            let bits = |image: &Image| -> Vec<u32> {
                image
                    .pixels
                    .iter()
                    .flat_map(|p| p.to_array().map(f32::to_bits))
                    .collect()
            };
            assert_eq!(bits(&read), bits(&image), "{name}");
        }
        let path = directory.path().join("image.png");
        write_image(&path, &image).unwrap();
        let read = read_image(&path).unwrap();
        assert_eq!(read.get(0, 0), Vec3::new(0.0, 1.0, 0.0));
        assert_eq!(read.get(1, 0), Vec3::new(1.0, 0.0, 0.0));
    }

    #[test]
    fn pixels_that_do_not_fill_the_size_are_an_encode_error() {
        let directory = tempfile::tempdir().unwrap();
        for pixels in [0, 14, 16] {
            let image = Image {
                pixels: vec![Vec3::ONE; pixels],
                ..gradient()
            };
            for name in ["image.png", "image.exr", "image.pfm"] {
                let path = directory.path().join(name);
                let error = write_image(&path, &image).unwrap_err();
                assert!(matches!(error, OutputError::Encode { .. }), "{error}");
                assert!(
                    error
                        .to_string()
                        .contains(&format!("{pixels} pixels, not 5 x 3"))
                );
                assert!(!path.exists());
            }
        }
    }

    #[test]
    fn an_empty_image_is_an_encode_error_for_png() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("empty.png");
        let error = write_image(&path, &Image::new(0, 0)).unwrap_err();
        assert!(matches!(error, OutputError::Encode { .. }), "{error}");
        assert!(!path.exists());
    }
}
