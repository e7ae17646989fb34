//! The BVH is only a shortcut: whatever it answers, testing every shape must answer too.

use glam::Vec3;
use rand::RngExt;
use rand_pcg::Pcg32;

use super::support::{random_unit_vector, rng};
use crate::Ray;
use crate::geometry::{Disc, Geometry, Parallelogram, Shape, Sphere, SurfaceHit, Triangle};

/// The nearest hit found by testing every shape in order.
fn brute_force_nearest(shapes: &[Shape], ray: &Ray) -> Option<SurfaceHit> {
    let mut nearest: Option<SurfaceHit> = None;
    for (index, shape) in shapes.iter().enumerate() {
        let t_max = nearest.map_or(ray.t_max, |hit| hit.t);
        if let Some(hit) = shape.intersect(&Ray { t_max, ..*ray }) {
            nearest = Some(SurfaceHit {
                shape: index as u32,
                ..hit
            });
        }
    }
    nearest
}

fn brute_force_occluded(shapes: &[Shape], ray: &Ray) -> bool {
    shapes.iter().any(|shape| shape.intersect(ray).is_some())
}

fn random_point(rng: &mut Pcg32, half_size: f32) -> Vec3 {
    Vec3::new(
        rng.random_range(-half_size..half_size),
        rng.random_range(-half_size..half_size),
        rng.random_range(-half_size..half_size),
    )
}

/// An axis direction, for shapes whose boxes are flat.
fn random_axis(rng: &mut Pcg32) -> Vec3 {
    [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z][rng.random_range(0..6)]
}

/// A jumble of every kind of shape, including flat boxes, zero-size boxes and shapes that can
/// never be hit.
fn random_scene(rng: &mut Pcg32, count: usize) -> Vec<Shape> {
    (0..count)
        .map(|_| {
            let at = random_point(rng, 10.0);
            let size = rng.random_range(0.05..2.0);
            match rng.random_range(0..8) {
                0 | 1 => Sphere::new(at, size).into(),
                2 | 3 => {
                    let [a, b] = [0, 1].map(|_| at + size * random_unit_vector(rng));
                    Triangle::new(at, a, b).into()
                }
                4 => Parallelogram::new(
                    at,
                    size * random_unit_vector(rng),
                    size * random_unit_vector(rng),
                )
                .into(),
                5 => {
                    // Axis-aligned, so its box is flat.
                    let normal = random_axis(rng);
                    let e1 = normal.any_orthonormal_vector() * size;
                    Parallelogram::new(at, e1, normal.cross(e1)).into()
                }
                6 => {
                    let normal = random_axis(rng);
                    if rng.random::<bool>() {
                        Disc::new(at, normal, size).into()
                    } else {
                        let tangent = normal.any_orthonormal_vector();
                        let axis_b = 0.3 * size * normal.cross(tangent);
                        Disc::ellipse(at, normal, size * tangent, axis_b).into()
                    }
                }
                _ => match rng.random_range(0..3) {
                    // Degenerate: a point, a segment, a sphere of radius zero.
                    0 => Triangle::new(at, at, at).into(),
                    1 => Triangle::new(at, at + Vec3::X, at + 2.0 * Vec3::X).into(),
                    _ => Sphere::new(at, 0.0).into(),
                },
            }
        })
        .collect()
}

/// Shapes whose boxes all have the same centre.
fn concentric_scene(rng: &mut Pcg32, count: usize) -> Vec<Shape> {
    let c = Vec3::new(1.0, -2.0, 0.5);
    (0..count)
        .map(|_| {
            let size = rng.random_range(0.1..5.0);
            match rng.random_range(0..4) {
                0 => Sphere::new(c, size).into(),
                1 => Disc::new(c, random_unit_vector(rng), size).into(),
                2 => {
                    let [e1, e2] = [0, 1].map(|_| size * random_unit_vector(rng));
                    Parallelogram::new(c - 0.5 * (e1 + e2), e1, e2).into()
                }
                _ => {
                    // Vertices c ± v and c + w with |w| <= |v| per axis: the box is c ± |v|.
                    let v = size * random_unit_vector(rng);
                    let w = v * Vec3::new(
                        rng.random_range(-1.0..1.0),
                        rng.random_range(-1.0..1.0),
                        rng.random_range(-1.0..1.0),
                    );
                    Triangle::new(c + v, c - v, c + w).into()
                }
            }
        })
        .collect()
}

/// Rays from all over: many aimed near some shape, half with a finite `t_max`, some along the
/// axes with `±0` components (which make the slab test compute `0 · ∞`), and some parallel to
/// an axis plane and starting exactly in the plane of a face of some shape's box (where that
/// `0 · ∞` becomes NaN).
fn random_ray(rng: &mut Pcg32, shapes: &[Shape]) -> Ray {
    let mut origin = random_point(rng, 15.0);
    let dir = match rng.random_range(0..5) {
        0 => {
            let axis = random_axis(rng);
            signed_zeros(rng, axis)
        }
        1 => {
            let axis = rng.random_range(0..3);
            let bounds = shapes[rng.random_range(0..shapes.len())].bounds();
            origin[axis] = if rng.random() {
                bounds.min[axis]
            } else {
                bounds.max[axis]
            };
            let mut dir = random_unit_vector(rng);
            dir[axis] = 0.0;
            signed_zeros(rng, dir)
        }
        2 | 3 => {
            let shape = &shapes[rng.random_range(0..shapes.len())];
            let near_shape = shape.bounds().centroid() + 0.5 * random_unit_vector(rng);
            (near_shape - origin).normalize()
        }
        _ => random_unit_vector(rng),
    };
    let t_max = if rng.random::<bool>() {
        f32::INFINITY
    } else {
        rng.random_range(0.0..30.0)
    };
    Ray {
        origin,
        dir,
        t_max,
        time: 0.0,
    }
}

/// `v` with each zero component made `-0` at random.
fn signed_zeros(rng: &mut Pcg32, v: Vec3) -> Vec3 {
    Vec3::from_array(
        v.to_array()
            .map(|c| if c == 0.0 && rng.random() { -0.0 } else { c }),
    )
}

/// Checks `intersect` and `occluded` against brute force; returns how many rays hit something.
fn check_against_brute_force(shapes: Vec<Shape>, rays: usize, rng: &mut Pcg32) -> usize {
    let geometry = Geometry::new(shapes);
    let mut hits = 0;
    for _ in 0..rays {
        let ray = random_ray(rng, geometry.shapes());
        let expected = brute_force_nearest(geometry.shapes(), &ray);
        assert_eq!(geometry.intersect(&ray), expected, "{ray:?}");
        assert_eq!(
            geometry.occluded(&ray),
            brute_force_occluded(geometry.shapes(), &ray),
            "{ray:?}"
        );
        hits += usize::from(expected.is_some());
    }
    hits
}

#[test]
fn random_scenes_give_the_same_nearest_hit_as_brute_force() {
    let mut rng = rng(7);
    let mut hits = 0;
    for count in [2, 5, 17, 300, 600] {
        let shapes = random_scene(&mut rng, count);
        hits += check_against_brute_force(shapes, 2000, &mut rng);
    }
    assert!(hits > 2000, "only {hits} of 10000 rays hit anything");
}

#[test]
fn shapes_with_coincident_centroids_give_the_same_nearest_hit_as_brute_force() {
    let mut rng = rng(8);
    let shapes = concentric_scene(&mut rng, 300);
    let hits = check_against_brute_force(shapes, 3000, &mut rng);
    assert!(hits > 1000, "only {hits} rays hit anything");
}

#[test]
fn an_empty_scene_hits_nothing() {
    let geometry = Geometry::new(Vec::new());
    let ray = Ray::new(Vec3::ZERO, Vec3::X);
    assert_eq!(geometry.intersect(&ray), None);
    assert!(!geometry.occluded(&ray));
    assert!(geometry.bounds().is_empty());
    assert_eq!(geometry.bvh().node_count(), 0);
}

#[test]
fn a_single_shape_works() {
    let sphere = Sphere::new(Vec3::new(0.0, 0.0, 5.0), 1.0);
    let geometry = Geometry::new(vec![sphere.into()]);
    let ray = Ray::new(Vec3::ZERO, Vec3::Z);
    assert_eq!(geometry.intersect(&ray), sphere.intersect(&ray));
    assert!(geometry.occluded(&ray));
    assert!(!geometry.occluded(&Ray { t_max: 3.9, ..ray }));
    assert_eq!(geometry.bounds(), sphere.bounds());
    assert_eq!(geometry.bvh().node_count(), 1);
}

#[test]
fn hits_report_the_index_of_their_shape() {
    let shapes: Vec<Shape> = (0..10)
        .map(|k| Sphere::new(Vec3::new(3.0 * k as f32, 0.0, 0.0), 1.0).into())
        .collect();
    let geometry = Geometry::new(shapes);
    for k in 0..10 {
        let ray = Ray::new(Vec3::new(3.0 * k as f32, 5.0, 0.0), -Vec3::Y);
        assert_eq!(geometry.intersect(&ray).unwrap().shape, k);
    }
}
