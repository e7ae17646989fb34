//! Chapter 06's fuzzy mirror as a BSDF: its `f cos θ_i` follows the lobe around the mirror
//! direction, which it samples (chapter 06's glossy exercise works out the weight). Directions
//! the lobe puts below the surface are dropped (chapter 06's `BelowSurface::Drop`): they carry no light, and `eval`
//! and `pdf` are 0 there too, so the light sample and the BSDF sample describe the same
//! material.

use super::{BsdfSample, facing_normal};
use ch01_whitted::optics::reflect;
use ch06_fuzzy_reflections::FuzzMethod;
use common::geometry::SurfaceHit;
use common::scene::Glossy;
use glam::{Vec2, Vec3};

/// A direction of the lobe around the mirror direction; the mirror direction itself for an
/// infinite exponent.
pub fn sample(
    hit: &SurfaceHit,
    wo: Vec3,
    glossy: &Glossy,
    fuzz: FuzzMethod,
    u: Vec2,
) -> Option<BsdfSample> {
    let normal = facing_normal(hit, wo, glossy.two_sided)?;
    let center = reflect(-wo, normal);
    if !glossy.exponent.is_finite() {
        return Some(BsdfSample {
            wi: center,
            weight: glossy.reflectance,
            pdf: f32::INFINITY,
            eta_scale: 1.0,
        });
    }
    let wi = fuzz.sample(center, glossy.exponent, u);
    let pdf = fuzz.pdf(wi.dot(center), glossy.exponent);
    (wi.dot(normal) > 0.0 && pdf > 0.0).then_some(BsdfSample {
        wi,
        weight: glossy.reflectance,
        pdf,
        eta_scale: 1.0,
    })
}

/// `f cos θ_i` at `wi` above the surface, else 0.
pub fn eval(hit: &SurfaceHit, wo: Vec3, wi: Vec3, glossy: &Glossy, fuzz: FuzzMethod) -> Vec3 {
    glossy.reflectance * pdf(hit, wo, wi, glossy, fuzz)
}

/// The lobe's density at `wi` above the surface, else 0 (and 0 for the mirror's delta).
pub fn pdf(hit: &SurfaceHit, wo: Vec3, wi: Vec3, glossy: &Glossy, fuzz: FuzzMethod) -> f32 {
    let Some(normal) = facing_normal(hit, wo, glossy.two_sided) else {
        return 0.0;
    };
    if wi.dot(normal) <= 0.0 {
        return 0.0;
    }
    fuzz.pdf(wi.dot(reflect(-wo, normal)), glossy.exponent)
}
