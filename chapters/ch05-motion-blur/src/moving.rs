//! Moving objects, and the BVH over their motion bounds.
//!
//! A [`MovingShape`] is a shape in its own space with an [`AnimatedTransform`]; it is hit by
//! taking the ray into object space at the ray's time. [`MovingObjects`] keeps them behind a
//! BVH built over boxes that hold each object for a stretch of the shutter interval.
//!
//! How long a stretch is the trade-off this chapter measures. With **one** stretch, the whole
//! shutter, a fast object's box is its entire sweep, and every ray crossing that sweep at any
//! time must test the object. With `k` stretches there are `k` BVHs, each over boxes for
//! `1/k` of the interval, and a ray uses the one for its time: boxes `k` times shorter,
//! for `k` times the memory and build work.

use crate::animated_transform::AnimatedTransform;
use crate::motion_bounds::motion_bounds;
use crate::shutter::Shutter;
use common::Ray;
use common::geometry::{Aabb, Bvh, Shape, SurfaceHit};

/// Samples per keyframe segment when bounding a motion.
const BOUND_STEPS: usize = 8;

/// A shape that moves: `motion.at(time)` maps its own space to world space.
#[derive(Clone, Debug)]
pub struct MovingShape {
    /// The shape in object space.
    pub shape: Shape,
    /// Object to world over time.
    pub motion: AnimatedTransform,
}

impl MovingShape {
    /// The shape placed by `motion`.
    pub fn new(shape: Shape, motion: AnimatedTransform) -> Self {
        Self { shape, motion }
    }

    // ANCHOR: moving_intersect
    /// The nearest hit, before `ray.t_max`, of the shape where its motion has it at the ray's
    /// shutter time, as a world-space [`SurfaceHit`]: the ray's own `t`, the point and its error
    /// bound ([`point_error_to_world`](crate::object_space::point_error_to_world)), both unit
    /// normals perpendicular to the placed surface and on the side the shape's own normals
    /// point to, and the shape's `uv` and `shape` index as it gave them.
    ///
    /// The shape itself only knows how to meet a ray in its own space. Which space should the
    /// intersection happen in, and what does each part of the hit become on the way back?
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        // BEGIN SOLUTION
        use crate::object_space::{point_error_to_world, to_object_space};
        use glam::Mat3;

        // Where the object is at the ray's time (not at the shutter's opening, nor at 0).
        let (object_to_world, world_to_object) = self.motion.at_with_inverse(ray.time);

        // The ray in the object's own space, where the shape sits still. Its direction is not
        // normalised, so the same t names the same point in both spaces, and t_max holds.
        let local_ray = to_object_space(ray, &world_to_object);
        let local = self.shape.intersect(&local_ray)?;

        // The hit back in world space. A point goes by the transform itself.
        let p = object_to_world.transform_point3(local.p);
        let p_error = point_error_to_world(local.p, local.p_error, &object_to_world);

        // A normal is no point or direction: under a stretch it would lean over with the
        // surface. The inverse transpose keeps it perpendicular to the placed surface; a scale
        // changes its length, so it is normalised again.
        let normal_matrix = Mat3::from_mat4(world_to_object).transpose();
        let n = (normal_matrix * local.n).normalize();
        let shading_n = (normal_matrix * local.shading_n).normalize();

        // t needs no conversion: the object-space ray's point at t is the world point at t.
        Some(SurfaceHit {
            t: local.t,
            p,
            p_error,
            n,
            shading_n,
            uv: local.uv,
            shape: local.shape,
        })
        // END SOLUTION
    }
    // ANCHOR_END: moving_intersect

    /// A box holding the shape at every time in `[time0, time1]`.
    pub fn bounds_over(&self, time0: f32, time1: f32) -> Aabb {
        motion_bounds(
            &self.shape.bounds(),
            &self.motion,
            time0,
            time1,
            BOUND_STEPS,
        )
    }
}

/// Moving shapes behind one BVH per stretch of the shutter interval.
#[derive(Clone, Debug)]
pub struct MovingObjects {
    shapes: Vec<MovingShape>,
    /// The index the first moving shape reports in [`SurfaceHit::shape`]: moving shapes come
    /// after the static ones in the scene's material list.
    first_index: u32,
    shutter: Shutter,
    /// `bvhs[j]` covers the `j`-th of `bvhs.len()` equal stretches of the shutter interval.
    bvhs: Vec<Bvh>,
}

impl MovingObjects {
    /// The shapes (their hits numbered from `first_index`) with one BVH per each of
    /// `stretches` equal parts of `shutter` (at least one; one for an instant).
    pub fn new(
        shapes: Vec<MovingShape>,
        first_index: u32,
        shutter: Shutter,
        stretches: usize,
    ) -> Self {
        let stretches = if shutter.is_instant() {
            1
        } else {
            stretches.max(1)
        };
        let bvhs = (0..stretches)
            .map(|j| {
                let (time0, time1) = stretch(&shutter, j, stretches);
                let boxes: Vec<Aabb> = shapes.iter().map(|s| s.bounds_over(time0, time1)).collect();
                Bvh::build(&boxes)
            })
            .collect();
        Self {
            shapes,
            first_index,
            shutter,
            bvhs,
        }
    }

    /// No moving shapes.
    pub fn empty() -> Self {
        Self::new(Vec::new(), 0, Shutter::INSTANT, 1)
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.shapes.is_empty()
    }

    /// Whether any of them actually moves.
    pub fn any_moving(&self) -> bool {
        self.shapes.iter().any(|s| s.motion.is_moving())
    }

    /// The shapes.
    pub fn shapes(&self) -> &[MovingShape] {
        &self.shapes
    }

    /// The shutter interval the bounds were built for.
    pub fn shutter(&self) -> Shutter {
        self.shutter
    }

    /// How many stretches (and BVHs) the shutter is cut into.
    pub fn stretches(&self) -> usize {
        self.bvhs.len()
    }

    /// The same shapes with the bounds rebuilt for `stretches` stretches of `shutter`.
    pub fn rebuilt(&self, shutter: Shutter, stretches: usize) -> Self {
        Self::new(self.shapes.clone(), self.first_index, shutter, stretches)
    }

    /// The BVH whose stretch holds `time` (rays' times lie in the shutter interval).
    fn bvh_at(&self, time: f32) -> &Bvh {
        let k = self.bvhs.len();
        let length = self.shutter.length();
        let j = if length > 0.0 {
            (((time - self.shutter.open) / length) * k as f32).floor()
        } else {
            0.0
        };
        // `as usize` saturates: NaN and negatives go to 0.
        &self.bvhs[(j as usize).min(k - 1)]
    }

    /// The nearest hit before `ray.t_max`, counting in `tests` the shapes whose box the ray
    /// entered and which were therefore intersected.
    pub fn intersect_counting(&self, ray: &Ray, tests: &mut u64) -> Option<SurfaceHit> {
        let mut nearest = None;
        self.bvh_at(ray.time).intersect(ray, |index, t_max| {
            *tests += 1;
            let hit = self.shapes[index].intersect(&Ray { t_max, ..*ray })?;
            nearest = Some(SurfaceHit {
                shape: self.first_index + index as u32,
                ..hit
            });
            Some(hit.t)
        });
        nearest
    }

    /// The nearest hit before `ray.t_max`.
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        self.intersect_counting(ray, &mut 0)
    }

    /// Whether a moving shape blocks the ray before `ray.t_max`, at the ray's time.
    pub fn occluded(&self, ray: &Ray) -> bool {
        self.bvh_at(ray.time)
            .any_hit(ray, |index| self.shapes[index].intersect(ray).is_some())
    }
}

/// The `j`-th of `k` equal stretches of the shutter interval.
fn stretch(shutter: &Shutter, j: usize, k: usize) -> (f32, f32) {
    let at = |i: usize| shutter.open + shutter.length() * (i as f32 / k as f32);
    let end = if j + 1 == k { shutter.close } else { at(j + 1) };
    (at(j), end)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::object_space::{point_error_to_world, to_object_space};
    use common::geometry::Sphere;
    use glam::{DVec3, Mat3, Mat4, Vec3};

    /// A unit sphere, stretched into an ellipsoid, turning and sliding over the shutter.
    fn stretched_sphere() -> MovingShape {
        MovingShape::new(
            Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0)),
            AnimatedTransform::new(&[
                (
                    0.0,
                    Mat4::from_translation(Vec3::new(-3.0, 0.0, 0.0))
                        * Mat4::from_rotation_y(0.3)
                        * Mat4::from_scale(Vec3::new(2.0, 0.5, 1.0)),
                ),
                (
                    1.0,
                    Mat4::from_translation(Vec3::new(3.0, 1.0, 0.0))
                        * Mat4::from_rotation_y(1.2)
                        * Mat4::from_scale(Vec3::new(1.0, 0.5, 2.0)),
                ),
            ])
            .unwrap(),
        )
    }

    /// The hit of `ray` with the unit sphere placed by `motion` at `time`, solved in world
    /// space in f64: `|W x| = 1` on the surface, `W` world to object. `(t, p, n)`, the normal
    /// the direction in which `|W x|` grows fastest at the point, by central differences.
    fn ellipsoid_hit(
        motion: &AnimatedTransform,
        ray: &Ray,
        time: f32,
    ) -> Option<(f32, Vec3, Vec3)> {
        let w = motion.at_with_inverse(time).1.as_dmat4();
        let (origin, dir) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
        let (o, d) = (w.transform_point3(origin), w.transform_vector3(dir));
        let (a, b, c) = (d.dot(d), 2.0 * o.dot(d), o.dot(o) - 1.0);
        let discriminant = b * b - 4.0 * a * c;
        if discriminant < 0.0 {
            return None;
        }
        let root = discriminant.sqrt();
        let t = [(-b - root) / (2.0 * a), (-b + root) / (2.0 * a)]
            .into_iter()
            .find(|&t| t > 1e-4 && t < f64::from(ray.t_max))?;
        let point = origin + t * dir;
        let size = |x: DVec3| w.transform_point3(x).length();
        let h = 1e-6;
        let normal = DVec3::new(
            size(point + DVec3::X * h) - size(point - DVec3::X * h),
            size(point + DVec3::Y * h) - size(point - DVec3::Y * h),
            size(point + DVec3::Z * h) - size(point - DVec3::Z * h),
        );
        Some((t as f32, point.as_vec3(), normal.normalize().as_vec3()))
    }

    /// What is wrong with `got = shape.intersect(ray)`, in words; `None` if it is right.
    fn moving_hit_mistake(
        shape: &MovingShape,
        ray: &Ray,
        got: Option<SurfaceHit>,
    ) -> Option<String> {
        let expected = ellipsoid_hit(&shape.motion, ray, ray.time);
        let (object_to_world, world_to_object) = shape.motion.at_with_inverse(ray.time);
        // How a hit at `got_t` was likely found, when it was not at the ray's time in the
        // object's space: only a hit says it (a miss agrees with too many mistakes).
        let found_how = |got_t: f32| -> Option<String> {
            let same = |t: Option<f32>| t.is_some_and(|t| (t - got_t).abs() < 1e-4 * t.max(1.0));
            if let Some(time) = [0.0, 0.5, 1.0].into_iter().find(|&time| {
                time != ray.time && same(ellipsoid_hit(&shape.motion, ray, time).map(|h| h.0))
            }) {
                return Some(format!(
                    "yours looks where the object is at time {time}; the object has to be where \
                     it is at the ray's own time"
                ));
            }
            if same(shape.shape.intersect(ray).map(|h| h.t)) {
                return Some(
                    "yours meets the shape where it sits in its own space, as if it never moved: \
                     the world ray has to be taken into the object's space first"
                        .to_string(),
                );
            }
            if same(
                shape
                    .shape
                    .intersect(&to_object_space(ray, &object_to_world))
                    .map(|h| h.t),
            ) {
                return Some(
                    "the ray was taken into object space by the object-to-world matrix; the one \
                     that takes world space to object space is its inverse, at_with_inverse's \
                     second"
                        .to_string(),
                );
            }
            None
        };
        let (got, (t, p, n)) = match (got, expected) {
            (None, None) => return None,
            (Some(got), Some(expected)) => (got, expected),
            (got, expected) => {
                let said = match (got, expected) {
                    (Some(got), None) => format!(
                        "yours hit it at t = {}, but at the ray's time {} the object is not there{}",
                        got.t,
                        ray.time,
                        if ellipsoid_hit(
                            &shape.motion,
                            &Ray {
                                t_max: f32::INFINITY,
                                ..*ray
                            },
                            ray.time
                        )
                        .is_some()
                        {
                            " before the ray's t_max (a shadow ray stops at its light)"
                        } else {
                            ""
                        }
                    ),
                    _ => format!(
                        "yours missed it, but at the ray's time {} the ray meets it at t = {}",
                        ray.time,
                        expected.map_or(0.0, |h| h.0)
                    ),
                };
                return Some(match got.and_then(|got| found_how(got.t)) {
                    Some(how) => format!("{said}: {how}"),
                    None if got.is_none() => format!(
                        "{said}: is the ray taken into the object's space by the world-to-object \
                         matrix at the ray's time, with its t_max kept?"
                    ),
                    None => said,
                });
            }
        };
        let close = |a: Vec3, b: Vec3| (a - b).length() <= 1e-3 * b.length().max(1.0);
        if (got.t - t).abs() > 1e-3 * t.max(1.0) {
            let scaled = got.t * ray.dir.length();
            let local_dir = world_to_object.transform_vector3(ray.dir);
            return Some(format!(
                "the hit is at t = {t} on the world ray, and yours says t = {}: {}",
                got.t,
                if let Some(how) = found_how(got.t) {
                    how
                } else if (got.t - t * local_dir.length()).abs() < 1e-3 * t.max(1.0)
                    || (got.t - t / local_dir.length()).abs() < 1e-3 * t.max(1.0)
                {
                    "t was rescaled by the length of the object-space direction; with that \
                     direction left as the transform made it, the same t names the same point in \
                     both spaces"
                        .to_string()
                } else if (scaled - t).abs() < 1e-3 * t.max(1.0)
                    || (got.t / ray.dir.length() - t).abs() < 1e-3 * t.max(1.0)
                {
                    "t was rescaled by the length of the ray's direction; it is the parameter of \
                     the ray as given, ray.at(t) = p"
                        .to_string()
                } else {
                    "is the object where it is at the ray's time, and is t the world ray's \
                     parameter of the point?"
                        .to_string()
                }
            ));
        }
        if !close(got.p, p) {
            let local = world_to_object.transform_point3(p);
            return Some(format!(
                "the hit point should be {p} (the world ray's point at t = {t}), and yours is {}{}",
                got.p,
                if close(got.p, local) {
                    ": that is the point in the object's own space; it goes back to world space \
                     by the object-to-world transform"
                } else {
                    ""
                }
            ));
        }
        let check_normal = |name: &str, got_n: Vec3| -> Option<String> {
            let length = got_n.length();
            if (length - 1.0).abs() > 1e-3 {
                return Some(format!(
                    "the {name} has length {length}: the transform changes a normal's length \
                     (the object is scaled), so it has to be made unit again"
                ));
            }
            if close(got_n, n) {
                return None;
            }
            let local_n = to_object_space(ray, &world_to_object);
            let local_hit = shape
                .shape
                .intersect(&local_n)
                .map(|h| h.n)
                .unwrap_or(Vec3::ZERO);
            let like_a_direction = object_to_world.transform_vector3(local_hit).normalize();
            let linear = Mat3::from_mat4(object_to_world);
            let by_transpose = (linear.transpose() * local_hit).normalize();
            let by_inverse = (linear.inverse() * local_hit).normalize();
            Some(format!(
                "the {name} should be {n}, perpendicular to the stretched surface, and yours is \
                 {got_n}{}",
                if close(got_n, like_a_direction) {
                    ": it was transformed like a direction, and under a stretch a normal moved \
                     that way leans over with the surface; what matrix keeps it perpendicular?"
                } else if close(got_n, by_transpose) {
                    ": it was transformed by the transpose of the object-to-world matrix, which \
                     stretches a normal as the surface is stretched, where it has to undo the \
                     stretch"
                } else if close(got_n, by_inverse) {
                    ": it was transformed by the world-to-object matrix itself, which keeps a \
                     normal perpendicular only where nothing is stretched"
                } else if close(got_n, -n) {
                    ": it points into the object"
                } else {
                    ""
                }
            ))
        };
        if let Some(mistake) = check_normal("normal n", got.n) {
            return Some(mistake);
        }
        if let Some(mistake) = check_normal("shading normal", got.shading_n) {
            return Some(mistake);
        }
        // The error bound: at least what the transform's rounding can do to the point.
        let local = shape
            .shape
            .intersect(&to_object_space(ray, &world_to_object))
            .expect("the reference hits");
        let bound = point_error_to_world(local.p, local.p_error, &object_to_world);
        if !(got.p_error.cmpge(0.5 * bound).all() && got.p_error.is_finite()) {
            return Some(format!(
                "the point's error bound is {}, where the transformed point may be off by up to \
                 {bound}{}: a secondary ray leaving from the point is offset by this bound, and \
                 too small a bound lets it hit the surface it leaves (point_error_to_world \
                 bounds a transformed point)",
                got.p_error,
                if got.p_error == local.p_error {
                    " (yours is the object-space bound, which the transform scales and adds to)"
                } else {
                    ""
                }
            ));
        }
        if got.uv != local.uv || got.shape != local.shape {
            return Some(
                "the surface coordinates (uv) and the shape index are the shape's own and stay as \
                 they are"
                    .to_string(),
            );
        }
        None
    }

    #[test]
    fn exercise_moving_intersect_finds_the_object_where_it_is_at_the_rays_time() {
        let shape = stretched_sphere();
        let mut hits = 0;
        for i in 0..200 {
            let time = (i as f32 + 0.5) / 200.0;
            let x = -4.0 + 8.0 * ((i * 37 % 200) as f32 / 200.0);
            let y = -0.2 + 1.4 * ((i * 91 % 200) as f32 / 200.0);
            let dir = Vec3::new(0.1 * ((i % 7) as f32 - 3.0), 0.05, 1.0);
            // Directions of several lengths: t is the parameter of the ray as given.
            let dir = dir.normalize() * [1.0, 2.5, 0.4][i % 3];
            let ray = Ray::new(Vec3::new(x, y, -6.0), dir).with_time(time);
            let got = shape.intersect(&ray);
            hits += usize::from(got.is_some());
            if let Some(mistake) = moving_hit_mistake(&shape, &ray, got) {
                panic!(
                    "MovingShape::intersect: a stretched sphere turning and sliding from x = -3 \
                     to x = 3 over the shutter [0, 1], and the ray {ray:?}: {mistake}"
                );
            }
        }
        assert!(
            hits > 20,
            "the test's rays should hit the object often ({hits})"
        );
    }

    #[test]
    fn exercise_moving_intersect_stops_at_t_max() {
        let shape = stretched_sphere();
        // At time 0.5 the object is around x = 0; the ray meets it near t = 5.
        for t_max in [4.0, 20.0] {
            let ray = Ray {
                t_max,
                ..Ray::new(Vec3::new(0.0, 0.5, -6.0), Vec3::Z).with_time(0.5)
            };
            if let Some(mistake) = moving_hit_mistake(&shape, &ray, shape.intersect(&ray)) {
                panic!(
                    "MovingShape::intersect: a ray stopping at t_max = {t_max} at time 0.5: \
                     {mistake}"
                );
            }
        }
    }

    fn crossing_sphere() -> MovingShape {
        MovingShape::new(
            Shape::Sphere(Sphere::new(Vec3::ZERO, 0.5)),
            AnimatedTransform::new(&[
                (0.0, Mat4::from_translation(Vec3::new(-10.0, 0.0, 0.0))),
                (1.0, Mat4::from_translation(Vec3::new(10.0, 0.0, 0.0))),
            ])
            .unwrap(),
        )
    }

    #[test]
    fn a_ray_hits_a_moving_sphere_only_when_it_is_there() {
        let objects = MovingObjects::new(
            vec![crossing_sphere()],
            7,
            Shutter::new(0.0, 1.0).unwrap(),
            1,
        );
        let down = |x: f32, time: f32| Ray::new(Vec3::new(x, 5.0, 0.0), -Vec3::Y).with_time(time);
        let hit = objects
            .intersect(&down(0.0, 0.5))
            .expect("at the centre at time 0.5");
        assert_eq!(hit.shape, 7);
        assert!((hit.t - 4.5).abs() < 1e-4);
        assert!(objects.intersect(&down(0.0, 0.1)).is_none());
        assert!(objects.intersect(&down(-8.0, 0.1)).is_some());
        assert!(objects.occluded(&down(-8.0, 0.1)));
        assert!(!objects.occluded(&down(-8.0, 0.9)));
    }

    #[test]
    fn every_stretch_count_finds_the_same_hits_and_more_stretches_test_fewer_shapes() {
        // A row of spheres crossing the whole scene: one box each spans everything.
        let shapes: Vec<MovingShape> = (0..20)
            .map(|i| {
                let y = i as f32 * 1.5;
                MovingShape::new(
                    Shape::Sphere(Sphere::new(Vec3::new(0.0, y, 0.0), 0.5)),
                    crossing_sphere().motion,
                )
            })
            .collect();
        let shutter = Shutter::new(0.0, 1.0).unwrap();
        let naive = MovingObjects::new(shapes.clone(), 0, shutter, 1);
        let split = MovingObjects::new(shapes, 0, shutter, 16);
        let (mut naive_tests, mut split_tests) = (0, 0);
        for i in 0..400 {
            let time = (i as f32 + 0.5) / 400.0;
            let x = -10.0 + 20.0 * ((i * 37 % 400) as f32 / 400.0);
            let ray = Ray::new(Vec3::new(x, 10.0, -5.0), Vec3::Z).with_time(time);
            let a = naive.intersect_counting(&ray, &mut naive_tests);
            let b = split.intersect_counting(&ray, &mut split_tests);
            assert_eq!(a.map(|h| h.shape), b.map(|h| h.shape), "ray {i}");
        }
        assert!(
            split_tests * 4 < naive_tests,
            "{split_tests} vs {naive_tests}"
        );
    }

    #[test]
    fn a_ray_that_hits_at_any_time_is_inside_the_motion_bounds() {
        let shape = MovingShape::new(
            Shape::Sphere(Sphere::new(Vec3::new(1.0, 0.0, 0.0), 0.3)),
            AnimatedTransform::spin(Vec3::Z, 1.3, 0.0, 1.0, Mat4::from_translation(Vec3::Y)),
        );
        let bounds = shape.bounds_over(0.0, 1.0);
        let mut hits = 0;
        for i in 0..2000 {
            let time = i as f32 / 2000.0;
            // The orbit is the circle of radius 1 about (0, 1, 0) in the xy-plane.
            let angle = (i * 7919 % 2000) as f32 / 2000.0 * std::f32::consts::TAU;
            let radius = 0.7 + 0.6 * ((i * 104_729 % 2000) as f32 / 2000.0);
            let origin = Vec3::new(radius * angle.cos(), 1.0 + radius * angle.sin(), -5.0);
            let ray = Ray::new(origin, Vec3::Z).with_time(time);
            if let Some(hit) = shape.intersect(&ray) {
                hits += 1;
                assert!(
                    bounds.contains(hit.p),
                    "time {time}: {} outside {bounds:?}",
                    hit.p
                );
            }
        }
        assert!(hits > 100, "{hits}");
    }
}
