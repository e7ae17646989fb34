//! What the lecture does not teach, below every chapter.
//!
//! The chapters of the workbook each own one idea of distribution ray tracing. Everything their
//! lectures need that is *not* one of those ideas lives here: vectors and rays, shapes and the
//! BVH that finds the nearest hit, the scene model, the plumbing that hands out random numbers
//! in a fixed order, the film that averages samples, the parallel render loop and error
//! metrics. Nothing here reads or writes a file, parses a command line or draws a plot (that is
//! the `workbench` crate's, above the lectures), so the chapters' lectures build for the
//! browser.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod exercise;
pub mod film;
pub mod geometry;
pub mod image;
pub mod metrics;
pub mod ray;
pub mod render;
pub mod sampler;
pub mod scene;
pub mod srgb;

pub use glam::{DVec3, UVec2, Vec2, Vec3};
pub use ray::Ray;
