//! The robust ray–plane step shared by parallelograms and discs.

use glam::Vec3;

use crate::Ray;
use crate::geometry::float::{MACHINE_EPSILON, TINY};
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
    /// A member of each component's interval, which the plain-float first look computes
    /// with: the lower end, or 0 where the interval holds 0. An exact zero component (every
    /// axis-aligned plane has two) becomes an interval of the two smallest subnormal numbers
    /// around 0, and a multiplication by a subnormal number costs x86 processors a microcode
    /// assist of about a hundred cycles; 0 costs nothing and is as good a member.
    normal_plain: Vec3,
    /// `|e1_j e2_k| + |e1_k e2_j|` for each component `i` of `e1 × e2`: the size of the
    /// numbers the component is made of, which bounds its interval's width even where the two
    /// products cancel.
    normal_size: Vec3,
}

/// A crossing computed in plain floats, with a bound on how far from it the crossing that the
/// interval arithmetic reports can be (see [`SpannedPlane::rough_crossing`]).
#[derive(Clone, Copy, Debug)]
struct RoughCrossing {
    /// The crossing, in plain floats.
    t: f32,
    /// `|t - t_exact| <= t_error` for the exact crossing, and likewise for the midpoint that
    /// [`SpannedPlane::interval_crossing`] would return; infinite (or NaN) when the plain
    /// floats cannot tell.
    t_error: f32,
}

/// How wide an interval result can be per unit of the magnitudes it is computed from (see
/// [`SpannedPlane::rough_crossing`]).
///
/// The numerator's and the denominator's chains of operations have at most seven steps (the
/// normal's two products and difference, a product with it, two sums), and each step rounds
/// by at most half a float and widens by one, a relative `3 ε` per step at most: `21 ε`. The
/// bound is six times that, so that no second-order term needs counting; it only sends a few
/// more crossings on to the intervals.
const WIDTH_PER_MAGNITUDE: f32 = 128.0 * MACHINE_EPSILON;

impl SpannedPlane {
    /// The plane through `anchor` containing the directions `e1` and `e2`.
    pub fn new(anchor: Vec3, e1: Vec3, e2: Vec3) -> Self {
        let normal = interval::cross(interval::exact_vec(e1), interval::exact_vec(e2));
        let products = |j: f32, k: f32, j2: f32, k2: f32| (j * k2).abs() + (k * j2).abs();
        Self {
            anchor,
            normal,
            normal_plain: Vec3::from_array(normal.map(|component| {
                if component.contains_zero() {
                    0.0
                } else {
                    component.lo
                }
            })),
            normal_size: Vec3::new(
                products(e1.y, e1.z, e2.y, e2.z),
                products(e1.z, e1.x, e2.z, e2.x),
                products(e1.x, e1.y, e2.x, e2.y),
            ),
        }
    }

    /// The ray parameter where the ray crosses the plane, if it certainly does so at some
    /// `0 < t < ray.t_max`.
    ///
    /// `t = dot(anchor - o, N) / dot(d, N)`, first in plain floats with a bound on its error
    /// ([`rough_crossing`](Self::rough_crossing)). When that range is all above 0, the
    /// crossing is certainly ahead and the plain `t` is the answer. Otherwise (a ray starting
    /// on or very near the plane, as every secondary ray leaving it does, or one nearly
    /// parallel to it) interval arithmetic decides ([`interval_crossing`](Self::interval_crossing)):
    /// a crossing whose interval reaches 0 or below is rejected, and so is one whose
    /// denominator might be zero. Both ways, a crossing counts only if it is certainly ahead,
    /// and they accept the same crossings; only the `t` they report differs, by less than
    /// the bound.
    pub fn crossing(&self, ray: &Ray) -> Option<f32> {
        let rough = self.rough_crossing(ray)?;
        if rough.certainly_ahead() {
            return (rough.t < ray.t_max).then_some(rough.t);
        }
        self.interval_crossing(ray)
    }

    /// The crossing in plain floats and a bound on its error, or `None` if the crossing is
    /// certainly not ahead of the origin, so that [`interval_crossing`](Self::interval_crossing)
    /// would reject it too.
    ///
    /// It repeats the interval computation operation by operation, in the same order, with a
    /// member of each of the normal's intervals. Rounding is monotone, so each plain result
    /// lies inside the interval of the same operation, and so does the plain `t` (when the
    /// denominator's interval holds zero the interval test rejects anyway). A plain `t` that
    /// is not positive therefore means an interval whose lower end is not positive. Most rays
    /// tested against a plane that is behind them stop here.
    ///
    /// The error bound: the plain numerator `n` and denominator `d` lie in their intervals,
    /// whose widths are at most `w_n = W Σ |anchor - o|_i size_i` and `w_d = W Σ |d|_i size_i`
    /// ([`WIDTH_PER_MAGNITUDE`] `W`, the normal's `size`, plus [`TINY`] allowances). The
    /// intervals hold the exact numerator and denominator too. Every quotient of a member of
    /// the one by a member of the other is then within `(w_n + (|n| + w_n) w_d / d_min) / d_min`
    /// of `n / d`, where `d_min = |d| - w_d` is the least size of the denominator; the plain
    /// `t` is `n / d` rounded once, and the interval's ends are rounded and widened by a few
    /// floats of `t`. So both the exact crossing and the interval's midpoint are within the
    /// bound of the plain `t`. The bound is doubled, which covers its own rounding; when
    /// `d_min` is not positive (a ray nearly parallel to the plane) it is infinite.
    fn rough_crossing(&self, ray: &Ray) -> Option<RoughCrossing> {
        let n = self.normal_plain;
        let dot = |a: Vec3| a.x * n.x + a.y * n.y + a.z * n.z;
        let towards_anchor = self.anchor - ray.origin;
        let numerator = dot(towards_anchor);
        let denominator = dot(ray.dir);
        let t = numerator / denominator;
        if t <= 0.0 {
            return None; // false for NaN: then the intervals decide
        }
        let towards_anchor = towards_anchor.abs();
        let numerator_width = WIDTH_PER_MAGNITUDE * towards_anchor.dot(self.normal_size)
            + TINY * (1.0 + towards_anchor.element_sum());
        let direction = ray.dir.abs();
        let denominator_width = WIDTH_PER_MAGNITUDE * direction.dot(self.normal_size)
            + TINY * (1.0 + direction.element_sum());
        let least_denominator = denominator.abs() - denominator_width;
        let t_error = if least_denominator > 0.0 {
            let spread = (numerator_width
                + (numerator.abs() + numerator_width) * denominator_width / least_denominator)
                / least_denominator;
            2.0 * spread + 16.0 * MACHINE_EPSILON * t + TINY
        } else {
            f32::INFINITY
        };
        Some(RoughCrossing { t, t_error })
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

impl RoughCrossing {
    /// Whether the whole range `t ± t_error`, and so the exact crossing, is ahead of the
    /// origin. (A difference of two floats rounds to a positive number only if it is
    /// positive.)
    fn certainly_ahead(&self) -> bool {
        self.t - self.t_error > 0.0 // false for NaN
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

    #[test]
    fn the_plain_normal_has_no_subnormal_components() {
        // The intervals of an axis-aligned wall's zero components reach the smallest
        // subnormal numbers on either side; the plain normal takes 0 from them.
        let wall = SpannedPlane::new(Vec3::new(1.0, 2.0, 3.0), 2.0 * Vec3::X, 2.0 * Vec3::Y);
        assert!(wall.normal[0].lo < 0.0 && wall.normal[1].hi > 0.0);
        assert_eq!((wall.normal_plain.x, wall.normal_plain.y), (0.0, 0.0));
        assert!(wall.normal_plain.z > 3.99);
        for (e1, e2) in [(Vec3::X, Vec3::Z), (Vec3::new(1.0, 1e-30, 0.0), Vec3::Y)] {
            let plane = SpannedPlane::new(Vec3::ZERO, e1, e2);
            assert!(
                plane
                    .normal_plain
                    .to_array()
                    .iter()
                    .all(|c| !c.is_subnormal()),
                "{:?}",
                plane.normal_plain
            );
        }
    }

    /// Random planes and rays for checking the plain-float first look against the intervals:
    /// all directions, near and far, some origins exactly on the plane (where rounding
    /// decides), some directions within a millionth of the plane (where the crossing is
    /// ill-conditioned), axis-aligned planes (whose normals have exact zeros) and planes far
    /// from the origin.
    fn random_planes_and_rays(
        count: usize,
        seed: u64,
    ) -> impl Iterator<Item = (Vec3, Vec3, Vec3, Ray)> {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg32::seed_from_u64(seed);
        (0..count).map(move |i| {
            let mut vec = |scale: f32| {
                Vec3::new(
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                    rng.random_range(-1.0..1.0),
                ) * scale
            };
            let scale = [1e-3, 1.0, 1e3][i % 3];
            let (e1, e2) = if i % 7 == 0 {
                (Vec3::X * scale, Vec3::Z * scale)
            } else {
                (vec(scale), vec(scale))
            };
            let far = if i % 11 == 0 {
                Vec3::splat(1e5)
            } else {
                Vec3::ZERO
            };
            let anchor = vec(scale) + far;
            let origin = if i % 5 == 0 {
                anchor + 0.5 * e1
            } else {
                vec(3.0 * scale) + far
            };
            let dir = if i % 13 == 0 {
                (e1 + 1e-6 * e1.cross(e2).normalize() * e1.length()).normalize()
            } else {
                vec(1.0)
            };
            (anchor, e1, e2, Ray::new(origin, dir))
        })
    }

    /// The crossing `t_exact` in double precision, from the same single-precision inputs: as
    /// good as exact at the scale of the bounds checked against it.
    fn crossing_in_f64(anchor: Vec3, e1: Vec3, e2: Vec3, ray: &Ray) -> f64 {
        let n = e1.as_dvec3().cross(e2.as_dvec3());
        (anchor.as_dvec3() - ray.origin.as_dvec3()).dot(n) / ray.dir.as_dvec3().dot(n)
    }

    /// The plain-float crossing and its bound against the intervals and against double
    /// precision: what the plain floats reject the intervals reject; the exact crossing and
    /// the interval's are within the bound; a crossing the bound calls certainly ahead is
    /// one the intervals accept; so `crossing` accepts exactly the crossings the intervals
    /// accept, and reports them within the bound.
    #[test]
    fn the_plain_crossing_agrees_with_the_intervals() {
        let (mut rejected_early, mut rejected, mut plain, mut accepted) = (0, 0, 0, 0);
        for (anchor, e1, e2, ray) in random_planes_and_rays(200_000, 8) {
            let plane = SpannedPlane::new(anchor, e1, e2);
            let full = plane.interval_crossing(&ray);
            let crossing = plane.crossing(&ray);
            assert_eq!(crossing.is_some(), full.is_some(), "{ray:?} {plane:?}");
            match plane.rough_crossing(&ray) {
                None => {
                    rejected_early += 1;
                    assert_eq!(full, None, "{ray:?} {plane:?}");
                }
                Some(rough) => {
                    if let Some(t) = full {
                        assert!((t - rough.t).abs() <= rough.t_error, "{t} {rough:?}");
                    }
                    let exact = crossing_in_f64(anchor, e1, e2, &ray);
                    // (An infinite bound holds anything, an infinite exact crossing too.)
                    let error = (exact - f64::from(rough.t)).abs();
                    let within = error <= f64::from(rough.t_error) || rough.t_error.is_nan();
                    assert!(within || exact.is_nan(), "{exact} {rough:?}");
                    if rough.certainly_ahead() {
                        plain += 1;
                        assert!(exact > 0.0 && full.is_some(), "{exact} {rough:?}");
                        assert_eq!(crossing, Some(rough.t));
                    }
                }
            }
            rejected += usize::from(full.is_none());
            accepted += usize::from(full.is_some());
        }
        // The plain floats do their job: they catch most rejections, and they answer for
        // most crossings (not for the fifth of the rays that start on the plane, nor for the
        // grazing ones, one in 13).
        assert!(
            rejected_early * 10 > rejected * 8,
            "{rejected_early} of {rejected}"
        );
        assert!(plain * 10 > accepted * 8, "{plain} of {accepted}");
    }

    /// The error bound is not a formality: it is a small fraction of `t` (a few hundred
    /// floats, from the generous allowance per operation).
    #[test]
    fn the_error_bound_is_tight_for_an_ordinary_ray() {
        let floor = SpannedPlane::new(Vec3::ZERO, Vec3::Z, Vec3::X);
        let ray = Ray::new(Vec3::new(0.3, 2.0, 0.1), Vec3::new(0.2, -1.0, 0.1));
        let rough = floor.rough_crossing(&ray).unwrap();
        assert!(rough.t_error < 1e-4 * rough.t, "{rough:?}");
        assert!(rough.certainly_ahead());
        // Just above the floor, the crossing is still certainly ahead: the bound scales with
        // the numbers it is computed from.
        let just_above = Ray::new(Vec3::new(0.3, 1e-7, 0.1), Vec3::new(0.2, -1.0, 0.1));
        assert!(floor.rough_crossing(&just_above).unwrap().certainly_ahead());
        let on_the_floor = Ray::new(Vec3::new(0.3, 0.0, 0.1), Vec3::new(0.2, -1.0, 0.1));
        assert!(floor.rough_crossing(&on_the_floor).is_none());
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
