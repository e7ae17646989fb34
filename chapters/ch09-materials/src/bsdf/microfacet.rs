//! A file's rough materials at a hit, rendered by the [`microfacet`](crate::microfacet)
//! module as Mitsuba 3 renders them: `roughconductor`, `roughplastic` and `roughdielectric`.
//!
//! The module works in a local frame (`z` the normal); this file puts that frame at the hit,
//! turns `wo` and `wi` into it and the sampled direction back out. The frame's normal is the
//! shading normal, on the side Mitsuba puts it:
//!
//! - a metal or a plastic is one-sided unless `twosided`: seen from behind it is black, or,
//!   two-sided, the frame's `z` turns round and its tangents stay (Mitsuba's `twosided`
//!   wrapper negates the local `z` of both directions);
//! - glass is two-sided by nature: the normal stays on the outside and the sign of `wo.z`
//!   says which medium the path is in.
//!
//! An anisotropic roughness (`alpha_u` along the tangent, `alpha_v` across) needs the
//! tangent. As in Mitsuba, it is the shape's `dp/du` made perpendicular to the shading normal
//! ([`LocalFrame::along`]): a sphere is brushed along its parallels, a mesh along its
//! texture's `u`. `Scene::material_at` puts `dp/du` in the roughness ([`Microfacet::dp_du`])
//! only where the widths differ; a round roughness looks the same about any tangent, and its
//! frame is the one Mitsuba's `coordinate_system(n)` builds from the normal alone
//! ([`LocalFrame::around`]).
//!
//! Random numbers: every sample draws one number that picks a lobe (reflection or refraction,
//! coat or base; the metal has one lobe and ignores it) and then two for the facet or the
//! direction, as Mitsuba's `sample(ctx, si, sample1, sample2)`, so the count is the same for
//! all three.

use crate::microfacet::coating::Coatings;
use crate::microfacet::{
    LocalBsdf, NormalDistribution, RoughConductor, RoughDielectric, RoughPlastic,
    RoughPlasticParameters,
};
use ch08_path_tracing::bsdf::{BsdfSample, facing_normal};
use common::geometry::SurfaceHit;
use common::scene::{Conductor, Microfacet, Plastic, RoughGlass, TintedGlass};
use glam::{Vec2, Vec3};

/// An orthonormal frame at a hit: `normal` is the local `z`.
#[derive(Clone, Copy, Debug)]
pub struct LocalFrame {
    tangent: Vec3,
    bitangent: Vec3,
    normal: Vec3,
}

impl LocalFrame {
    /// A frame around the unit `normal` as Mitsuba's `coordinate_system(n)` builds it (Duff
    /// et al. 2017, "Building an orthonormal basis, revisited", which glam's
    /// `any_orthonormal_pair` implements with the same signs).
    pub fn around(normal: Vec3) -> Self {
        let (tangent, bitangent) = normal.any_orthonormal_pair();
        Self {
            tangent,
            bitangent,
            normal,
        }
    }

    /// A frame around the unit `normal` whose tangent is `dp_du` made perpendicular to it, as
    /// Mitsuba's shading frame (`s` the normalised remainder of `dp/du`, `t = n × s`); the frame
    /// [`around`](Self::around) the normal where nothing of `dp_du` remains (it is zero, or
    /// along the normal, where what is left is rounding error that points anywhere).
    pub fn along(normal: Vec3, dp_du: Vec3) -> Self {
        let remainder = dp_du - normal * normal.dot(dp_du);
        let enough = remainder.length_squared() > 1e-10 * dp_du.length_squared();
        if !enough {
            return Self::around(normal); // also for a NaN
        }
        let tangent = remainder.normalize();
        Self {
            tangent,
            bitangent: normal.cross(tangent),
            normal,
        }
    }

    /// The frame at a one-sided or `twosided` surface seen from `wo`: around the shading
    /// normal with its tangent along `dp_du`, its `z` turned towards `wo` when `two_sided`
    /// and `wo` is behind (the tangents unchanged, as Mitsuba's `twosided` does); `None` from
    /// behind a one-sided surface.
    pub fn facing(hit: &SurfaceHit, wo: Vec3, two_sided: bool, dp_du: Vec3) -> Option<Self> {
        let normal = facing_normal(hit, wo, two_sided)?;
        let frame = Self::along(hit.shading_n, dp_du);
        Some(Self { normal, ..frame })
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

/// The facets' distribution of a file's roughness, `alpha_u` along the frame's tangent.
fn distribution(roughness: Microfacet) -> NormalDistribution {
    NormalDistribution::new(roughness.distribution, roughness.alpha_u, roughness.alpha_v)
}

/// A microfacet material placed at a hit: the BSDF and its frame.
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
pub fn rough_conductor(
    hit: &SurfaceHit,
    wo: Vec3,
    metal: &Conductor,
    roughness: Microfacet,
) -> Option<Placed<RoughConductor>> {
    let frame = LocalFrame::facing(hit, wo, metal.two_sided, roughness.dp_du)?;
    Some(Placed {
        bsdf: RoughConductor {
            distribution: distribution(roughness),
            eta: metal.eta,
            k: metal.k,
            specular_reflectance: metal.specular_reflectance,
        },
        frame,
    })
}

/// Mitsuba's `roughplastic` at `hit`, seen from `wo`, over its coating's tables from
/// `coatings` (made before the render, [`Coatings::of`]).
/// Mitsuba's `roughplastic` is isotropic (the loader reads only `alpha` for it); a model built
/// in code with two widths gets their mean, [`Microfacet::alpha`].
///
/// # Panics
///
/// If `coatings` lacks this plastic's coating: they were made from another scene than the
/// one being rendered, which is the workbook's mistake, not the scene's.
pub fn rough_plastic<'c>(
    hit: &SurfaceHit,
    wo: Vec3,
    plastic: &Plastic,
    roughness: Microfacet,
    coatings: &'c Coatings,
) -> Option<Placed<RoughPlastic<'c>>> {
    let frame = LocalFrame::facing(hit, wo, plastic.two_sided, roughness.dp_du)?;
    let parameters = RoughPlasticParameters {
        kind: roughness.distribution,
        alpha: roughness.alpha(),
        eta: plastic.int_ior / plastic.ext_ior,
        diffuse_reflectance: plastic.diffuse_reflectance,
        specular_reflectance: plastic.specular_reflectance,
        nonlinear: plastic.nonlinear,
    };
    let coating = coatings
        .get(&parameters.distribution(), parameters.eta)
        .expect("every rough plastic of the scene has its coating in the tracer's Coatings");
    Some(Placed {
        bsdf: RoughPlastic::new(parameters, coating),
        frame,
    })
}

/// Mitsuba's `roughdielectric` at `hit`: the normal on the outside, whichever side `wo` is.
pub fn rough_dielectric(
    hit: &SurfaceHit,
    glass: &RoughGlass,
    roughness: Microfacet,
) -> Placed<RoughDielectric> {
    Placed {
        bsdf: RoughDielectric::new(distribution(roughness), glass.int_ior, glass.ext_ior),
        frame: LocalFrame::along(hit.shading_n, roughness.dp_du),
    }
}

/// Mitsuba's `roughdielectric` with factors on its lobes, at `hit`.
pub fn tinted_rough_dielectric(
    hit: &SurfaceHit,
    glass: &TintedGlass,
    roughness: Microfacet,
) -> Placed<RoughDielectric> {
    let mut bsdf = RoughDielectric::new(distribution(roughness), glass.int_ior, glass.ext_ior);
    bsdf.specular_reflectance = glass.specular_reflectance;
    bsdf.specular_transmittance = glass.specular_transmittance;
    Placed {
        bsdf,
        frame: LocalFrame::along(hit.shading_n, roughness.dp_du),
    }
}

#[cfg(test)]
mod tests {
    use super::LocalFrame;
    use glam::Vec3;

    #[test]
    fn the_frame_is_mitsubas_coordinate_system() {
        // Mitsuba 3.9.1's `mi.coordinate_system` of these normals: its first vector.
        for (n, s) in [
            (
                Vec3::new(0.3, 0.2, 0.932738),
                Vec3::new(0.953434, -0.0310441, -0.3),
            ),
            (
                Vec3::new(0.911043, 0.4, 0.1),
                Vec3::new(0.245454, -0.331289, -0.911043),
            ),
            (Vec3::new(0.0, 1.0, 0.0), Vec3::new(1.0, 0.0, 0.0)),
        ] {
            let frame = LocalFrame::around(n.normalize());
            assert!(
                (frame.tangent - s).length() < 1e-4,
                "{n}: {}",
                frame.tangent
            );
        }
    }

    #[test]
    fn the_frame_round_trips_and_puts_the_normal_on_z() {
        let normal = Vec3::new(0.3, -0.5, 0.8).normalize();
        let frame = LocalFrame::around(normal);
        assert!((frame.to_local(normal) - Vec3::Z).length() < 1e-6);
        let w = Vec3::new(-0.2, 0.9, 0.1).normalize();
        assert!((frame.to_world(frame.to_local(w)) - w).length() < 1e-6);
    }

    #[test]
    fn the_tangent_is_dp_du_made_perpendicular_to_the_normal() {
        let normal = Vec3::new(0.0, 0.6, 0.8);
        // dp/du leans out of the tangent plane; what is left of it runs along +x.
        let frame = LocalFrame::along(normal, Vec3::new(2.0, 0.3, 0.4));
        assert!(
            (frame.tangent - Vec3::X).length() < 1e-6,
            "{}",
            frame.tangent
        );
        // Right-handed, as Mitsuba's frame (s, n × s, n).
        assert!((frame.bitangent - normal.cross(Vec3::X)).length() < 1e-6);
        assert!((frame.to_local(normal) - Vec3::Z).length() < 1e-6);
    }

    #[test]
    fn without_a_tangent_the_frame_is_built_from_the_normal() {
        let normal = Vec3::new(0.3, -0.5, 0.8).normalize();
        let around = LocalFrame::around(normal);
        for dp_du in [Vec3::ZERO, normal * 3.0, Vec3::NAN] {
            let frame = LocalFrame::along(normal, dp_du);
            assert_eq!(frame.tangent, around.tangent, "dp/du {dp_du}");
            assert_eq!(frame.bitangent, around.bitangent, "dp/du {dp_du}");
        }
    }
}
