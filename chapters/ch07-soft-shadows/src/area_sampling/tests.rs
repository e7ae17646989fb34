//! The area samplers: every point on its light, every claimed density the true one (chi-square
//! in the light's plane), except for the naive disc, which must fail.

use std::f32::consts::PI;

use approx::assert_relative_eq;
use ch02_monte_carlo::chi2::chi2_test_density;
use ch02_monte_carlo::warps::{Domain, WarpPoint, invert_parallelogram, sample_uniform_disc_polar};

use super::*;
use crate::test_support::{
    CHI2_SAMPLES, PlaneFrame, bounds_in, chi2_on_plane, passes, uniform_points,
};

fn slanted_quad() -> Parallelogram {
    Parallelogram::new(
        Vec3::new(1.0, 2.0, -1.0),
        Vec3::new(2.0, 0.5, 0.0),
        Vec3::new(0.6, 0.3, 1.5),
    )
}

fn slanted_disc() -> Disc {
    Disc::new(Vec3::new(-1.0, 3.0, 2.0), Vec3::new(0.3, -1.0, 0.2), 1.5)
}

/// The edge coordinates of `p` in the parallelogram, in `f64`.
fn quad_coordinates(quad: &Parallelogram, p: Vec3) -> Vec2 {
    let frame = PlaneFrame::new(quad.corner(), quad.normal());
    let q = |v: Vec3| frame.coordinates(v);
    invert_parallelogram(
        q(p),
        q(quad.corner()),
        q(quad.corner() + quad.e1()),
        q(quad.corner() + quad.e2()),
    )
}

#[test]
fn exercise_parallelogram_light_point_lies_on_the_light() {
    let quad = slanted_quad();
    for u in uniform_points(500, 1) {
        let s = sample_parallelogram_light(&quad, u).expect(
            "sample_parallelogram_light: this parallelogram has an area, so it gives a sample",
        );
        let at = quad_coordinates(&quad, s.p);
        let problem = if quad.corner() != Vec3::ZERO
            && (quad_coordinates(&quad, s.p + quad.corner()) - u)
                .abs()
                .max_element()
                < 1e-4
        {
            Some("the point is missing the corner: it starts from the corner".to_string())
        } else if (at - Vec2::new(u.y, u.x)).abs().max_element() < 1e-4 && u.x != u.y {
            Some("ξ1 and ξ2 are swapped: ξ1 goes along the first edge, ξ2 along the second".into())
        } else if (at - u).abs().max_element() > 1e-4 {
            let corners_taken_as_edges = quad.corner()
                + u.x * (quad.e1() - quad.corner())
                + u.y * (quad.e2() - quad.corner());
            Some(
                if (s.p - corners_taken_as_edges).length() < 1e-4 * quad.corner().length().max(1.0)
                {
                    "the edges were given where corners are expected: chapter 02's \
                     sample_parallelogram(u, p0, p1, p2) takes three corners, the edges being \
                     p1 - p0 and p2 - p0"
                        .to_string()
                } else {
                    format!("the point lies at edge coordinates {at}, where ξ puts it at {u}")
                },
            )
        } else if s.n != quad.normal() {
            Some(format!(
                "the normal {} is not the light's {}",
                s.n,
                quad.normal()
            ))
        } else if (s.pdf - 1.0 / quad.area()).abs() > 1e-6 / quad.area() {
            Some(format!(
                "the density is {}: a point uniform over an area A has density 1 / A = {} per \
                 unit area",
                s.pdf,
                1.0 / quad.area()
            ))
        } else if s.pdf_solid_angle.is_some() {
            Some("an area sample has no density per solid angle: leave it None".into())
        } else {
            None
        };
        if let Some(problem) = problem {
            panic!(
                "sample_parallelogram_light: {problem}.\n  ξ = {u}, corner {}, edges {} and {}: \
                 your sample {s:?}",
                quad.corner(),
                quad.e1(),
                quad.e2()
            );
        }
    }
    let corner = sample_parallelogram_light(&quad, Vec2::ZERO).unwrap();
    assert!(
        corner.p == quad.corner(),
        "sample_parallelogram_light: ξ = (0, 0) is the corner {} itself, exactly; yours gave {}",
        quad.corner(),
        corner.p
    );
}

#[test]
fn exercise_parallelogram_light_point_is_uniform() {
    let quad = slanted_quad();
    let frame = PlaneFrame::new(quad.corner(), quad.normal());
    let corners = [0.0, 1.0].map(|a| [0.0, 1.0].map(|b| quad.point_at(a, b)));
    let result = chi2_on_plane(
        frame,
        bounds_in(frame, corners.as_flattened()),
        1,
        |u| sample_parallelogram_light(&quad, u),
        |q| {
            let p = frame.origin + q.x * frame.t + q.y * frame.b;
            let c = quad_coordinates(&quad, p);
            let inside = c.cmpge(Vec2::ZERO).all() && c.cmple(Vec2::ONE).all();
            if inside { 1.0 / quad.area() } else { 0.0 }
        },
    );
    if !passes(&result) {
        // The picture: the points in the parallelogram's own edge coordinates, where uniform
        // by area is uniform over the unit square.
        let points: Vec<Vec2> = uniform_points(20_000, 1)
            .into_iter()
            .filter_map(|u| sample_parallelogram_light(&quad, u))
            .map(|s| quad_coordinates(&quad, s.p))
            .collect();
        let message = workbench::test_support::not_uniform(
            "ch07-parallelogram-light-point",
            "sample_parallelogram_light",
            "parallelogram, drawn in its edge coordinates (along e1, along e2)",
            result.p_value,
            &points,
            &|_| 1.0,
            [Vec2::ZERO, Vec2::ONE],
        );
        panic!("{message}");
    }
}

#[test]
fn exercise_parallelogram_light_point_has_none_without_area() {
    for quad in [
        Parallelogram::new(Vec3::ZERO, Vec3::X, 2.0 * Vec3::X),
        Parallelogram::new(Vec3::ZERO, Vec3::ZERO, Vec3::Z),
    ] {
        let got = sample_parallelogram_light(&quad, Vec2::splat(0.5));
        assert!(
            got.is_none(),
            "sample_parallelogram_light: a parallelogram whose edges are parallel (or zero) has \
             no area and no density; it gives no sample (None), not {got:?}"
        );
    }
}

#[test]
fn exercise_disc_light_point_lies_on_the_disc_with_the_uniform_density() {
    let disc = slanted_disc();
    let radius = disc.radii().x;
    for u in uniform_points(500, 2) {
        let s = sample_disc_light_polar(&disc, u)
            .expect("sample_disc_light_polar: this disc has an area, so it gives a sample");
        let offset = s.p - disc.center();
        let problem = if offset.dot(disc.normal()).abs() >= 1e-5 {
            "the point is off the disc's plane".to_string()
        } else if offset.length() > radius * (1.0 + 1e-6) {
            format!(
                "the point is {} from the centre, outside the disc of radius {radius}",
                offset.length()
            )
        } else if s.n != disc.normal() {
            format!("the normal {} is not the disc's {}", s.n, disc.normal())
        } else if (s.pdf - 1.0 / (PI * radius * radius)).abs() > 1e-6 * s.pdf.abs().max(1e-6) {
            format!(
                "the density is {}: uniform over the disc's area π R² it is {} per unit area",
                s.pdf,
                1.0 / (PI * radius * radius)
            )
        } else {
            continue;
        };
        panic!("sample_disc_light_polar: {problem}.\n  ξ = {u}: your sample {s:?}");
    }
}

#[test]
fn exercise_disc_light_point_follows_the_lectures_parametrisation() {
    // ξ1 is the angle (a quarter turn goes to the bitangent), ξ2 picks the radius as in
    // chapter 02's polar map.
    let disc = slanted_disc();
    let radius = disc.radii().x;
    for u in [Vec2::new(0.25, 0.64)]
        .into_iter()
        .chain(uniform_points(100, 3))
    {
        let s = sample_disc_light_polar(&disc, u)
            .expect("sample_disc_light_polar: this disc has an area, so it gives a sample");
        let q = radius * sample_uniform_disc_polar(u);
        let expected = disc.point_at(q.x, q.y);
        if (s.p - expected).length() <= 1e-5 * radius.max(1.0) {
            continue;
        }
        let r = (s.p - disc.center()).length() / radius;
        let mistake = if (r - u.y).abs() < 1e-4 {
            "the radius came out as R ξ2: rings of equal width then get equal shares of the \
             points, but an inner ring has less area than an outer one"
                .to_string()
        } else if (r - q.length() / radius).abs() < 1e-4 {
            "the radius is right but the angle is not: ξ1 is the share of a turn, measured from \
             the disc's tangent towards its bitangent"
                .to_string()
        } else {
            format!(
                "the point should lie {} of the radius from the centre",
                q.length() / radius
            )
        };
        panic!(
            "sample_disc_light_polar: {mistake}.\n  ξ = {u}: your point {}, the lecture's map \
             gives {expected}",
            s.p
        );
    }
}

#[test]
fn exercise_disc_light_point_stretches_over_an_ellipse() {
    // An ellipse light (a disc under a non-uniform scale): the polar map stretched by its two
    // semi-axes, 2 along the tangent and 0.5 along the bitangent.
    let ellipse = slanted_ellipse();
    let r = ellipse.radii();
    for u in uniform_points(100, 9) {
        let s = sample_disc_light_polar(&ellipse, u)
            .expect("sample_disc_light_polar: this ellipse has an area, so it gives a sample");
        let q = sample_uniform_disc_polar(u);
        let expected = ellipse.point_at(r.x * q.x, r.y * q.y);
        if (s.p - expected).length() <= 1e-5 * r.max_element() {
            continue;
        }
        let circle = |radius: f32| ellipse.point_at(radius * q.x, radius * q.y);
        let mistake = if (s.p - circle(r.x)).length() <= 1e-5 * r.x
            || (s.p - circle(r.y)).length() <= 1e-5 * r.x
        {
            "the point is on a circle: an ellipse's semi-axes differ, so the map is stretched by \
             the first radius along the tangent and by the second along the bitangent"
        } else {
            "the polar map's point is stretched by the semi-axis along each of the ellipse's two \
             directions"
        };
        panic!(
            "sample_disc_light_polar: an ellipse with semi-axes {} (tangent) and {} (bitangent): \
             {mistake}.\n  ξ = {u}: your point {}, expected {expected}",
            r.x, r.y, s.p
        );
    }
}

#[test]
fn exercise_disc_light_point_is_uniform() {
    let result = chi2_on_disc(DiscWarp::Polar, 4);
    if !passes(&result) {
        // The picture: the points in the disc's own coordinates, as fractions of its radius.
        let disc = slanted_disc();
        let r = disc.radii().x;
        let points: Vec<Vec2> = uniform_points(20_000, 4)
            .into_iter()
            .filter_map(|u| sample_disc_light_polar(&disc, u))
            .map(|s| {
                let offset = s.p - disc.center();
                Vec2::new(offset.dot(disc.tangent()), offset.dot(disc.bitangent())) / r
            })
            .collect();
        let message = workbench::test_support::not_uniform(
            "ch07-disc-light-point",
            "sample_disc_light_polar",
            "disc, drawn along its tangent and bitangent in units of its radius",
            result.p_value,
            &points,
            &|q| {
                if q.length() <= 1.0 {
                    std::f64::consts::FRAC_1_PI
                } else {
                    0.0
                }
            },
            [Vec2::splat(-1.0), Vec2::ONE],
        );
        panic!("{message}");
    }
}

#[test]
fn exercise_disc_light_point_has_none_without_area() {
    for radius in [0.0, -1.0, f32::NAN] {
        let disc = Disc::new(Vec3::ZERO, Vec3::Y, radius);
        let got = sample_disc_light_polar(&disc, Vec2::splat(0.3));
        assert!(
            got.is_none(),
            "sample_disc_light_polar: a disc of radius {radius} has no area and no density; it \
             gives no sample (None), not {got:?}"
        );
    }
}

/// The disc light's samples by `warp` against the uniform density every disc sample claims.
fn chi2_on_disc(warp: DiscWarp, seed: u64) -> ch02_monte_carlo::chi2::Chi2Result {
    let disc = slanted_disc();
    let frame = PlaneFrame::new(disc.center(), disc.normal());
    let r = disc.radii().x;
    chi2_on_plane(
        frame,
        (Vec2::splat(-1.01 * r), Vec2::splat(1.01 * r)),
        seed,
        |u| sample_disc_light(&disc, u, warp),
        |q| {
            if q.length() <= r {
                LightShape::Disc(disc).pdf_area()
            } else {
                0.0
            }
        },
    )
}

#[test]
fn uniform_disc_warps_pass_and_the_naive_one_fails() {
    for warp in [DiscWarp::Concentric, DiscWarp::Polar] {
        let result = chi2_on_disc(warp, 5);
        assert!(passes(&result), "{}: {result:?}", warp.name());
    }
    let naive = chi2_on_disc(DiscWarp::Naive, 5);
    assert!(naive.p_value < 1e-12, "the naive disc passed: {naive:?}");
}

/// An ellipse light (a scene file's disk under a non-uniform scale), 2 by 0.5, tilted.
fn slanted_ellipse() -> Disc {
    let normal = Vec3::new(0.3, -1.0, 0.2).normalize();
    let tangent = normal.any_orthonormal_vector();
    Disc::ellipse(
        Vec3::new(-1.0, 3.0, 2.0),
        normal,
        2.0 * tangent,
        0.5 * normal.cross(tangent),
    )
}

#[test]
fn ellipse_lights_are_uniform_by_area_with_the_uniform_warps() {
    let ellipse = slanted_ellipse();
    let r = ellipse.radii();
    // The ellipse's own axes, so that its rim is (x / r_t)² + (y / r_b)² = 1 there.
    let frame = PlaneFrame {
        origin: ellipse.center(),
        t: ellipse.tangent(),
        b: ellipse.bitangent(),
    };
    let pdf = LightShape::Disc(ellipse).pdf_area();
    assert_relative_eq!(pdf, 1.0 / (PI * 2.0 * 0.5), max_relative = 1e-5);
    for warp in [DiscWarp::Concentric, DiscWarp::Polar] {
        let result = chi2_on_plane(
            frame,
            (-1.01 * r, 1.01 * r),
            7,
            |u| sample_disc_light(&ellipse, u, warp),
            |q| if (q / r).length() <= 1.0 { pdf } else { 0.0 },
        );
        assert!(passes(&result), "{}: {result:?}", warp.name());
    }
}

#[test]
fn triangle_light_points_are_uniform_on_the_triangle() {
    let triangle = Triangle::new(
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(2.0, 1.5, 0.5),
        Vec3::new(0.5, 2.5, 1.0),
    );
    let frame = PlaneFrame::new(
        triangle.p[0],
        (triangle.p[1] - triangle.p[0]).cross(triangle.p[2] - triangle.p[0]),
    );
    let [a, b, c] = triangle.p.map(|p| frame.coordinates(p));
    let area = triangle.area();
    let result = chi2_on_plane(
        frame,
        bounds_in(frame, &triangle.p),
        6,
        |u| {
            let s = sample_triangle_light(&triangle, u)?;
            assert_relative_eq!(s.pdf, 1.0 / area, max_relative = 1e-6);
            Some(s)
        },
        |q| {
            // Inside when q is on the inner side of all three edges.
            let side = |p: Vec2, r: Vec2| (r - p).perp_dot(q - p);
            let inside = side(a, b) >= 0.0 && side(b, c) >= 0.0 && side(c, a) >= 0.0;
            if inside { 1.0 / area } else { 0.0 }
        },
    );
    assert!(passes(&result), "{result:?}");
}

#[test]
fn sphere_area_points_are_uniform_on_the_sphere() {
    let sphere = Sphere::new(Vec3::new(1.0, -2.0, 0.5), 0.7);
    // Directions from the centre: a density per unit area is R² times one per steradian.
    let result = chi2_test_density(
        Domain::Sphere,
        CHI2_SAMPLES,
        7,
        (16, 32),
        |u| {
            let s = sample_sphere_area(&sphere, u).expect("the sphere has an area");
            assert_relative_eq!(s.n, (s.p - sphere.center) / 0.7, epsilon = 1e-5);
            WarpPoint::Direction((s.p - sphere.center).normalize())
        },
        |_| LightShape::Sphere(sphere).pdf_area() * 0.7 * 0.7,
    );
    assert!(passes(&result), "{result:?}");
}

/// How far `p` is from the exact shape's plane or sphere, in `f64`, against its bound.
fn check_error_bound(shape: &LightShape, s: &LightSample) {
    let p = s.p.as_dvec3();
    let distance = match shape {
        LightShape::Parallelogram(q) => {
            let n = q.e1().as_dvec3().cross(q.e2().as_dvec3()).normalize();
            (p - q.corner().as_dvec3()).dot(n).abs()
        }
        LightShape::Triangle(t) => {
            let [p0, p1, p2] = t.p.map(|v| v.as_dvec3());
            (p - p0).dot((p1 - p0).cross(p2 - p0).normalize()).abs()
        }
        LightShape::Disc(d) => {
            let n = d
                .tangent()
                .as_dvec3()
                .cross(d.bitangent().as_dvec3())
                .normalize();
            (p - d.center().as_dvec3()).dot(n).abs()
        }
        LightShape::Sphere(sp) => ((p - sp.center.as_dvec3()).length() - sp.radius as f64).abs(),
    };
    let bound = s.n.abs().as_dvec3().dot(s.p_error.as_dvec3());
    assert!(
        distance <= bound,
        "{shape:?}: {s:?} is {distance} off, bound {bound}"
    );
}

#[test]
fn sampled_points_are_within_their_error_bounds_at_every_scale() {
    for scale in [1e-4f32, 1.0, 1e5] {
        let at = |v: Vec3| v * scale;
        let shapes: [LightShape; 4] = [
            Parallelogram::new(
                at(Vec3::new(3.0, 7.0, -2.0)),
                at(Vec3::new(0.3, 0.1, 0.0)),
                at(Vec3::new(0.05, 0.2, 0.4)),
            )
            .into(),
            Triangle::new(
                at(Vec3::new(3.0, 7.0, -2.0)),
                at(Vec3::new(3.3, 7.1, -2.0)),
                at(Vec3::new(3.05, 7.2, -1.6)),
            )
            .into(),
            Disc::new(
                at(Vec3::new(3.0, 7.0, -2.0)),
                Vec3::new(0.2, -1.0, 0.4),
                0.3 * scale,
            )
            .into(),
            Sphere::new(at(Vec3::new(3.0, 7.0, -2.0)), 0.3 * scale).into(),
        ];
        for shape in shapes {
            for u in uniform_points(300, 8) {
                let s = shape.sample_area(u, DiscWarp::Concentric).unwrap();
                check_error_bound(&shape, &s);
            }
        }
    }
}
