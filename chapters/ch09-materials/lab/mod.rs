//! The crate's workbench, apart from its materials: the renderer for real scene files (its
//! binary, `lab/main.rs`, with chapter 08's options), the figures of the microfacet models
//! (the lobes, the furnace, the samplers' chi-square table), and the scenes on which Mitsuba's
//! materials are checked against Mitsuba 3. Built with the `lab` feature (on by default); the
//! library without it is the materials alone.

pub mod agreement;
pub mod diagrams;
pub mod figure_scene;
pub mod figures;
pub mod microfacet_chi2_table;
pub mod microfacet_figures;

use workbench::capabilities::{Capabilities, Chapter};

/// What the renderer of real scene files renders: everything the workbook knows. Nothing is
/// approximated: a file's rough metals, plastics and glass are Mitsuba's microfacet models,
/// not chapter 06's lobes, and its metals keep their Fresnel reflectance, so no note says
/// otherwise.
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::MATERIALS,
    approximates: &[],
};
