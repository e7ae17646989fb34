//! The disc: a flat circle, the shape of spot-light apertures and lens-like area lights, or,
//! under a scene file's non-uniform scale, a flat ellipse.

use std::f32::consts::{PI, TAU};

use glam::{Vec2, Vec3};

use super::Crossing;
use super::plane::SpannedPlane;
use crate::Ray;
use crate::geometry::aabb::Aabb;
use crate::geometry::float::gamma;
use crate::geometry::hit::SurfaceHit;

/// The disc around `center` in the plane perpendicular to `normal`: a circle of one radius, or
/// an ellipse whose semi-axes lie along [`tangent`](Self::tangent) and
/// [`bitangent`](Self::bitangent) with the lengths [`radii`](Self::radii).
///
/// Its normal is the given one (normalised) and its surface parameters are
/// `uv = (ρ, φ / 2π)`, where the point is `center + ρ (r_t cos φ tangent + r_b sin φ bitangent)`:
/// `ρ` is the distance from the centre as a share of the rim's, as in Mitsuba's `disk`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disc {
    center: Vec3,
    normal: Vec3,
    /// The semi-axes' lengths along the tangent and the bitangent; equal for a circle.
    radii: Vec2,
    tangent: Vec3,
    bitangent: Vec3,
    plane: SpannedPlane,
}

impl Disc {
    /// The disc of `radius` around `center`, facing `normal` (which need not be unit length).
    ///
    /// A zero normal or a non-positive radius gives a disc that is never hit.
    pub fn new(center: Vec3, normal: Vec3, radius: f32) -> Self {
        let normal = normal.normalize_or_zero();
        let (tangent, bitangent) = if normal == Vec3::ZERO {
            (Vec3::ZERO, Vec3::ZERO)
        } else {
            let tangent = normal.any_orthonormal_vector();
            (tangent, normal.cross(tangent))
        };
        Self {
            center,
            normal,
            radii: Vec2::splat(radius),
            tangent,
            bitangent,
            // The disc lies exactly in the plane spanned by its tangents; the stored unit normal
            // is a rounded version of their cross product.
            plane: SpannedPlane::new(center, tangent, bitangent),
        }
    }

    /// The ellipse around `center` whose semi-axes are the perpendicular vectors `axis_t` and
    /// `axis_b`, facing `normal` (any length; it should be perpendicular to both axes).
    ///
    /// What a scene file's `disk` becomes under a scale that is not the same along its two
    /// axes: the image of the unit circle under any linear map is such an ellipse, its
    /// semi-axes the map's principal directions. Axes that are not perpendicular, or a zero
    /// normal, give an ellipse that is never hit.
    pub fn ellipse(center: Vec3, normal: Vec3, axis_t: Vec3, axis_b: Vec3) -> Self {
        let normal = normal.normalize_or_zero();
        let radii = Vec2::new(axis_t.length(), axis_b.length());
        let tangent = axis_t.normalize_or_zero();
        // On the side `axis_b` points to, so that the angle in `uv` turns from `axis_t`
        // towards `axis_b` (the shape is the same either way).
        let across = normal.cross(tangent);
        let bitangent = if across.dot(axis_b) < 0.0 {
            -across
        } else {
            across
        };
        let perpendicular = axis_t.dot(axis_b).abs() <= 1e-4 * radii.x * radii.y;
        Self {
            center,
            normal,
            radii: if perpendicular { radii } else { Vec2::ZERO },
            tangent,
            bitangent,
            plane: SpannedPlane::new(center, tangent, bitangent),
        }
    }

    /// The centre.
    pub fn center(&self) -> Vec3 {
        self.center
    }

    /// The unit normal.
    pub fn normal(&self) -> Vec3 {
        self.normal
    }

    /// The semi-axes' lengths along the [`tangent`](Self::tangent) and the
    /// [`bitangent`](Self::bitangent): the radius twice for a circle.
    pub fn radii(&self) -> Vec2 {
        self.radii
    }

    /// Whether the disc is a circle (both semi-axes of one length).
    pub fn is_circle(&self) -> bool {
        self.radii.x == self.radii.y
    }

    /// The in-plane direction where `φ = 0`.
    pub fn tangent(&self) -> Vec3 {
        self.tangent
    }

    /// The in-plane direction where `φ = π/2`: `normal × tangent` or its opposite (the side
    /// of the second axis an ellipse was made with, so that `uv` turn as the scene file's
    /// `to_world` turns them).
    pub fn bitangent(&self) -> Vec3 {
        self.bitangent
    }

    /// The point `center + a tangent + b bitangent` of the disc's plane.
    pub fn point_at(&self, a: f32, b: f32) -> Vec3 {
        self.center + a * self.tangent + b * self.bitangent
    }

    /// A box certainly containing the disc.
    ///
    /// Along axis `i` the disc reaches `√((r_t tangent_i)² + (r_b bitangent_i)²)` from its
    /// centre (so a floor disc is a flat box); that is grown a little for its own rounding.
    pub fn bounds(&self) -> Aabb {
        let t = self.tangent;
        let b = self.bitangent;
        let reach = if self.is_circle() {
            self.radii.x.abs() * (t * t + b * b).sqrt()
        } else {
            let (t, b) = (self.radii.x * t, self.radii.y * b);
            (t * t + b * b).sqrt()
        } * (1.0 + gamma(5));
        Aabb::from_points(self.center - reach, self.center + reach).rounded_outward()
    }

    /// The area `π r_t r_b` (`π r²` for a circle).
    pub fn area(&self) -> f32 {
        PI * self.radii.x * self.radii.y
    }

    /// The hit with `0 < t < ray.t_max`, seen from either side.
    ///
    /// Like [`Parallelogram::intersect`](super::Parallelogram::intersect): a robust plane crossing, then in-plane
    /// coordinates `(a, b)` along the tangents, then `p = center + a tangent + b bitangent` with
    /// the error bound `γ(3) (|center| + |a tangent| + |b bitangent|)`.
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        self.crossing(ray)
            .map(|crossing| self.surface_hit(crossing))
    }

    /// The crossing behind [`intersect`](Self::intersect), with `(a, b)`.
    pub(crate) fn crossing(&self, ray: &Ray) -> Option<Crossing> {
        // False for a NaN radius too.
        let has_area = self.radii.min_element() > 0.0 && self.normal != Vec3::ZERO;
        if !has_area {
            return None;
        }
        let t = self.plane.crossing(ray)?;
        let from_center = ray.at(t) - self.center;
        let a = from_center.dot(self.tangent);
        let b = from_center.dot(self.bitangent);
        // The distance from the centre as a share of the rim's.
        let rho = if self.is_circle() {
            let r = a.hypot(b);
            if r > self.radii.x {
                return None;
            }
            r / self.radii.x
        } else {
            (a / self.radii.x).hypot(b / self.radii.y)
        };
        if rho > 1.0 {
            return None;
        }
        Some(Crossing {
            t,
            coords: [a, b, rho],
        })
    }

    /// The hit record of a crossing.
    pub(crate) fn surface_hit(&self, crossing: Crossing) -> SurfaceHit {
        let [a, b, rho] = crossing.coords;
        let p = self.point_at(a, b);
        let p_error =
            gamma(3) * (self.center.abs() + (a * self.tangent).abs() + (b * self.bitangent).abs());
        let phi = if self.is_circle() {
            b.atan2(a)
        } else {
            (b / self.radii.y).atan2(a / self.radii.x)
        };
        let phi = if phi < 0.0 { phi + TAU } else { phi };
        SurfaceHit {
            t: crossing.t,
            p,
            p_error,
            n: self.normal,
            shading_n: self.normal,
            uv: Vec2::new(rho, phi / TAU),
            shape: 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use approx::assert_relative_eq;

    use super::*;

    fn floor_disc() -> Disc {
        Disc::new(Vec3::new(1.0, 0.5, -1.0), Vec3::Y * 3.0, 2.0)
    }

    #[test]
    fn hit_has_known_t_p_n_and_uv() {
        let disc = floor_disc();
        let target = disc.point_at(0.0, 1.0);
        let ray = Ray::new(target + Vec3::Y * 4.0, -Vec3::Y);
        let hit = disc.intersect(&ray).unwrap();
        assert_relative_eq!(hit.t, 4.0, max_relative = 1e-6);
        assert_relative_eq!(hit.p, target, epsilon = 1e-6);
        assert_eq!(hit.n, Vec3::Y);
        assert_relative_eq!(hit.uv, Vec2::new(0.5, 0.25), epsilon = 1e-6);
        assert!(hit.front_face(ray.dir));
    }

    #[test]
    fn the_tangent_frame_is_right_handed_and_orthonormal() {
        let disc = Disc::new(Vec3::ZERO, Vec3::new(0.3, -0.4, 0.8), 1.0);
        let (t, b, n) = (disc.tangent(), disc.bitangent(), disc.normal());
        assert_relative_eq!(t.cross(b), n, epsilon = 1e-6);
        assert_relative_eq!(t.dot(n), 0.0, epsilon = 1e-6);
        assert!(t.is_normalized() && b.is_normalized() && n.is_normalized());
    }

    #[test]
    fn misses_outside_the_rim_and_behind() {
        let disc = floor_disc();
        let outside = disc.point_at(1.5, 1.5) + Vec3::Y;
        assert!(disc.intersect(&Ray::new(outside, -Vec3::Y)).is_none());
        let above = disc.center() + Vec3::Y;
        assert!(disc.intersect(&Ray::new(above, Vec3::Y)).is_none());
    }

    #[test]
    fn grazing_rays_hit_inside_and_miss_outside() {
        let disc = Disc::new(Vec3::ZERO, Vec3::Y, 1.0);
        let dir = Vec3::new(1.0, -1e-4, 0.0);
        let inside = Ray::new(Vec3::new(-2.0, 1.5e-4, 0.0), dir);
        let hit = disc
            .intersect(&inside)
            .expect("nearly parallel ray inside hits");
        assert_relative_eq!(hit.p.x, -0.5, epsilon = 1e-3);
        let outside = Ray::new(Vec3::new(-2.0, 3.5e-4, 0.0), dir);
        assert!(disc.intersect(&outside).is_none());
    }

    #[test]
    fn t_max_is_respected() {
        let disc = floor_disc();
        let ray = Ray::new(disc.center() + 2.0 * Vec3::Y, -Vec3::Y);
        assert!(disc.intersect(&Ray { t_max: 2.0, ..ray }).is_none());
        assert!(
            disc.intersect(&Ray {
                t_max: 2.001,
                ..ray
            })
            .is_some()
        );
    }

    #[test]
    fn degenerate_discs_are_never_hit() {
        let ray = Ray::new(Vec3::Y, -Vec3::Y);
        assert!(
            Disc::new(Vec3::ZERO, Vec3::ZERO, 1.0)
                .intersect(&ray)
                .is_none()
        );
        assert!(
            Disc::new(Vec3::ZERO, Vec3::Y, 0.0)
                .intersect(&ray)
                .is_none()
        );
    }

    #[test]
    fn bounds_are_flat_for_a_floor_disc_and_area_is_pi_r_squared() {
        let disc = floor_disc();
        let b = disc.bounds();
        assert!(b.diagonal().y < 1e-6);
        assert_relative_eq!(b.diagonal().x, 4.0, max_relative = 1e-5);
        for phi in [0.0f32, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0] {
            assert!(b.contains(disc.point_at(2.0 * phi.cos(), 2.0 * phi.sin())));
        }
        assert_relative_eq!(disc.area(), 4.0 * PI);
    }

    /// An ellipse on the floor, 3 along x and 1 along z.
    fn floor_ellipse() -> Disc {
        Disc::ellipse(Vec3::new(1.0, 0.5, -1.0), Vec3::Y, 3.0 * Vec3::X, Vec3::Z)
    }

    #[test]
    fn an_ellipse_is_hit_inside_its_rim_along_both_axes() {
        let ellipse = floor_ellipse();
        let down = |x: f32, z: f32| Ray::new(ellipse.center() + Vec3::new(x, 2.0, z), -Vec3::Y);
        for (x, z, inside) in [
            (2.9, 0.0, true),
            (3.1, 0.0, false),
            (0.0, 0.9, true),
            (0.0, 1.1, false),
            // (2, 0.7): (2/3)² + 0.7² = 0.93 inside; (2, 0.8): 1.08 outside.
            (2.0, 0.7, true),
            (2.0, 0.8, false),
        ] {
            assert_eq!(
                ellipse.intersect(&down(x, z)).is_some(),
                inside,
                "({x}, {z})"
            );
        }
        let hit = ellipse.intersect(&down(1.5, 0.0)).unwrap();
        assert_eq!(hit.n, Vec3::Y);
        assert_relative_eq!(hit.uv.x, 0.5, epsilon = 1e-6);
    }

    #[test]
    fn an_ellipse_has_area_pi_ab_and_bounds_around_its_rim() {
        let ellipse = floor_ellipse();
        assert!(!ellipse.is_circle());
        assert_relative_eq!(ellipse.area(), 3.0 * PI, max_relative = 1e-6);
        let b = ellipse.bounds();
        assert!(b.diagonal().y < 1e-6);
        assert_relative_eq!(b.diagonal().x, 6.0, max_relative = 1e-5);
        assert_relative_eq!(b.diagonal().z, 2.0, max_relative = 1e-5);
        let (t, s) = (ellipse.tangent(), ellipse.bitangent());
        // The bitangent is on the side of the second axis given, Z (not Y x X = -Z).
        assert_relative_eq!(t, Vec3::X, epsilon = 1e-6);
        assert_relative_eq!(s, Vec3::Z, epsilon = 1e-6);
        // Axes that are not perpendicular describe no ellipse: never hit.
        let skew = Disc::ellipse(Vec3::ZERO, Vec3::Y, Vec3::X, Vec3::X + Vec3::Z);
        assert!(skew.intersect(&Ray::new(Vec3::Y, -Vec3::Y)).is_none());
    }
}
