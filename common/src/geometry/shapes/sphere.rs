//! The sphere, intersected with interval arithmetic as in pbrt-v4.

use std::f32::consts::{PI, TAU};

use glam::{Mat3, Vec2, Vec3};

use super::Crossing;
use crate::Ray;
use crate::geometry::aabb::Aabb;
use crate::geometry::float::{MACHINE_EPSILON, TINY, gamma};
use crate::geometry::hit::SurfaceHit;
use crate::geometry::interval::{self, Interval};

/// What the plain-float roots can say on their own (see [`Sphere::plain_root`]).
#[derive(Clone, Copy, Debug, PartialEq)]
enum PlainRoot {
    /// The root that counts, certainly ahead of the origin, and a bound on its error.
    Found { t: f32, error: f32 },
    /// The ray's line certainly passes farther than the radius from the centre: most rays that
    /// reach a sphere's box miss the sphere, and this answers them first, in a few
    /// instructions.
    LineMisses,
    /// Certainly no root ahead otherwise: the line misses by less, or the sphere is behind.
    Missed,
    /// The bounds cannot tell: the intervals decide.
    Unsure,
}

/// A sphere; its normal points outwards, or inwards once [`flipped`](Sphere::flipped).
///
/// Its surface parameters are `uv = (φ / 2π, θ / π)`, with `θ` measured from the `+z` pole and
/// `φ` around `z`, counter-clockwise from `+x`: the axes of its own frame
/// ([`to_object`](Sphere::to_object)), the world's unless the sphere was [`turned`](Sphere::turned).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// The centre.
    pub center: Vec3,
    /// The radius; a sphere whose radius is not positive is never hit.
    pub radius: f32,
    /// Whether the normal points inwards (a scene file's `flip_normals`): a dome lit from
    /// inside, or a room's walls, whose one-sided materials and lights then face the centre.
    pub inward: bool,
    /// The rotation from world axes to the sphere's own, in which its `uv` are measured: a
    /// scene file's sphere turned by its `to_world` carries its texture round with it, as in
    /// Mitsuba. The identity for a sphere built in world axes.
    pub to_object: Mat3,
}

impl Sphere {
    /// The sphere of `radius` around `center`, its normal pointing outwards.
    pub fn new(center: Vec3, radius: f32) -> Self {
        Self {
            center,
            radius,
            inward: false,
            to_object: Mat3::IDENTITY,
        }
    }

    /// The same sphere with its `uv` measured in the axes `rotation` turns the world's into
    /// (the rotation of a scene file's `to_world`; a reflection is allowed).
    pub fn turned(self, rotation: Mat3) -> Self {
        Self {
            to_object: rotation.transpose(),
            ..self
        }
    }

    /// The same sphere with its normal turned the other way; `uv` stay where they were, as
    /// Mitsuba's `flip_normals` keeps them.
    pub fn flipped(self) -> Self {
        Self {
            inward: !self.inward,
            ..self
        }
    }

    /// The unit normal at a point whose outward unit normal is `outward`: `outward`, or its
    /// opposite for a flipped sphere. Everything that puts a normal on a sphere point (hits,
    /// light samples) goes through here, so that the two never disagree.
    #[inline]
    pub fn oriented(&self, outward: Vec3) -> Vec3 {
        if self.inward { -outward } else { outward }
    }

    /// A box certainly containing the sphere.
    pub fn bounds(&self) -> Aabb {
        let r = Vec3::splat(self.radius.abs());
        Aabb::from_points(self.center - r, self.center + r).rounded_outward()
    }

    /// The surface area `4π r²`.
    pub fn area(&self) -> f32 {
        4.0 * PI * self.radius * self.radius
    }

    /// The nearest hit with `0 < t < ray.t_max`; from inside, that is the far wall.
    ///
    /// The quadratic `|o + t d - c|² = r²` is solved in three careful steps:
    ///
    /// 1. Everything is relative to the centre, so a sphere 10⁵ away from the origin is solved
    ///    with the same small numbers as one at the origin.
    /// 2. The discriminant is computed as `4a (r + |v|)(r - |v|)`, where `v` is the vector from
    ///    the centre to the point of the ray's line closest to it. The textbook `b² - 4ac`
    ///    subtracts two nearly equal large numbers for a ray from far away, and loses every
    ///    digit; this form only subtracts `r - |v|`, which is small exactly when the ray grazes.
    /// 3. The roots are `q / a` and `c / q` with `q = -(b ± √disc) / 2`, the sign chosen so that
    ///    `b` and `√disc` are never subtracted from each other.
    ///
    /// All of it with a range certain to contain each exact root: a root counts only if its
    /// whole range is above 0. The ranges come from plain floats and a bound on their error
    /// where that settles the question, and from interval arithmetic where it does not.
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        self.crossing(ray)
            .map(|crossing| self.surface_hit(crossing))
    }

    /// The crossing behind [`intersect`](Self::intersect), with the point's offset from the
    /// centre.
    ///
    /// The roots are first found in plain floats with a bound on their errors
    /// ([`plain_root`](Self::plain_root)); the intervals are computed only when that bound
    /// cannot settle which root counts: a ray leaving the sphere (whose root near 0 may be
    /// either side of it), a grazing ray (whose two roots nearly meet). A ray leaving it
    /// outwards, as the sphere's own shadow rays and reflections do, is answered before that
    /// ([`certainly_behind`](Self::certainly_behind)).
    pub(crate) fn crossing(&self, ray: &Ray) -> Option<Crossing> {
        let has_area = self.radius > 0.0; // false for a NaN radius too
        if !has_area {
            return None;
        }
        let t = match self.plain_root(ray) {
            PlainRoot::Found { t, .. } => t,
            PlainRoot::LineMisses | PlainRoot::Missed => return None,
            PlainRoot::Unsure if self.certainly_behind(ray) => return None,
            PlainRoot::Unsure => self.interval_root(ray)?,
        };
        self.crossing_at(ray, t)
    }

    /// The crossing found in interval arithmetic alone (the steps above).
    #[cfg(test)]
    fn interval_crossing(&self, ray: &Ray) -> Option<Crossing> {
        self.crossing_at(ray, self.interval_root(ray)?)
    }

    /// Whether both roots are certainly at or behind the origin because the origin is outside
    /// the sphere or on it (`c = |o|² - r² ≥ 0`: the roots' product `c / a` is not negative)
    /// and the ray heads away from the centre (`b = 2 d·o ≥ 0`: their sum `-b / a` is not
    /// positive). The intervals contain the exact roots, so they too would find no root ahead:
    /// the answer is the same, without them.
    ///
    /// This is the question the plain `f32` bounds cannot settle for a ray leaving the surface
    /// outwards: its origin is off the surface by a few rounding errors, so `c` is as small as
    /// its own error. In `f64` it is settled with room to spare: the `f32` inputs are widened
    /// exactly, and `o` (one rounding), `d·o` and `o·o` (a few more) are each off by at most
    /// a few units of `2⁻⁵³` of their sizes; the bounds below are twice that. A NaN or
    /// infinite input makes a comparison false, and the intervals decide.
    fn certainly_behind(&self, ray: &Ray) -> bool {
        let o = ray.origin.as_dvec3() - self.center.as_dvec3();
        let d = ray.dir.as_dvec3();
        let r_squared = f64::from(self.radius) * f64::from(self.radius); // exact in f64
        let bound = 8.0 * f64::EPSILON;
        let heads_away = d.dot(o) >= bound * d.abs().dot(o.abs());
        let o_squared = o.length_squared();
        let outside = o_squared - r_squared >= bound * (o_squared + r_squared);
        heads_away && outside
    }

    /// The crossing at root `t`, if it is before `t_max` and the point has a direction from
    /// the centre to be projected along.
    fn crossing_at(&self, ray: &Ray, t: f32) -> Option<Crossing> {
        let within_reach = t < ray.t_max; // false for NaN too
        if !within_reach {
            return None;
        }
        let unprojected = (ray.origin - self.center) + t * ray.dir;
        let length = unprojected.length();
        if length == 0.0 || length.is_nan() {
            return None; // no direction to project along
        }
        Some(Crossing {
            t,
            coords: unprojected.to_array(),
        })
    }

    /// The root that counts, found in interval arithmetic: the nearer one if it is certainly
    /// in front of the origin, else the farther one if that is.
    fn interval_root(&self, ray: &Ray) -> Option<f32> {
        let o = interval::difference(ray.origin, self.center);
        let d = interval::exact_vec(ray.dir);
        let r = Interval::exact(self.radius);

        let a = interval::length_squared(d);
        let b = interval::dot_exact(ray.dir, o).scaled(2.0);
        let c = interval::length_squared(o) - r.squared();
        let along = b / a.scaled(2.0);
        let v = [
            o[0] - along.scaled(ray.dir.x),
            o[1] - along.scaled(ray.dir.y),
            o[2] - along.scaled(ray.dir.z),
        ];
        let v_length = interval::length_squared(v).sqrt();
        let discriminant = a.scaled(4.0) * (r + v_length) * (r - v_length);
        if discriminant.lo < 0.0 {
            return None;
        }
        let root = discriminant.sqrt();
        let q = if b.midpoint() < 0.0 {
            (b - root).scaled(-0.5)
        } else {
            (b + root).scaled(-0.5)
        };
        let (mut t0, mut t1) = (q / a, c / q);
        if t0.lo > t1.lo {
            std::mem::swap(&mut t0, &mut t1);
        }
        let t = if t0.lo > 0.0 {
            t0
        } else if t1.lo > 0.0 {
            t1
        } else {
            return None;
        };
        Some(t.midpoint())
    }

    /// The same steps in plain floats, each result with a bound on its error, and the root
    /// chosen by the same rule when the bounds make the choice certain.
    ///
    /// With `ε` the unit roundoff, `O = |o|` and the roots `t0 = q / a`, `t1 = c / q`:
    ///
    /// * The line's distance from the centre is `|v|` with `v = o - (d·o / d·d) d`, the part
    ///   of `o = origin - center` across the direction. Every rounding in computing `v` and its
    ///   length errs by a few units in the last place of `|o|` (the projection `(d·o / d·d) d`
    ///   is never longer than `o`), far less than the allowance `e_v = 128 ε (O + r)`. So when
    ///   the computed `|v|` exceeds `r` by more than `e_v`, the exact `|v|` exceeds `r`: the
    ///   line certainly misses ([`PlainRoot::LineMisses`]). The interval test rejects such a
    ///   ray too, since its `|v|` range contains the exact value and a negative `r - |v|`
    ///   makes the discriminant's lower end negative.
    /// * Otherwise the discriminant `4a (r + |v|)(r - |v|)` is off by at most
    ///   `4a ((r + |v|) + |r - |v||) e_v` plus `e_v²` and its own few roundings; the root of a
    ///   discriminant certainly above 0 by that over `√disc`.
    /// * `b = 2 d·o` is off by a few roundings of `2 Σ |d_i| |o_i|`, `c = |o|² - r²` by a few of
    ///   `O² + r²`, `a = d·d` by a few of itself; `q = -(b ± √disc) / 2` adds two numbers of
    ///   the same sign, so its error is half the sum of theirs.
    /// * A quotient `x / y` whose parts are off by `e_x` and `e_y` (with `|y| > e_y`) is off by
    ///   at most `(e_x + |x / y| e_y) / (|y| - e_y)`, plus its own rounding.
    ///
    /// Each allowance is at least twice what the count of roundings gives, so the rounding of
    /// the bounds themselves is covered. With the bounds, "certainly ahead" and "certainly
    /// behind" are tests on `t ± e`; whatever they cannot settle is [`PlainRoot::Unsure`].
    fn plain_root(&self, ray: &Ray) -> PlainRoot {
        const EPS: f32 = MACHINE_EPSILON;
        let (d, r) = (ray.dir, self.radius);
        let o = ray.origin - self.center;
        let o_length = o.length();
        let a = d.length_squared();
        let b = 2.0 * d.dot(o);
        let along = b / (2.0 * a);
        let v_length = (o - along * d).length();
        let v_error = 128.0 * EPS * (o_length + r);
        if v_length > r + v_error {
            return PlainRoot::LineMisses; // false for NaN: then the bounds below say Unsure
        }
        let c = o.length_squared() - r * r;
        let (sum, difference) = (r + v_length, r - v_length);
        let discriminant = 4.0 * a * sum * difference;

        let discriminant_error = 2.0
            * (4.0 * a * ((sum + difference.abs()) * v_error + v_error * v_error)
                + 8.0 * EPS * discriminant.abs());
        if discriminant + discriminant_error < 0.0 {
            return PlainRoot::Missed; // the exact line misses the sphere
        }
        let certainly_hit = discriminant - discriminant_error > 0.0; // false for NaN
        if !certainly_hit {
            return PlainRoot::Unsure; // grazing
        }
        let root = discriminant.sqrt();
        let root_error = discriminant_error / root + 2.0 * EPS * root;
        let b_error = 16.0 * EPS * d.abs().dot(o.abs());
        let q = if b < 0.0 {
            -0.5 * (b - root)
        } else {
            -0.5 * (b + root)
        };
        let q_error = 0.5 * (b_error + root_error) + 4.0 * EPS * q.abs();
        let a_error = 8.0 * EPS * a;
        let c_error = 16.0 * EPS * (o_length * o_length + r * r);
        let quotient = |x: f32, x_error: f32, y: f32, y_error: f32| {
            let t = x / y;
            let least_y = y.abs() - y_error;
            let error = if least_y > 0.0 {
                2.0 * (x_error + t.abs() * y_error) / least_y + 4.0 * EPS * t.abs() + TINY
            } else {
                f32::INFINITY
            };
            (t, error)
        };
        let (t0, t0_error) = quotient(q, q_error, a, a_error);
        let (t1, t1_error) = quotient(c, c_error, q, q_error);
        let ((near, near_error), (far, far_error)) = if t0 <= t1 {
            ((t0, t0_error), (t1, t1_error))
        } else {
            ((t1, t1_error), (t0, t0_error))
        };
        let certainly_ordered = far - far_error > near + near_error; // false for NaN
        if !certainly_ordered {
            return PlainRoot::Unsure; // which root is nearer is not certain
        }
        if near - near_error > 0.0 {
            PlainRoot::Found {
                t: near,
                error: near_error,
            }
        } else if far - far_error > 0.0 {
            // The near root is behind, or is the surface being left.
            PlainRoot::Found {
                t: far,
                error: far_error,
            }
        } else if far + far_error < 0.0 {
            PlainRoot::Missed // both roots certainly behind
        } else {
            PlainRoot::Unsure
        }
    }

    /// The hit record at ray parameter `t`.
    ///
    /// The point `o + t d` is off the sphere by the error of `t`, so it is projected back onto
    /// the sphere (`p · r / |p|`); that projection is within `γ(5) |p|` of the exact surface.
    /// Adding the centre back costs one more rounding of at most `γ(2) |center + p|`.
    pub(crate) fn surface_hit(&self, crossing: Crossing) -> SurfaceHit {
        let Crossing { t, coords } = crossing;
        let unprojected = Vec3::from_array(coords);
        let length = unprojected.length();
        let local = unprojected * (self.radius / length);
        let p = self.center + local;
        let p_error = gamma(5) * local.abs() + gamma(2) * p.abs();
        let n = self.oriented(local.normalize());

        let own = self.to_object * local;
        let phi = own.y.atan2(own.x);
        let phi = if phi < 0.0 { phi + TAU } else { phi };
        let theta = (own.z / self.radius).clamp(-1.0, 1.0).acos();
        SurfaceHit {
            t,
            p,
            p_error,
            n,
            shading_n: n,
            uv: Vec2::new(phi / TAU, theta / PI),
            shape: 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use approx::assert_relative_eq;

    use super::*;

    fn unit_sphere_at(center: Vec3) -> Sphere {
        Sphere::new(center, 1.0)
    }

    #[test]
    fn the_quick_rejection_agrees_with_the_intervals() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg32::seed_from_u64(3);
        let mut unit = || {
            Vec3::new(
                rng.random_range(-1.0f32..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
        };
        let (mut rejected_early, mut missed) = (0, 0);
        for i in 0..200_000 {
            let scale = [1e-4f32, 1.0, 1e5][i % 3];
            let far_away = if i % 7 == 0 { 1e5 } else { 0.0 };
            let center = unit() * scale + Vec3::splat(far_away);
            let radius = scale * (0.1 + unit().x.abs());
            let sphere = Sphere::new(center, radius);
            let origin = center + unit() * (4.0 * scale);
            // Aim at points at distances near the radius, many of them grazing within a few
            // parts in a million.
            let across = unit().normalize_or(Vec3::X) * radius;
            let closeness = [1.0 + 1e-6 * unit().x, 1.0 + 0.1 * unit().x, 2.0 * unit().x][i % 3];
            let ray = Ray::new(origin, center + across * closeness - origin);
            let full = sphere.interval_crossing(&ray);
            if sphere.plain_root(&ray) == PlainRoot::LineMisses {
                rejected_early += 1;
                assert_eq!(full, None, "{ray:?} {sphere:?}");
            }
            assert_eq!(sphere.crossing(&ray).is_some(), full.is_some());
            missed += usize::from(full.is_none());
        }
        // Most misses are answered early (the rest are grazing rays or misses behind).
        assert!(
            rejected_early * 10 > missed * 7,
            "{rejected_early} of {missed}"
        );
    }

    /// The sphere's two roots in double precision, from the same single-precision inputs, in
    /// increasing order (`None` if the line misses).
    fn roots_in_f64(sphere: &Sphere, ray: &Ray) -> Option<(f64, f64)> {
        let o = ray.origin.as_dvec3() - sphere.center.as_dvec3();
        let d = ray.dir.as_dvec3();
        let r = f64::from(sphere.radius);
        let (a, b, c) = (d.dot(d), 2.0 * d.dot(o), o.dot(o) - r * r);
        let v = o - d * (d.dot(o) / a);
        let discriminant = 4.0 * a * (r + v.length()) * (r - v.length());
        if discriminant < 0.0 {
            return None;
        }
        let q = -0.5 * (b + b.signum() * discriminant.sqrt());
        let (t0, t1) = (q / a, c / q);
        Some((t0.min(t1), t0.max(t1)))
    }

    /// Random spheres and rays at scales 1e-4 to 1e5 and 1e5 from the origin: grazing ones,
    /// ones from far away and ones leaving the surface outwards or inwards as secondary rays
    /// do (from an offset hit point).
    fn random_spheres_and_rays(count: usize, seed: u64) -> Vec<(Sphere, Ray)> {
        use crate::geometry::spawn::offset_ray_origin;
        use rand::{RngExt, SeedableRng};
        let mut rng = rand_pcg::Pcg32::seed_from_u64(seed);
        let mut unit = move || {
            Vec3::new(
                rng.random_range(-1.0f32..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            )
        };
        (0..count)
            .map(|i| {
                let scale = [1e-4f32, 1.0, 1e5][i % 3];
                let far_away = if i % 7 == 0 { 1e5 } else { 0.0 };
                let center = unit() * scale + Vec3::splat(far_away);
                let radius = scale * (0.1 + unit().x.abs());
                let sphere = Sphere::new(center, radius);
                let ray = if i % 4 == 3 {
                    // Leaving the surface, towards a random side.
                    let n = unit().normalize_or(Vec3::X);
                    let hit = sphere
                        .intersect(&Ray::new(center + n * (3.0 * radius), -n))
                        .expect("aimed at the centre");
                    let dir = unit();
                    Ray::new(offset_ray_origin(hit.p, hit.p_error, hit.n, dir), dir)
                } else {
                    let origin = center + unit() * (4.0 * scale);
                    let across = unit().normalize_or(Vec3::X) * radius;
                    let closeness =
                        [1.0 + 1e-6 * unit().x, 1.0 + 0.1 * unit().x, 2.0 * unit().x][i % 3];
                    Ray::new(origin, center + across * closeness - origin)
                };
                (sphere, ray)
            })
            .collect()
    }

    /// The plain-float roots against double precision and against the intervals: a root the
    /// bounds call certain is the exact root that counts, within its bound; a miss they call
    /// certain is one; the crossings accepted are the intervals' (but for a few rays whose
    /// interval was wider than the bound); and the plain floats answer most rays themselves.
    #[test]
    fn the_plain_roots_agree_with_double_precision_and_the_intervals() {
        let (mut plain, mut unsure, mut disagreements) = (0, 0, 0);
        let cases = random_spheres_and_rays(200_000, 4);
        for (sphere, ray) in &cases {
            let exact = roots_in_f64(sphere, ray);
            match sphere.plain_root(ray) {
                PlainRoot::Found { t, error } => {
                    plain += 1;
                    let (near, far) = exact.expect("a root found means the line hits");
                    // The root that counts: the near one, unless it is (about) 0 or behind.
                    let (t, error) = (f64::from(t), f64::from(error));
                    let counts = if (t - near).abs() <= error { near } else { far };
                    assert!(counts > 0.0, "{sphere:?} {ray:?} {t} {exact:?}");
                    assert!(
                        (counts - t).abs() <= error,
                        "{sphere:?} {ray:?} {t} {exact:?}"
                    );
                }
                PlainRoot::LineMisses | PlainRoot::Missed => {
                    assert!(
                        exact.is_none_or(|(_, far)| far <= 0.0),
                        "{sphere:?} {ray:?} {exact:?}"
                    );
                }
                PlainRoot::Unsure => unsure += 1,
            }
            let with_plain = sphere.crossing(ray).map(|c| c.t);
            let intervals_only = sphere.interval_crossing(ray).map(|c| c.t);
            disagreements += usize::from(with_plain.is_some() != intervals_only.is_some());
        }
        assert!(disagreements * 10_000 < cases.len(), "{disagreements}");
        assert!(
            plain * 10 > cases.len() * 5,
            "{plain} plain, {unsure} unsure"
        );
    }

    /// A ray the double-precision test calls behind has no root ahead, in double precision and
    /// in the intervals; and the test answers nearly all the rays it is for: those leaving the
    /// surface outwards (not along it) that the plain bounds leave unsure.
    #[test]
    fn rays_certainly_behind_are_missed_by_the_intervals() {
        let (mut answered, mut leaving) = (0, 0);
        for (sphere, ray) in random_spheres_and_rays(200_000, 5) {
            let behind = sphere.certainly_behind(&ray);
            if behind {
                assert_eq!(sphere.interval_crossing(&ray), None, "{sphere:?} {ray:?}");
                let exact = roots_in_f64(&sphere, &ray);
                assert!(
                    exact.is_none_or(|(_, far)| far <= 0.0),
                    "{sphere:?} {ray:?} {exact:?}"
                );
            }
            let o = ray.origin - sphere.center;
            let on_surface = (o.length() - sphere.radius).abs() < 1e-3 * sphere.radius;
            let outwards = ray.dir.dot(o) > 0.1 * ray.dir.length() * o.length();
            if on_surface && outwards && sphere.plain_root(&ray) == PlainRoot::Unsure {
                leaving += 1;
                answered += usize::from(behind);
            }
        }
        assert!(leaving > 1000, "{leaving} rays leaving outwards");
        assert!(
            answered * 100 >= leaving * 99,
            "answered {answered} of {leaving}"
        );
    }

    #[test]
    fn head_on_hit_has_known_t_p_n_and_uv() {
        let sphere = unit_sphere_at(Vec3::new(1.0, 2.0, 3.0));
        let ray = Ray::new(Vec3::new(1.0, 2.0, 10.0), -Vec3::Z);
        let hit = sphere.intersect(&ray).unwrap();
        assert_relative_eq!(hit.t, 6.0, max_relative = 1e-6);
        assert_relative_eq!(hit.p, Vec3::new(1.0, 2.0, 4.0), epsilon = 1e-6);
        assert_relative_eq!(hit.n, Vec3::Z, epsilon = 1e-6);
        assert_eq!(hit.shading_n, hit.n);
        assert_relative_eq!(hit.uv.y, 0.0, epsilon = 1e-3); // the +z pole
        assert!(hit.front_face(ray.dir));
        // From -x towards +x we meet the point at φ = π, θ = π/2.
        let side = Ray::new(Vec3::new(-5.0, 2.0, 3.0), Vec3::X);
        let hit = sphere.intersect(&side).unwrap();
        assert_relative_eq!(hit.t, 5.0, max_relative = 1e-6);
        assert_relative_eq!(hit.n, -Vec3::X, epsilon = 1e-6);
        assert_relative_eq!(hit.uv, Vec2::new(0.5, 0.5), epsilon = 1e-6);
    }

    #[test]
    fn misses_beside_and_behind() {
        let sphere = unit_sphere_at(Vec3::ZERO);
        assert!(
            sphere
                .intersect(&Ray::new(Vec3::new(0.0, 1.5, -5.0), Vec3::Z))
                .is_none()
        );
        assert!(
            sphere
                .intersect(&Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::Z))
                .is_none()
        );
    }

    #[test]
    fn grazing_rays_hit_just_inside_and_miss_just_outside() {
        let sphere = unit_sphere_at(Vec3::ZERO);
        let inside = Ray::new(Vec3::new(0.0, 0.999, -5.0), Vec3::Z);
        let hit = sphere.intersect(&inside).unwrap();
        let half_chord = (1.0f32 - 0.999 * 0.999).sqrt();
        assert_relative_eq!(hit.t, 5.0 - half_chord, max_relative = 1e-4);
        assert!(
            sphere
                .intersect(&Ray::new(Vec3::new(0.0, 1.001, -5.0), Vec3::Z))
                .is_none()
        );
        // Exactly tangent: either answer is fine, but it must not be NaN.
        if let Some(hit) = sphere.intersect(&Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z)) {
            assert!(hit.t.is_finite() && hit.p.is_finite() && hit.n.is_finite());
        }
    }

    #[test]
    fn grazing_rays_from_far_away_at_large_scale_still_hit() {
        // The textbook discriminant b² - 4ac cancels catastrophically here.
        let sphere = Sphere::new(Vec3::splat(1e5), 1e5);
        let ray = Ray::new(Vec3::new(1e5, 1e5 + 0.99e5, -1e7), Vec3::Z);
        let hit = sphere
            .intersect(&ray)
            .expect("grazing ray from afar should hit");
        assert_relative_eq!(hit.p.distance(sphere.center), 1e5, max_relative = 1e-5);
    }

    #[test]
    fn from_inside_the_far_wall_is_hit_with_an_outward_normal() {
        let sphere = unit_sphere_at(Vec3::new(3.0, 0.0, 0.0));
        let ray = Ray::new(Vec3::new(3.2, 0.0, 0.0), Vec3::Y);
        let hit = sphere.intersect(&ray).unwrap();
        let expected_t = (1.0f32 - 0.2 * 0.2).sqrt();
        assert_relative_eq!(hit.t, expected_t, max_relative = 1e-5);
        assert!(hit.n.dot(Vec3::Y) > 0.9, "normal points outwards");
        assert!(!hit.front_face(ray.dir));
    }

    #[test]
    fn a_flipped_sphere_turns_its_normals_inwards_and_keeps_its_uv() {
        let sphere = unit_sphere_at(Vec3::new(3.0, 0.0, 0.0));
        let ray = Ray::new(Vec3::new(3.2, 0.0, 0.0), Vec3::Y);
        let outward = sphere.intersect(&ray).unwrap();
        let inward = sphere.flipped().intersect(&ray).unwrap();
        assert_eq!(
            (inward.t, inward.p, inward.uv),
            (outward.t, outward.p, outward.uv)
        );
        assert_eq!(
            inward.n, -outward.n,
            "the geometric normal points to the centre"
        );
        assert_eq!(inward.shading_n, -outward.shading_n);
        assert!(inward.front_face(ray.dir), "from inside, the front is seen");
        assert_eq!(sphere.flipped().flipped(), sphere);
    }

    #[test]
    fn t_max_is_respected() {
        let sphere = unit_sphere_at(Vec3::ZERO);
        let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
        assert!(sphere.intersect(&Ray { t_max: 3.9, ..ray }).is_none());
        assert!(sphere.intersect(&Ray { t_max: 4.1, ..ray }).is_some());
    }

    #[test]
    fn non_positive_radius_is_never_hit() {
        let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
        for radius in [0.0, -1.0, f32::NAN] {
            assert!(Sphere::new(Vec3::ZERO, radius).intersect(&ray).is_none());
        }
    }

    #[test]
    fn bounds_and_area() {
        let sphere = Sphere::new(Vec3::new(1.0, 2.0, 3.0), 2.0);
        let b = sphere.bounds();
        assert!(b.contains(Vec3::new(-1.0, 0.0, 1.0)) && b.contains(Vec3::new(3.0, 4.0, 5.0)));
        assert_relative_eq!(b.diagonal(), Vec3::splat(4.0), max_relative = 1e-6);
        assert_relative_eq!(sphere.area(), 16.0 * PI);
    }
}
