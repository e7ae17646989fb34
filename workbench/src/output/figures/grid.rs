//! Images side by side, each with a caption: the figure every chapter ends with.

use std::path::Path;

use plotters::element::Text;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::canvas::{Canvas, figure_error, require_png_path};
use super::fonts::label_style;
use crate::output::{OutputError, to_srgb8};
use common::image::Image;

/// White space between cells and around the figure, in pixels.
const GAP: u32 = 12;
/// Height of the caption strip under each image.
const CAPTION_HEIGHT: u32 = 30;
/// Refuse figures larger than this in either direction: more likely a wrong `scale` than a wish.
const MAX_SIDE: u32 = 16_384;

/// Saves a grid of labelled images as a PNG: `columns` cells per row, each image magnified
/// `scale` times with its caption below.
///
/// Magnification repeats pixels (nearest neighbour) rather than smoothing them, so the jagged
/// edges of a 1-sample-per-pixel render stay visible: they are what the figure is there to
/// show. Cells may differ in size; each sits centred in a slot as large as the largest cell
/// (or its caption, if that is wider). Images are shown as an sRGB PNG shows them, clamped
/// to `[0, 1]`.
///
/// Errors: an empty list, `columns == 0` or `scale == 0`, or a grid over 16 384 pixels wide or
/// tall, are refused before anything is drawn.
pub fn comparison_grid(
    path: &Path,
    cells: &[(String, Image)],
    columns: usize,
    scale: u32,
) -> Result<(), OutputError> {
    require_png_path(path)?;
    if cells.is_empty() {
        return Err(figure_error(path, "the grid has no images to show"));
    }
    if columns == 0 || scale == 0 {
        return Err(figure_error(
            path,
            format!("columns ({columns}) and scale ({scale}) must both be at least 1"),
        ));
    }

    let mut canvas = Canvas::new(1, 1);
    let caption_widths = caption_widths(&mut canvas, cells);
    let widest_caption = caption_widths.into_iter().max().unwrap_or(0);
    let slot_width = cells
        .iter()
        .map(|(_, image)| u64::from(image.width) * u64::from(scale))
        .max()
        .unwrap_or(0)
        .max(u64::from(widest_caption) + 8);
    let slot_height = cells
        .iter()
        .map(|(_, image)| u64::from(image.height) * u64::from(scale))
        .max()
        .unwrap_or(0);

    let columns = columns.min(cells.len()) as u64;
    let rows = (cells.len() as u64).div_ceil(columns);
    let gap = u64::from(GAP);
    let width = columns * (slot_width + gap) + gap;
    let height = rows * (slot_height + u64::from(CAPTION_HEIGHT) + gap) + gap;
    if width > u64::from(MAX_SIDE) || height > u64::from(MAX_SIDE) {
        return Err(figure_error(
            path,
            format!(
                "the grid would be {width} x {height} pixels; use a smaller scale or crop the images"
            ),
        ));
    }
    // All sizes now fit in u32: they are at most MAX_SIDE.
    let (slot_width, slot_height) = (slot_width as u32, slot_height as u32);
    let mut canvas = Canvas::new(width as u32, height as u32);

    let slot_origin = |index: usize| {
        let (column, row) = (index as u32 % columns as u32, index as u32 / columns as u32);
        (
            GAP + column * (slot_width + GAP),
            GAP + row * (slot_height + CAPTION_HEIGHT + GAP),
        )
    };
    for (index, (_, image)) in cells.iter().enumerate() {
        let (slot_x, slot_y) = slot_origin(index);
        let left = slot_x + (slot_width - image.width * scale) / 2;
        let top = slot_y + (slot_height - image.height * scale) / 2;
        paint_magnified(&mut canvas, image, scale, (left, top));
    }

    canvas
        .draw(|area| {
            for (index, (caption, _)) in cells.iter().enumerate() {
                let (slot_x, slot_y) = slot_origin(index);
                let centre = (slot_x + slot_width / 2) as i32;
                let below_image = (slot_y + slot_height + CAPTION_HEIGHT / 2) as i32;
                let style = label_style().pos(Pos::new(HPos::Center, VPos::Center));
                area.draw(&Text::new(caption.as_str(), (centre, below_image), style))?;
            }
            Ok(())
        })
        .map_err(|error| figure_error(path, format!("drawing the captions failed: {error}")))?;
    canvas.save(path)
}

/// How wide each caption will be, in pixels, in the caption font.
fn caption_widths(canvas: &mut Canvas, cells: &[(String, Image)]) -> Vec<u32> {
    let mut widths = Vec::with_capacity(cells.len());
    // Measuring text needs a drawing area; a 1 x 1 canvas is enough. Should measuring fail, we
    // fall back to a generous estimate rather than abandon the figure.
    let measured = canvas.draw(|area| {
        for (caption, _) in cells {
            widths.push(area.estimate_text_size(caption, &label_style())?.0);
        }
        Ok(())
    });
    if measured.is_err() {
        widths = cells
            .iter()
            .map(|(caption, _)| 12 * caption.chars().count() as u32)
            .collect();
    }
    widths
}

/// Paints `image` with its top-left corner at `(left, top)`, each pixel a `scale x scale` block.
fn paint_magnified(canvas: &mut Canvas, image: &Image, scale: u32, (left, top): (u32, u32)) {
    for y in 0..image.height {
        for x in 0..image.width {
            let rgb = image.get(x, y).to_array().map(to_srgb8);
            for dy in 0..scale {
                for dx in 0..scale {
                    canvas.put(left + x * scale + dx, top + y * scale + dy, rgb);
                }
            }
        }
    }
}

/// The `w x h` block of `image` whose top-left pixel is `(x, y)`: for a zoomed-in detail of a
/// render, to pass to [`comparison_grid`] with a large `scale`.
///
/// # Panics
///
/// If the block reaches outside the image: a crop window that misses the image is a mistake in
/// the figure's code, better caught at once than shown as a black square.
pub fn crop(image: &Image, x: u32, y: u32, w: u32, h: u32) -> Image {
    let fits = |start: u32, length: u32, size: u32| {
        start.checked_add(length).is_some_and(|end| end <= size)
    };
    assert!(
        fits(x, w, image.width) && fits(y, h, image.height),
        "crop of {w} x {h} at ({x}, {y}) reaches outside the {} x {} image",
        image.width,
        image.height
    );
    let mut cropped = Image::new(w, h);
    for row in 0..h {
        for column in 0..w {
            cropped.set(column, row, image.get(x + column, y + row));
        }
    }
    cropped
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::figures::canvas::assert_figure;
    use glam::Vec3;

    fn checkerboard(size: u32) -> Image {
        let mut image = Image::new(size, size);
        for y in 0..size {
            for x in 0..size {
                let bright = (x + y) % 2 == 0;
                image.set(x, y, Vec3::splat(if bright { 0.8 } else { 0.05 }));
            }
        }
        image
    }

    #[test]
    fn draws_a_labelled_grid_of_the_expected_size() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("grid.png");
        let cells = vec![
            ("1 spp".to_string(), checkerboard(16)),
            (
                "16 spp".to_string(),
                Image::filled(16, 16, Vec3::new(0.2, 0.4, 0.9)),
            ),
            ("reference".to_string(), checkerboard(8)),
        ];
        comparison_grid(&path, &cells, 2, 8).unwrap();
        // Two columns of 128-pixel slots, two rows.
        let width = 2 * (128 + GAP) + GAP;
        let height = 2 * (128 + CAPTION_HEIGHT + GAP) + GAP;
        assert_figure(&path, width, height);

        // The first image's top-left pixel, magnified 8 times, fills an 8 x 8 block.
        let decoded = image::open(&path).unwrap().to_rgb8();
        let bright = to_srgb8(0.8);
        for offset in 0..8 {
            assert_eq!(decoded.get_pixel(GAP + offset, GAP + offset).0, [bright; 3]);
        }
        assert_eq!(decoded.get_pixel(GAP + 8, GAP).0, [to_srgb8(0.05); 3]);
    }

    #[test]
    fn wide_captions_widen_the_slots() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("grid.png");
        let caption = "a caption far wider than the tiny image".to_string();
        comparison_grid(&path, &[(caption, checkerboard(4))], 3, 1).unwrap();
        let decoded = image::open(&path).unwrap().to_rgb8();
        assert!(decoded.width() > 200, "{}", decoded.width());
    }

    #[test]
    fn bad_input_is_an_error_not_a_panic() {
        let directory = tempfile::tempdir().unwrap();
        let path = directory.path().join("grid.png");
        let one = vec![("one".to_string(), checkerboard(4))];
        for (cells, columns, scale) in [(&[][..], 2, 4), (&one[..], 0, 4), (&one[..], 2, 0)] {
            let error = comparison_grid(&path, cells, columns, scale).unwrap_err();
            assert!(matches!(error, OutputError::Figure { .. }), "{error}");
            assert!(error.to_string().contains("grid.png"));
        }
        let huge = comparison_grid(&path, &one, 1, 10_000).unwrap_err();
        assert!(huge.to_string().contains("smaller scale"), "{huge}");
        assert!(!path.exists());
    }

    #[test]
    fn crop_takes_the_block_at_the_corner() {
        let mut image = Image::new(4, 3);
        image.set(2, 1, Vec3::X);
        let cropped = crop(&image, 1, 1, 2, 2);
        assert_eq!((cropped.width, cropped.height), (2, 2));
        assert_eq!(cropped.get(1, 0), Vec3::X);
        assert_eq!(
            cropped.pixels.iter().filter(|p| **p != Vec3::ZERO).count(),
            1
        );
    }

    #[test]
    #[should_panic(expected = "reaches outside")]
    fn crop_outside_the_image_panics() {
        crop(&Image::new(4, 4), 3, 0, 2, 2);
    }
}
