//! The lens a scene file asks for: the `thinlens` sensor's aperture and focus.
//!
//! Chapter 01 refuses a `thinlens` sensor with an aperture, since its pinhole cannot render
//! it. This chapter reads the lens from the scene's camera and puts it in front of the
//! pinhole: a disc aperture of the file's radius, focused on the plane at the file's
//! distance, sampled with the concentric warp as Mitsuba does.

use crate::lens::Lens;
use common::scene::{Camera, CameraModel};

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
