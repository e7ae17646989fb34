//! The sphere's cone and its sampling: the cone's numbers, uniform in solid angle (chi-square),
//! on the visible side, accurate for tiny cones, the fall-back inside the sphere, and the point
//! a direction meets.

use approx::assert_relative_eq;
use ch02_monte_carlo::chi2::chi2_test_density;
use ch02_monte_carlo::warps::{Domain, WarpPoint};
use glam::Quat;
use std::f32::consts::TAU;

use super::*;
use crate::test_support::{CHI2_SAMPLES, passes, uniform_points};

#[test]
fn the_cone_density_is_chapter_02s_spherical_cap() {
    for cos_max in [-1.0f32, -0.5, 0.0, 0.8] {
        assert_relative_eq!(
            cone_pdf(1.0 - cos_max),
            ch02_monte_carlo::warps::spherical_cap_pdf(cos_max)
        );
    }
}

// The cone (exercise).

#[test]
fn exercise_sphere_cone_finds_the_cone_a_sphere_covers() {
    // (centre, radius, receiver, 1 - cos θ_max, and what it comes to when cos θ_max is taken
    // as R / d in the identity with sin² θ_max): a large cone seen along a tilted axis, a
    // small one, a sphere far off and one so far that cos θ_max rounds to 1 in f32. The last
    // two columns were worked out beforehand in f64 from the receiver's distance, to 9 digits.
    let cases = [
        (
            Vec3::new(0.3, 1.0, -0.4),
            1.0f32,
            Vec3::new(-0.3, 0.25, -1.2),
            3.999_999_674e-1,
            3.555_555_387e-1,
        ),
        (
            Vec3::new(0.0, 0.0, 4.0),
            1.0,
            Vec3::ZERO,
            3.175_416_345e-2,
            5.0e-2,
        ),
        (
            Vec3::new(1.0, 2.0, 3.0),
            0.5,
            Vec3::new(-0.5, 1.0, 2.0),
            2.985_749_985e-2,
            4.734_152_344e-2,
        ),
        (
            Vec3::new(0.0, 1e4, 0.0),
            1.0,
            Vec3::ZERO,
            5.000_000_013e-9,
            9.999_000_100e-9,
        ),
        (
            Vec3::new(0.0, 1e6, 0.0),
            1.0,
            Vec3::ZERO,
            5.0e-13,
            9.999_990_000e-13,
        ),
    ];
    for (center, radius, x, expected, with_cos_as_sin) in cases {
        let sphere = Sphere::new(center, radius);
        let d = (center.as_dvec3() - x.as_dvec3()).length();
        let s = radius as f64 / d;
        let Some(cone) = sphere_cone(&sphere, x) else {
            panic!(
                "sphere_cone: a receiver at {x}, {d} from the centre of a sphere of radius \
                 {radius}, is outside it and sees a cone, but yours gave None"
            );
        };
        let axis = ((center.as_dvec3() - x.as_dvec3()) / d).as_vec3();
        assert!(
            (cone.axis - axis).length() < 1e-5,
            "sphere_cone: the axis is {}, expected {axis}: {}",
            cone.axis,
            if (cone.axis + axis).length() < 1e-5 {
                "the axis points from the sphere to the receiver; it goes from x to the centre"
            } else {
                "the axis is the unit direction from x to the sphere's centre"
            }
        );
        let close = |a: f32, b: f64| ((a as f64) - b).abs() <= 1e-5 * b.abs();
        assert!(
            close(cone.distance, d),
            "sphere_cone: the distance is {}, expected {d}",
            cone.distance
        );
        assert!(
            close(cone.sin_theta_max, s) && close(cone.sin2_theta_max, s * s),
            "sphere_cone: sin θ_max = {} and sin² θ_max = {}, expected {s} and {} for a sphere \
             of radius {radius} seen from {d} away",
            cone.sin_theta_max,
            cone.sin2_theta_max,
            s * s
        );
        let got = cone.one_minus_cos_theta_max;
        if !close(got, expected) {
            let why = if close(got, with_cos_as_sin) || close(got, 1.0 - s) {
                "cos θ_max came out as R / d, which is sin θ_max: θ_max is the angle whose sine \
                 is R / d, so what is its cosine?"
                    .to_string()
            } else if s < 1e-3 {
                format!(
                    "1 - cos θ_max lost its digits: cos θ_max = {:.9} rounds in f32 to a float \
                     near 1, and subtracting it from 1 leaves noise or nothing; compute \
                     1 - cos θ_max from sin² θ_max, without that subtraction",
                    1.0 - expected
                )
            } else {
                "it is one minus the cosine of the cone's half-angle".to_string()
            };
            panic!(
                "sphere_cone: 1 - cos θ_max = {got:e} for R / d = {s:e}, expected {expected:e}: \
                 {why}"
            );
        }
    }
}

#[test]
fn exercise_sphere_cone_has_none_on_or_inside_the_sphere() {
    let sphere = Sphere::new(Vec3::new(1.0, 0.0, 0.0), 2.0);
    for x in [
        sphere.center,
        Vec3::new(1.0, 2.0, 0.0),
        Vec3::new(0.5, 0.5, 0.5),
    ] {
        let cone = sphere_cone(&sphere, x);
        assert!(
            cone.is_none(),
            "sphere_cone: a receiver at {x}, on or inside the sphere of radius 2 around {}, \
             sees no cone (the sphere surrounds it): None, not {cone:?}",
            sphere.center
        );
    }
    for radius in [0.0, -1.0] {
        let cone = sphere_cone(&Sphere::new(Vec3::Y, radius), Vec3::ZERO);
        assert!(
            cone.is_none(),
            "sphere_cone: a sphere of radius {radius} covers no cone: None, not {cone:?}"
        );
    }
}

// Sampling the cone (exercise).

const SAMPLE: &str = "ch07-sample-sphere-solid-angle";

/// Where the direction from `x` to `p` lies in the cone `sphere` covers from `x`: the turn
/// about the axis and `1 - cos θ`, both as shares of their whole range, so that a sampler
/// uniform in solid angle makes them uniform in the unit square, in any frame about the axis.
fn cone_coordinates(sphere: &Sphere, x: Vec3, p: Vec3) -> Vec2 {
    let cone = sphere_cone(sphere, x).unwrap();
    let (t, b) = cone.axis.any_orthonormal_pair();
    let w = (p - x).normalize();
    let phi = w.dot(b).atan2(w.dot(t)).rem_euclid(TAU);
    let one_minus_cos = (w - cone.axis).length_squared() / 2.0;
    Vec2::new(phi / TAU, one_minus_cos / cone.one_minus_cos_theta_max)
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
        |u| match sample_sphere_solid_angle(&sphere, x, u) {
            Some(s) => WarpPoint::Direction(to_local * (s.p - x).normalize()),
            None => panic!(
                "sample_sphere_solid_angle: no sample for a receiver outside the sphere (u = {u})"
            ),
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
fn exercise_sample_sphere_solid_angle_is_uniform_in_solid_angle() {
    // A large cone (θ_max = 53°) seen along a tilted axis, and a small one (θ_max = 14°).
    let cases = [
        (
            Sphere::new(Vec3::new(0.3, 1.0, -0.4), 1.0),
            Vec3::new(0.3, 1.0, -0.4) - 1.25 * Vec3::new(0.48, 0.6, 0.64),
            1,
        ),
        (Sphere::new(Vec3::new(0.0, 0.0, 4.0), 1.0), Vec3::ZERO, 2),
    ];
    for (sphere, x, seed) in cases {
        let result = chi2_of_cone(sphere, x, seed);
        if passes(&result) {
            continue;
        }
        // The picture: the directions' place in the cone, which uniform sampling spreads
        // evenly over the square.
        let points: Vec<Vec2> = uniform_points(20_000, seed)
            .into_iter()
            .filter_map(|u| sample_sphere_solid_angle(&sphere, x, u))
            .map(|s| cone_coordinates(&sphere, x, s.p))
            .collect();
        let message = workbench::test_support::not_uniform(
            SAMPLE,
            "sample_sphere_solid_angle",
            "cone, drawn as (turn about the axis, (1 - cos θ) / (1 - cos θ_max))",
            result.p_value,
            &points,
            &|_| 1.0,
            [Vec2::ZERO, Vec2::ONE],
        );
        panic!(
            "{message}. The directions are not uniform in solid angle: what share of the cone \
             lies within θ of its axis?"
        );
    }
}

#[test]
fn exercise_sample_sphere_solid_angle_stays_in_the_cone_on_the_visible_side() {
    let sphere = Sphere::new(Vec3::new(1.0, 2.0, 3.0), 0.5);
    let x = Vec3::new(-0.5, 1.0, 2.0);
    for u in uniform_points(1000, 3) {
        let s = sample_sphere_solid_angle(&sphere, x, u).unwrap_or_else(|| {
            panic!("sample_sphere_solid_angle: no sample from outside the sphere (u = {u})")
        });
        assert!(
            ((s.p - sphere.center).length() - 0.5).abs() < 1e-5,
            "sample_sphere_solid_angle: the point {} is not on the sphere",
            s.p
        );
        assert!(
            (s.n - (s.p - sphere.center) / 0.5).length() < 1e-5,
            "sample_sphere_solid_angle: n = {} is not the sphere's outward normal at the point",
            s.n
        );
        let in_cone = cone_coordinates(&sphere, x, s.p).y;
        assert!(
            in_cone <= 1.0 + 1e-3,
            "sample_sphere_solid_angle: the direction to {} lies outside the cone the sphere \
             covers ((1 - cos θ) is {in_cone:.3} of (1 - cos θ_max))",
            s.p
        );
        let to_x = x - s.p;
        assert!(
            s.n.dot(to_x) >= -1e-5 * to_x.length(),
            "sample_sphere_solid_angle: the point {} is on the back of the sphere, which the \
             receiver cannot see: the direction meets the sphere first on its near side",
            s.p
        );
    }
}

#[test]
fn exercise_sample_sphere_solid_angle_carries_both_densities() {
    let sphere = Sphere::new(Vec3::new(1.0, 2.0, 3.0), 0.5);
    let x = Vec3::new(-0.5, 1.0, 2.0);
    let cone = sphere_cone(&sphere, x).unwrap();
    let solid_angle = TAU * cone.one_minus_cos_theta_max;
    for u in uniform_points(1000, 3) {
        let s = sample_sphere_solid_angle(&sphere, x, u).expect(
            "sample_sphere_solid_angle: a receiver outside the sphere sees it in a cone of \
             directions, so every ξ gives a sample",
        );
        let Some(pdf_solid_angle) = s.pdf_solid_angle else {
            panic!(
                "sample_sphere_solid_angle: a point chosen by its direction carries its density \
                 per unit solid angle too (pdf_solid_angle is None)"
            );
        };
        assert!(
            (pdf_solid_angle * solid_angle - 1.0).abs() < 1e-4,
            "sample_sphere_solid_angle: the density per unit solid angle is {pdf_solid_angle}, \
             but the cone covers {solid_angle} sr and every direction in it is as likely"
        );
        let to_x = x - s.p;
        let cos_light = s.n.dot(to_x.normalize());
        let area = pdf_area_to_solid_angle(s.pdf, to_x.length_squared(), cos_light);
        if (area / pdf_solid_angle - 1.0).abs() > 1e-3 {
            let why = if s.pdf < 0.0 {
                "a density is never negative: the light's normal at the point faces the \
                 receiver, away from the direction the receiver looks along, so the cosine \
                 between them that converts the density is taken as |cos θ′|"
            } else if (s.pdf / pdf_solid_angle - 1.0).abs() < 1e-4 {
                "it is the density per unit solid angle, not converted to area: a patch dA of \
                 the light, seen from x at distance d and at angle θ′ to its normal, covers the \
                 solid angle |cos θ′| dA / d²"
            } else {
                "the two densities describe the same choice, so p_ω dω = p_A dA"
            };
            panic!(
                "sample_sphere_solid_angle: the density per unit area is {}, which is {area} per \
                 steradian seen from x, not the cone's {pdf_solid_angle}: {why}",
                s.pdf
            );
        }
    }
}

#[test]
fn exercise_sample_sphere_solid_angle_keeps_the_digits_of_tiny_cones() {
    // R / d = 1e-6: 1 - cos θ_max = 5e-13, far below the spacing of floats near 1.
    let sphere = Sphere::new(Vec3::new(0.0, 1e6, 0.0), 1.0);
    for u in uniform_points(200, 4) {
        let s = sample_sphere_solid_angle(&sphere, Vec3::ZERO, u).unwrap_or_else(|| {
            panic!(
                "sample_sphere_solid_angle: a sphere of radius 1 a million away is small but \
                 has a cone f32 can describe, so it gets a sample (u = {u})"
            )
        });
        assert!(
            s.p.is_finite() && s.pdf.is_finite() && s.pdf > 0.0,
            "sample_sphere_solid_angle: a sphere of radius 1 a million away gave {s:?}: its \
             point is finite, and its density per unit area finite and positive"
        );
        assert!(s.p.y < 1e6, "on the near side: {s:?}");
        // On the sphere within its bound: near 1e6 floats are 0.06 apart.
        let off = ((s.p.as_dvec3() - sphere.center.as_dvec3()).length() - 1.0).abs();
        assert!(off <= s.n.abs().dot(s.p_error) as f64, "{off}: {s:?}");
        let pdf = s.pdf_solid_angle.unwrap_or(0.0);
        assert!(
            (pdf as f64 * TAU as f64 * 5e-13 - 1.0).abs() < 1e-4,
            "sample_sphere_solid_angle: the density of a cone of 1 - cos θ_max = 5e-13 is \
             1 / (2π · 5e-13), not {pdf}: it comes from the cone's own 1 - cos θ_max"
        );
    }
    // So small a cone that f32 cannot hold its solid angle: no sample, no NaN.
    for dust in [
        Sphere::new(Vec3::new(0.0, 1e10, 0.0), 1e-10),
        Sphere::new(Vec3::new(0.0, 1e30, 0.0), 1e-10),
    ] {
        let s = sample_sphere_solid_angle(&dust, Vec3::ZERO, Vec2::splat(0.5));
        assert!(
            s.is_none(),
            "sample_sphere_solid_angle: a sphere of radius {} at {} covers a cone whose \
             density f32 cannot hold (infinite): None, not {s:?}",
            dust.radius,
            dust.center
        );
    }
}

#[test]
fn exercise_sample_sphere_solid_angle_falls_back_to_area_inside_the_sphere() {
    let sphere = Sphere::new(Vec3::new(1.0, 0.0, 0.0), 2.0);
    for x in [
        sphere.center,
        Vec3::new(1.0, 2.0, 0.0),
        Vec3::new(0.5, 0.5, 0.5),
    ] {
        assert_eq!(sphere_solid_angle_pdf(&sphere, x, Vec3::X), None);
        let Some(s) = sample_sphere_solid_angle(&sphere, x, Vec2::new(0.3, 0.6)) else {
            panic!(
                "sample_sphere_solid_angle: a receiver at {x}, on or inside the sphere, sees \
                 no cone but still gets a point, chosen by area"
            );
        };
        assert!(
            s.pdf_solid_angle.is_none()
                && (s.pdf - 1.0 / (16.0 * std::f32::consts::PI)).abs() < 1e-6,
            "sample_sphere_solid_angle: a receiver at {x}, inside the sphere, gets a point \
             chosen by area, with density 1 / (4π R²) per unit area and no density per solid \
             angle; yours is {s:?}"
        );
    }
}

#[test]
fn points_are_where_the_direction_meets_the_sphere() {
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
            // Directions all over the cone, by their angles.
            let theta = u.y * cone.sin_theta_max.asin();
            let (sin_theta, cos_theta) = theta.sin_cos();
            let phi = TAU * u.x;
            let (p, _, _) =
                point_seen_along(&sphere, x, &cone, cos_theta, sin_theta * sin_theta, phi);
            let sideways = phi.cos() * t + phi.sin() * b;
            let expected = sin_theta * sideways + cos_theta * cone.axis;
            assert_relative_eq!((p - x).normalize(), expected, epsilon = tolerance);
        }
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
