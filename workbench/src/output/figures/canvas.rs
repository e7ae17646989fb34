//! A blank page to draw a figure on, and how it becomes a PNG file.
//!
//! Plotters can draw into a plain byte buffer (three sRGB bytes per pixel). We draw there, then
//! encode the buffer with our own PNG writer and save it through [`write_atomic`], so figures
//! obey the same whole-file-or-nothing rule as rendered images.

use std::error::Error;
use std::path::Path;

use plotters::coord::Shift;
use plotters::element::Text;
use plotters::prelude::{BitMapBackend, DrawingArea, IntoDrawingArea};
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::output::{OutputError, png, write_atomic};

/// The drawing area plotters hands to a figure's drawing code.
pub(super) type Area<'a> = DrawingArea<BitMapBackend<'a>, Shift>;

/// What drawing code returns: plotters reports failures through several error types, and all a
/// figure can do with any of them is pass it on.
pub(super) type DrawResult = Result<(), Box<dyn Error>>;

/// An RGB image in display (sRGB) bytes, white to begin with.
pub(super) struct Canvas {
    width: u32,
    height: u32,
    rgb: Vec<u8>,
}

impl Canvas {
    /// A white canvas of `width x height` pixels.
    pub(super) fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            rgb: vec![255; width as usize * height as usize * 3],
        }
    }

    /// Sets one pixel; `(x, y)` must lie on the canvas.
    pub(super) fn put(&mut self, x: u32, y: u32, rgb: [u8; 3]) {
        let start = (y as usize * self.width as usize + x as usize) * 3;
        self.rgb[start..start + 3].copy_from_slice(&rgb);
    }

    /// Runs plotters drawing code on the canvas.
    pub(super) fn draw(&mut self, draw: impl FnOnce(&Area) -> DrawResult) -> DrawResult {
        super::fonts::register_dejavu();
        let area = BitMapBackend::with_buffer(&mut self.rgb, (self.width, self.height))
            .into_drawing_area();
        draw(&area)?;
        area.present()?;
        Ok(())
    }

    /// Saves the canvas as a PNG at `path`, atomically.
    pub(super) fn save(&self, path: &Path) -> Result<(), OutputError> {
        let bytes = png::encode_rgb8(self.width, self.height, &self.rgb).map_err(|source| {
            OutputError::Encode {
                path: path.to_owned(),
                source,
            }
        })?;
        write_atomic(path, |out| out.write_all(&bytes))
    }
}

/// Draws a `width x height` figure on white and saves it at `path`: the whole life of a plot.
///
/// The extension is checked first, so a wrong one costs no drawing time.
pub(super) fn draw_figure(
    path: &Path,
    (width, height): (u32, u32),
    draw: impl FnOnce(&Area) -> DrawResult,
) -> Result<(), OutputError> {
    require_png_path(path)?;
    let mut canvas = Canvas::new(width, height);
    canvas
        .draw(draw)
        .map_err(|error| figure_error(path, format!("the plotting library failed: {error}")))?;
    canvas.save(path)
}

/// Writes `title` centred in `area`, in the title font.
pub(super) fn draw_title(area: &Area, title: &str) -> DrawResult {
    let (width, height) = area.dim_in_pixel();
    let style = super::fonts::title_style().pos(Pos::new(HPos::Center, VPos::Center));
    area.draw(&Text::new(
        title,
        (width as i32 / 2, height as i32 / 2),
        style,
    ))?;
    Ok(())
}

/// Figures are PNG files; any other extension is refused before work starts.
pub(super) fn require_png_path(path: &Path) -> Result<(), OutputError> {
    let is_png = path
        .extension()
        .is_some_and(|extension| extension.eq_ignore_ascii_case("png"));
    if is_png {
        Ok(())
    } else {
        Err(OutputError::UnknownExtension {
            path: path.to_owned(),
            expected: ".png (figures are always PNG files)",
        })
    }
}

/// An [`OutputError::Figure`] for `path`.
pub(super) fn figure_error(path: &Path, problem: impl Into<String>) -> OutputError {
    OutputError::Figure {
        path: path.to_owned(),
        problem: problem.into(),
    }
}

/// Test helper: decodes the figure at `path`, checks its size, and checks that it is not blank
/// (it has more than one colour).
#[cfg(test)]
pub(super) fn assert_figure(path: &Path, width: u32, height: u32) {
    let decoded = image::open(path).expect("the figure decodes").to_rgb8();
    assert_eq!(
        decoded.dimensions(),
        (width, height),
        "size of {}",
        path.display()
    );
    let first = decoded.get_pixel(0, 0);
    assert!(
        decoded.pixels().any(|pixel| pixel != first),
        "{} is blank",
        path.display()
    );
}
