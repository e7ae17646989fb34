//! Axis-aligned bounding boxes and the slab test that decides whether a ray can reach one.

use glam::{BVec3A, Vec3, Vec3A};

use super::float::{gamma, next_float_down, next_float_up};
use crate::Ray;

/// How close to zero [`Aabb::rounded_outward`] lets a bound be: `2^-64`, about `5e-20`.
///
/// The box of a flat shape at zero (a floor at `y = 0`) would otherwise end one float from
/// zero, at `±1.4e-45`, a subnormal number. Every slab test against such a box then computes
/// with subnormals, which x86 processors handle in microcode at many times the cost of an
/// ordinary multiplication: chapter 01's spheres over their floor rendered a third faster
/// without them. A bound this far from zero keeps the slab test's differences and products
/// normal for every ray of any scene from `1e-5` to `1e5` in size, and as a margin it is far
/// below anything such a scene can resolve, so no box reaches more than it did by any visible
/// amount.
pub const SMALLEST_BOUND: f32 = f32::from_bits((127 - 64) << 23);

/// An axis-aligned box `{ x : min <= x <= max }` (componentwise).
///
/// A box with `min > max` on some axis contains nothing; [`Aabb::empty`] is the one with
/// `min = +∞` and `max = -∞`, which every [`union`](Aabb::union) replaces. Flat boxes
/// (`min == max` on an axis, such as the box of a floor parallelogram) and single points are fine.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The corner with the smallest coordinates.
    pub min: Vec3,
    /// The corner with the largest coordinates.
    pub max: Vec3,
}

impl Aabb {
    /// The box containing nothing: the starting point for a union of boxes.
    pub fn empty() -> Self {
        Self {
            min: Vec3::INFINITY,
            max: Vec3::NEG_INFINITY,
        }
    }

    /// The smallest box containing both points (in either order).
    pub fn from_points(a: Vec3, b: Vec3) -> Self {
        Self {
            min: a.min(b),
            max: a.max(b),
        }
    }

    /// The smallest box containing all the points (empty for no points).
    pub fn from_point_set(points: impl IntoIterator<Item = Vec3>) -> Self {
        points
            .into_iter()
            .fold(Self::empty(), |bounds, p| bounds.union_point(p))
    }

    /// Whether the box contains nothing (`min > max` on some axis, or NaN bounds).
    pub fn is_empty(&self) -> bool {
        // Written as "not (all min <= max)" so that NaN bounds count as empty too.
        !self.min.cmple(self.max).all()
    }

    /// The smallest box containing both boxes.
    pub fn union(self, other: Aabb) -> Self {
        Self {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    /// The smallest box containing the box and the point.
    pub fn union_point(self, p: Vec3) -> Self {
        Self {
            min: self.min.min(p),
            max: self.max.max(p),
        }
    }

    /// Whether `p` lies inside or on the boundary.
    pub fn contains(&self, p: Vec3) -> bool {
        self.min.cmple(p).all() && p.cmple(self.max).all()
    }

    /// Whether `other` lies entirely inside this box (an empty box lies inside every box).
    pub fn contains_box(&self, other: &Aabb) -> bool {
        other.is_empty() || (self.contains(other.min) && self.contains(other.max))
    }

    /// The centre of the box.
    pub fn centroid(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    /// The vector from `min` to `max` (zero for an empty box).
    pub fn diagonal(&self) -> Vec3 {
        if self.is_empty() {
            Vec3::ZERO
        } else {
            self.max - self.min
        }
    }

    /// The index (0, 1, 2 for x, y, z) of the axis along which the box is longest.
    pub fn largest_axis(&self) -> usize {
        self.diagonal().max_position()
    }

    /// The total area of the six faces: the probability that a random ray hitting a parent
    /// box also hits this one is proportional to it, which is what the BVH's surface-area
    /// heuristic relies on. Zero for an empty box.
    pub fn surface_area(&self) -> f32 {
        let d = self.diagonal();
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
    }

    /// The box grown by `margin` on every side.
    pub fn expanded(self, margin: Vec3) -> Self {
        Self {
            min: self.min - margin,
            max: self.max + margin,
        }
    }

    /// The box grown by one float on every side, and out to at least
    /// [`SMALLEST_BOUND`] from zero.
    ///
    /// Shapes whose corners are *computed* (`center - radius`, `corner + e1`) round their box
    /// outwards like this, so that the box certainly contains the exact surface even though
    /// each computed corner may have been rounded inwards by half a float.
    pub fn rounded_outward(self) -> Self {
        // A rounded bound closer to zero than `SMALLEST_BOUND` goes out to `outmost`.
        let at_least = |bound: f32, outmost: f32| {
            if bound.abs() < SMALLEST_BOUND {
                outmost
            } else {
                bound
            }
        };
        Self {
            min: self
                .min
                .to_array()
                .map(|v| at_least(next_float_down(v), -SMALLEST_BOUND))
                .into(),
            max: self
                .max
                .to_array()
                .map(|v| at_least(next_float_up(v), SMALLEST_BOUND))
                .into(),
        }
    }

    /// The part `(t_enter, t_exit)` of the ray's `[0, t_max]` that lies inside the box, if any.
    ///
    /// This is the slab test of [`Aabb::entry`], for one-off use; the BVH precomputes the
    /// [`SlabRay`] once per ray instead.
    pub fn intersect(&self, ray: &Ray) -> Option<(f32, f32)> {
        self.slab_interval(&SlabRay::new(ray), ray.t_max)
    }

    /// Where the ray enters the box (0 if it starts inside), if it passes through it somewhere
    /// in `[0, t_max]`.
    ///
    /// Conservative: a box the exact ray touches is never reported as missed. A ray that goes
    /// nowhere (an origin or a direction with a NaN or infinite component, a zero direction)
    /// passes through no box, as in the BVH's walk.
    #[inline]
    pub fn entry(&self, ray: &SlabRay, t_max: f32) -> Option<f32> {
        self.slab_interval(ray, t_max).map(|(t_enter, _)| t_enter)
    }

    /// The slab test (Kay and Kajiya 1986), made robust as in pbrt-v4.
    ///
    /// The box is the intersection of three slabs `min[a] <= x[a] <= max[a]`. The ray is inside
    /// slab `a` for `t` between `(min[a] - o[a]) / d[a]` and `(max[a] - o[a]) / d[a]`, and inside
    /// the box where all three ranges overlap. Two details make it robust:
    ///
    /// * Rounding can make the computed exit slightly too small, and then a ray that grazes a
    ///   flat box would miss it. Each exit is multiplied by `1 + 2 γ(3)`, which provably covers
    ///   the three roundings in `(max - o) * inv_dir`.
    /// * A ray parallel to a slab has `inv_dir = ±∞`. If its origin lies exactly on the slab's
    ///   plane, `0 * ∞` is NaN. Such a bound is replaced by one that cannot narrow the range
    ///   (0 for an entry, `∞` for an exit): the ray counts as inside that slab, which is the
    ///   conservative answer.
    ///
    /// The three axes are computed at once in SIMD lanes; each lane rounds exactly as the
    /// scalar `f32` operations would, so the answer does not depend on the instruction set.
    fn slab_interval(&self, ray: &SlabRay, t_max: f32) -> Option<(f32, f32)> {
        const EXIT_SLACK: f32 = 1.0 + 2.0 * gamma(3);
        // Its NaN bounds would not be the `0 × ∞` below but anything, even for an empty box.
        if !ray.goes_somewhere {
            return None;
        }
        let (min, max) = (Vec3A::from(self.min), Vec3A::from(self.max));
        let near = Vec3A::select(ray.negative, max, min);
        let far = Vec3A::select(ray.negative, min, max);
        let t_near = (near - ray.origin) * ray.inv_dir;
        let t_far = (far - ray.origin) * ray.inv_dir * EXIT_SLACK;
        // A NaN slab bound (0 × ∞) must not narrow the range: it becomes a bound that cannot.
        let t_near = Vec3A::select(t_near.is_nan_mask(), Vec3A::ZERO, t_near);
        let t_far = Vec3A::select(t_far.is_nan_mask(), Vec3A::INFINITY, t_far);
        // Comparisons rather than `f32::max` and `f32::min`, so that a NaN `t_max` is kept
        // (and nothing is hit) rather than skipped.
        let later = |a: f32, b: f32| if b > a { b } else { a };
        let earlier = |a: f32, b: f32| if b < a { b } else { a };
        let t_enter = later(0.0, t_near.max_element());
        let t_exit = earlier(t_max, t_far.min_element());
        (t_enter <= t_exit).then_some((t_enter, t_exit)) // false for a NaN t_max
    }
}

/// A ray prepared for many slab tests: the three divisions are done once, not once per box.
///
/// Kept as SIMD vectors: the slab test runs for every BVH node a ray visits, and a SIMD vector
/// computes all three axes in one instruction per operation, each lane rounding exactly as
/// `f32` does.
#[derive(Clone, Copy, Debug)]
pub struct SlabRay {
    /// The ray's origin.
    pub origin: Vec3A,
    /// `1 / dir`, componentwise; `±∞` where `dir` is `±0`.
    pub inv_dir: Vec3A,
    /// Whether the ray travels towards smaller coordinates on each axis, as a SIMD mask for
    /// choosing each axis's near and far side. Decided from the sign of `inv_dir`, so
    /// `dir = -0` counts as negative, matching `inv_dir = -∞`.
    negative: BVec3A,
    /// Whether the origin and the direction are finite and the direction is not zero: only
    /// then is a NaN bound the `0 × ∞` of a ray parallel to a slab.
    goes_somewhere: bool,
}

impl SlabRay {
    /// Precompute the inverse direction of `ray`.
    pub fn new(ray: &Ray) -> Self {
        let inv_dir = Vec3A::from(ray.dir.recip());
        Self {
            origin: ray.origin.into(),
            inv_dir,
            negative: inv_dir.cmplt(Vec3A::ZERO),
            goes_somewhere: ray.origin.is_finite()
                && ray.dir.is_finite()
                && ray.dir != glam::Vec3::ZERO,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_box() -> Aabb {
        Aabb::from_points(Vec3::ZERO, Vec3::ONE)
    }

    #[test]
    fn empty_is_the_identity_of_union() {
        let b = unit_box();
        assert_eq!(Aabb::empty().union(b), b);
        assert!(Aabb::empty().is_empty());
        assert_eq!(Aabb::empty().surface_area(), 0.0);
        assert_eq!(Aabb::from_point_set([]), Aabb::empty());
        let points = Aabb::from_point_set([Vec3::new(1.0, -2.0, 3.0), Vec3::new(-1.0, 2.0, 0.0)]);
        assert_eq!(points.min, Vec3::new(-1.0, -2.0, 0.0));
        assert_eq!(points.max, Vec3::new(1.0, 2.0, 3.0));
    }

    #[test]
    fn measures_of_a_box() {
        let b = Aabb::from_points(Vec3::new(1.0, 2.0, 3.0), Vec3::new(2.0, 4.0, 6.0));
        assert_eq!(b.centroid(), Vec3::new(1.5, 3.0, 4.5));
        assert_eq!(b.diagonal(), Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(b.largest_axis(), 2);
        assert_eq!(b.surface_area(), 2.0 * (2.0 + 6.0 + 3.0));
        assert!(b.contains(Vec3::new(1.0, 4.0, 5.0)));
        assert!(!b.contains(Vec3::new(0.9, 4.0, 5.0)));
        assert!(b.contains_box(&Aabb::from_points(Vec3::new(1.5, 3.0, 4.0), b.max)));
        let flat = Aabb::from_points(Vec3::ZERO, Vec3::new(1.0, 0.0, 1.0));
        assert_eq!(flat.surface_area(), 2.0);
        assert!(!flat.is_empty());
    }

    #[test]
    fn rounding_outward_strictly_grows_the_box() {
        let b = unit_box().rounded_outward();
        assert!(b.min.cmplt(Vec3::ZERO).all() && b.max.cmpgt(Vec3::ONE).all());
        assert_eq!(b.max, Vec3::ONE.to_array().map(f32::next_up).into());
    }

    #[test]
    fn rounding_outward_keeps_the_bounds_of_a_flat_box_at_zero_normal_numbers() {
        // A floor at y = 0, and a speck of dust a subnormal distance from zero.
        let floor = Aabb::from_points(Vec3::new(-1.0, 0.0, -1.0), Vec3::new(1.0, 0.0, 1.0));
        let dust = Aabb::from_points(Vec3::splat(-1e-40), Vec3::splat(1e-40));
        for flat in [floor, dust] {
            let b = flat.rounded_outward();
            assert!(b.contains_box(&flat), "{b:?} must still hold {flat:?}");
            for bound in b.min.to_array().into_iter().chain(b.max.to_array()) {
                assert!(
                    bound.is_normal(),
                    "{bound:e} in {b:?}: subnormal bounds make every slab test slow"
                );
            }
        }
        let b = floor.rounded_outward();
        assert_eq!((b.min.y, b.max.y), (-SMALLEST_BOUND, SMALLEST_BOUND));
        assert_eq!(
            b.max.x,
            1.0f32.next_up(),
            "far from zero a bound moves by one float only"
        );
        assert_eq!(b.min.x, (-1.0f32).next_down());
        // The bounds stay normal in the slab test's differences and products too, for a ray
        // from the origin of a scene of size 1e5 (direction components up to about 1e8).
        assert!((SMALLEST_BOUND / 1e8).is_normal());
        assert_eq!(SMALLEST_BOUND, 2.0f32.powi(-64));
    }

    #[test]
    fn slab_test_hits_and_misses() {
        let b = unit_box();
        let through = Ray::new(Vec3::new(-1.0, 0.5, 0.5), Vec3::X);
        let (t_enter, t_exit) = b.intersect(&through).unwrap();
        assert_eq!(t_enter, 1.0);
        assert!((t_exit - 2.0).abs() < 1e-5);
        let beside = Ray::new(Vec3::new(-1.0, 1.5, 0.5), Vec3::X);
        assert_eq!(b.intersect(&beside), None);
        let away = Ray::new(Vec3::new(-1.0, 0.5, 0.5), -Vec3::X);
        assert_eq!(b.intersect(&away), None);
        let too_short = Ray {
            t_max: 0.5,
            ..through
        };
        assert_eq!(b.intersect(&too_short), None);
        let from_inside = Ray::new(Vec3::splat(0.5), Vec3::new(0.3, -0.2, 0.9));
        assert_eq!(b.intersect(&from_inside).unwrap().0, 0.0);
    }

    #[test]
    fn rays_parallel_to_a_face_and_lying_in_its_plane_still_hit() {
        // dir.y = ±0 makes inv_dir.y = ±∞ and (min.y - origin.y) * inv_dir.y = 0 * ∞ = NaN.
        let b = unit_box();
        for zero in [0.0, -0.0] {
            for y in [0.0, 1.0] {
                let ray = Ray::new(Vec3::new(-1.0, y, 0.5), Vec3::new(1.0, zero, 0.0));
                assert!(b.intersect(&ray).is_some(), "y = {y}, dir.y = {zero:?}");
            }
            let outside = Ray::new(Vec3::new(-1.0, 1.5, 0.5), Vec3::new(1.0, zero, 0.0));
            assert!(b.intersect(&outside).is_none());
        }
    }

    #[test]
    fn flat_boxes_are_hit() {
        let floor = Aabb::from_points(Vec3::ZERO, Vec3::new(1.0, 0.0, 1.0));
        let down = Ray::new(Vec3::new(0.3, 1.0, 0.7), Vec3::new(0.1, -1.0, 0.05));
        assert!(floor.intersect(&down).is_some());
        let point = Aabb::from_points(Vec3::splat(0.25), Vec3::splat(0.25));
        let at_point = Ray::new(Vec3::new(0.25, 0.25, -3.0), Vec3::Z);
        assert!(point.intersect(&at_point).is_some());
    }
}
