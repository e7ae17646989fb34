//! The chapter's workbench, apart from its lecture: the command-line options later chapters
//! flatten into theirs (`cli`), a scene file's film filter and sampler in the chapter's terms
//! (`scene_file`), the book's figures and the scenes on which the chapter is checked against
//! Mitsuba 3. Built with the `lab` feature (on by default); the library without it is the
//! lecture alone.

pub mod agreement;
pub mod cli;
pub mod diagrams;
pub mod figures;
pub mod scene_file;

use workbench::capabilities::{Capabilities, Chapter};

/// What chapter 03 renders of a scene: chapter 01's, with the film's reconstruction filter.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::ANTI_ALIASING,
    approximates: &[],
};
