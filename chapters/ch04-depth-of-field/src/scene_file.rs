//! Scenes from Mitsuba 3 XML files, now with the `thinlens` sensor's aperture.
//!
//! Chapter 01 refuses a `thinlens` sensor with an aperture, since its pinhole cannot render
//! it. This chapter takes the lens from the file itself and lets chapter 03 convert the rest:
//! a copy of the description with a plain `perspective` sensor (the same position, field of
//! view and film) goes through chapter 03's conversion, and the lens is put back in front.

use crate::lens::Lens;
use ch01_whitted::scene::Scene;
use ch03_anti_aliasing::ReconstructionFilter;
use common::scene::{CameraModel, SceneDescription};

/// A scene ready for the thin-lens camera, and what the conversion had to say about it.
pub struct ConvertedScene {
    /// The scene, with the pinhole part of its camera.
    pub scene: Scene,
    /// The lens of the file's sensor; [`Lens::PINHOLE`] for a `perspective` sensor.
    pub lens: Lens,
    /// The film's reconstruction filter.
    pub filter: ReconstructionFilter,
    /// Samples per pixel the file asks for.
    pub spp: u64,
    /// The pixel sampler closest to the file's `<sampler>` type.
    pub sampler: ch03_anti_aliasing::PixelSamplerKind,
    /// Light the method leaves out, and settings it ignores.
    pub notes: Vec<String>,
}

// ANCHOR: convert
/// Converts a description for the thin-lens camera, or says why it cannot be rendered.
pub fn convert(description: &SceneDescription) -> Result<ConvertedScene, String> {
    let lens = match description.sensor.model {
        CameraModel::Perspective => Lens::PINHOLE,
        CameraModel::ThinLens {
            aperture_radius,
            focus_distance,
        } => Lens::new(aperture_radius, focus_distance)
            .map_err(|e| format!("the thinlens sensor: {e}"))?,
    };
    let mut pinhole = description.clone();
    pinhole.sensor.model = CameraModel::Perspective;
    let converted = ch03_anti_aliasing::scene_file::convert(&pinhole)?;
    Ok(ConvertedScene {
        scene: converted.scene,
        lens,
        filter: converted.filter,
        spp: converted.spp,
        sampler: converted.sampler,
        notes: converted.notes,
    })
}
// ANCHOR_END: convert
