//! The chapter's workbench, apart from its lecture: the options of `render` (`cli`), a scene
//! file's path options (`scene_file`), the book's figures, and the scenes on which the chapter
//! is checked against Mitsuba 3's `path`. Built with the `lab` feature (on by default); the library without it is
//! the lecture alone.

pub mod agreement;
pub mod cli;
pub mod diagrams;
pub mod estimate;
pub mod figures;
pub mod scene_file;

use ch06_fuzzy_reflections::lab::MICROFACET_AS_LOBE;
use workbench::capabilities::{Capabilities, Chapter, Feature};

/// What chapter 08 renders of a scene: chapter 07's, with indirect light, the environment's
/// light on matte surfaces, environment maps, directional lights and Mitsuba's integrator
/// settings. Its materials are the lecture's: a file's rough materials become chapter 06's
/// `cos^n` lobes, its metals the lecture's mirror or lobe, and what has no stand-in (plastic,
/// masks, thin or tinted glass) is refused, as in the chapters before; chapter 09 renders them.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::PATH_TRACING,
    approximates: &[(Feature::MicrofacetMaterial, MICROFACET_AS_LOBE)],
};
