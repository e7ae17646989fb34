//! A cut-out (Mitsuba 3's `mask`): where the surface has opacity `α`, a ray meets the nested
//! material with probability `α` and passes straight on otherwise.
//!
//! Passing on is a delta lobe (`wi = -wo`, weight 1, infinite density) that the choice picks
//! with probability `1 - α`, so light found beyond it is weighted 1, as after a mirror. The
//! nested material's lobes keep their weight `f cos θ / pdf` (its share `α` and the
//! probability `α` of choosing it cancel), while `eval` and `pdf` are the nested ones times
//! `α`: what a light sample at the surface sees, and the density of the whole mask.
//!
//! Two choices follow Mitsuba 3's `path` integrator. Passing through the surface counts as a
//! segment towards `max_depth` and the roulette. And a shadow ray is stopped by a masked
//! surface wherever it crosses it, however transparent the surface is there: light reaches a
//! point behind a cut-out only by paths that pass through it. (Mitsuba's `mask` reports the
//! nested density without the factor `α` when it samples the nested material; its light
//! samples use the density with it, as here.)
//!
//! One number is drawn for the choice, before the nested material's own.

use super::{Bsdf, BsdfSample};
use common::sampler::Sampler;
use common::scene::Opacity;
use glam::Vec3;

/// The opacity of a mask whose texture [`Scene::material_at`](common::scene::Scene) has read:
/// in [0, 1]. A texture left unread (a material taken from the scene as it is) counts as
/// opaque: the nested material alone.
pub fn opacity(opacity: Opacity) -> f32 {
    match opacity {
        Opacity::Uniform(alpha) if alpha >= 0.0 => alpha.min(1.0),
        Opacity::Uniform(_) => 0.0, // negative or NaN: no surface
        Opacity::Texture(_) => 1.0,
    }
}

/// Passes on with probability `1 - alpha`, else samples `nested`.
pub fn sample<S: Sampler>(
    alpha: f32,
    nested: &Bsdf,
    wo: Vec3,
    sampler: &mut S,
) -> Option<BsdfSample> {
    if sampler.get_1d() >= alpha {
        return Some(BsdfSample {
            wi: -wo,
            weight: Vec3::ONE,
            pdf: f32::INFINITY,
            eta_scale: 1.0,
        });
    }
    let sample = nested.sample(wo, sampler)?;
    Some(BsdfSample {
        pdf: alpha * sample.pdf,
        ..sample
    })
}

/// `α f cos θ` of the nested material.
pub fn eval(alpha: f32, nested: &Bsdf, wo: Vec3, wi: Vec3) -> Vec3 {
    alpha * nested.eval(wo, wi)
}

/// `α pdf` of the nested material.
pub fn pdf(alpha: f32, nested: &Bsdf, wo: Vec3, wi: Vec3) -> f32 {
    alpha * nested.pdf(wo, wi)
}
