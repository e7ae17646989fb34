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
use ch03_anti_aliasing::cli::AntiAliasingArgs;
use common::cli::{CliError, print_note, read_scene_file};
use common::metrics::AGREEMENT_SPP;
use common::render::{Budget, RenderSettings};
use common::scene::{Capabilities, Scene};
use common::scene_file::load_scene_file;
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
/// lens, the film's filter, the pixel sampler closest to the file's and its sample count.
/// Later chapters render the same camera rays, so they read the same.
#[derive(Clone, Debug)]
pub struct CameraSide {
    /// The lens of the file's sensor (chapter 04).
    pub lens: ch04_depth_of_field::Lens,
    /// The film's reconstruction filter (chapter 03).
    pub filter: ch03_anti_aliasing::ReconstructionFilter,
    /// The pixel sampler closest to the file's `<sampler>` type (chapter 03).
    pub sampler: ch03_anti_aliasing::PixelSamplerKind,
    /// Samples per pixel the file asks for.
    pub spp: u64,
    /// What the choices leave out or change, to print.
    pub notes: Vec<String>,
}

/// The camera side of `scene`, or why a part of it makes no sense.
pub fn camera_side(scene: &Scene) -> Result<CameraSide, String> {
    let lens = ch04_depth_of_field::scene_file::lens_of(&scene.camera)?;
    let filter = ch03_anti_aliasing::scene_file::filter_of(scene.film.filter)?;
    let (sampler, note) = ch03_anti_aliasing::scene_file::sampler_of(&scene.sampler.type_name);
    Ok(CameraSide {
        lens,
        filter,
        sampler,
        spp: u64::from(scene.sampler.sample_count.max(1)),
        notes: note.into_iter().collect(),
    })
}

/// A scene file for a chapter's `render`: loaded with the `-D` overrides, checked against the
/// chapter's `capabilities`, its camera side read; every note printed.
pub fn read_with_camera_side(
    path: &Path,
    defines: &[(String, String)],
    capabilities: &Capabilities,
) -> Result<(Scene, CameraSide), CliError> {
    let scene = read_scene_file(path, defines, capabilities)?;
    let side = camera_side(&scene).map_err(|message| CliError::Unrenderable {
        file: path.to_path_buf(),
        message,
    })?;
    for note in &side.notes {
        print_note(note);
    }
    Ok((scene, side))
}

/// A scene file as a chapter checks it against Mitsuba 3: loaded, checked against the
/// chapter's `capabilities`, its motion made ready, and the settings and pixel sampler of a
/// render at [`AGREEMENT_SPP`] samples per pixel at the file's size; errors name the file.
pub fn for_agreement(
    path: &Path,
    capabilities: &Capabilities,
) -> Result<(MotionScene, CameraSide, RenderSettings, PixelSampler), String> {
    let in_file = |e: String| format!("{}: {e}", path.display());
    let loaded = load_scene_file(path, &[]).map_err(|e| e.to_string())?;
    capabilities.check(&loaded.scene).map_err(in_file)?;
    let side = camera_side(&loaded.scene).map_err(in_file)?;
    let (world, _) = motion_of(loaded.scene).map_err(in_file)?;
    let film = world.scene.film;
    let settings = RenderSettings::new(film.width, film.height, AGREEMENT_SPP);
    let sampler = AntiAliasingArgs::default()
        .pixel_sampler(side.sampler, &Budget::Samples(AGREEMENT_SPP), 0)
        .map_err(|e| e.to_string())?;
    Ok((world, side, settings, sampler))
}

/// [`motion_of`] for a chapter's `render`: the note, if any, printed.
pub fn motion_for_render(scene: Scene) -> Result<MotionScene, String> {
    let (world, note) = motion_of(scene)?;
    if let Some(note) = note {
        print_note(&note);
    }
    Ok(world)
}
