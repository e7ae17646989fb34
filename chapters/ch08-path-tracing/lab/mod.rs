//! The chapter's workbench, apart from its lecture: the options of `render` (`cli`), a scene
//! file's path options (`scene_file`), the book's figures (with the microfacet chapter's lobes,
//! furnace and chi-square table), and the scenes on which the chapter is checked against
//! Mitsuba 3's `path`. Built with the `lab` feature (on by default); the library without it is
//! the lecture alone.

pub mod agreement;
pub mod cli;
pub mod figures;
pub mod microfacet_chi2_table;
pub mod microfacet_figures;
pub mod scene_file;

use workbench::capabilities::{Capabilities, Chapter};

/// What chapter 08 renders of a scene: everything the workbook knows, indirect light and the
/// environment's light on matte surfaces included. Nothing is approximated: a file's rough
/// metals, plastics and glass are Mitsuba's microfacet models ([`microfacet`]), not chapter
/// 06's lobes, so no note says otherwise.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::PATH_TRACING,
    approximates: &[],
};
