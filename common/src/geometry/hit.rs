//! What an intersection routine reports, and how the next ray leaves from it.

use glam::{Vec2, Vec3};

use super::spawn::{SHADOW_EPSILON, offset_ray_origin};
use crate::Ray;

/// A ray–surface intersection.
///
/// The normal `n` is the shape's own geometric normal (outward for spheres) and is *not* turned
/// towards the ray: whether the ray arrived from the front or the back is information the
/// chapters need (refraction enters or leaves a glass), so [`front_face`](Self::front_face)
/// answers that question instead of hiding it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceHit {
    /// The ray parameter of the hit: `p ≈ ray.origin + t * ray.dir`.
    pub t: f32,
    /// The hit point, computed from the surface's own parameters rather than from `t`.
    pub p: Vec3,
    /// A conservative bound, per axis, on how far `p` is from the exact surface point.
    pub p_error: Vec3,
    /// Unit geometric normal, as the shape defines it (see [`Shape`](super::Shape)).
    pub n: Vec3,
    /// Unit shading normal: interpolated vertex normals on meshes that have them, else `n`.
    pub shading_n: Vec3,
    /// The surface parameters at the hit (their meaning depends on the shape).
    pub uv: Vec2,
    /// Index of the shape inside its [`Geometry`](super::Geometry); 0 from `Shape::intersect`.
    pub shape: u32,
}

impl SurfaceHit {
    /// Whether a ray travelling along `dir` arrives on the side `n` points to
    /// (`dot(dir, n) < 0`): outside a sphere, in front of a parallelogram.
    pub fn front_face(&self, dir: Vec3) -> bool {
        dir.dot(self.n) < 0.0
    }

    /// The origin for a ray leaving towards `w`, certainly on `w`'s side of the surface.
    #[inline]
    pub fn offset_origin(&self, w: Vec3) -> Vec3 {
        offset_ray_origin(self.p, self.p_error, self.n, w)
    }

    /// A secondary ray (reflection, refraction, a sampled direction) leaving along `dir`,
    /// unbounded in `t`.
    #[inline]
    pub fn spawn_ray(&self, dir: Vec3, time: f32) -> Ray {
        Ray {
            origin: self.offset_origin(dir),
            dir,
            t_max: f32::INFINITY,
            time,
        }
    }

    /// A shadow ray towards the point `target` (a point light, a sampled point on a light).
    ///
    /// `dir = target - origin` is *not* normalised, so the target is at `t = 1`; the ray stops at
    /// `t_max = 1 - SHADOW_EPSILON`, just short of it, so a surface at the target itself does
    /// not count as a blocker.
    #[inline]
    pub fn spawn_ray_to(&self, target: Vec3, time: f32) -> Ray {
        let origin = self.offset_origin(target - self.p);
        Ray {
            origin,
            dir: target - origin,
            t_max: 1.0 - SHADOW_EPSILON,
            time,
        }
    }

    /// A shadow ray between two surface points (this one and a point on an area light, say),
    /// with *both* ends offset off their surfaces, each towards the other end.
    #[inline]
    pub fn spawn_ray_to_hit(&self, other: &SurfaceHit, time: f32) -> Ray {
        let from = self.offset_origin(other.p - self.p);
        let to = other.offset_origin(from - other.p);
        Ray {
            origin: from,
            dir: to - from,
            t_max: 1.0 - SHADOW_EPSILON,
            time,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn floor_hit() -> SurfaceHit {
        SurfaceHit {
            t: 1.0,
            p: Vec3::new(0.5, 0.0, 0.5),
            p_error: Vec3::splat(1e-6),
            n: Vec3::Y,
            shading_n: Vec3::Y,
            uv: Vec2::splat(0.5),
            shape: 0,
        }
    }

    #[test]
    fn front_face_compares_the_arrival_direction_with_n() {
        let hit = floor_hit();
        assert!(hit.front_face(Vec3::new(0.0, -1.0, 0.3)));
        assert!(!hit.front_face(Vec3::new(0.0, 1.0, 0.3)));
    }

    #[test]
    fn spawned_rays_start_on_the_side_they_leave_towards() {
        let hit = floor_hit();
        let up = hit.spawn_ray(Vec3::new(0.1, 0.9, 0.0), 0.25);
        assert!(up.origin.y > 0.0);
        assert_eq!(up.time, 0.25);
        assert_eq!(up.t_max, f32::INFINITY);
        let down = hit.spawn_ray(Vec3::new(0.1, -0.9, 0.0), 0.0);
        assert!(down.origin.y < 0.0);
    }

    #[test]
    fn shadow_rays_stop_short_of_their_target() {
        let hit = floor_hit();
        let light = Vec3::new(2.0, 3.0, -1.0);
        let ray = hit.spawn_ray_to(light, 0.5);
        assert!(ray.origin.y > 0.0);
        assert!(ray.at(1.0).abs_diff_eq(light, 1e-6));
        assert!(ray.at(ray.t_max).distance(light) > 0.0);
        assert_eq!(ray.t_max, 1.0 - SHADOW_EPSILON);
        assert_eq!(ray.time, 0.5);
    }

    #[test]
    fn rays_between_two_hits_are_offset_at_both_ends() {
        let floor = floor_hit();
        let ceiling = SurfaceHit {
            p: Vec3::new(0.5, 2.0, 0.5),
            n: -Vec3::Y,
            shading_n: -Vec3::Y,
            ..floor
        };
        let ray = floor.spawn_ray_to_hit(&ceiling, 0.0);
        assert!(ray.origin.y > 0.0);
        let end = ray.origin + ray.dir;
        assert!(end.y < 2.0);
        assert_eq!(ray.t_max, 1.0 - SHADOW_EPSILON);
    }
}
