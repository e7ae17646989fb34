//! Scenes from Mitsuba 3 XML files for the path tracer: chapter 07's conversion (materials,
//! lens, filter, motion, point and area lights, the `constant` environment as the scene's
//! background), and the `path` integrator's `max_depth` and `rr_depth`.
//!
//! The earlier chapters' notes about light they leave out (indirect light, the environment
//! on matte surfaces) do not apply here: the path tracer computes all of it.

use crate::options::PathOptions;
use ch01_whitted::scene_file::UNLIMITED_DEPTH;
use common::scene::{Integrator, SceneDescription};

/// Chapter 07's converted scene, with the path tracer's options from the file.
pub struct ConvertedScene {
    /// The scene, lens, filter, sampler and the notes that still apply.
    pub converted: ch07_soft_shadows::scene_file::ConvertedScene,
    /// NEE and the power heuristic as Mitsuba's `path`, its depth and roulette from the file.
    pub options: PathOptions,
}

/// Converts a description, or says why it cannot.
pub fn convert(description: &SceneDescription) -> Result<ConvertedScene, String> {
    let mut converted = ch07_soft_shadows::scene_file::convert(description)?;
    converted.notes.retain(|note| {
        !(note.contains("leaves out indirect light") || note.contains("does not light matte"))
    });
    let depth = |d: i32| {
        if d < 0 {
            UNLIMITED_DEPTH
        } else {
            (d.max(1)) as u32
        }
    };
    let options = match description.integrator {
        Integrator::Path {
            max_depth,
            rr_depth,
        } => PathOptions {
            max_depth: depth(max_depth),
            rr_depth: Some(rr_depth.max(1) as u32),
            ..PathOptions::default()
        },
        // `direct`: one light and one BSDF sample with the power heuristic, no bounce.
        _ => PathOptions {
            max_depth: 2,
            ..PathOptions::default()
        },
    };
    converted.scene.scene.world.scene.max_depth = options.max_depth;
    Ok(ConvertedScene { converted, options })
}
