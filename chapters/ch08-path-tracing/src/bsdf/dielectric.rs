//! Smooth glass: reflection with probability `F` (the Fresnel reflectance), else refraction,
//! as chapter 06's [`choose_fresnel`] and Mitsuba's `dielectric`. The chance equals the
//! share, so the weight is 1, times `(eta_i / eta_t)²` for radiance carried through the
//! refraction.

use super::BsdfSample;
use ch01_whitted::optics::{fresnel_dielectric, reflect, refract};
use ch06_fuzzy_reflections::glass_choice::choose_fresnel;
use common::geometry::SurfaceHit;
use glam::Vec3;

/// The shading normal on `wo`'s side and the relative index `eta = eta_i / eta_t` of a ray
/// arriving from that side. Glass bends light about the shading normal, as Mitsuba's does in
/// its shading frame: on a mesh with vertex normals a smooth glass object then looks smooth,
/// not cut into facets (on spheres and planes the two normals are one).
pub fn side(hit: &SurfaceHit, wo: Vec3, int_ior: f32, ext_ior: f32) -> (Vec3, f32) {
    let n = hit.shading_n;
    if wo.dot(n) > 0.0 {
        (n, ext_ior / int_ior)
    } else {
        (-n, int_ior / ext_ior)
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
    fn glass_and_mirrors_turn_about_the_shading_normal_as_mitsuba_does() {
        // A facet of a smooth mesh: its geometric normal is +z, the normal interpolated from
        // its vertices is tilted by 10 degrees. Mitsuba reflects and refracts about the
        // latter, so that the mesh looks smooth.
        let (mut hit, _) = hit_and_wo();
        hit.n = Vec3::Z;
        hit.shading_n = Vec3::new(10f32.to_radians().sin(), 0.0, 10f32.to_radians().cos());
        let wo = Vec3::Z;
        let reflected = sample(&hit, wo, 1.5, 1.0, 0.0).unwrap();
        let about_shading = reflect(-wo, hit.shading_n);
        assert!(
            reflected.wi.abs_diff_eq(about_shading, 1e-6),
            "glass reflects about the shading normal: {} against {about_shading} (about the \
             geometric normal it would go straight back, {})",
            reflected.wi,
            reflect(-wo, hit.n)
        );
        let refracted = sample(&hit, wo, 1.5, 1.0, 0.99).unwrap();
        let through_shading = refract(-wo, hit.shading_n, 1.0 / 1.5).unwrap();
        assert!(
            refracted.wi.abs_diff_eq(through_shading, 1e-6),
            "{}",
            refracted.wi
        );
        let mirrored = super::super::mirror::sample(&hit, wo, Vec3::ONE).unwrap();
        assert!(
            mirrored.wi.abs_diff_eq(about_shading, 1e-6),
            "{}",
            mirrored.wi
        );
    }
}
