//! Secondary rays never hit the surface they leave, at any scale and any distance from the
//! origin.
//!
//! Every shape here is convex (or flat), so a ray leaving its surface towards the side it was
//! hit from can never meet it again, not even far away: *any* hit of the same shape counts as
//! a self-intersection.

use glam::Vec3;
use rand::RngExt;
use rand_pcg::Pcg32;

use super::support::{Placement, log_uniform, random_direction_on_side, random_unit_vector, rng};
use crate::Ray;
use crate::geometry::{Disc, Parallelogram, Shape, Sphere, SurfaceHit, Triangle};

/// One of each shape kind, deliberately not aligned with the axes, plus an axis-aligned floor;
/// all within distance 2 of `placement.point(Vec3::ZERO)`.
fn shapes_under_test(placement: &Placement) -> Vec<(&'static str, Shape)> {
    let at = |x: f32, y: f32, z: f32| placement.point(Vec3::new(x, y, z));
    let along = |x: f32, y: f32, z: f32| placement.vector(Vec3::new(x, y, z));
    vec![
        (
            "sphere",
            Sphere::new(at(0.1, -0.2, 0.3), placement.scale).into(),
        ),
        (
            "triangle",
            Triangle::new(at(-0.9, -0.6, 0.2), at(1.1, -0.3, -0.4), at(0.2, 0.9, 0.5)).into(),
        ),
        (
            "quad",
            Parallelogram::new(
                at(-0.7, -0.5, 0.1),
                along(1.3, 0.2, -0.4),
                along(0.1, 1.1, 0.6),
            )
            .into(),
        ),
        (
            "floor quad",
            Parallelogram::new(
                at(-0.5, 0.25, -0.5),
                along(0.0, 0.0, 1.0),
                along(1.0, 0.0, 0.0),
            )
            .into(),
        ),
        (
            "disc",
            Disc::new(
                at(0.2, 0.1, -0.3),
                Vec3::new(0.3, 0.8, -0.5),
                placement.scale,
            )
            .into(),
        ),
        ("ellipse", {
            let normal = Vec3::new(-0.6, 0.7, 0.2).normalize();
            let tangent = normal.any_orthonormal_vector();
            Disc::ellipse(
                at(-0.1, 0.2, 0.3),
                normal,
                1.3 * placement.scale * tangent,
                0.35 * placement.scale * normal.cross(tangent),
            )
            .into()
        }),
    ]
}

/// A random point on the shape (up to rounding), to aim a camera ray at.
fn random_point_on(shape: &Shape, rng: &mut Pcg32) -> Vec3 {
    match shape {
        Shape::Sphere(s) => s.center + s.radius * random_unit_vector(rng),
        Shape::Triangle(t) => {
            let (mut b1, mut b2) = (rng.random::<f32>(), rng.random::<f32>());
            if b1 + b2 > 1.0 {
                (b1, b2) = (1.0 - b1, 1.0 - b2);
            }
            let [p0, p1, p2] = t.p;
            p0 + b1 * (p1 - p0) + b2 * (p2 - p0)
        }
        Shape::Parallelogram(q) => q.point_at(rng.random(), rng.random()),
        Shape::Disc(d) => {
            let r = d.radii() * rng.random::<f32>().sqrt();
            let phi = rng.random_range(0.0..std::f32::consts::TAU);
            d.point_at(r.x * phi.cos(), r.y * phi.sin())
        }
    }
}

/// Counts of what happened to the rays spawned from one shape at one placement.
#[derive(Debug, Default)]
struct Outcome {
    camera_rays: usize,
    hits: usize,
    self_intersections: usize,
    first_failure: Option<String>,
}

impl Outcome {
    fn fail(&mut self, what: &str, hit: &SurfaceHit, ray: &Ray, again: Option<SurfaceHit>) {
        self.self_intersections += 1;
        self.first_failure.get_or_insert_with(|| {
            format!("{what}: from {hit:?} the ray {ray:?} met the surface again: {again:?}")
        });
    }
}

/// Shoots `count` camera rays at the shape and checks every ray spawned from every hit.
fn spawn_from_hits(shape: &Shape, placement: &Placement, count: usize, seed: u64) -> Outcome {
    let mut rng = rng(seed);
    let mut outcome = Outcome::default();
    let middle = placement.point(Vec3::ZERO);
    for _ in 0..count {
        let camera = middle + placement.vector(4.0 * random_unit_vector(&mut rng));
        let target = random_point_on(shape, &mut rng);
        let camera_ray = Ray::new(camera, target - camera);
        outcome.camera_rays += 1;
        let Some(hit) = shape.intersect(&camera_ray) else {
            continue;
        };
        outcome.hits += 1;
        // The side of the surface the camera ray came from.
        let outside = if hit.front_face(camera_ray.dir) {
            hit.n
        } else {
            -hit.n
        };

        let d = camera_ray.dir.normalize();
        let reflected = d - 2.0 * d.dot(hit.n) * hit.n;
        let ray = hit.spawn_ray(reflected, 0.0);
        if let Some(again) = shape.intersect(&ray) {
            outcome.fail("reflected", &hit, &ray, Some(again));
        }

        for _ in 0..4 {
            let w = random_direction_on_side(&mut rng, outside);
            let ray = hit.spawn_ray(w, 0.0);
            if let Some(again) = shape.intersect(&ray) {
                outcome.fail("random direction", &hit, &ray, Some(again));
            }

            // A point light a little above the surface, but certainly above it: its height
            // must be well clear of the error bound of `p`.
            let error_along_n = hit.n.abs().dot(hit.p_error);
            let w = random_direction_on_side(&mut rng, outside);
            let height = w.dot(outside);
            let distance = log_uniform(&mut rng, 1e-4, 10.0) * placement.scale;
            let light = hit.p + distance.max(64.0 * error_along_n / height) * w;
            let ray = hit.spawn_ray_to(light, 0.0);
            if let Some(again) = shape.intersect(&ray) {
                outcome.fail("shadow ray", &hit, &ray, Some(again));
            }
        }

        // Leaving through the surface: a flat shape is left behind; a sphere is crossed, so
        // the next hit is the far wall, at least a radius away.
        let inward = -outside;
        let ray = hit.spawn_ray(inward, 0.0);
        let again = shape.intersect(&ray);
        let fine = match shape {
            Shape::Sphere(s) => {
                again.is_some_and(|far| far.t > s.radius && !far.front_face(inward))
            }
            _ => again.is_none(),
        };
        if !fine {
            outcome.fail("transmitted", &hit, &ray, again);
        }
    }
    outcome
}

#[test]
fn secondary_rays_never_hit_the_surface_they_leave() {
    for (placement_index, placement) in Placement::all().iter().enumerate() {
        for (shape_index, (name, shape)) in shapes_under_test(placement).iter().enumerate() {
            let seed = (placement_index * 16 + shape_index) as u64;
            let outcome = spawn_from_hits(shape, placement, 2000, seed);
            assert_eq!(
                outcome.self_intersections, 0,
                "{name} at {placement:?}: {outcome:?}"
            );
            if placement.resolves_shapes() {
                assert!(
                    outcome.hits * 2 > outcome.camera_rays,
                    "{name} at {placement:?}: too few hits to test anything: {outcome:?}"
                );
            }
        }
    }
}

#[test]
fn rays_starting_inside_a_sphere_and_reflecting_inside_hit_the_far_wall_only() {
    for (placement_index, placement) in Placement::all().iter().enumerate() {
        if !placement.resolves_shapes() {
            continue;
        }
        let sphere = Sphere::new(placement.point(Vec3::ZERO), placement.scale);
        let mut rng = rng(1000 + placement_index as u64);
        for _ in 0..1000 {
            let inside = placement.point(0.5 * random_unit_vector(&mut rng));
            let ray = Ray::new(inside, random_unit_vector(&mut rng));
            let hit = sphere
                .intersect(&ray)
                .expect("a ray from inside hits the wall");
            assert!(!hit.front_face(ray.dir), "the normal points outwards");
            // Bounce inside, well away from grazing: the chord ahead is at least a radius long.
            let w = -hit.n + 0.5 * random_unit_vector(&mut rng);
            let bounced = hit.spawn_ray(w, 0.0);
            let again = sphere.intersect(&bounced).expect("the bounce stays inside");
            assert!(
                again.t * w.length() > 0.5 * sphere.radius,
                "{placement:?}: {hit:?} re-hit at {again:?}"
            );
        }
    }
}
