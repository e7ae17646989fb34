//! Scenes from Mitsuba 3 XML files, with the workbook's `<animation>` extension.
//!
//! Mitsuba 3 has no moving objects, so motion is written as Mitsuba 0.6 wrote it: an
//! `<animation name="to_world">` of `<transform time="...">` keyframes in place of a shape's
//! (or the sensor's) `<transform name="to_world">`; the sensor's `shutter_open` and
//! `shutter_close` give the interval. Earlier chapters refuse such a file; this one splits it:
//! the shapes that do not move, and the sensor at its first keyframe, go through chapter 04's
//! conversion unchanged, and each moving shape is placed in its own space (its `to_world` left
//! out) with its keyframes as an [`AnimatedTransform`].

use crate::animated_transform::AnimatedTransform;
use crate::moving::MovingShape;
use crate::shutter::Shutter;
use crate::world::MotionScene;
use ch03_anti_aliasing::{PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use common::scene::{SceneDescription, ShapeDescription, world_shapes};
use glam::Mat4;

/// A scene ready for the motion-blur render, and what the conversion had to say about it.
pub struct ConvertedScene {
    /// The scene in motion, with the file's shutter.
    pub world: MotionScene,
    /// The lens of the file's sensor.
    pub lens: Lens,
    /// The film's reconstruction filter.
    pub filter: ReconstructionFilter,
    /// Samples per pixel the file asks for.
    pub spp: u64,
    /// The pixel sampler closest to the file's `<sampler>` type.
    pub sampler: PixelSamplerKind,
    /// Light the method leaves out, and settings it ignores.
    pub notes: Vec<String>,
}

// ANCHOR: convert
/// Converts a description with moving shapes or a moving sensor, or says why it cannot.
pub fn convert(description: &SceneDescription) -> Result<ConvertedScene, String> {
    let sensor = &description.sensor;
    let shutter = Shutter::new(sensor.shutter_open, sensor.shutter_close).map_err(|e| {
        format!(
            "the sensor's shutter_open {} and shutter_close {}: {e}",
            sensor.shutter_open, sensor.shutter_close
        )
    })?;
    let mut still = description.clone();
    still.sensor.to_world_keyframes.clear();
    still
        .shapes
        .retain(|shape| shape.to_world_keyframes.is_empty());
    let converted = ch04_depth_of_field::scene_file::convert(&still)?;
    let mut notes = converted.notes;

    let mut moving = Vec::new();
    for (index, shape) in description.shapes.iter().enumerate() {
        if shape.to_world_keyframes.is_empty() {
            continue;
        }
        let name = format!("shape {} ({})", index + 1, shape.position);
        let motion = AnimatedTransform::new(&shape.to_world_keyframes)
            .map_err(|e| format!("{name}: {e}"))?;
        let at_rest = ShapeDescription {
            to_world: Mat4::IDENTITY,
            to_world_keyframes: Vec::new(),
            ..shape.clone()
        };
        // The material: chapter 01's conversion of this shape alone, which also refuses what
        // that chapter refuses (an area light, a rough material) with its reason.
        let mut alone = still.clone();
        alone.shapes = vec![at_rest.clone()];
        let material = ch01_whitted::scene_file::convert(&alone)
            .map_err(|e| e.replace(&format!("shape 1 ({})", shape.position), &name))?
            .scene
            .materials[0];
        for object_shape in world_shapes(&at_rest).map_err(|e| format!("{name}: {e}"))? {
            moving.push((MovingShape::new(object_shape, motion.clone()), material));
        }
    }
    let camera_motion = if sensor.to_world_keyframes.is_empty() {
        None
    } else {
        Some(
            AnimatedTransform::new(&sensor.to_world_keyframes)
                .map_err(|e| format!("the sensor: {e}"))?,
        )
    };
    let world = MotionScene::new(converted.scene, moving, camera_motion, shutter);
    if world.moves() && shutter.is_instant() {
        notes.push(format!(
            "the scene moves, but the sensor's shutter opens and closes at time {}: the image shows that instant, without blur (set shutter_open and shutter_close, or --shutter-open and --shutter-close)",
            shutter.open
        ));
    }
    Ok(ConvertedScene {
        world,
        lens: converted.lens,
        filter: converted.filter,
        spp: converted.spp,
        sampler: converted.sampler,
        notes,
    })
}
// ANCHOR_END: convert
