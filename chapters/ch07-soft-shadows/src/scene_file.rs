//! Scenes from Mitsuba 3 XML files, with area lights.
//!
//! Mitsuba 3 makes any shape a light by giving it an `<emitter type="area">` with a
//! `radiance`: it glows on the side its normal points to. Every piece of the shape glows
//! alike, so a `cube` becomes six parallelogram lights and an `obj` mesh one triangle light
//! per face, each with the file's radiance.
//!
//! Chapters 01 to 06 refuse area lights, so the file is converted in two steps: a copy with
//! the emitters taken off goes through chapter 06's conversion (materials, lens, filter,
//! moving shapes, point lights), and the lights are then named by their place in the shapes
//! chapter 06 lays out: the still shapes in file order, then the moving ones, each as many
//! pieces as `common::scene::world_shapes` makes of it. A light's geometry is read back from
//! the converted world, so it is exactly the surface the camera sees.
//!
//! A light that moves is refused: it would need its points sampled at the ray's time.

use crate::scene::SoftShadowScene;
use ch03_anti_aliasing::{PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use common::scene::{Integrator, SceneDescription, ShapeGeometry, world_shapes};

/// A scene ready for the soft-shadow renderer, and what the conversion had to say about it.
pub struct ConvertedScene {
    /// The scene.
    pub scene: SoftShadowScene,
    /// The lens of the file's sensor.
    pub lens: Lens,
    /// The film's reconstruction filter.
    pub filter: ReconstructionFilter,
    /// Samples per pixel the file asks for.
    pub spp: u64,
    /// The pixel sampler closest to the file's `<sampler>` type.
    pub sampler: PixelSamplerKind,
    /// Light the method leaves out, approximations, and settings it ignores.
    pub notes: Vec<String>,
}

// ANCHOR: convert
/// Converts a description with area lights, or says why it cannot.
pub fn convert(description: &SceneDescription) -> Result<ConvertedScene, String> {
    for (index, shape) in description.shapes.iter().enumerate() {
        let name = || format!("shape {} ({})", index + 1, shape.position);
        if shape.emitter.is_none() {
            continue;
        }
        if !shape.to_world_keyframes.is_empty() {
            return Err(format!(
                "{} is an area light that moves: this chapter samples lights that stand still",
                name()
            ));
        }
        if shape.flip_normals && matches!(shape.geometry, ShapeGeometry::Sphere { .. }) {
            return Err(format!(
                "{} is a sphere light with flip_normals, which glows inwards: this chapter's sphere lights glow outwards",
                name()
            ));
        }
    }
    let mut dark = description.clone();
    for shape in &mut dark.shapes {
        shape.emitter = None;
    }
    let converted = ch06_fuzzy_reflections::scene_file::convert(&dark)?;

    // The still shapes come first, in file order; only they can glow.
    let mut emitters = Vec::new();
    let mut first_piece = 0;
    for shape in description
        .shapes
        .iter()
        .filter(|shape| shape.to_world_keyframes.is_empty())
    {
        let pieces = world_shapes(shape)
            .map_err(|e| format!("shape at {}: {e}", shape.position))?
            .len();
        if let Some(emitter) = shape.emitter {
            emitters.extend((first_piece..first_piece + pieces).map(|i| (i, emitter.radiance)));
        }
        first_piece += pieces;
    }
    let scene = SoftShadowScene::new(converted.scene, &emitters)?;
    Ok(ConvertedScene {
        scene,
        lens: converted.lens,
        filter: converted.filter,
        spp: converted.spp,
        sampler: converted.sampler,
        notes: notes_for(&description.integrator, converted.notes),
    })
}
// ANCHOR_END: convert

/// The notes of the earlier chapters, less the one on indirect light where the file's `path`
/// integrator has none either: with `max_depth` 2 it computes direct light only, as we do.
fn notes_for(integrator: &Integrator, notes: Vec<String>) -> Vec<String> {
    let direct_only =
        matches!(integrator, Integrator::Path { max_depth, .. } if (1..=2).contains(max_depth));
    notes
        .into_iter()
        .filter(|note| !(direct_only && note.contains("leaves out indirect light")))
        .collect()
}
