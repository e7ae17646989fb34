//! The perfect mirror: one direction, a delta. Nothing to evaluate for a light sample.

use super::BsdfSample;
use ch01_whitted::optics::reflect;
use common::geometry::SurfaceHit;
use glam::Vec3;

/// The mirror direction about the shading normal (Mitsuba's shading frame: a smooth mesh
/// mirrors smoothly) with weight `reflectance`, on the front side only (Mitsuba's
/// `conductor` is one-sided).
pub fn sample(hit: &SurfaceHit, wo: Vec3, reflectance: Vec3) -> Option<BsdfSample> {
    (wo.dot(hit.shading_n) > 0.0).then(|| BsdfSample {
        wi: reflect(-wo, hit.shading_n),
        weight: reflectance,
        pdf: f32::INFINITY,
        eta_scale: 1.0,
    })
}
