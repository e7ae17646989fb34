//! Four triangles tested against one ray at once: the watertight test of [`RaySpace`] with a
//! triangle in each SIMD lane.
//!
//! A BVH leaf of a mesh holds up to four triangles, and a ray misses nearly all of the
//! triangles it is tested against. Tested one by one, each miss costs a pass through the test's
//! branches; side by side, the four share every instruction up to the first question that
//! rules a lane out, and the test ends for all four when none is left. Each lane computes
//! exactly what the one-triangle test computes, operation by operation, so a leaf's answer is
//! bit for bit the answer of testing its triangles in order.

use glam::{Vec3, Vec4};

use super::Crossing;
use crate::Ray;
use crate::geometry::float::gamma;

/// Lanes: triangles side by side.
pub(crate) const LANES: usize = 4;

/// The watertight test, following pbrt-v4 (section 6.5.3).
///
/// The vertices are moved into a coordinate system where the ray starts at the origin and
/// runs along `+z`: translate by `-o`, permute the axes so that the largest component of
/// the direction becomes z, then shear x and y so that the direction becomes `(0, 0, 1)`.
/// The ray then hits the triangle if the 2D point `(0, 0)` is inside the projected triangle,
/// which the signs of the three edge functions `e_i` decide.
///
/// *Watertight* means a ray through an edge shared by two triangles hits at least one of
/// them. Both triangles compute that edge's function from the same two transformed vertices,
/// a difference of two products: in `f32` its sign is exact or it is 0, and where it is 0 it
/// is computed again in `f64`, where the products of `f32`s are exact. So its sign is exact,
/// and the two triangles see exactly opposite values and cannot both reject the ray.
///
/// The test is split at what depends on the ray alone, which is this coordinate system: which
/// axis becomes z and the shear that turns the direction into `(0, 0, 1)`. A walk through a
/// mesh works it out once per ray and tests the triangles of each leaf it meets four at a time
/// ([`nearest_crossing`](Self::nearest_crossing) and [`any_crossing`](Self::any_crossing),
/// below), from their vertices alone ([`FourTriangles`]: the walk keeps them apart
/// from the rest of a triangle). A triangle without area must be left out before (it is never
/// hit).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RaySpace {
    /// The ray's origin, its axes renamed: `origin.x` is its coordinate along `axes[0]`.
    origin: Vec3,
    /// The axes that become x, y and z.
    axes: [usize; 3],
    shear_x: f32,
    shear_y: f32,
    scale_z: f32,
}

impl RaySpace {
    /// The ray's space; none for a zero direction, which crosses nothing.
    #[inline]
    pub(crate) fn new(ray: &Ray) -> Option<Self> {
        let kz = ray.dir.abs().max_position();
        let kx = (kz + 1) % 3;
        let ky = (kx + 1) % 3;
        let permute = |v: Vec3| {
            let v = v.to_array();
            Vec3::new(v[kx], v[ky], v[kz])
        };
        let d = permute(ray.dir);
        if d.z == 0.0 {
            return None; // a zero direction
        }
        Some(Self {
            origin: permute(ray.origin),
            axes: [kx, ky, kz],
            shear_x: -d.x / d.z,
            shear_y: -d.y / d.z,
            scale_z: 1.0 / d.z,
        })
    }
}

/// Up to four triangles' vertices, stored so that one SIMD register holds the same coordinate
/// of the same vertex of all four: `corners[v][axis]` is lane `i`'s vertex `v` along `axis`.
///
/// Lanes beyond the triangles hold zeros; the tests are told how many lanes count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FourTriangles {
    corners: [[Vec4; 3]; 3],
}

impl FourTriangles {
    /// The triangles `triangles` (at most four; their vertices `p0 p1 p2`) in lanes `0, 1, ...`.
    pub(crate) fn new(triangles: &[[Vec3; 3]]) -> Self {
        assert!(triangles.len() <= LANES, "at most four triangles");
        let mut corners = [[Vec4::ZERO; 3]; 3];
        for (lane, p) in triangles.iter().enumerate() {
            for (vertex, point) in p.iter().enumerate() {
                for axis in 0..3 {
                    corners[vertex][axis][lane] = point[axis];
                }
            }
        }
        Self { corners }
    }
}

/// What a ray's test of four triangles leaves to decide lane by lane: the quantities that do
/// not depend on `t_max`, for the lanes that may still hold a crossing.
struct LaneCrossings {
    /// Bit `i` for lane `i`: the ray passes inside its edges, and its crossing is in front of
    /// the origin and before the `t_max` the test was given.
    candidates: u32,
    /// The edge functions `e0, e1, e2`, lane by lane.
    e: [[f32; LANES]; 3],
    /// Their sum, the determinant.
    det: [f32; LANES],
    /// `t` times the determinant, before dividing.
    t_scaled: [f32; LANES],
    /// The ray parameter of the crossing.
    t: [f32; LANES],
    /// The bound on the error of `t`.
    delta_t: [f32; LANES],
    /// `1 / det`.
    inv_det: [f32; LANES],
}

impl LaneCrossings {
    /// Whether lane `lane`'s crossing is certainly at `0 < t < t_max`. The first test was
    /// given a `t_max` at least this large, so only its comparisons with `t_max` are redone.
    #[inline]
    fn in_range(&self, lane: usize, t_max: f32) -> bool {
        let (t_scaled, det, t) = (self.t_scaled[lane], self.det[lane], self.t[lane]);
        !out_of_range(t_scaled, det, t_max) && self.delta_t[lane] < t && t < t_max
    }

    /// Lane `lane`'s crossing.
    fn crossing(&self, lane: usize) -> Crossing {
        let inv_det = self.inv_det[lane];
        Crossing {
            t: self.t[lane],
            coords: self.e.map(|e| e[lane] * inv_det),
        }
    }
}

/// Whether `t = t_scaled / det` is outside `(0, t_max]`, decided before dividing (for a lane
/// whose `t_scaled` and `det` are not NaN; a NaN one is ruled out later, by its `t`).
#[inline]
fn out_of_range(t_scaled: f32, det: f32, t_max: f32) -> bool {
    let t_max_scaled = t_max * det;
    if det < 0.0 {
        t_scaled >= 0.0 || t_scaled < t_max_scaled
    } else {
        t_scaled <= 0.0 || t_scaled > t_max_scaled
    }
}

impl RaySpace {
    /// The nearest crossing at `0 < t < t_max` among the first `count` lanes of `triangles`,
    /// with its lane: the one testing them in lane order would keep, each hit shrinking
    /// `t_max` (so of two crossings at the same `t`, the first lane's).
    #[inline]
    pub(crate) fn nearest_crossing(
        &self,
        triangles: &FourTriangles,
        count: usize,
        mut t_max: f32,
    ) -> Option<(usize, Crossing)> {
        let lanes = self.lane_crossings(triangles, count, t_max)?;
        let mut nearest = None;
        let mut candidates = lanes.candidates;
        while candidates != 0 {
            let lane = candidates.trailing_zeros() as usize;
            candidates &= candidates - 1;
            if lanes.in_range(lane, t_max) {
                t_max = lanes.t[lane];
                nearest = Some(lane);
            }
        }
        nearest.map(|lane| (lane, lanes.crossing(lane)))
    }

    /// Whether the ray crosses any of the first `count` lanes of `triangles` at
    /// `0 < t < t_max`.
    #[inline]
    pub(crate) fn any_crossing(&self, triangles: &FourTriangles, count: usize, t_max: f32) -> bool {
        self.lane_crossings(triangles, count, t_max)
            .is_some_and(|lanes| {
                (0..LANES)
                    .any(|lane| lanes.candidates & (1 << lane) != 0 && lanes.in_range(lane, t_max))
            })
    }

    /// The test of [`RaySpace`] in four lanes, up to what depends on `t_max`; none if no lane
    /// of the first `count` can hold a crossing before `t_max`.
    ///
    /// The vertices are moved into the ray's space (translated, axes renamed, sheared), and
    /// the three edge functions decide whether `(0, 0)` is inside the projected triangle. Each
    /// edge function is a difference of two products with its exact sign ([`edge_functions`]:
    /// in `f32`, and in `f64` where `f32` gives 0), and two triangles sharing an edge see
    /// exactly opposite values and cannot both reject a ray through it (watertightness).
    #[inline(always)]
    fn lane_crossings(
        &self,
        triangles: &FourTriangles,
        count: usize,
        t_max: f32,
    ) -> Option<LaneCrossings> {
        let [kx, ky, kz] = self.axes;
        // Vertex v of every lane: translated and permuted (`x`, `y`, `depth`), then sheared
        // and scaled (`p_x`, `p_y`, `p_z`); the depths before scaling are kept for the error
        // bound of the shear below.
        let corners = &triangles.corners;
        let x: [Vec4; 3] = std::array::from_fn(|v| corners[v][kx] - Vec4::splat(self.origin.x));
        let y: [Vec4; 3] = std::array::from_fn(|v| corners[v][ky] - Vec4::splat(self.origin.y));
        let depth: [Vec4; 3] = std::array::from_fn(|v| corners[v][kz] - Vec4::splat(self.origin.z));
        let p_x: [Vec4; 3] = std::array::from_fn(|v| x[v] + self.shear_x * depth[v]);
        let p_y: [Vec4; 3] = std::array::from_fn(|v| y[v] + self.shear_y * depth[v]);
        let p_z = depth.map(|d| d * self.scale_z);

        let lanes = (1u32 << count) - 1;
        let edge = |a: usize, b: usize| edge_functions(p_x[a], p_y[a], p_x[b], p_y[b], lanes);
        let e = [edge(1, 2), edge(2, 0), edge(0, 1)];
        let any_negative = e[0].cmplt(Vec4::ZERO) | e[1].cmplt(Vec4::ZERO) | e[2].cmplt(Vec4::ZERO);
        let any_positive = e[0].cmpgt(Vec4::ZERO) | e[1].cmpgt(Vec4::ZERO) | e[2].cmpgt(Vec4::ZERO);
        let det = e[0] + e[1] + e[2];
        let inside = !(any_negative & any_positive).bitmask() & det.cmpne(Vec4::ZERO).bitmask();
        let mut candidates = inside & lanes;
        if candidates == 0 {
            return None;
        }

        // t = (Σ e_i z_i) / det, but compared before dividing to avoid the division on misses.
        let t_scaled = e[0] * p_z[0] + e[1] * p_z[1] + e[2] * p_z[2];
        let (t_scaled_lanes, det_lanes) = (t_scaled.to_array(), det.to_array());
        for lane in 0..LANES {
            if candidates & (1 << lane) != 0
                && out_of_range(t_scaled_lanes[lane], det_lanes[lane], t_max)
            {
                candidates &= !(1 << lane);
            }
        }
        if candidates == 0 {
            return None;
        }
        let inv_det = 1.0 / det;
        let t = t_scaled * inv_det;

        // Accept t only if it is positive beyond its rounding error (pbrt-v4, section 6.8.7).
        let largest = |v: [Vec4; 3]| v[0].abs().max(v[1].abs()).max(v[2].abs());
        let max_z = largest(p_z);
        let max_x = largest(p_x);
        let max_y = largest(p_y);
        let delta_z = gamma(3) * max_z;
        // The shear `x + shear_x z` rounds relative to the depth *before* scaling (|shear| <= 1).
        // pbrt-v4 uses the scaled depth, which is the same for a unit direction, but far too
        // large for a short one (a ray taken into the space of an object scaled up 1e5 times
        // has a direction 1e-5 long, and every hit was rejected) and too small for a long one.
        let max_depth = largest(depth);
        let delta_x = gamma(5) * (max_x + max_depth);
        let delta_y = gamma(5) * (max_y + max_depth);
        let delta_e = 2.0 * (gamma(2) * max_x * max_y + delta_y * max_x + delta_x * max_y);
        let max_e = largest(e);
        let delta_t =
            3.0 * (gamma(3) * max_e * max_z + delta_e * max_z + delta_z * max_e) * inv_det.abs();
        Some(LaneCrossings {
            candidates,
            e: e.map(|e| e.to_array()),
            det: det_lanes,
            t_scaled: t_scaled_lanes,
            t: t.to_array(),
            delta_t: delta_t.to_array(),
            inv_det: inv_det.to_array(),
        })
    }
}

/// `a.x b.y - a.y b.x` in each lane of `lanes` (bit `i` for lane `i`; the others are left as
/// they come): twice the signed area of the 2D triangle `(0, 0), a, b`, with its exact sign.
///
/// First in `f32`, four lanes at once. Rounding is monotone, so of two products `p > q` the
/// rounded `p` is never below the rounded `q`, and a difference of two floats has the sign of
/// their exact difference: the `f32` value has the exact sign or is 0 (pbrt-v4, section
/// 6.5.3). Only a lane where it is 0, or NaN (products that overflow to `∞ - ∞`), is computed
/// again in `f64`, where the two products are exact, so that its sign is exact too. Both ways,
/// swapping `a` and `b` gives exactly the opposite value (a product does not depend on the
/// order of its factors, and a difference rounds symmetrically), and the two ways are chosen
/// alike: two triangles sharing an edge see opposite values.
#[inline]
fn edge_functions(a_x: Vec4, a_y: Vec4, b_x: Vec4, b_y: Vec4, lanes: u32) -> Vec4 {
    let quick = a_x * b_y - a_y * b_x;
    let unsure = (quick.cmpeq(Vec4::ZERO) | quick.is_nan_mask()).bitmask() & lanes;
    if unsure == 0 {
        return quick;
    }
    let exact = |a: f32, b: f32| f64::from(a) * f64::from(b);
    let [a_x, a_y, b_x, b_y] = [a_x, a_y, b_x, b_y].map(|v| v.to_array());
    let mut e = quick.to_array();
    for (lane, e) in e.iter_mut().enumerate() {
        if unsure & (1 << lane) != 0 {
            *e = (exact(a_x[lane], b_y[lane]) - exact(a_y[lane], b_x[lane])) as f32;
        }
    }
    Vec4::from_array(e)
}

#[cfg(test)]
mod tests {
    use rand::{RngExt, SeedableRng};
    use rand_pcg::Pcg32;

    use super::*;
    use crate::Ray;
    use crate::geometry::Triangle;

    /// Triangles around the origin, small enough that rays through the unit cube often miss
    /// them and large enough that they often hit, with shared vertices (fans) among them.
    fn random_triangles(rng: &mut Pcg32) -> [[Vec3; 3]; 4] {
        let mut point = || Vec3::new(rng.random(), rng.random(), rng.random()) * 2.0 - 1.0;
        let shared = point();
        let (a, b) = (point(), point());
        [
            [shared, a, b],
            [shared, b, point()],
            [point(), point(), point()],
            [a, point(), shared],
        ]
    }

    fn random_ray(rng: &mut Pcg32) -> Ray {
        let mut point = || Vec3::new(rng.random(), rng.random(), rng.random()) * 4.0 - 2.0;
        let (origin, target) = (point(), point() * 0.25);
        Ray {
            t_max: rng.random_range(0.5..2.0),
            ..Ray::new(origin, target - origin)
        }
    }

    /// The answer of testing the first `count` triangles one by one in order, each hit
    /// shrinking `t_max`.
    fn one_by_one(triangles: &[[Vec3; 3]], count: usize, ray: &Ray) -> Option<(usize, Crossing)> {
        let mut t_max = ray.t_max;
        let mut nearest = None;
        for (lane, p) in triangles[..count].iter().enumerate() {
            let triangle = Triangle::new(p[0], p[1], p[2]);
            if let Some(crossing) = triangle.checked_crossing(&Ray { t_max, ..*ray }) {
                t_max = crossing.t;
                nearest = Some((lane, crossing));
            }
        }
        nearest
    }

    #[test]
    fn four_lanes_answer_as_the_triangles_tested_one_by_one_in_order() {
        let mut rng = Pcg32::seed_from_u64(7);
        let (mut hits, mut several) = (0, 0);
        for _ in 0..20_000 {
            let triangles = random_triangles(&mut rng);
            let ray = random_ray(&mut rng);
            let space = RaySpace::new(&ray).expect("a non-zero direction");
            let four = FourTriangles::new(&triangles);
            for count in 1..=LANES {
                let expected = one_by_one(&triangles, count, &ray);
                assert_eq!(
                    space.nearest_crossing(&four, count, ray.t_max),
                    expected,
                    "{count} lanes of {triangles:?}, {ray:?}"
                );
                assert_eq!(
                    space.any_crossing(&four, count, ray.t_max),
                    expected.is_some(),
                    "{count} lanes of {triangles:?}, {ray:?}"
                );
            }
            hits += usize::from(one_by_one(&triangles, LANES, &ray).is_some());
            let crossed = (0..LANES)
                .filter(|&lane| one_by_one(&triangles[lane..], 1, &ray).is_some())
                .count();
            several += usize::from(crossed > 1);
        }
        // The comparison means something only if rays hit, and often more than one lane.
        assert!(
            hits > 2_000 && several > 500,
            "{hits} hits, {several} with several"
        );
    }

    #[test]
    fn lanes_beyond_the_count_are_never_hit() {
        let near = [
            Vec3::new(-1.0, -1.0, 1.0),
            Vec3::new(1.0, -1.0, 1.0),
            Vec3::new(0.0, 1.0, 1.0),
        ];
        let far = near.map(|p| p - Vec3::Z);
        let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), -Vec3::Z);
        let space = RaySpace::new(&ray).unwrap();
        let four = FourTriangles::new(&[far, far, far, near]);
        let (lane, crossing) = space.nearest_crossing(&four, 3, ray.t_max).unwrap();
        assert_eq!(
            (lane, crossing.t),
            (0, 5.0),
            "the nearest of the first three"
        );
        assert_eq!(space.nearest_crossing(&four, 4, ray.t_max).unwrap().0, 3);
        let only_near = FourTriangles::new(&[far, near]);
        assert!(
            !space.any_crossing(&only_near, 1, 5.0),
            "lane 0 is at t = 5, not before"
        );
        assert!(space.any_crossing(&only_near, 2, 5.0));
    }

    #[test]
    fn of_two_crossings_at_the_same_t_the_first_lane_is_kept() {
        let triangle = [
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        ];
        let ray = Ray::new(Vec3::new(0.1, 0.0, 2.0), -Vec3::Z);
        let space = RaySpace::new(&ray).unwrap();
        let four = FourTriangles::new(&[triangle, triangle, triangle]);
        assert_eq!(space.nearest_crossing(&four, 3, ray.t_max).unwrap().0, 0);
    }

    /// `a.x b.y - a.y b.x` from the exact products (its `f64` rounding keeps its sign).
    fn exact_value(a: [f32; 2], b: [f32; 2]) -> f64 {
        f64::from(a[0]) * f64::from(b[1]) - f64::from(a[1]) * f64::from(b[0])
    }

    #[test]
    fn edge_functions_have_the_exact_sign_and_swap_to_the_opposite_value() {
        // Points `b` nearly on the line through the origin and `a` (the edge functions of a
        // ray passing within rounding of an edge, which `f32` alone may round to 0), mixed with
        // points anywhere, at sizes from 1e-20 (products that underflow) to 1e20 (products
        // that overflow `f32`).
        let mut rng = Pcg32::seed_from_u64(11);
        let mut settled_by_f64 = 0;
        for case in 0..20_000 {
            let scale = 10f32.powi(rng.random_range(-20..=20));
            let a = [
                rng.random_range(-1.0..1.0) * scale,
                rng.random_range(-1.0..1.0) * scale,
            ];
            let k = rng.random_range(-3.0f32..3.0);
            let b = match case % 4 {
                0 => [
                    rng.random_range(-1.0..1.0) * scale,
                    rng.random_range(-1.0..1.0) * scale,
                ],
                _ => {
                    let mut nudge =
                        |x: f32| x * (1.0 + rng.random_range(-4.0f32..4.0) * f32::EPSILON);
                    [nudge(a[0] * k), nudge(a[1] * k)]
                }
            };
            let lanes = |p: [f32; 2], q: [f32; 2]| {
                edge_functions(
                    Vec4::splat(p[0]),
                    Vec4::splat(p[1]),
                    Vec4::splat(q[0]),
                    Vec4::splat(q[1]),
                    0b1111,
                )
            };
            let (ab, ba) = (lanes(a, b), lanes(b, a));
            let exact = exact_value(a, b);
            for lane in 0..LANES {
                let (e, swapped) = (ab[lane], ba[lane]);
                // The exact sign; 0 only where the exact value is too small for any `f32`.
                let right_sign = if e == 0.0 {
                    exact as f32 == 0.0
                } else {
                    f64::from(e.signum()) == exact.signum() && exact != 0.0
                };
                assert!(
                    right_sign,
                    "a = {a:?}, b = {b:?}: the edge function is {e}, the exact value {exact:e}"
                );
                // Finite inputs never give NaN: an `f32` NaN is computed again in `f64`.
                assert!(
                    e == -swapped,
                    "a = {a:?}, b = {b:?}: {e} one way, {swapped} the other"
                );
            }
            let quick = a[0] * b[1] - a[1] * b[0];
            if quick == 0.0 && exact as f32 != 0.0 {
                settled_by_f64 += 1;
            }
        }
        // The cases must include some whose `f32` value is 0 though the exact one is not (the
        // `f64` path settles them), or the test proves nothing.
        assert!(settled_by_f64 > 100, "{settled_by_f64}");
    }
}
