//! The robust ray–plane step shared by quads and discs.

use glam::Vec3;

use crate::Ray;
use crate::geometry::interval::{self, Interval, IntervalVec3};

/// The plane through `anchor` spanned by the exact vectors `e1` and `e2`.
///
/// Its normal `e1 × e2` is kept as intervals computed once, so the plane the intersection test
/// uses is *exactly* the plane of the points `anchor + u e1 + v e2` that the hit records report,
/// not a rounded neighbour of it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SpannedPlane {
    anchor: Vec3,
    normal: IntervalVec3,
}

impl SpannedPlane {
    /// The plane through `anchor` containing the directions `e1` and `e2`.
    pub fn new(anchor: Vec3, e1: Vec3, e2: Vec3) -> Self {
        Self {
            anchor,
            normal: interval::cross(interval::exact_vec(e1), interval::exact_vec(e2)),
        }
    }

    /// The ray parameter where the ray crosses the plane, if it certainly does so at some
    /// `0 < t < ray.t_max`.
    ///
    /// `t = dot(anchor - o, N) / dot(d, N)`, evaluated in interval arithmetic: a crossing whose
    /// interval reaches 0 or below is rejected, and so is one whose denominator might be zero
    /// (a ray parallel to the plane). The returned `t` is the midpoint of the interval.
    pub fn crossing(&self, ray: &Ray) -> Option<f32> {
        if self.certainly_not_ahead(ray) {
            return None;
        }
        self.interval_crossing(ray)
    }

    /// A cheap first look, in plain floats: whether the crossing is certainly not ahead of the
    /// origin, so that [`interval_crossing`](Self::interval_crossing) would reject it too.
    ///
    /// It repeats the interval computation operation by operation, in the same order, with the
    /// normal's lower ends. Rounding is monotone, so each plain result lies inside the interval
    /// of the same operation, and so does the plain `t` (when the denominator's interval holds
    /// zero the interval test rejects anyway). A plain `t` that is not positive therefore
    /// means an interval whose lower end is not positive. Most rays tested against a plane
    /// that is behind them stop here, at a fraction of the interval arithmetic's cost; the
    /// answer is the same either way.
    fn certainly_not_ahead(&self, ray: &Ray) -> bool {
        let n = Vec3::new(self.normal[0].lo, self.normal[1].lo, self.normal[2].lo);
        let dot = |a: Vec3| a.x * n.x + a.y * n.y + a.z * n.z;
        let t = dot(self.anchor - ray.origin) / dot(ray.dir);
        t <= 0.0 // false for NaN: then the intervals decide
    }

    /// The crossing by interval arithmetic alone: what [`crossing`](Self::crossing) returns.
    fn interval_crossing(&self, ray: &Ray) -> Option<f32> {
        let towards_anchor = interval::difference(self.anchor, ray.origin);
        let numerator: Interval = interval::dot(towards_anchor, self.normal);
        let denominator = interval::dot_exact(ray.dir, self.normal);
        let t = numerator / denominator;
        let certainly_ahead = t.lo > 0.0;
        if !certainly_ahead {
            return None;
        }
        let t = t.midpoint();
        (t < ray.t_max).then_some(t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_in_front_behind_and_parallel() {
        let floor = SpannedPlane::new(Vec3::ZERO, Vec3::Z, Vec3::X);
        let down = Ray::new(Vec3::new(0.3, 2.0, 0.1), -Vec3::Y);
        let t = floor.crossing(&down).unwrap();
        assert!((t - 2.0).abs() < 1e-6, "{t}");
        let up = Ray::new(Vec3::new(0.3, 2.0, 0.1), Vec3::Y);
        assert_eq!(floor.crossing(&up), None);
        let parallel = Ray::new(Vec3::new(0.3, 2.0, 0.1), Vec3::X);
        assert_eq!(floor.crossing(&parallel), None);
        assert_eq!(floor.crossing(&Ray { t_max: 2.0, ..down }), None);
    }

    /// The quick test only ever rejects what the intervals reject, so `crossing` is the
    /// interval computation's answer, bit for bit, for rays in all directions, from near and
    /// far, on and off the plane.
    #[test]
    fn the_quick_rejection_agrees_with_the_intervals() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg32::seed_from_u64(8);
        let mut vec = |scale: f32| {
            Vec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            ) * scale
        };
        let (mut rejected_early, mut rejected) = (0, 0);
        for i in 0..200_000 {
            let scale = [1e-3, 1.0, 1e3][i % 3];
            let (anchor, e1, e2) = (vec(scale), vec(1.0), vec(1.0));
            let plane = SpannedPlane::new(anchor, e1, e2);
            // Some origins exactly on the plane, where rounding decides.
            let origin = if i % 5 == 0 {
                anchor + 0.5 * e1
            } else {
                vec(scale)
            };
            let ray = Ray::new(origin, vec(1.0));
            let full = plane.interval_crossing(&ray);
            if plane.certainly_not_ahead(&ray) {
                rejected_early += 1;
                assert_eq!(full, None, "{ray:?} {plane:?}");
            }
            assert_eq!(plane.crossing(&ray), full);
            rejected += usize::from(full.is_none());
        }
        // The quick test does its job: it catches most rejections.
        assert!(
            rejected_early * 10 > rejected * 8,
            "{rejected_early} of {rejected}"
        );
    }

    #[test]
    fn a_ray_starting_on_the_plane_does_not_cross_it() {
        // Binary fractions, so that `on_plane` is exactly on the plane.
        let anchor = Vec3::new(0.5, 0.25, 0.125);
        let e1 = Vec3::new(1.0, 0.5, 0.0);
        let tilted = SpannedPlane::new(anchor, e1, Vec3::new(0.0, 0.75, 1.0));
        let on_plane = anchor + 0.5 * e1;
        for dir in [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::ONE] {
            assert_eq!(tilted.crossing(&Ray::new(on_plane, dir)), None);
        }
    }
}
