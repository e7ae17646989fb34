//! Scenes from Mitsuba 3 XML files: chapter 01's conversion, plus the film's filter.
//!
//! Chapter 01 renders everything Whitted's method can and averages each pixel's own samples.
//! This chapter renders the same scenes but honours the file's `<rfilter>`: the only thing a
//! scene file says about anti-aliasing besides its sample count.

use crate::filters::{FilterKind, ReconstructionFilter};
use ch01_whitted::scene::Scene;
use common::scene::{self, SceneDescription};

/// A scene ready for Whitted's tracer with the filter its file asks for.
pub struct ConvertedScene {
    /// The scene.
    pub scene: Scene,
    /// The film's reconstruction filter.
    pub filter: ReconstructionFilter,
    /// Samples per pixel the file asks for.
    pub spp: u64,
    /// Light the method leaves out, and settings it ignores.
    pub notes: Vec<String>,
}

/// Converts a description with chapter 01's rules, except that the film's filter is ours to
/// use rather than a setting to note and ignore.
pub fn convert(description: &SceneDescription) -> Result<ConvertedScene, String> {
    let filter = filter_of(description.sensor.film.filter)?;
    let mut boxed = description.clone();
    // Chapter 01 would note that it ignores any filter but the box; this chapter does not.
    boxed.sensor.film.filter = scene::ReconstructionFilter::Box;
    let converted = ch01_whitted::scene_file::convert(&boxed)?;
    Ok(ConvertedScene {
        scene: converted.scene,
        filter,
        spp: converted.spp,
        notes: converted.notes,
    })
}

/// The chapter's filter for a file's `<rfilter>`, with Mitsuba's parameters.
pub fn filter_of(filter: scene::ReconstructionFilter) -> Result<ReconstructionFilter, String> {
    let in_file = |e: String| format!("the film's rfilter: {e}");
    match filter {
        scene::ReconstructionFilter::Box => ReconstructionFilter::new(FilterKind::Box, None),
        scene::ReconstructionFilter::Tent { radius } => {
            ReconstructionFilter::new(FilterKind::Tent, Some(radius)).map_err(in_file)
        }
        scene::ReconstructionFilter::Gaussian { stddev } => {
            ReconstructionFilter::new(FilterKind::Gaussian, Some(4.0 * stddev)).map_err(in_file)
        }
    }
}
