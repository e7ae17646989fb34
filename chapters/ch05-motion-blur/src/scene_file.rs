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
use ch03_anti_aliasing::scene_file::{FilmSide, film_side, read_with_film_side};
use common::cli::{CliError, print_note};
use common::render::RenderSettings;
use common::scene::{Capabilities, Scene};
use std::path::Path;

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

/// What chapters 03 to 05 read from a scene file for the camera's side of a render: the
/// lens (chapter 04), and the film's filter and the pixel sampler (chapter 03). Later chapters
/// render the same camera rays, so they read the same.
#[derive(Clone, Debug)]
pub struct CameraSide {
    /// The lens of the file's sensor.
    pub lens: ch04_depth_of_field::Lens,
    /// The film's filter, the pixel sampler and its sample count.
    pub film: FilmSide,
}

/// The camera side of `scene`, or why a part of it makes no sense.
pub fn camera_side(scene: &Scene) -> Result<CameraSide, String> {
    let lens = ch04_depth_of_field::scene_file::lens_of(&scene.camera)?;
    let film = film_side(scene)?;
    Ok(CameraSide { lens, film })
}

/// A scene file for a chapter's `render`: loaded with the `-D` overrides, checked against the
/// chapter's `capabilities`, its camera side read; every note printed.
pub fn read_with_camera_side(
    path: &Path,
    defines: &[(String, String)],
    capabilities: &Capabilities,
) -> Result<(Scene, CameraSide), CliError> {
    let (scene, film) = read_with_film_side(path, defines, capabilities)?;
    let lens = ch04_depth_of_field::scene_file::lens_of(&scene.camera).map_err(|message| {
        CliError::Unrenderable {
            file: path.to_path_buf(),
            message,
        }
    })?;
    Ok((scene, CameraSide { lens, film }))
}

/// A scene file as a chapter checks it against Mitsuba 3 (chapter 03's
/// [`for_agreement`](ch03_anti_aliasing::scene_file::for_agreement)), with its lens, and its
/// motion made ready; errors name the file.
pub fn for_agreement(
    path: &Path,
    capabilities: &Capabilities,
) -> Result<(MotionScene, CameraSide, RenderSettings, PixelSampler), String> {
    let in_file = |e: String| format!("{}: {e}", path.display());
    let (scene, film, settings, sampler) =
        ch03_anti_aliasing::scene_file::for_agreement(path, capabilities)?;
    let lens = ch04_depth_of_field::scene_file::lens_of(&scene.camera).map_err(in_file)?;
    let (world, _) = motion_of(scene).map_err(in_file)?;
    Ok((world, CameraSide { lens, film }, settings, sampler))
}

/// [`motion_of`] for a chapter's `render`: the note, if any, printed.
pub fn motion_for_render(scene: Scene) -> Result<MotionScene, String> {
    let (world, note) = motion_of(scene)?;
    if let Some(note) = note {
        print_note(&note);
    }
    Ok(world)
}
