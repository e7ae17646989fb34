//! What the lecture does not teach, shared by every chapter.
//!
//! The chapters of the workbook each own one idea of distribution ray tracing. Everything they
//! need that is *not* one of those ideas lives here: vectors and rays, shapes and the BVH that
//! finds the nearest hit, the plumbing that hands out random numbers in a fixed order, the film
//! that averages samples, image files, the parallel render loop, error metrics and plots.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod cli;
pub mod exercise;
pub mod figure_set;
pub mod film;
pub mod geometry;
pub mod image;
pub mod metrics;
pub mod output;
pub mod ray;
pub mod render;
pub mod sampler;
pub mod scene;
pub mod scene_file;
pub mod test_support;

pub use glam::{DVec3, UVec2, Vec2, Vec3};
pub use ray::Ray;
