//! Triangles that share an edge or a vertex leave no crack between them.
//!
//! A ray through the shared edge (or vertex) of a mesh passes through the interior of the
//! surface, so it must hit at least one of the triangles. A test that computes each triangle's
//! edge functions independently and slightly inaccurately can reject it in both.

use glam::Vec3;
use rand::RngExt;
use rand_pcg::Pcg32;

use super::support::{Placement, random_unit_vector, rng};
use crate::Ray;
use crate::geometry::Triangle;

/// A direction within 45° of the unit vector `axis`, on either side of the surface at random.
fn camera_direction(rng: &mut Pcg32, axis: Vec3) -> Vec3 {
    let side = if rng.random::<bool>() { axis } else { -axis };
    (side + random_unit_vector(rng) * rng.random_range(0.0..0.7)).normalize()
}

/// Whether a ray from `camera` aimed exactly at `target` hits one of the triangles.
fn ray_at_hits_one_of(triangles: &[Triangle], camera: Vec3, target: Vec3) -> bool {
    let ray = Ray::new(camera, target - camera);
    triangles.iter().any(|t| t.intersect(&ray).is_some())
}

#[test]
fn rays_at_the_diagonal_of_a_split_quad_always_hit() {
    for (i, placement) in Placement::all().iter().enumerate() {
        if !placement.resolves_shapes() {
            continue;
        }
        let at = |x: f32, y: f32, z: f32| placement.point(Vec3::new(x, y, z));
        let v = [
            at(-0.6, -0.5, 0.1),
            at(0.7, -0.4, -0.2),
            at(0.8, 0.6, 0.3),
            at(-0.5, 0.5, 0.4),
        ];
        let triangles = [
            Triangle::new(v[0], v[1], v[2]),
            Triangle::new(v[0], v[2], v[3]),
        ];
        let normal = (v[1] - v[0]).cross(v[2] - v[0]).normalize();
        let mut rng = rng(i as u64);
        for _ in 0..5000 {
            let s = rng.random_range(0.02..0.98);
            let target = v[0] + s * (v[2] - v[0]);
            let camera = target + placement.vector(3.0 * camera_direction(&mut rng, normal));
            assert!(
                ray_at_hits_one_of(&triangles, camera, target),
                "{placement:?}: crack at {target} seen from {camera}"
            );
        }
    }
}

#[test]
fn rays_at_the_centre_and_spokes_of_a_triangle_fan_always_hit() {
    for (i, placement) in Placement::all().iter().enumerate() {
        if !placement.resolves_shapes() {
            continue;
        }
        // A low six-sided pyramid: every spoke and the apex are inside the surface.
        let apex = placement.point(Vec3::new(0.05, 0.2, -0.03));
        let rim: Vec<Vec3> = (0..6)
            .map(|k| {
                let angle = k as f32 * std::f32::consts::TAU / 6.0 + 0.1;
                placement.point(Vec3::new(angle.cos(), 0.0, angle.sin()))
            })
            .collect();
        let triangles: Vec<Triangle> = (0..6)
            .map(|k| Triangle::new(apex, rim[(k + 1) % 6], rim[k]))
            .collect();
        let mut rng = rng(100 + i as u64);
        for _ in 0..5000 {
            let target = if rng.random::<bool>() {
                apex
            } else {
                let spoke = rim[rng.random_range(0..6)];
                apex + rng.random_range(0.0..0.9) * (spoke - apex)
            };
            let camera = target + placement.vector(3.0 * camera_direction(&mut rng, Vec3::Y));
            assert!(
                ray_at_hits_one_of(&triangles, camera, target),
                "{placement:?}: crack at {target} seen from {camera}"
            );
        }
    }
}
