//! The lens a scene file asks for: the `thinlens` sensor's aperture and focus.
//!
//! Chapter 01 refuses a `thinlens` sensor with an aperture, since its pinhole cannot render
//! it. This chapter reads the lens from the scene's camera and puts it in front of the
//! pinhole: a disc aperture of the file's radius, focused on the plane at the file's
//! distance, sampled with the concentric warp as Mitsuba does.

use crate::lens::Lens;
use ch03_anti_aliasing::PixelSampler;
use ch03_anti_aliasing::lab::scene_file::FilmSide;
use common::render::RenderSettings;
use common::scene::{Camera, CameraModel, Scene};
use std::path::Path;
use workbench::capabilities::Capabilities;
use workbench::cli::CliError;
use workbench::driver::FromSceneFile;

// ANCHOR: lens_of
/// The lens of the scene's camera: [`Lens::PINHOLE`] for a pinhole, else the thin lens of its
/// aperture radius and focus distance (or why they make no lens).
pub fn lens_of(camera: &Camera) -> Result<Lens, String> {
    match camera.model {
        CameraModel::Pinhole => Ok(Lens::PINHOLE),
        CameraModel::ThinLens {
            aperture_radius,
            focus_distance,
        } => Lens::new(aperture_radius, focus_distance)
            .map_err(|e| format!("the thinlens sensor: {e}")),
    }
}
// ANCHOR_END: lens_of

/// What chapters 04 on read from a scene file for the camera's side of a render: the lens,
/// and chapter 03's film side (the film's filter and the pixel sampler).
#[derive(Clone, Debug)]
pub struct CameraSide {
    /// The lens of the file's sensor.
    pub lens: Lens,
    /// The film's filter and the pixel sampler.
    pub film: FilmSide,
}

/// A scene file for a chapter's `render`: read with the `-D` overrides and checked against
/// the chapter's `capabilities`, its film side and its lens read; every note printed.
impl FromSceneFile for CameraSide {
    fn read(
        path: &Path,
        defines: &[(String, String)],
        capabilities: &Capabilities,
    ) -> Result<(Scene, CameraSide), CliError> {
        let (scene, film) = FilmSide::read(path, defines, capabilities)?;
        let lens = lens_of(&scene.camera).map_err(|message| CliError::Unrenderable {
            file: path.to_path_buf(),
            message,
        })?;
        Ok((scene, CameraSide { lens, film }))
    }
}

/// A scene file as a chapter checks it against Mitsuba 3 (chapter 03's
/// [`for_agreement`](ch03_anti_aliasing::lab::scene_file::for_agreement)), with its lens; errors
/// name the file.
pub fn for_agreement(
    path: &Path,
    capabilities: &Capabilities,
) -> Result<(Scene, CameraSide, RenderSettings, PixelSampler), String> {
    let (scene, film, settings, sampler) =
        ch03_anti_aliasing::lab::scene_file::for_agreement(path, capabilities)?;
    let lens = lens_of(&scene.camera).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok((scene, CameraSide { lens, film }, settings, sampler))
}
