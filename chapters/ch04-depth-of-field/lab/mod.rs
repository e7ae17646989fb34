//! The chapter's workbench, apart from its lecture: the lens options of the command line
//! (`cli`), the lens a scene file's camera asks for (`scene_file`), the book's figures and the
//! scenes on which the chapter is checked against Mitsuba 3. Built with the `lab` feature (on by
//! default); the library without it is the lecture alone.

pub mod agreement;
pub mod cli;
pub mod diagrams;
pub mod figures;
pub mod scene_file;

use workbench::capabilities::{Capabilities, Chapter};

/// What chapter 04 renders of a scene: chapter 03's, through a lens with an aperture.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::DEPTH_OF_FIELD,
    approximates: &[],
};
