//! How fast a shape's surface point moves as its `u` grows: `dp/du`, the direction an
//! anisotropic material's first width (`alpha_u`) runs along.
//!
//! Only a rough material whose widths differ along and across the surface asks for it, so a
//! hit does not carry it: [`Shape::dp_du`] works it out from the shape and the hit's `uv`,
//! with Mitsuba 3's parametrisation of each shape, so that a scene file's anisotropic metal
//! is brushed the way Mitsuba brushes it:
//!
//! - a sphere: along its parallels, `u` turning about its own `z` (zero at the poles);
//! - a rectangle: along its first edge (`to_world`'s `x`);
//! - a disk: outwards from its centre, along the radius (Mitsuba's `u` is the radius);
//! - a triangle with texture coordinates: where its texture's `u` grows; without them, along
//!   its first edge `p1 - p0` (Mitsuba's barycentric parametrisation).
//!
//! Zero where the parametrisation has no direction (a pole, a triangle whose texture
//! coordinates are degenerate): the material then takes Mitsuba's frame built from the normal
//! alone. The length is not Mitsuba's in every case; only the direction is used.

use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};

use super::{Disc, Shape, Sphere, Triangle};

impl Shape {
    /// `dp/du` at surface parameters `uv` (a hit's [`uv`](crate::geometry::SurfaceHit::uv)),
    /// in world space; zero where it has no direction. The `dp_du` module says why.
    pub fn dp_du(&self, uv: Vec2) -> Vec3 {
        match self {
            Shape::Sphere(sphere) => sphere_dp_du(sphere, uv),
            Shape::Triangle(triangle) => triangle_dp_du(triangle),
            Shape::Parallelogram(parallelogram) => parallelogram.e1(),
            Shape::Disc(disc) => disc_dp_du(disc, uv),
        }
    }
}

/// Along the parallel at `uv = (φ / 2π, θ / π)`, measured in the sphere's own axes: its length
/// `sin θ` vanishes at the poles.
fn sphere_dp_du(sphere: &Sphere, uv: Vec2) -> Vec3 {
    let (sin_phi, cos_phi) = (uv.x * TAU).sin_cos();
    let sin_theta = (uv.y * PI).sin();
    let own = Vec3::new(-sin_phi, cos_phi, 0.0) * sin_theta;
    // `to_object` is a rotation: its transpose takes the sphere's axes back to the world's.
    sphere.to_object.transpose() * own
}

/// Where the texture's `u` grows across the triangle, from its three texture coordinates;
/// the first edge without them (or with coordinates that span no area, where Mitsuba falls
/// back to a frame around the normal: zero here, which the caller treats alike).
fn triangle_dp_du(triangle: &Triangle) -> Vec3 {
    let [p0, p1, p2] = triangle.p;
    let (dp0, dp1) = (p1 - p0, p2 - p0);
    let Some([uv0, uv1, uv2]) = triangle.uvs else {
        return dp0;
    };
    let (duv0, duv1) = (uv1 - uv0, uv2 - uv0);
    let det = duv0.x * duv1.y - duv0.y * duv1.x;
    if det == 0.0 || !det.is_finite() {
        return Vec3::ZERO;
    }
    (duv1.y * dp0 - duv0.y * dp1) / det
}

/// Outwards along the radius through `uv = (ρ, φ / 2π)`, on an ellipse through its axes.
fn disc_dp_du(disc: &Disc, uv: Vec2) -> Vec3 {
    let (sin_phi, cos_phi) = (uv.y * TAU).sin_cos();
    let radii = disc.radii();
    disc.tangent() * (radii.x * cos_phi) + disc.bitangent() * (radii.y * sin_phi)
}

#[cfg(test)]
mod tests {
    use approx::assert_relative_eq;
    use glam::Mat3;

    use super::*;
    use crate::Ray;
    use crate::geometry::shapes::Parallelogram;

    /// The hit of a ray from `origin` towards `target` on `shape`.
    fn uv_of(shape: &Shape, origin: Vec3, target: Vec3) -> Vec2 {
        let ray = Ray::new(origin, (target - origin).normalize());
        shape.intersect(&ray).expect("the ray hits").uv
    }

    /// Asserts that `dp/du` at `uv` runs along `expected`.
    fn assert_along(shape: &Shape, uv: Vec2, expected: Vec3) {
        let dp_du = shape.dp_du(uv);
        assert!(
            dp_du.normalize().dot(expected) > 0.9999,
            "dp/du at uv {uv} is {dp_du}, expected along {expected}"
        );
    }

    #[test]
    fn a_sphere_is_brushed_along_its_parallels() {
        let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 2.0));
        // On the equator at +x, u grows towards +y (φ turns from x to y).
        let uv = uv_of(&sphere, Vec3::new(5.0, 0.0, 0.0), Vec3::ZERO);
        assert_along(&sphere, uv, Vec3::Y);
        // At +y it points to -x.
        let uv = uv_of(&sphere, Vec3::new(0.0, 5.0, 0.3), Vec3::ZERO);
        assert_along(&sphere, uv, -Vec3::X);
        // At a pole it has no direction.
        let uv = uv_of(&sphere, Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO);
        assert!(sphere.dp_du(uv).length() < 1e-3);
    }

    #[test]
    fn a_turned_sphere_turns_its_parallels() {
        // Turned so that its own z is the world's x and its own x the world's -z: its
        // parallels circle the world's x axis, and at the world's +y (its own +y) u grows
        // towards its own -x, the world's +z.
        let rotation = Mat3::from_rotation_y(std::f32::consts::FRAC_PI_2);
        let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0).turned(rotation));
        let uv = uv_of(&sphere, Vec3::new(0.0, 5.0, 0.0), Vec3::ZERO);
        assert_along(&sphere, uv, Vec3::Z);
    }

    #[test]
    fn a_rectangle_is_brushed_along_its_first_edge() {
        let rectangle = Shape::Parallelogram(Parallelogram::new(
            Vec3::ZERO,
            Vec3::new(0.0, 0.0, 2.0),
            Vec3::new(2.0, 0.0, 0.0),
        ));
        assert_eq!(rectangle.dp_du(Vec2::splat(0.5)), Vec3::new(0.0, 0.0, 2.0));
    }

    #[test]
    fn a_disk_is_brushed_along_its_radius() {
        let disc = Shape::Disc(Disc::new(Vec3::ZERO, Vec3::Z, 1.0));
        for target in [Vec3::new(0.5, 0.0, 0.0), Vec3::new(-0.3, 0.4, 0.0)] {
            let uv = uv_of(&disc, target + Vec3::Z, target);
            let dp_du = disc.dp_du(uv);
            assert_relative_eq!(dp_du.normalize(), target.normalize(), epsilon = 1e-4);
        }
    }

    #[test]
    fn a_textured_triangle_is_brushed_where_its_u_grows() {
        // u grows along -y on this triangle, whatever its edges' order.
        let triangle = Triangle::new(Vec3::ZERO, Vec3::X, Vec3::Y).with_uvs([
            Vec2::new(0.5, 0.0),
            Vec2::new(0.5, 1.0),
            Vec2::new(0.0, 0.0),
        ]);
        let dp_du = Shape::Triangle(triangle).dp_du(Vec2::ZERO);
        // One unit of u is two units of length: u goes from 0 at p2 to 1/2 at p0.
        assert_relative_eq!(dp_du, Vec3::new(0.0, -2.0, 0.0), epsilon = 1e-6);
    }

    #[test]
    fn without_texture_coordinates_a_triangle_is_brushed_along_its_first_edge() {
        let triangle = Triangle::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 3.0), Vec3::Y);
        assert_eq!(
            Shape::Triangle(triangle).dp_du(Vec2::ZERO),
            Vec3::new(0.0, 0.0, 3.0)
        );
    }

    #[test]
    fn degenerate_texture_coordinates_give_no_direction() {
        let triangle = Triangle::new(Vec3::ZERO, Vec3::X, Vec3::Y).with_uvs([Vec2::ZERO; 3]);
        assert_eq!(Shape::Triangle(triangle).dp_du(Vec2::ZERO), Vec3::ZERO);
    }
}
