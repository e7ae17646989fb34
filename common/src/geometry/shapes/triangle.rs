//! The triangle, with the watertight ray–triangle test of Woop, Benthin and Wald (2013).

use glam::{Vec2, Vec3};

use super::Crossing;
use super::four_triangles::{FourTriangles, RaySpace};
use crate::Ray;
use crate::geometry::aabb::Aabb;
use crate::geometry::float::gamma;
use crate::geometry::hit::SurfaceHit;

/// A triangle, optionally with a normal at each vertex for smooth shading and texture
/// coordinates at each vertex.
///
/// Its geometric normal is `normalize((p1 - p0) × (p2 - p0))`: counter-clockwise vertices seen
/// from the front. Its surface parameters at the hit point `b0 p0 + b1 p1 + b2 p2` are, as in
/// Mitsuba 3's meshes, the vertices' texture coordinates interpolated,
/// `uv = b0 uv0 + b1 uv1 + b2 uv2`, when it has them, and else the barycentric coordinates
/// `uv = (b1, b2)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle {
    /// The three vertices.
    pub p: [Vec3; 3],
    /// Unit normals at the vertices, interpolated into the shading normal.
    pub normals: Option<[Vec3; 3]>,
    /// Texture coordinates at the vertices, interpolated into the hit's `uv`.
    pub uvs: Option<[Vec2; 3]>,
}

impl Triangle {
    /// The flat triangle `p0 p1 p2`.
    pub fn new(p0: Vec3, p1: Vec3, p2: Vec3) -> Self {
        Self {
            p: [p0, p1, p2],
            normals: None,
            uvs: None,
        }
    }

    /// A triangle whose shading normal interpolates the vertex normals `n`.
    pub fn with_normals(p: [Vec3; 3], n: [Vec3; 3]) -> Self {
        Self {
            p,
            normals: Some(n),
            uvs: None,
        }
    }

    /// The same triangle with texture coordinates `uv` at its vertices.
    pub fn with_uvs(self, uv: [Vec2; 3]) -> Self {
        Self {
            uvs: Some(uv),
            ..self
        }
    }

    /// The box of the three vertices (exact: nothing is computed).
    pub fn bounds(&self) -> Aabb {
        Aabb::from_point_set(self.p)
    }

    /// The area `|(p1 - p0) × (p2 - p0)| / 2`.
    pub fn area(&self) -> f32 {
        0.5 * self.unnormalized_normal().length()
    }

    fn unnormalized_normal(&self) -> Vec3 {
        let [p0, p1, p2] = self.p;
        (p1 - p0).cross(p2 - p0)
    }

    /// The hit with `0 < t < ray.t_max`, seen from either side; degenerate triangles (zero area,
    /// or non-finite vertices) are never hit.
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        self.checked_crossing(ray)
            .map(|crossing| self.surface_hit(crossing))
    }

    /// The crossing behind [`intersect`](Self::intersect), with the barycentrics; none for a
    /// degenerate triangle.
    pub(crate) fn checked_crossing(&self, ray: &Ray) -> Option<Crossing> {
        let has_area = self.unnormalized_normal().length_squared() > 0.0; // false for NaN too
        if !has_area {
            return None;
        }
        self.crossing(ray)
    }

    /// The hit record of a crossing.
    pub(crate) fn surface_hit(&self, crossing: Crossing) -> SurfaceHit {
        let b = crossing.coords;
        let [p0, p1, p2] = self.p;
        // The point from the barycentrics, not from t: then its error does not depend on how
        // far the ray travelled. Bound from pbrt-v4, section 6.8.6.
        let p = b[0] * p0 + b[1] * p1 + b[2] * p2;
        let p_error = gamma(7) * ((b[0] * p0).abs() + (b[1] * p1).abs() + (b[2] * p2).abs());
        let n = self.unnormalized_normal().normalize();
        let shading_n = match self.normals {
            Some([n0, n1, n2]) => (b[0] * n0 + b[1] * n1 + b[2] * n2)
                .try_normalize()
                .unwrap_or(n),
            None => n,
        };
        SurfaceHit {
            t: crossing.t,
            p,
            p_error,
            n,
            shading_n,
            uv: match self.uvs {
                Some([uv0, uv1, uv2]) => b[0] * uv0 + b[1] * uv1 + b[2] * uv2,
                None => Vec2::new(b[1], b[2]),
            },
            shape: 0,
        }
    }

    /// The watertight test of [`RaySpace`], in the first of four lanes.
    fn crossing(&self, ray: &Ray) -> Option<Crossing> {
        let space = RaySpace::new(ray)?;
        let (_, crossing) = space.nearest_crossing(&FourTriangles::new(&[self.p]), 1, ray.t_max)?;
        Some(crossing)
    }
}

#[cfg(test)]
mod tests {
    use approx::assert_relative_eq;

    use super::*;

    fn right_triangle() -> Triangle {
        // In the plane z = 1, normal +z (x × y).
        Triangle::new(
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(1.0, 0.0, 1.0),
            Vec3::new(0.0, 1.0, 1.0),
        )
    }

    #[test]
    fn a_hit_does_not_depend_on_the_length_of_the_direction() {
        // Rays taken into the space of a scaled object have directions far from unit length.
        let triangle = Triangle::new(
            Vec3::new(-1.0, 0.0, -1.0),
            Vec3::new(1.0, 0.0, -1.0),
            Vec3::new(0.0, 0.0, 1.0),
        );
        let origin = Vec3::new(0.1, 2.0, 0.2);
        let unit = Vec3::new(0.05, -1.0, -0.1).normalize();
        for length in [1e-6f32, 1e-3, 1.0, 1e3, 1e6] {
            let ray = Ray::new(origin, unit * length);
            let hit = triangle
                .intersect(&ray)
                .unwrap_or_else(|| panic!("missed at {length}"));
            assert!(
                (hit.t * length - 2.0 / unit.y.abs()).abs() < 1e-5,
                "{length}: {}",
                hit.t
            );
        }
    }
    #[test]
    fn hit_has_known_t_p_n_and_barycentrics() {
        let ray = Ray::new(Vec3::new(0.25, 0.5, 5.0), -Vec3::Z);
        let hit = right_triangle().intersect(&ray).unwrap();
        assert_relative_eq!(hit.t, 4.0, max_relative = 1e-6);
        assert_relative_eq!(hit.p, Vec3::new(0.25, 0.5, 1.0), epsilon = 1e-6);
        assert_eq!(hit.n, Vec3::Z);
        assert_eq!(hit.shading_n, hit.n);
        assert_relative_eq!(hit.uv, Vec2::new(0.25, 0.5), epsilon = 1e-6);
        assert!(hit.front_face(ray.dir));
        assert!(hit.p_error.cmpgt(Vec3::ZERO).all());
    }

    #[test]
    fn texture_coordinates_are_interpolated_with_the_barycentrics() {
        let ray = Ray::new(Vec3::new(0.25, 0.5, 5.0), -Vec3::Z);
        let uvs = [
            Vec2::new(0.5, 1.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(0.5, 0.0),
        ];
        let hit = right_triangle().with_uvs(uvs).intersect(&ray).unwrap();
        // b = (0.25, 0.25, 0.5): 0.25 (0.5, 1) + 0.25 (1, 1) + 0.5 (0.5, 0).
        assert_relative_eq!(hit.uv, Vec2::new(0.625, 0.5), epsilon = 1e-6);
    }

    #[test]
    fn hit_from_behind_keeps_the_normal_and_is_not_front_facing() {
        let ray = Ray::new(Vec3::new(0.25, 0.25, -5.0), Vec3::Z);
        let hit = right_triangle().intersect(&ray).unwrap();
        assert_eq!(hit.n, Vec3::Z);
        assert!(!hit.front_face(ray.dir));
    }

    #[test]
    fn misses_outside_the_edges_and_behind_the_origin() {
        let triangle = right_triangle();
        let beyond_hypotenuse = Ray::new(Vec3::new(0.6, 0.6, 5.0), -Vec3::Z);
        assert!(triangle.intersect(&beyond_hypotenuse).is_none());
        let behind = Ray::new(Vec3::new(0.25, 0.25, 0.0), -Vec3::Z);
        assert!(triangle.intersect(&behind).is_none());
    }

    #[test]
    fn rays_in_the_triangles_plane_never_hit() {
        let triangle = right_triangle();
        for dir in [
            Vec3::X,
            Vec3::Y,
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(-1.0, 0.5, 0.0),
        ] {
            let ray = Ray::new(Vec3::new(-1.0, 0.2, 1.0), dir);
            assert!(triangle.intersect(&ray).is_none(), "dir {dir}");
        }
    }

    #[test]
    fn grazing_rays_hit_inside_and_miss_outside() {
        let triangle = right_triangle();
        let dir = Vec3::new(1.0, 0.0, -1e-3);
        let inside = Ray::new(Vec3::new(-1.0, 0.1, 1.0 + 1.1e-3), dir);
        let hit = triangle
            .intersect(&inside)
            .expect("nearly parallel ray inside hits");
        assert_relative_eq!(hit.p.x, 0.1, epsilon = 1e-3);
        let outside = Ray::new(Vec3::new(-1.0, 0.1, 1.0 + 2.0e-3), dir);
        assert!(triangle.intersect(&outside).is_none());
    }

    #[test]
    fn t_max_is_respected() {
        let ray = Ray::new(Vec3::new(0.25, 0.25, 5.0), -Vec3::Z);
        let triangle = right_triangle();
        assert!(triangle.intersect(&Ray { t_max: 4.0, ..ray }).is_none());
        assert!(
            triangle
                .intersect(&Ray {
                    t_max: 4.001,
                    ..ray
                })
                .is_some()
        );
    }

    #[test]
    fn degenerate_triangles_never_hit_and_never_produce_nan() {
        let p = Vec3::new(0.3, 0.2, 0.1);
        let degenerate = [
            Triangle::new(p, p, p),
            Triangle::new(p, p + Vec3::X, p + 2.0 * Vec3::X),
            Triangle::new(p, p + Vec3::Y, p),
            Triangle::new(p, Vec3::NAN, p + Vec3::Y),
        ];
        for triangle in degenerate {
            let area = triangle.area();
            assert!(area == 0.0 || area.is_nan(), "{triangle:?}");
            for dir in [-Vec3::Z, Vec3::X, Vec3::new(0.3, -0.2, 0.9), Vec3::ZERO] {
                for origin in [p - dir, Vec3::new(0.3, 0.2, 2.0), p] {
                    assert_eq!(triangle.intersect(&Ray::new(origin, dir)), None);
                }
            }
        }
    }

    #[test]
    fn shading_normal_interpolates_vertex_normals() {
        let [p0, p1, p2] = right_triangle().p;
        let tilted = Vec3::new(1.0, 0.0, 1.0).normalize();
        let triangle = Triangle::with_normals([p0, p1, p2], [Vec3::Z, tilted, Vec3::Z]);
        let at_p1 = Ray::new(Vec3::new(0.999, 0.0005, 2.0), -Vec3::Z);
        let hit = triangle.intersect(&at_p1).unwrap();
        assert_eq!(hit.n, Vec3::Z);
        assert_relative_eq!(hit.shading_n, tilted, epsilon = 1e-3);
        assert_relative_eq!(hit.shading_n.length(), 1.0, epsilon = 1e-6);
        // Opposite vertex normals cancel; the shading normal falls back to the geometric one.
        let cancelling = Triangle::with_normals([p0, p1, p2], [Vec3::Z, -Vec3::Z, Vec3::Z]);
        let midway = Ray::new(Vec3::new(0.5, 0.0, 2.0), -Vec3::Z);
        let hit = cancelling.intersect(&midway).unwrap();
        assert!(hit.shading_n.is_finite() && hit.shading_n.is_normalized());
    }

    #[test]
    fn bounds_and_area() {
        let triangle = right_triangle();
        assert_eq!(triangle.area(), 0.5);
        let b = triangle.bounds();
        assert_eq!(
            (b.min, b.max),
            (Vec3::new(0.0, 0.0, 1.0), Vec3::new(1.0, 1.0, 1.0))
        );
    }
}
