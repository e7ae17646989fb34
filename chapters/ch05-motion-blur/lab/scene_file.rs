//! Scenes from Mitsuba 3 XML files, with the workbook's `<animation>` extension.
//!
//! Mitsuba 3 has no moving objects, so motion is written as Mitsuba 0.6 wrote it: an
//! `<animation name="to_world">` of `<transform time="...">` keyframes in place of a shape's
//! (or the sensor's) `<transform name="to_world">`; the sensor's `shutter_open` and
//! `shutter_close` give the interval. The loader keeps each moving shape in its own space with
//! its keyframes; this chapter makes the motion ready to follow, and says when a scene that
//! moves is seen through a shutter that opens and closes at one instant.

use crate::world::MotionScene;
use ch03_anti_aliasing::PixelSampler;
pub use ch04_depth_of_field::lab::scene_file::CameraSide;
use common::render::RenderSettings;
use common::scene::Scene;
use std::path::Path;
use workbench::capabilities::Capabilities;
use workbench::cli::{CliError, print_note};

// ANCHOR: motion_of
/// The motion of a scene file's `scene` made ready for tracing (or why it cannot be), with a
/// note when the scene moves but its shutter shows only one instant.
pub fn motion_of(scene: Scene) -> Result<(MotionScene, Option<String>), String> {
    let world = MotionScene::new(scene)?;
    let shutter = world.shutter;
    let note = (world.moves() && shutter.is_instant()).then(|| {
        format!(
            "the scene moves, but the sensor's shutter opens and closes at time {}: the image shows that instant, without blur (set shutter_open and shutter_close, or --shutter-open and --shutter-close)",
            shutter.open
        )
    });
    Ok((world, note))
}
// ANCHOR_END: motion_of

/// A scene file as a chapter checks it against Mitsuba 3 (chapter 04's
/// [`for_agreement`](ch04_depth_of_field::lab::scene_file::for_agreement)), its motion made ready;
/// errors name the file.
pub fn for_agreement(
    path: &Path,
    capabilities: &Capabilities,
) -> Result<(MotionScene, CameraSide, RenderSettings, PixelSampler), String> {
    let (scene, side, settings, sampler) =
        ch04_depth_of_field::lab::scene_file::for_agreement(path, capabilities)?;
    let (world, _) = motion_of(scene).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok((world, side, settings, sampler))
}

/// [`motion_of`] for a chapter's `render` of the scene `name` (a file's path, or a built-in
/// scene's name, which a refusal starts with): the note, if any, printed.
pub fn motion_for_render(scene: Scene, name: &str) -> Result<MotionScene, CliError> {
    let (world, note) = motion_of(scene).map_err(|message| CliError::Unrenderable {
        file: name.into(),
        message,
    })?;
    if let Some(note) = note {
        print_note(&note);
    }
    Ok(world)
}
