//! Everything around the lecture, written once: the workbench the chapters' binaries, figures
//! and checks stand on.
//!
//! A chapter's library holds its lecture and nothing else; what a student uses to *run* the
//! lecture lives here, above it: what each chapter renders of a scene and the course map that
//! names the chapter bringing the rest ([`capabilities`]), the shared command-line options and
//! Ctrl-C ([`cli`]), the render driver every chapter's `render` runs through ([`driver`]), the
//! Mitsuba 3 scene-file reader ([`scene_file`]), image files and plots ([`output`]), the
//! figures a chapter writes and the time each took ([`figure_set`]), error against time
//! ([`convergence`]), agreement with Mitsuba 3 ([`agreement`]), and what the checks use to
//! explain a failure ([`test_support`]).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod agreement;
pub mod capabilities;
pub mod cli;
pub mod convergence;
pub mod driver;
pub mod figure_set;
pub mod output;
pub mod scene_file;
pub mod test_support;
