//! Smooth glass with factors on its two lobes (Mitsuba's `specular_reflectance` and
//! `specular_transmittance` on `dielectric`): chapter 08's smooth glass chooses the branch,
//! then the branch's factor scales it.

use ch08_path_tracing::bsdf::BsdfSample;
use ch08_path_tracing::bsdf::dielectric;
use common::geometry::SurfaceHit;
use common::scene::TintedGlass;
use glam::Vec3;

/// Smooth glass with factors on its lobes (Mitsuba's `specular_reflectance` and
/// `specular_transmittance`): the branch is chosen by `F` as for plain glass, with the same
/// number `u`, and its weight is multiplied by its lobe's factor.
pub fn sample(hit: &SurfaceHit, wo: Vec3, glass: &TintedGlass, u: f32) -> Option<BsdfSample> {
    let sample = dielectric::sample(hit, wo, glass.int_ior, glass.ext_ior, u)?;
    let reflected = sample.wi.dot(hit.shading_n) * wo.dot(hit.shading_n) > 0.0;
    let factor = if reflected {
        glass.specular_reflectance
    } else {
        glass.specular_transmittance
    };
    Some(BsdfSample {
        weight: sample.weight * factor,
        ..sample
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use common::Ray;
    use common::geometry::{Shape, Sphere};

    /// A hit on the top of the unit sphere, seen from above at 30 degrees.
    fn hit_and_wo() -> (SurfaceHit, Vec3) {
        let wo = Vec3::new(0.5, 0.75f32.sqrt(), 0.0);
        let ray = Ray::new(Vec3::Y + 3.0 * wo, -wo);
        let hit = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0))
            .intersect(&ray)
            .unwrap();
        (hit, wo)
    }

    #[test]
    fn tinted_glass_chooses_as_glass_does_and_scales_each_branch_by_its_factor() {
        let (hit, wo) = hit_and_wo();
        let glass = TintedGlass {
            int_ior: 1.5,
            ext_ior: 1.0,
            specular_reflectance: Vec3::new(0.9, 0.5, 0.1),
            specular_transmittance: Vec3::new(0.2, 0.4, 0.8),
            reflectance_texture: None,
            transmittance_texture: None,
            roughness: None,
        };
        // About 4 % is reflected at 30 degrees: u = 0.01 reflects, u = 0.5 refracts.
        for (u, factor) in [
            (0.01, glass.specular_reflectance),
            (0.5, glass.specular_transmittance),
        ] {
            let plain = dielectric::sample(&hit, wo, 1.5, 1.0, u).unwrap();
            let tinted = sample(&hit, wo, &glass, u).unwrap();
            assert_eq!(tinted.wi, plain.wi);
            assert_eq!(tinted.weight, plain.weight * factor);
            assert_eq!((tinted.pdf, tinted.eta_scale), (plain.pdf, plain.eta_scale));
        }
    }
}
