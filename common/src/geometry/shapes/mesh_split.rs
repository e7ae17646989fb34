//! Splitting every triangle of a mesh in four: the same surface with four times the
//! triangles, for measuring how a real model's cost grows with its size.

use std::collections::HashMap;

use super::mesh::TriangleMesh;

impl TriangleMesh {
    /// The mesh with every triangle split in four at the midpoints of its edges: the same
    /// flat surface, four times the triangles.
    ///
    /// A midpoint is made once per edge and shared by the triangles on both sides, computed
    /// from the edge's two vertices in one fixed order: so the split mesh is as watertight as
    /// the mesh was. The four triangles keep their parent's winding (and so its normal).
    /// Vertex normals are averaged and texture coordinates interpolated at the midpoints.
    ///
    /// # Panics
    ///
    /// If the split mesh would have more than `u32::MAX` vertices, or if the mesh is malformed
    /// (see [`validate`](Self::validate)).
    pub fn split_in_four(&self) -> TriangleMesh {
        let mut positions = self.positions.clone();
        let mut normals = self.normals.clone();
        let mut uvs = self.uvs.clone();
        let mut midpoints: HashMap<(u32, u32), u32> =
            HashMap::with_capacity(self.indices.len() * 3 / 2);
        let mut midpoint = |a: u32, b: u32| -> u32 {
            let edge = (a.min(b), a.max(b));
            *midpoints.entry(edge).or_insert_with(|| {
                let (a, b) = (edge.0 as usize, edge.1 as usize);
                positions.push(0.5 * (positions[a] + positions[b]));
                if let Some(normals) = &mut normals {
                    let mean = (normals[a] + normals[b]).try_normalize();
                    normals.push(mean.unwrap_or(normals[a]));
                }
                if let Some(uvs) = &mut uvs {
                    uvs.push(0.5 * (uvs[a] + uvs[b]));
                }
                u32::try_from(positions.len() - 1).expect("at most u32::MAX vertices")
            })
        };
        let mut indices = Vec::with_capacity(4 * self.indices.len());
        for &[a, b, c] in &self.indices {
            let (ab, bc, ca) = (midpoint(a, b), midpoint(b, c), midpoint(c, a));
            indices.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        TriangleMesh {
            positions,
            normals,
            indices,
            uvs,
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::Vec3;

    use super::*;

    /// The eight faces of the octahedron with corners on the unit axes, wound outward.
    fn octahedron() -> TriangleMesh {
        let positions = vec![Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z];
        let indices = vec![
            [0, 2, 4],
            [2, 1, 4],
            [1, 3, 4],
            [3, 0, 4],
            [2, 0, 5],
            [1, 2, 5],
            [3, 1, 5],
            [0, 3, 5],
        ];
        TriangleMesh::new(positions, None, indices).unwrap()
    }

    fn area(mesh: &TriangleMesh) -> f32 {
        mesh.triangles().map(|t| t.area()).sum()
    }

    #[test]
    fn a_split_mesh_has_four_times_the_triangles_and_one_new_vertex_per_edge() {
        let mesh = octahedron();
        let split = mesh.split_in_four();
        split.validate().unwrap();
        assert_eq!(split.indices.len(), 4 * mesh.indices.len());
        assert_eq!(
            split.positions.len(),
            mesh.positions.len() + mesh.edge_uses().len()
        );
        let twice = split.split_in_four();
        assert_eq!(twice.indices.len(), 16 * mesh.indices.len());
    }

    #[test]
    fn a_closed_mesh_stays_closed_with_the_same_surface_and_winding() {
        let mesh = octahedron();
        let split = mesh.split_in_four().split_in_four();
        // Every edge between exactly two triangles: no crack, no midpoint made twice.
        assert!(split.edge_uses().values().all(|&uses| uses == 2));
        assert!((area(&split) - area(&mesh)).abs() < 1e-5 * area(&mesh));
        // Outward faces stay outward: each normal points away from the centre.
        for triangle in split.triangles() {
            let [p0, p1, p2] = triangle.p;
            let outward = (p1 - p0).cross(p2 - p0).dot(p0 + p1 + p2);
            assert!(outward > 0.0, "{triangle:?}");
        }
    }

    #[test]
    fn normals_and_texture_coordinates_are_carried_to_the_midpoints() {
        let mesh = TriangleMesh::new(
            vec![Vec3::ZERO, Vec3::X, Vec3::Y],
            Some(vec![Vec3::Z, Vec3::X, Vec3::Z]),
            vec![[0, 1, 2]],
        )
        .unwrap()
        .with_uvs(Some(vec![glam::Vec2::ZERO, glam::Vec2::X, glam::Vec2::Y]))
        .unwrap();
        let split = mesh.split_in_four();
        split.validate().unwrap();
        let at = |p: Vec3| split.positions.iter().position(|&q| q == p).unwrap();
        let middle_of_01 = at(Vec3::new(0.5, 0.0, 0.0));
        let normals = split.normals.as_ref().unwrap();
        assert!((normals[middle_of_01] - (Vec3::Z + Vec3::X).normalize()).length() < 1e-6);
        assert_eq!(
            split.uvs.as_ref().unwrap()[middle_of_01],
            glam::Vec2::new(0.5, 0.0)
        );
    }
}
