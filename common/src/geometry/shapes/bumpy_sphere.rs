//! A generated mesh of any size: a sphere with bumps, for measuring what meshes cost.
//!
//! Speed measurements need meshes of 10^3 to 10^6 triangles that are alike at every size, so
//! that a change in cost comes from the count and not from the shape. A latitude–longitude
//! sphere does that, and bumps on it give its triangles different sizes and orientations, as
//! a scanned model's have, so that the BVH has real work to do.

use std::f32::consts::PI;

use glam::Vec3;

use super::mesh::TriangleMesh;

/// How far the bumps reach, as a fraction of the radius.
const BUMP_HEIGHT: f32 = 0.05;

impl TriangleMesh {
    /// A closed sphere of radius about 1 around the origin, with bumps and smooth vertex
    /// normals, made of at least `min_triangles` triangles (and at least 16).
    ///
    /// It has `segments` vertices around each of `rings - 1` parallels and one at each pole;
    /// the poles are fans, the bands between parallels strips, `2 · segments · (rings - 1)`
    /// triangles in all. Neighbouring triangles share their vertices by index, so the surface
    /// has no cracks.
    pub fn bumpy_sphere(min_triangles: usize) -> Self {
        let min_triangles = min_triangles.max(16);
        let segments = ((min_triangles as f64).sqrt().ceil() as usize).max(4);
        let rings = min_triangles.div_ceil(2 * segments).max(1) + 1;
        // The bumps fade towards the poles (the factor sin θ), where the parallels shrink to a
        // point: there a bump that still varied with φ would make a spike.
        let radius_at = |theta: f32, phi: f32| {
            let bumps = (5.0 * theta).sin() * (6.0 * phi).sin()
                + 0.5 * (13.0 * theta + 1.0).cos() * (11.0 * phi).cos();
            1.0 + BUMP_HEIGHT * theta.sin() * bumps
        };
        let point = |theta: f32, phi: f32| {
            let direction = Vec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                theta.sin() * phi.sin(),
            );
            radius_at(theta, phi) * direction
        };

        let mut positions = vec![point(0.0, 0.0)];
        for ring in 1..rings {
            let theta = PI * ring as f32 / rings as f32;
            for segment in 0..segments {
                positions.push(point(theta, 2.0 * PI * segment as f32 / segments as f32));
            }
        }
        positions.push(point(PI, 0.0));
        let south = (positions.len() - 1) as u32;

        // Vertex `segment` (taken around) of parallel `ring` (1 ..= rings - 1).
        let vertex =
            |ring: usize, segment: usize| (1 + (ring - 1) * segments + segment % segments) as u32;
        let mut indices = Vec::with_capacity(2 * segments * (rings - 1));
        for segment in 0..segments {
            indices.push([0, vertex(1, segment + 1), vertex(1, segment)]);
        }
        for ring in 1..rings - 1 {
            for segment in 0..segments {
                let (a, b) = (vertex(ring, segment), vertex(ring, segment + 1));
                let (c, d) = (vertex(ring + 1, segment), vertex(ring + 1, segment + 1));
                indices.push([a, b, d]);
                indices.push([a, d, c]);
            }
        }
        for segment in 0..segments {
            indices.push([
                south,
                vertex(rings - 1, segment),
                vertex(rings - 1, segment + 1),
            ]);
        }

        let mut mesh = Self {
            positions,
            normals: None,
            indices,
            uvs: None,
        };
        mesh.recompute_vertex_normals();
        mesh
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn has_at_least_the_triangles_asked_for_and_not_many_more() {
        for asked in [1, 100, 1000, 12_345, 100_000] {
            let mesh = TriangleMesh::bumpy_sphere(asked);
            let count = mesh.indices.len();
            assert!(count >= asked.max(16), "{asked}: {count} triangles");
            assert!(
                (count as f64) < 1.05 * asked as f64 + 64.0,
                "{asked}: {count} triangles is too many"
            );
            mesh.validate().unwrap();
        }
    }

    /// Outward normals, no degenerate triangle, and every edge shared by exactly two
    /// triangles that run along it in opposite directions: a closed, consistently wound surface.
    #[test]
    fn is_closed_and_wound_outwards() {
        let mesh = TriangleMesh::bumpy_sphere(2000);
        let mut edges = std::collections::HashMap::new();
        for corners in &mesh.indices {
            let p = corners.map(|i| mesh.positions[i as usize]);
            let normal = (p[1] - p[0]).cross(p[2] - p[0]);
            assert!(normal.length() > 0.0, "degenerate triangle {corners:?}");
            let centre = (p[0] + p[1] + p[2]) / 3.0;
            assert!(
                normal.dot(centre) > 0.0,
                "triangle {corners:?} faces inwards"
            );
            for k in 0..3 {
                *edges.entry((corners[k], corners[(k + 1) % 3])).or_insert(0) += 1;
            }
        }
        for (&(a, b), &count) in &edges {
            assert_eq!(count, 1, "edge {a}->{b} used {count} times");
            assert_eq!(edges.get(&(b, a)), Some(&1), "edge {a}->{b} has no twin");
        }
        for (p, n) in mesh.positions.iter().zip(mesh.normals.as_ref().unwrap()) {
            assert!(
                n.dot(p.normalize()) > 0.7,
                "normal {n} at {p} does not point outwards"
            );
            let r = p.length();
            assert!((r - 1.0).abs() <= 1.5 * BUMP_HEIGHT + 1e-6, "radius {r}");
        }
    }
}
