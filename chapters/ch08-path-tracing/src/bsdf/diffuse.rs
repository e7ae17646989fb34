//! Matte: `f = ρ / π`, sampled by the cosine-weighted hemisphere, so `f cos θ / pdf = ρ`.

use super::{BsdfSample, facing_normal, to_world};
use ch02_monte_carlo::warps::{cosine_hemisphere_pdf, sample_cosine_hemisphere};
use common::geometry::SurfaceHit;
use glam::{Vec2, Vec3};
use std::f32::consts::FRAC_1_PI;

/// A cosine-distributed direction on `wo`'s side; weight `albedo`.
pub fn sample(
    hit: &SurfaceHit,
    wo: Vec3,
    albedo: Vec3,
    two_sided: bool,
    u: Vec2,
) -> Option<BsdfSample> {
    let normal = facing_normal(hit, wo, two_sided)?;
    let local = sample_cosine_hemisphere(u);
    let pdf = cosine_hemisphere_pdf(local.z);
    (pdf > 0.0).then(|| BsdfSample {
        wi: to_world(normal, local),
        weight: albedo,
        pdf,
        eta_scale: 1.0,
    })
}

/// `ρ / π · cos θ_i` for `wi` on `wo`'s side, else 0.
pub fn eval(hit: &SurfaceHit, wo: Vec3, wi: Vec3, albedo: Vec3, two_sided: bool) -> Vec3 {
    match facing_normal(hit, wo, two_sided) {
        Some(normal) => albedo * (FRAC_1_PI * wi.dot(normal).max(0.0)),
        None => Vec3::ZERO,
    }
}

/// `cos θ_i / π` for `wi` on `wo`'s side, else 0.
pub fn pdf(hit: &SurfaceHit, wo: Vec3, wi: Vec3, two_sided: bool) -> f32 {
    match facing_normal(hit, wo, two_sided) {
        Some(normal) => cosine_hemisphere_pdf(wi.dot(normal).max(0.0)),
        None => 0.0,
    }
}
