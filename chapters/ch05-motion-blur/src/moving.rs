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
use crate::object_space::{hit_to_world, to_object_space};
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
    /// The nearest hit at the ray's time: the ray goes into object space, the hit comes back.
    pub fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        let (object_to_world, world_to_object) = self.motion.at_with_inverse(ray.time);
        let local_hit = self
            .shape
            .intersect(&to_object_space(ray, &world_to_object))?;
        Some(hit_to_world(&local_hit, &object_to_world, &world_to_object))
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
    use common::geometry::Sphere;
    use glam::{Mat4, Vec3};

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
