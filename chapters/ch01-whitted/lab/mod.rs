//! The chapter's workbench, apart from its lecture: the figures the book shows and the scenes
//! on which the chapter is checked against Mitsuba 3. Built with the `lab` feature (on by
//! default); the library without it is the lecture alone.

pub mod agreement;
pub mod diagrams;
pub mod figures;

use workbench::capabilities::{Capabilities, Chapter};

/// What chapter 01 renders of a scene: point lights, matte surfaces, mirrors and glass seen
/// through a pinhole, and nothing of the later chapters. It leaves out indirect light and the
/// environment's light on matte surfaces, and averages each pixel's own samples.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::WHITTED,
    approximates: &[],
};
