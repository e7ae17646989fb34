//! The chapter's workbench, apart from its lecture: the options of a fuzzy render, which later
//! chapters flatten into theirs (`cli`), the book's figures, and the scenes on which the
//! chapter is checked against Mitsuba 3. Built with the `lab` feature (on by default); the
//! library without it is the lecture alone.

pub mod agreement;
pub mod cli;
pub mod diagrams;
pub mod figures;

use workbench::capabilities::{Capabilities, Chapter, Feature};

// ANCHOR: capabilities
/// How chapter 06 renders a scene file's microfacet roughness.
pub const MICROFACET_AS_LOBE: &str = "rendered as a cos^n lobe of exponent n = 2/alpha^2 - 2: about as wide as Mitsuba's microfacet lobe, not the same shape";

/// What chapter 06 renders of a scene: chapter 05's, with glossy and frosted materials; a
/// scene file's rough materials become `cos^n` lobes of about the same width.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::FUZZY_REFLECTIONS,
    approximates: &[(Feature::MicrofacetMaterial, MICROFACET_AS_LOBE)],
};
// ANCHOR_END: capabilities
