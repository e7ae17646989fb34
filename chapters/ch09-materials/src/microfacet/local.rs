//! The three things a path tracer asks of a BSDF, in the local frame, for every microfacet
//! material alike: so that one test, one figure or one caller serves all three.

use super::{RoughConductor, RoughDielectric, RoughPlastic};
use ch08_path_tracing::BsdfSample;
use glam::{Vec2, Vec3};

/// A BSDF in the local frame (`z` the normal); `wo` points towards where the path came from,
/// `wi` towards the light. `Sync`: a quadrature evaluates it on several threads at once.
pub trait LocalBsdf: Sync {
    /// `f(wo, wi) cos θ_i`.
    fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3;
    /// The density per unit solid angle with which [`sample`](Self::sample) picks `wi`.
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32;
    /// A direction drawn with `choice` (which lobe; ignored by a single lobe) and `u`
    /// (where in it), its weight `eval / pdf`; `None` when the path ends.
    fn sample(&self, wo: Vec3, choice: f32, u: Vec2) -> Option<BsdfSample>;
}

impl LocalBsdf for RoughConductor {
    fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        RoughConductor::eval(self, wo, wi)
    }
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        RoughConductor::pdf(self, wo, wi)
    }
    fn sample(&self, wo: Vec3, _choice: f32, u: Vec2) -> Option<BsdfSample> {
        RoughConductor::sample(self, wo, u)
    }
}

impl LocalBsdf for RoughDielectric {
    fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        RoughDielectric::eval(self, wo, wi)
    }
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        RoughDielectric::pdf(self, wo, wi)
    }
    fn sample(&self, wo: Vec3, choice: f32, u: Vec2) -> Option<BsdfSample> {
        RoughDielectric::sample(self, wo, choice, u)
    }
}

impl LocalBsdf for RoughPlastic<'_> {
    fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        RoughPlastic::eval(self, wo, wi)
    }
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        RoughPlastic::pdf(self, wo, wi)
    }
    fn sample(&self, wo: Vec3, choice: f32, u: Vec2) -> Option<BsdfSample> {
        RoughPlastic::sample(self, wo, choice, u)
    }
}
