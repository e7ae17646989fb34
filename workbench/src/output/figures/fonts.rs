//! The one typeface of every figure: DejaVu Sans, compiled into the program.
//!
//! Plotters looks fonts up by family name in a table that starts out empty (we build it without
//! the system font loader). Registering the embedded DejaVu files under `"sans-serif"` makes every
//! figure look the same on every machine, and keeps a missing system font from turning into an
//! error halfway through a long run.

use std::sync::Once;

use plotters::style::{FontStyle, IntoFont, RGBColor, TextStyle, register_font};

/// The family name plotters asks for by default; we make it mean DejaVu Sans.
const FAMILY: &str = "sans-serif";

/// Point sizes (in pixels) that stay legible when an 800-pixel-wide figure is shrunk to the width
/// of a book page.
pub(super) const TITLE_SIZE: f64 = 26.0;
pub(super) const LABEL_SIZE: f64 = 20.0;
pub(super) const TICK_SIZE: f64 = 16.0;

/// Registers the DejaVu fonts with plotters; only the first call does anything.
pub(super) fn register_dejavu() {
    static REGISTER: Once = Once::new();
    REGISTER.call_once(|| {
        let faces = [
            (FontStyle::Normal, dejavu::sans::regular()),
            (FontStyle::Bold, dejavu::sans::bold()),
            (FontStyle::Oblique, dejavu::sans::oblique()),
            (FontStyle::Italic, dejavu::sans::oblique()),
        ];
        for (style, bytes) in faces {
            let registered = register_font(FAMILY, style, bytes).is_ok();
            assert!(registered, "the embedded DejaVu Sans font failed to parse");
        }
    });
}

/// Bold, for figure titles.
pub(super) fn title_style() -> TextStyle<'static> {
    register_dejavu();
    (FAMILY, TITLE_SIZE, FontStyle::Bold).into_font().into()
}

/// Regular, in the given colour and size.
pub(super) fn text_style(size: f64, colour: RGBColor) -> TextStyle<'static> {
    register_dejavu();
    (FAMILY, size).into_font().color(&colour)
}

/// For axis descriptions, panel captions and legends.
pub(super) fn label_style() -> TextStyle<'static> {
    text_style(LABEL_SIZE, plotters::style::BLACK)
}

/// For the numbers along an axis.
pub(super) fn tick_style() -> TextStyle<'static> {
    text_style(TICK_SIZE, RGBColor(60, 60, 60))
}
