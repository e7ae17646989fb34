//! The chapter's workbench, apart from its lecture: a scene file's motion made ready
//! (`scene_file`), what every `render` from this chapter on traces (`shot`: the scene in
//! motion, chapter 04's lens, chapter 03's pixel sampler and filter, the shutter time), and
//! the book's figures. Built with the `lab` feature (on by default); the library without it
//! is the lecture alone.

pub mod diagrams;
pub mod figures;
pub mod scene_file;
pub mod shot;

use workbench::capabilities::{Capabilities, Chapter};

/// What chapter 05 renders of a scene: chapter 04's, with shapes and a camera that move.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::MOTION_BLUR,
    approximates: &[],
};
