//! The crate's workbench, apart from the lecture: the binary's `render` (the light and BSDF
//! samples at the surface the camera sees, combined by `--mis optimal|power|balance`) and the
//! figures. Built with the `lab` feature (on by default).

pub mod agreement;
pub mod cli;
pub mod diagrams;
pub mod figures;

use workbench::capabilities::{Capabilities, Chapter};

/// What the binary renders of a scene file: every material chapter 09 knows, lit straight
/// from the lights (Mitsuba's `direct` with one light and one BSDF sample, whatever the file's
/// integrator; see [`cli`]).
pub const CAPABILITIES: Capabilities = Capabilities {
    chapter: Chapter::OPTIMAL_MIS,
    approximates: &[],
};
