//! Smooth glass: reflection with probability `F` (the Fresnel reflectance), else refraction,
//! as chapter 06's [`choose_fresnel`] and Mitsuba's `dielectric`. The chance equals the
//! share, so the weight is 1, times `(eta_i / eta_t)²` for radiance carried through the
//! refraction.

use super::BsdfSample;
use ch01_whitted::optics::{fresnel_dielectric, reflect, refract};
use ch06_fuzzy_reflections::glass_choice::choose_fresnel;
use common::geometry::SurfaceHit;
use glam::Vec3;

/// The normal on `wo`'s side and the relative index `eta = eta_i / eta_t` of a ray arriving
/// from that side.
pub fn side(hit: &SurfaceHit, wo: Vec3, int_ior: f32, ext_ior: f32) -> (Vec3, f32) {
    if wo.dot(hit.n) > 0.0 {
        (hit.n, ext_ior / int_ior)
    } else {
        (-hit.n, int_ior / ext_ior)
    }
}

/// The reflected or the refracted direction, chosen by `F` with the number `u`.
pub fn sample(
    hit: &SurfaceHit,
    wo: Vec3,
    int_ior: f32,
    ext_ior: f32,
    u: f32,
) -> Option<BsdfSample> {
    let (normal, eta) = side(hit, wo, int_ior, ext_ior);
    let reflectance = fresnel_dielectric(wo.dot(normal), eta);
    if choose_fresnel(u, reflectance).reflect {
        return Some(BsdfSample {
            wi: reflect(-wo, normal),
            weight: Vec3::ONE,
            pdf: f32::INFINITY,
            eta_scale: 1.0,
        });
    }
    let wi = refract(-wo, normal, eta)?;
    let eta_scale = eta * eta;
    Some(BsdfSample {
        wi,
        weight: Vec3::splat(eta_scale),
        pdf: f32::INFINITY,
        eta_scale,
    })
}
