//! The sphere's cone sampling: chapter 02's cap, uniform in solid angle (chi-square), on the
//! visible side, accurate for tiny cones, and the fall-back inside the sphere.

use approx::assert_relative_eq;
use ch02_monte_carlo::chi2::chi2_test_density;
use ch02_monte_carlo::warps::{Domain, WarpPoint, sample_spherical_cap};
use glam::Quat;

use super::*;
use crate::test_support::{CHI2_SAMPLES, passes, uniform_points};

#[test]
fn the_cone_is_chapter_02s_spherical_cap() {
    for cos_max in [-1.0f32, -0.5, 0.0, 0.8] {
        for u in uniform_points(200, 1) {
            let ours = sample_cone(u, 1.0 - cos_max);
            assert_relative_eq!(ours, sample_spherical_cap(u, cos_max), epsilon = 1e-6);
        }
        assert_relative_eq!(
            cone_pdf(1.0 - cos_max),
            ch02_monte_carlo::warps::spherical_cap_pdf(cos_max)
        );
    }
}

/// The chi-square test of the directions from `x` to the cone samples of `sphere`, seen in a
/// frame whose +z is the cone's axis, against [`sphere_solid_angle_pdf`].
fn chi2_of_cone(sphere: Sphere, x: Vec3, seed: u64) -> ch02_monte_carlo::chi2::Chi2Result {
    let axis = (sphere.center - x).normalize();
    let to_local = Quat::from_rotation_arc(axis, Vec3::Z);
    chi2_test_density(
        Domain::Sphere,
        CHI2_SAMPLES,
        seed,
        (16, 64),
        |u| {
            let s = sample_sphere_solid_angle(&sphere, x, u).expect("outside the sphere");
            WarpPoint::Direction(to_local * (s.p - x).normalize())
        },
        |point| match point {
            WarpPoint::Direction(d) => {
                sphere_solid_angle_pdf(&sphere, x, to_local.inverse() * d).unwrap()
            }
            WarpPoint::Plane(_) => 0.0,
        },
    )
}

#[test]
fn cone_samples_are_uniform_in_solid_angle() {
    // A large cone (θ_max = 53°) seen along a tilted axis, and a small one (θ_max = 14°).
    let near = chi2_of_cone(
        Sphere::new(Vec3::new(0.3, 1.0, -0.4), 1.0),
        Vec3::new(0.3, 1.0, -0.4) - 1.25 * Vec3::new(0.48, 0.6, 0.64),
        1,
    );
    assert!(passes(&near), "near: {near:?}");
    let far = chi2_of_cone(Sphere::new(Vec3::new(0.0, 0.0, 4.0), 1.0), Vec3::ZERO, 2);
    assert!(passes(&far), "far: {far:?}");
}

#[test]
fn cone_samples_go_where_the_cone_points() {
    // The direction to the point is the cone's direction, near and far, up to rounding.
    for (d, tolerance) in [
        (1.0001f32, 2e-3),
        (1.1, 1e-5),
        (1.9, 1e-5),
        (2.1, 1e-5),
        (10.0, 1e-5),
        (1e4, 1e-3),
    ] {
        let sphere = Sphere::new(Vec3::new(0.3, 0.2, 0.1) + d * Vec3::new(0.6, 0.0, 0.8), 1.0);
        let x = Vec3::new(0.3, 0.2, 0.1);
        let cone = sphere_cone(&sphere, x).unwrap();
        let (t, b) = cone.axis.any_orthonormal_pair();
        for u in uniform_points(200, 5) {
            let s = sample_sphere_solid_angle(&sphere, x, u).unwrap();
            let local = sample_cone(u, cone.one_minus_cos_theta_max);
            let expected = local.x * t + local.y * b + local.z * cone.axis;
            assert_relative_eq!((s.p - x).normalize(), expected, epsilon = tolerance);
        }
    }
}

#[test]
fn cone_samples_lie_on_the_visible_side_with_consistent_densities() {
    let sphere = Sphere::new(Vec3::new(1.0, 2.0, 3.0), 0.5);
    let x = Vec3::new(-0.5, 1.0, 2.0);
    let cone = sphere_cone(&sphere, x).unwrap();
    for u in uniform_points(1000, 3) {
        let s = sample_sphere_solid_angle(&sphere, x, u).unwrap();
        assert_relative_eq!((s.p - sphere.center).length(), 0.5, max_relative = 1e-5);
        assert_relative_eq!(s.n, (s.p - sphere.center) / 0.5, epsilon = 1e-5);
        let to_x = x - s.p;
        assert!(
            s.n.dot(to_x) >= -1e-5 * to_x.length(),
            "the back of the sphere: {s:?}"
        );
        let pdf_solid_angle = s.pdf_solid_angle.unwrap();
        assert_relative_eq!(pdf_solid_angle, cone_pdf(cone.one_minus_cos_theta_max));
        let cos_light = s.n.dot(to_x.normalize());
        assert_relative_eq!(
            pdf_area_to_solid_angle(s.pdf, to_x.length_squared(), cos_light),
            pdf_solid_angle,
            max_relative = 1e-3
        );
    }
}

#[test]
fn tiny_cones_keep_their_digits() {
    // R / d = 1e-6: 1 - cos θ_max = 5e-13, far below the spacing of floats near 1.
    let sphere = Sphere::new(Vec3::new(0.0, 1e6, 0.0), 1.0);
    let cone = sphere_cone(&sphere, Vec3::ZERO).unwrap();
    assert_relative_eq!(cone.one_minus_cos_theta_max, 5e-13, max_relative = 1e-5);
    for u in uniform_points(200, 4) {
        let s = sample_sphere_solid_angle(&sphere, Vec3::ZERO, u).unwrap();
        assert!(s.p.is_finite() && s.pdf.is_finite() && s.pdf > 0.0, "{s:?}");
        assert!(s.p.y < 1e6, "on the near side: {s:?}");
        // On the sphere within its bound: near 1e6 floats are 0.06 apart.
        let off = ((s.p.as_dvec3() - sphere.center.as_dvec3()).length() - 1.0).abs();
        assert!(off <= s.n.abs().dot(s.p_error) as f64, "{off}: {s:?}");
        assert_relative_eq!(
            s.pdf_solid_angle.unwrap(),
            1.0 / (TAU * 5e-13),
            max_relative = 1e-5
        );
    }
    // So small a cone that f32 cannot hold its solid angle: no sample, no NaN.
    for dust in [
        Sphere::new(Vec3::new(0.0, 1e10, 0.0), 1e-10),
        Sphere::new(Vec3::new(0.0, 1e30, 0.0), 1e-10),
    ] {
        assert_eq!(
            sample_sphere_solid_angle(&dust, Vec3::ZERO, Vec2::splat(0.5)),
            None
        );
    }
}

#[test]
fn receivers_on_or_inside_the_sphere_fall_back_to_area_sampling() {
    let sphere = Sphere::new(Vec3::new(1.0, 0.0, 0.0), 2.0);
    for x in [
        sphere.center,
        Vec3::new(1.0, 2.0, 0.0),
        Vec3::new(0.5, 0.5, 0.5),
    ] {
        assert_eq!(sphere_cone(&sphere, x), None);
        assert_eq!(sphere_solid_angle_pdf(&sphere, x, Vec3::X), None);
        let s = sample_sphere_solid_angle(&sphere, x, Vec2::new(0.3, 0.6)).unwrap();
        assert_eq!(s.pdf_solid_angle, None);
        assert_relative_eq!(s.pdf, 1.0 / (16.0 * std::f32::consts::PI));
    }
}

#[test]
fn densities_convert_between_area_and_solid_angle() {
    // A patch of 1e-4 at distance 2 seen at 60° covers 1e-4 · 0.5 / 4 steradians.
    let pdf_area = 1e4;
    let pdf_solid_angle = pdf_area_to_solid_angle(pdf_area, 4.0, -0.5);
    assert_relative_eq!(
        pdf_solid_angle,
        1.0 / (1e-4 * 0.5 / 4.0),
        max_relative = 1e-6
    );
    assert_relative_eq!(
        pdf_solid_angle_to_area(pdf_solid_angle, 4.0, 0.5),
        pdf_area,
        max_relative = 1e-6
    );
    assert_eq!(pdf_area_to_solid_angle(1.0, 1.0, 0.0), f32::INFINITY);
}
