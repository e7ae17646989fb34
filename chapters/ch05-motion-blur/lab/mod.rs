//! The chapter's workbench, apart from its lecture: a scene file's motion made ready
//! (`scene_file`), the setup every `render` from this chapter on shares (`render_setup`: the
//! pixel sampler and filter of chapter 03, the lens of chapter 04, the scene, budget and
//! outputs), and the book's figures. Built with the `lab` feature (on by default); the library
//! without it is the lecture alone.

pub mod figures;
pub mod render_setup;
pub mod scene_file;

use workbench::capabilities::{Capabilities, Chapter};

/// What chapter 05 renders of a scene: chapter 04's, with shapes and a camera that move.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::MOTION_BLUR,
    approximates: &[],
};
