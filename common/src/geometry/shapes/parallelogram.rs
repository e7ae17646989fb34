//! The parallelogram: a parallelogram, the usual shape of walls, floors and area lights.

use glam::{Vec2, Vec3};

use super::Crossing;
use super::plane::SpannedPlane;
use crate::Ray;
use crate::geometry::aabb::Aabb;
use crate::geometry::float::gamma;
use crate::geometry::hit::SurfaceHit;

/// The parallelogram `corner + u e1 + v e2` for `u, v` in `[0, 1]`.
///
/// Its normal is `normalize(e1 × e2)` and its surface parameters are `uv = (u, v)`. The fields
/// are private because the parallelogram caches what its intersection test needs; read them back with
/// [`corner`](Self::corner), [`e1`](Self::e1) and [`e2`](Self::e2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parallelogram {
    corner: Vec3,
    e1: Vec3,
    e2: Vec3,
    normal: Vec3,
    plane: SpannedPlane,
    /// `u = dot(p - corner, dual_u)`: the dual basis vector of `e1` within the plane.
    dual_u: Vec3,
    /// `v = dot(p - corner, dual_v)`.
    dual_v: Vec3,
}

impl Parallelogram {
    /// The parallelogram with one corner at `corner` and edges `e1` and `e2` leaving it.
    ///
    /// Parallel (or zero) edges give a degenerate parallelogram that is never hit.
    pub fn new(corner: Vec3, e1: Vec3, e2: Vec3) -> Self {
        let n = e1.cross(e2);
        let n_squared = n.length_squared();
        Self {
            corner,
            e1,
            e2,
            normal: n.normalize_or_zero(),
            plane: SpannedPlane::new(corner, e1, e2),
            // Dividing by |n|² makes dot(e1, dual_u) = dot(e1, e2 × n) / |n|² = 1.
            dual_u: e2.cross(n) / n_squared,
            dual_v: n.cross(e1) / n_squared,
        }
    }

    /// The same parallelogram facing the other way: its normal becomes `-normalize(e1 × e2)`
    /// and its `uv` stay where they were, as a scene file's `flip_normals` keeps them (and as
    /// the faces of Mitsuba's cube, whose `uv` turn the other way about their normals, need).
    pub fn flipped(self) -> Self {
        Self {
            normal: -self.normal,
            ..self
        }
    }

    /// The corner where `u = v = 0`.
    pub fn corner(&self) -> Vec3 {
        self.corner
    }

    /// The edge along which `u` grows.
    pub fn e1(&self) -> Vec3 {
        self.e1
    }

    /// The edge along which `v` grows.
    pub fn e2(&self) -> Vec3 {
        self.e2
    }

    /// The unit normal `normalize(e1 × e2)` (zero for a degenerate parallelogram).
    pub fn normal(&self) -> Vec3 {
        self.normal
    }

    /// The surface parameters `(u, v)` of the point `p` of its plane (of its projection
    /// onto the plane, for a point off it).
    pub fn uv_of(&self, p: Vec3) -> Vec2 {
        let d = p - self.corner;
        Vec2::new(d.dot(self.dual_u), d.dot(self.dual_v))
    }

    /// The point with surface parameters `(u, v)`.
    pub fn point_at(&self, u: f32, v: f32) -> Vec3 {
        self.corner + u * self.e1 + v * self.e2
    }

    /// A box certainly containing the parallelogram: the four computed corners, grown by their rounding
    /// error.
    pub fn bounds(&self) -> Aabb {
        let corners = [
            self.corner,
            self.corner + self.e1,
            self.corner + self.e2,
            self.corner + self.e1 + self.e2,
        ];
        let rounding = gamma(3) * (self.corner.abs() + self.e1.abs() + self.e2.abs());
        Aabb::from_point_set(corners)
            .expanded(rounding)
            .rounded_outward()
    }

    /// The area `|e1 × e2|`.
    pub fn area(&self) -> f32 {
        self.e1.cross(self.e2).length()
    }

    /// The hit with `0 < t < ray.t_max`, seen from either side.
    ///
    /// The plane crossing is found robustly (see `plane.rs`); `(u, v)` then come from the
    /// approximate crossing point, and the reported `p` is recomputed from them as
    /// `corner + u e1 + v e2`. That sum is *on* the exact plane up to its own three roundings,
    /// whatever the errors in `t`, `u` and `v`, which gives the bound
    /// `γ(3) (|corner| + |u e1| + |v e2|)`.
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        self.crossing(ray)
            .map(|crossing| self.surface_hit(crossing))
    }

    /// The crossing behind [`intersect`](Self::intersect), with `(u, v)`.
    pub(crate) fn crossing(&self, ray: &Ray) -> Option<Crossing> {
        if self.normal == Vec3::ZERO {
            return None;
        }
        let t = self.plane.crossing(ray)?;
        let from_corner = ray.at(t) - self.corner;
        let u = from_corner.dot(self.dual_u);
        let v = from_corner.dot(self.dual_v);
        if !((0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v)) {
            return None;
        }
        Some(Crossing {
            t,
            coords: [u, v, 0.0],
        })
    }

    /// The hit record of a crossing.
    pub(crate) fn surface_hit(&self, crossing: Crossing) -> SurfaceHit {
        let [u, v, _] = crossing.coords;
        let p = self.point_at(u, v);
        let p_error = gamma(3) * (self.corner.abs() + (u * self.e1).abs() + (v * self.e2).abs());
        SurfaceHit {
            t: crossing.t,
            p,
            p_error,
            n: self.normal,
            shading_n: self.normal,
            uv: Vec2::new(u, v),
            shape: 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use approx::assert_relative_eq;

    use super::*;

    /// The unit square in the floor plane y = 0, facing up (z × x = y).
    fn floor() -> Parallelogram {
        Parallelogram::new(Vec3::ZERO, Vec3::Z, Vec3::X)
    }

    #[test]
    fn hit_has_known_t_p_n_and_uv() {
        let ray = Ray::new(Vec3::new(0.75, 2.0, 0.25), -Vec3::Y);
        let hit = floor().intersect(&ray).unwrap();
        assert_relative_eq!(hit.t, 2.0, max_relative = 1e-6);
        // p comes from (u, v), not from t, so it is exact here.
        assert_eq!(hit.p, Vec3::new(0.75, 0.0, 0.25));
        assert_eq!(hit.n, Vec3::Y);
        assert_eq!(hit.uv, Vec2::new(0.25, 0.75));
        assert!(hit.front_face(ray.dir));
    }

    #[test]
    fn hit_on_a_slanted_parallelogram() {
        let quad = Parallelogram::new(
            Vec3::new(1.0, 2.0, 3.0),
            Vec3::new(2.0, 0.0, 1.0),
            Vec3::new(0.5, 1.5, -0.5),
        );
        let target = quad.point_at(0.3, 0.6);
        let origin = target + Vec3::new(-1.0, 2.0, 4.0);
        let hit = quad.intersect(&Ray::new(origin, target - origin)).unwrap();
        assert_relative_eq!(hit.t, 1.0, max_relative = 1e-5);
        assert_relative_eq!(hit.uv, Vec2::new(0.3, 0.6), epsilon = 1e-5);
        assert_relative_eq!(hit.p, target, epsilon = 1e-5);
        assert_relative_eq!(hit.n, quad.normal());
        assert_relative_eq!(hit.n.dot(quad.e1()), 0.0, epsilon = 1e-6);
    }

    #[test]
    fn misses_outside_behind_and_parallel() {
        let quad = floor();
        assert!(
            quad.intersect(&Ray::new(Vec3::new(1.1, 2.0, 0.5), -Vec3::Y))
                .is_none()
        );
        assert!(
            quad.intersect(&Ray::new(Vec3::new(0.5, 2.0, -0.1), -Vec3::Y))
                .is_none()
        );
        assert!(
            quad.intersect(&Ray::new(Vec3::new(0.5, 2.0, 0.5), Vec3::Y))
                .is_none()
        );
        assert!(
            quad.intersect(&Ray::new(Vec3::new(-1.0, 0.0, 0.5), Vec3::X))
                .is_none()
        );
    }

    #[test]
    fn grazing_rays_hit_inside_and_miss_outside() {
        let quad = floor();
        let dir = Vec3::new(1.0, -1e-4, 0.0);
        let inside = Ray::new(Vec3::new(-1.0, 1.5e-4, 0.5), dir);
        let hit = quad
            .intersect(&inside)
            .expect("nearly parallel ray inside hits");
        assert_relative_eq!(hit.p.x, 0.5, epsilon = 1e-3);
        let outside = Ray::new(Vec3::new(-1.0, 2.5e-4, 0.5), dir);
        assert!(quad.intersect(&outside).is_none());
    }

    #[test]
    fn hit_from_behind_keeps_the_normal() {
        let ray = Ray::new(Vec3::new(0.5, -1.0, 0.5), Vec3::Y);
        let hit = floor().intersect(&ray).unwrap();
        assert_eq!(hit.n, Vec3::Y);
        assert!(!hit.front_face(ray.dir));
    }

    #[test]
    fn t_max_is_respected() {
        let ray = Ray::new(Vec3::new(0.5, 2.0, 0.5), -Vec3::Y);
        assert!(floor().intersect(&Ray { t_max: 2.0, ..ray }).is_none());
        assert!(
            floor()
                .intersect(&Ray {
                    t_max: 2.001,
                    ..ray
                })
                .is_some()
        );
    }

    #[test]
    fn degenerate_quads_are_never_hit() {
        let ray = Ray::new(Vec3::new(0.5, 2.0, 0.5), -Vec3::Y);
        for quad in [
            Parallelogram::new(Vec3::ZERO, Vec3::X, 2.0 * Vec3::X),
            Parallelogram::new(Vec3::ZERO, Vec3::ZERO, Vec3::Z),
        ] {
            assert_eq!(quad.intersect(&ray), None);
            assert_eq!(quad.area(), 0.0);
        }
    }

    #[test]
    fn bounds_contain_all_corners_and_area_is_the_cross_product() {
        let quad = Parallelogram::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(2.0, 0.0, 1.0), Vec3::Y);
        let b = quad.bounds();
        for (u, v) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)] {
            assert!(b.contains(quad.point_at(u, v)));
        }
        assert_relative_eq!(quad.area(), 5.0f32.sqrt());
    }
}
