//! What a mesh costs the BVH: build time, memory and time per ray, measured against its size.
//!
//! A BVH promises a build in `O(n log n)` (the SAH sorts primitives into bins at every level
//! of a tree `log n` deep) and a walk in `O(log n)` per ray for rays that meet the surface
//! (a path down the tree, and a few leaves around the hit). [`measure_bvh_cost`] measures the
//! three numbers a user of a mesh feels, for one mesh, and counts the walk's steps, so that a
//! figure can plot them against the triangle count beside those slopes: the count shows the
//! structure's promise, the time what the machine's caches make of it.

use std::time::Instant;

use glam::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg32;
use rayon::prelude::*;

use super::{Geometry, Shape, TriangleMesh, WalkCount};
use crate::Ray;

/// The measured cost of one mesh's geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BvhCost {
    /// Triangles in the mesh.
    pub triangles: usize,
    /// Seconds to build the geometry (boxes, BVH, the walk's layout) on one thread and on two,
    /// each the best of a few builds (of one, for a build of a second or more). The SAH splits
    /// the work of large nodes over the threads, so the two differ above a few ten thousand
    /// triangles; the tree is the same.
    pub build_seconds: [f64; 2],
    /// Bytes of the geometry (shapes, BVH nodes, the walk's layout) per triangle.
    pub bytes_per_triangle: f64,
    /// Nanoseconds per nearest-hit query on one thread, the best of a few passes.
    pub nanoseconds_per_ray: f64,
    /// Nearest-hit queries per second on one thread and on two.
    pub rays_per_second: [f64; 2],
    /// The fraction of the rays that hit the mesh.
    pub hit_fraction: f64,
    /// BVH nodes a ray is tested against, on average over the first [`COUNTED_RAYS`] rays:
    /// the walk's steps, which the structure promises to grow as `log n` whatever the machine.
    pub nodes_per_ray: f64,
    /// Leaves a ray opens, on average over the same rays.
    pub leaves_per_ray: f64,
}

/// The rays whose walks are counted: enough for a mean known to a few hundredths of a node.
pub const COUNTED_RAYS: usize = 20_000;

/// Measures `mesh` with `ray_count` rays from a sphere around it, aimed at random points of its
/// box (the same rays for a seed, whatever the mesh's size).
pub fn measure_bvh_cost(mesh: &TriangleMesh, ray_count: usize, seed: u64) -> BvhCost {
    let pool = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a pool of threads")
    };
    let (one_thread, two_threads) = (pool(1), pool(2));
    let (geometry, build_one) = one_thread.install(|| best_build(mesh));
    let (_, build_two) = two_threads.install(|| best_build(mesh));

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
    let mut best_parallel = f64::INFINITY;
    for _ in 0..3 {
        let started = Instant::now();
        let parallel_hits: usize = two_threads.install(|| rays.par_chunks(1024).map(&trace).sum());
        best_parallel = best_parallel.min(started.elapsed().as_secs_f64());
        assert_eq!(parallel_hits, hits, "the same rays hit the same triangles");
    }
    // The steps are counted, not timed: a mean over the first rays is as good as over all.
    let counted_rays = &rays[..rays.len().min(COUNTED_RAYS)];
    let counted = counted_rays.iter().fold(WalkCount::default(), |sum, ray| {
        let (_, count) = geometry.intersect_counted(ray);
        WalkCount {
            nodes: sum.nodes + count.nodes,
            leaves: sum.leaves + count.leaves,
        }
    });
    BvhCost {
        triangles: mesh.indices.len(),
        build_seconds: [build_one, build_two],
        bytes_per_triangle: geometry.memory_bytes() as f64 / mesh.indices.len() as f64,
        nanoseconds_per_ray: 1e9 * best / rays.len() as f64,
        rays_per_second: [rays.len() as f64 / best, rays.len() as f64 / best_parallel],
        hit_fraction: hits as f64 / rays.len() as f64,
        nodes_per_ray: counted.nodes as f64 / counted_rays.len() as f64,
        leaves_per_ray: counted.leaves as f64 / counted_rays.len() as f64,
    }
}

/// The geometry of `mesh` and the seconds of its quickest build on the current thread pool.
///
/// Builds of small meshes take microseconds: they are repeated for a tenth of a second at
/// least. The best of three otherwise, but no more repeats once a second is spent: a build that
/// long (a million triangles) is long beside the noise it would average out.
fn best_build(mesh: &TriangleMesh) -> (Geometry, f64) {
    let mut best = f64::INFINITY;
    let mut spent = 0.0;
    let mut builds = 0;
    let mut geometry = Geometry::default();
    while builds == 0 || (builds < 3 && spent < 1.0) || (spent < 0.1 && builds < 1000) {
        let shapes: Vec<Shape> = mesh.triangles().map(Shape::from).collect();
        let started = Instant::now();
        geometry = Geometry::new(shapes);
        let seconds = started.elapsed().as_secs_f64();
        best = best.min(seconds);
        spent += seconds;
        builds += 1;
    }
    (geometry, best)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ray_walks_about_log_n_nodes() {
        let small = measure_bvh_cost(&TriangleMesh::bumpy_sphere(1_000), 2_000, 1);
        let large = measure_bvh_cost(&TriangleMesh::bumpy_sphere(64_000), 2_000, 1);
        // Nodes of four: 64 times the triangles is three more levels. A walk that grew with
        // n (a list, or a tree whose boxes all overlap) would take about 64 times the steps.
        let more_steps = large.nodes_per_ray - small.nodes_per_ray;
        assert!(
            (1.0..6.0).contains(&more_steps),
            "{} nodes per ray at 1k triangles, {} at 64k",
            small.nodes_per_ray,
            large.nodes_per_ray
        );
        // And few steps at all: a tree of nodes of four is about log4(n) levels deep, and a
        // ray walks about one path down it (a tree built badly, one triangle split off at a
        // time, walks three times as many).
        for cost in [small, large] {
            let levels = (cost.triangles as f64).log(4.0);
            assert!(
                cost.nodes_per_ray < 2.0 * levels,
                "{} nodes per ray at {} triangles, about {levels:.1} levels",
                cost.nodes_per_ray,
                cost.triangles
            );
        }
        // A ray that meets the surface opens a few leaves around its hit, at any size.
        assert!(small.leaves_per_ray < 4.0 && large.leaves_per_ray < 4.0);
        assert!(
            (0.5..1.0).contains(&small.hit_fraction),
            "{}",
            small.hit_fraction
        );
    }
}
