//! A file's rough materials at a hit, rendered by the [`microfacet`](crate::microfacet)
//! module as Mitsuba 3 renders them: `roughconductor`, `roughplastic` and `roughdielectric`.
//!
//! The module works in a local frame (`z` the normal); this file puts that frame at the hit,
//! turns `wo` and `wi` into it and the sampled direction back out. The frame's normal is the
//! shading normal, on the side Mitsuba puts it:
//!
//! - a metal or a plastic is one-sided unless `twosided` (Mitsuba's `twosided` wrapper): seen
//!   from behind it is black, or, two-sided, its normal turns towards `wo`;
//! - glass is two-sided by nature: the normal stays on the outside and the sign of `wo.z`
//!   says which medium the path is in.
//!
//! Every roughness here is isotropic, so the tangent's direction around the normal does not
//! change the result: any orthonormal pair will do (the scene loader refuses `alpha_u` and
//! `alpha_v`, which would need the shape's `dp/du`).
//!
//! Random numbers: every sample draws one number that picks a lobe (reflection or refraction,
//! coat or base; the metal has one lobe and ignores it) and then two for the facet or the
//! direction, as Mitsuba's `sample(ctx, si, sample1, sample2)`, so the count is the same for
//! all three.

use super::{BsdfSample, facing_normal};
use crate::microfacet::{
    LocalBsdf, NormalDistribution, RoughConductor, RoughDielectric, RoughPlastic,
    RoughPlasticParameters,
};
use common::geometry::SurfaceHit;
use common::scene::{Conductor, Microfacet, Plastic, RoughGlass};
use glam::{Vec2, Vec3};

/// An orthonormal frame at a hit: `normal` is the local `z`.
#[derive(Clone, Copy, Debug)]
pub struct LocalFrame {
    tangent: Vec3,
    bitangent: Vec3,
    normal: Vec3,
}

impl LocalFrame {
    /// A frame around the unit `normal`, its tangent any direction across it (enough for
    /// isotropic roughness).
    pub fn around(normal: Vec3) -> Self {
        let (tangent, bitangent) = normal.any_orthonormal_pair();
        Self {
            tangent,
            bitangent,
            normal,
        }
    }

    /// `w` in the frame's coordinates.
    pub fn to_local(&self, w: Vec3) -> Vec3 {
        Vec3::new(
            w.dot(self.tangent),
            w.dot(self.bitangent),
            w.dot(self.normal),
        )
    }

    /// Local coordinates back in world space.
    pub fn to_world(&self, v: Vec3) -> Vec3 {
        v.x * self.tangent + v.y * self.bitangent + v.z * self.normal
    }
}

/// The facets' distribution of a file's roughness.
fn distribution(roughness: Microfacet) -> NormalDistribution {
    NormalDistribution::isotropic(roughness.distribution, roughness.alpha)
}

/// A microfacet material placed at a hit: the BSDF and its frame, or nothing to scatter
/// (`None`: the back of a one-sided surface).
pub struct Placed<B> {
    bsdf: B,
    frame: LocalFrame,
}

impl<B: LocalBsdf> Placed<B> {
    /// Draws the lobe choice, then the two direction numbers, and samples.
    pub fn sample(&self, wo: Vec3, choice: f32, u: Vec2) -> Option<BsdfSample> {
        let local = self.bsdf.sample(self.frame.to_local(wo), choice, u)?;
        Some(BsdfSample {
            wi: self.frame.to_world(local.wi).normalize(),
            ..local
        })
    }

    /// `f(wo, wi) cos θ_i`.
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        self.bsdf
            .eval(self.frame.to_local(wo), self.frame.to_local(wi))
    }

    /// The density of [`sample`](Self::sample) at `wi`.
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        self.bsdf
            .pdf(self.frame.to_local(wo), self.frame.to_local(wi))
    }
}

/// Mitsuba's `roughconductor` at `hit`, seen from `wo`.
pub fn conductor(
    hit: &SurfaceHit,
    wo: Vec3,
    metal: &Conductor,
    roughness: Microfacet,
) -> Option<Placed<RoughConductor>> {
    let normal = facing_normal(hit, wo, metal.two_sided)?;
    Some(Placed {
        bsdf: RoughConductor {
            distribution: distribution(roughness),
            eta: metal.eta,
            k: metal.k,
            specular_reflectance: metal.specular_reflectance,
        },
        frame: LocalFrame::around(normal),
    })
}

/// Mitsuba's `roughplastic` at `hit`, seen from `wo`. Its coating's table is tabulated once
/// per roughness and index and looked up here ([`crate::microfacet::coating::Coating::shared`]).
pub fn plastic(
    hit: &SurfaceHit,
    wo: Vec3,
    plastic: &Plastic,
    roughness: Microfacet,
) -> Option<Placed<RoughPlastic>> {
    let normal = facing_normal(hit, wo, plastic.two_sided)?;
    let bsdf = RoughPlastic::new(RoughPlasticParameters {
        kind: roughness.distribution,
        alpha: roughness.alpha,
        eta: plastic.int_ior / plastic.ext_ior,
        diffuse_reflectance: plastic.diffuse_reflectance,
        specular_reflectance: plastic.specular_reflectance,
        nonlinear: plastic.nonlinear,
    });
    Some(Placed {
        bsdf,
        frame: LocalFrame::around(normal),
    })
}

/// Mitsuba's `roughdielectric` at `hit`: the normal on the outside, whichever side `wo` is.
pub fn dielectric(
    hit: &SurfaceHit,
    glass: &RoughGlass,
    roughness: Microfacet,
) -> Placed<RoughDielectric> {
    Placed {
        bsdf: RoughDielectric::new(distribution(roughness), glass.int_ior, glass.ext_ior),
        frame: LocalFrame::around(hit.shading_n),
    }
}

#[cfg(test)]
mod tests {
    use super::LocalFrame;
    use glam::Vec3;

    #[test]
    fn the_frame_round_trips_and_puts_the_normal_on_z() {
        let normal = Vec3::new(0.3, -0.5, 0.8).normalize();
        let frame = LocalFrame::around(normal);
        assert!((frame.to_local(normal) - Vec3::Z).length() < 1e-6);
        let w = Vec3::new(-0.2, 0.9, 0.1).normalize();
        assert!((frame.to_world(frame.to_local(w)) - w).length() < 1e-6);
    }
}
