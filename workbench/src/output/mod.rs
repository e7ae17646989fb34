//! Image files, plots and figure helpers: how results leave the program.
//!
//! Two rules hold for everything written here:
//!
//! - **Floats for measuring, PNG for looking.** A render is saved as EXR or PFM (linear f32,
//!   exact) when it will be compared against, and as PNG (sRGB, 8-bit) when a person will look
//!   at it. See [`write_image`].
//! - **Whole files or none.** Every writer goes through [`write_atomic`], so an interrupted run
//!   never leaves a truncated file for the next run to trip over.
//!
//! The [`figures`] module draws the book's figures: labelled image grids, sample scatter plots,
//! histograms against densities, convergence curves and bar charts.

mod atomic;
mod error;
mod exr;
pub mod figures;
mod image_file;
mod pfm;
mod png;

pub use atomic::{write_atomic, write_text};
pub use error::OutputError;
pub use image_file::{check_image_path, read_image, write_image};
// The sRGB curve is `common`'s: the live demos encode their pixels with it too.
pub use common::srgb::{linear_to_srgb, srgb_to_linear, srgb8_to_linear, to_srgb8};
