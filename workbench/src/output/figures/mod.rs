//! The figures of the book, saved as PNG files.
//!
//! Each function draws one kind of figure, complete with title, axis descriptions and legend,
//! and saves it atomically. They all share one look: white background, DejaVu Sans compiled
//! into the program (so a figure never depends on the fonts of the machine that drew it), a
//! colour-blind-safe palette for series, and the perceptual *viridis* scale for magnitudes.
//!
//! | figure | shows |
//! |---|---|
//! | [`comparison_grid`] | renders side by side, magnified without smoothing |
//! | [`scatter_plot`] | where samples land: in a pixel, on a lens, after a warp |
//! | [`histogram_vs_pdf`] | whether a sampler draws from the density it claims |
//! | [`line_plot`] | error against samples or time, usually on log-log axes |
//! | [`bar_chart`] | a number per named case |
//! | [`Diagram`] | geometry drawn from the chapter's own numbers, as SVG |

#[cfg(test)]
mod awkward_data;
mod axis;
mod bar;
mod canvas;
mod diagram;
mod fonts;
mod grid;
mod heatmap;
mod legend;
mod line;
mod palette;
mod scatter;

pub use bar::bar_chart;
pub use diagram::{Anchor, Diagram, Ink, Point};
pub use grid::{comparison_grid, crop};
pub use heatmap::histogram_vs_pdf;
pub use line::{Axes, Series, SeriesStyle, line_plot};
pub use scatter::scatter_plot;
