//! Where two surfaces touch, light neither leaks through the crease nor is blocked by it.
//!
//! A floor and a wall meet along an edge. A shadow ray from a floor point right next to the
//! wall towards a light *behind* the wall must be blocked by the wall, however close to it the
//! point is: an "ignore hits closer than ε" rule fails exactly here. A shadow ray from the same
//! point towards a light in *front* of the wall must not be blocked by either surface.

use glam::Vec3;
use rand::RngExt;

use super::support::{Placement, log_uniform, rng};
use crate::Ray;
use crate::geometry::{Geometry, Parallelogram, Shape, Triangle};

/// A unit floor (y = 0, facing +y) and wall (x = 0, facing +x) meeting along the z axis, as
/// two parallelograms or as four triangles.
fn floor_and_wall(placement: &Placement, as_triangles: bool) -> Geometry {
    let at = |x: f32, y: f32, z: f32| placement.point(Vec3::new(x, y, z));
    let floor = [
        at(0.0, 0.0, 0.0),
        at(0.0, 0.0, 1.0),
        at(1.0, 0.0, 1.0),
        at(1.0, 0.0, 0.0),
    ];
    let wall = [
        at(0.0, 0.0, 0.0),
        at(0.0, 1.0, 0.0),
        at(0.0, 1.0, 1.0),
        at(0.0, 0.0, 1.0),
    ];
    let shapes: Vec<Shape> = if as_triangles {
        [floor, wall]
            .iter()
            .flat_map(|[a, b, c, d]| [Triangle::new(*a, *b, *c), Triangle::new(*a, *c, *d)])
            .map(Shape::from)
            .collect()
    } else {
        [floor, wall]
            .iter()
            .map(|[a, b, _, d]| Parallelogram::new(*a, *b - *a, *d - *a).into())
            .collect()
    };
    Geometry::new(shapes)
}

/// Shoots at points of one surface close to the other and checks the shadow rays from there.
///
/// `surface_point(s, along)` is a point at distance `s` from the crease, `along` the crease;
/// `distance_from_crease(p)` measures how far a hit point is from it; `camera`, `blocked_light`
/// and `visible_light` are in unit coordinates.
struct CreaseTest {
    surface_point: fn(f32, f32) -> Vec3,
    distance_from_crease: fn(Vec3) -> f32,
    camera: Vec3,
    blocked_light: Vec3,
    visible_light: Vec3,
}

fn check_crease(geometry: &Geometry, placement: &Placement, test: &CreaseTest, seed: u64) {
    let mut rng = rng(seed);
    let origin = placement.point(Vec3::ZERO);
    let blocked = placement.point(test.blocked_light);
    let visible = placement.point(test.visible_light);
    let camera = placement.point(test.camera);
    let mut checked = 0;
    for _ in 0..2000 {
        let from_crease = log_uniform(&mut rng, 1e-5, 0.5);
        let along = rng.random_range(0.1..0.9);
        let target = placement.point((test.surface_point)(from_crease, along));
        let Some(hit) = geometry.intersect(&Ray::new(camera, target - camera)) else {
            continue;
        };
        // Only points certainly on the lit side of the crease count; one that rounded onto
        // the other surface's plane is genuinely ambiguous.
        if (test.distance_from_crease)(hit.p - origin) <= 0.0 {
            continue;
        }
        checked += 1;
        let to_blocked = hit.spawn_ray_to(blocked, 0.0);
        assert!(
            geometry.occluded(&to_blocked),
            "{placement:?}: light leaks at {hit:?}"
        );
        let to_visible = hit.spawn_ray_to(visible, 0.0);
        assert!(
            !geometry.occluded(&to_visible),
            "{placement:?}: shadow acne at {hit:?}: {:?}",
            geometry.intersect(&to_visible)
        );
    }
    if placement.resolves_shapes() {
        assert!(
            checked > 1000,
            "{placement:?}: only {checked} points checked"
        );
    }
}

const FLOOR_NEAR_WALL: CreaseTest = CreaseTest {
    surface_point: |x, z| Vec3::new(x, 0.0, z),
    distance_from_crease: |p| p.x,
    camera: Vec3::new(0.5, 2.0, 0.5),
    blocked_light: Vec3::new(-0.5, 0.5, 0.5),
    visible_light: Vec3::new(0.5, 0.5, 0.5),
};

const WALL_NEAR_FLOOR: CreaseTest = CreaseTest {
    surface_point: |y, z| Vec3::new(0.0, y, z),
    distance_from_crease: |p| p.y,
    camera: Vec3::new(2.0, 0.5, 0.5),
    blocked_light: Vec3::new(0.5, -0.5, 0.5),
    visible_light: Vec3::new(0.5, 0.5, 0.5),
};

#[test]
fn no_light_leaks_and_no_acne_where_quads_touch() {
    for (i, placement) in Placement::all().iter().enumerate() {
        let geometry = floor_and_wall(placement, false);
        check_crease(&geometry, placement, &FLOOR_NEAR_WALL, i as u64);
        check_crease(&geometry, placement, &WALL_NEAR_FLOOR, 100 + i as u64);
    }
}

#[test]
fn no_light_leaks_and_no_acne_where_triangles_touch() {
    for (i, placement) in Placement::all().iter().enumerate() {
        let geometry = floor_and_wall(placement, true);
        check_crease(&geometry, placement, &FLOOR_NEAR_WALL, 200 + i as u64);
        check_crease(&geometry, placement, &WALL_NEAR_FLOOR, 300 + i as u64);
    }
}
