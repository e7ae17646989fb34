//! The chapter's workbench, apart from its lecture: the light options of `render`, which
//! chapter 08 flattens into its own (`cli`), the book's figures, and the scenes on which the
//! chapter is checked against Mitsuba 3. Built with the `lab` feature (on by default); the
//! library without it is the lecture alone.

pub mod agreement;
pub mod cli;
pub mod diagrams;
pub mod figures;

use ch06_fuzzy_reflections::lab::MICROFACET_AS_LOBE;
use workbench::capabilities::{Capabilities, Chapter, Feature};

/// What chapter 07 renders of a scene: chapter 06's, lit by area lights too.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::SOFT_SHADOWS,
    approximates: &[(Feature::MicrofacetMaterial, MICROFACET_AS_LOBE)],
};
