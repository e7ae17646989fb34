//! The crate's workbench, apart from the lecture: the binary's `render` (a scene file path
//! traced as chapter 08 does, guided as `--guiding off|radiance|variance` says) and the
//! figures. Built with the `lab` feature (on by default).

pub mod agreement;
pub mod cli;
pub mod diagrams;
pub mod figures;

use workbench::capabilities::{Capabilities, Chapter};

/// What the binary renders of a scene file: every material chapter 09 knows, path traced as
/// chapter 08 does.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::PATH_GUIDING,
    approximates: &[],
};
