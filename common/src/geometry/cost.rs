//! What a mesh costs the BVH: build time, memory and time per ray, measured against its size.
//!
//! A BVH promises a build in `O(n log n)` (the SAH sorts primitives into bins at every level
//! of a tree `log n` deep) and a walk in `O(log n)` per ray for rays that meet the surface
//! (a path down the tree, and a few leaves around the hit). [`measure_bvh_cost`] measures the
//! three numbers a user of a mesh feels, for one mesh, so that a figure can plot them against
//! the triangle count beside those slopes.

use std::time::Instant;

use glam::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg32;
use rayon::prelude::*;

use super::{Geometry, Shape, TriangleMesh};
use crate::Ray;

/// The measured cost of one mesh's geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BvhCost {
    /// Triangles in the mesh.
    pub triangles: usize,
    /// Seconds to build the geometry (boxes, BVH, the walk's layout), the best of a few builds.
    pub build_seconds: f64,
    /// Bytes of the geometry (shapes, BVH nodes, the walk's layout) per triangle.
    pub bytes_per_triangle: f64,
    /// Nanoseconds per nearest-hit query on one thread, the best of a few passes.
    pub nanoseconds_per_ray: f64,
    /// Nearest-hit queries per second on one thread and on two.
    pub rays_per_second: [f64; 2],
    /// The fraction of the rays that hit the mesh.
    pub hit_fraction: f64,
}

/// Measures `mesh` with `ray_count` rays from a sphere around it, aimed at random points of its
/// box (the same rays for a seed, whatever the mesh's size).
pub fn measure_bvh_cost(mesh: &TriangleMesh, ray_count: usize, seed: u64) -> BvhCost {
    let shapes = || -> Vec<Shape> { mesh.triangles().map(Shape::from).collect() };
    // Builds of small meshes take microseconds: repeat them for a tenth of a second at least.
    let mut build_seconds = f64::INFINITY;
    let mut spent = 0.0;
    let mut builds = 0;
    let mut geometry = Geometry::default();
    while builds < 3 || (spent < 0.1 && builds < 1000) {
        let shapes = shapes();
        let started = Instant::now();
        geometry = Geometry::new(shapes);
        let seconds = started.elapsed().as_secs_f64();
        build_seconds = build_seconds.min(seconds);
        spent += seconds;
        builds += 1;
    }

    let rays = rays_at(&geometry, ray_count, seed);
    let trace = |rays: &[Ray]| {
        rays.iter()
            .filter(|ray| geometry.intersect(ray).is_some())
            .count()
    };
    let mut hits = 0;
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let started = Instant::now();
        hits = trace(&rays);
        best = best.min(started.elapsed().as_secs_f64());
    }
    let two_threads = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .expect("a pool of two threads");
    let mut best_parallel = f64::INFINITY;
    for _ in 0..3 {
        let started = Instant::now();
        let parallel_hits: usize = two_threads.install(|| rays.par_chunks(1024).map(&trace).sum());
        best_parallel = best_parallel.min(started.elapsed().as_secs_f64());
        assert_eq!(parallel_hits, hits, "the same rays hit the same triangles");
    }
    BvhCost {
        triangles: mesh.indices.len(),
        build_seconds,
        bytes_per_triangle: geometry.memory_bytes() as f64 / mesh.indices.len() as f64,
        nanoseconds_per_ray: 1e9 * best / rays.len() as f64,
        rays_per_second: [rays.len() as f64 / best, rays.len() as f64 / best_parallel],
        hit_fraction: hits as f64 / rays.len() as f64,
    }
}

/// Rays from a sphere twice the size of the geometry's box around its centre, each towards a
/// random point of the box.
fn rays_at(geometry: &Geometry, count: usize, seed: u64) -> Vec<Ray> {
    let bounds = geometry.bounds();
    let centre = 0.5 * (bounds.min + bounds.max);
    let radius = (bounds.max - bounds.min).length();
    let mut rng = Pcg32::seed_from_u64(seed);
    let mut unit = || Vec3::new(rng.random(), rng.random(), rng.random());
    (0..count)
        .map(|_| {
            // A point of the ball, drawn by rejection, pushed out to its sphere.
            let on_sphere = loop {
                let v = 2.0 * unit() - Vec3::ONE;
                if (1e-6..=1.0).contains(&v.length_squared()) {
                    break v.normalize();
                }
            };
            let origin = centre + radius * on_sphere;
            let target = bounds.min + unit() * (bounds.max - bounds.min);
            Ray::new(origin, (target - origin).normalize())
        })
        .collect()
}
