//! Indexed triangle meshes, as loaded from model files.

use glam::Vec3;

use super::triangle::Triangle;

/// A triangle mesh: shared vertex positions (and optionally normals) and, for each triangle,
/// the indices of its three vertices.
///
/// The renderer does not intersect meshes directly: [`triangles`](Self::triangles) turns one
/// into independent [`Triangle`]s, which go into the scene's BVH like every other shape. The
/// shared vertices still matter: neighbouring triangles get *bit-identical* copies of their
/// common vertices, which the watertight triangle test needs to leave no cracks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleMesh {
    /// Vertex positions.
    pub positions: Vec<Vec3>,
    /// Unit vertex normals, one per position, for smooth shading.
    pub normals: Option<Vec<Vec3>>,
    /// Three indices into `positions` (and `normals`) per triangle.
    pub indices: Vec<[u32; 3]>,
}

/// Why a [`TriangleMesh`] is malformed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum MeshError {
    /// A triangle refers to a vertex that does not exist.
    #[error(
        "triangle {triangle} refers to vertex {index}, but the mesh has {vertex_count} vertices"
    )]
    IndexOutOfRange {
        /// Which triangle (its position in `indices`).
        triangle: usize,
        /// The offending index.
        index: u32,
        /// How many positions there are.
        vertex_count: usize,
    },
    /// There are normals, but not exactly one per position.
    #[error("the mesh has {positions} positions but {normals} normals")]
    NormalCountMismatch {
        /// How many positions there are.
        positions: usize,
        /// How many normals there are.
        normals: usize,
    },
}

impl TriangleMesh {
    /// A mesh, checked with [`validate`](Self::validate).
    pub fn new(
        positions: Vec<Vec3>,
        normals: Option<Vec<Vec3>>,
        indices: Vec<[u32; 3]>,
    ) -> Result<Self, MeshError> {
        let mesh = Self {
            positions,
            normals,
            indices,
        };
        mesh.validate()?;
        Ok(mesh)
    }

    /// Checks that every index names an existing vertex and that normals, if present, match
    /// the positions one to one.
    pub fn validate(&self) -> Result<(), MeshError> {
        if let Some(normals) = &self.normals
            && normals.len() != self.positions.len()
        {
            return Err(MeshError::NormalCountMismatch {
                positions: self.positions.len(),
                normals: normals.len(),
            });
        }
        let vertex_count = self.positions.len();
        for (triangle, corners) in self.indices.iter().enumerate() {
            if let Some(&index) = corners.iter().find(|&&i| i as usize >= vertex_count) {
                return Err(MeshError::IndexOutOfRange {
                    triangle,
                    index,
                    vertex_count,
                });
            }
        }
        Ok(())
    }

    /// The mesh's triangles, with vertex normals if the mesh has them.
    ///
    /// # Panics
    ///
    /// If the mesh is malformed; a mesh made with [`new`](Self::new), or one that passed
    /// [`validate`](Self::validate), is not.
    pub fn triangles(&self) -> impl Iterator<Item = Triangle> + '_ {
        self.indices.iter().map(|corners| {
            let [i0, i1, i2] = corners.map(|i| i as usize);
            let p = [self.positions[i0], self.positions[i1], self.positions[i2]];
            match &self.normals {
                Some(n) => Triangle::with_normals(p, [n[i0], n[i1], n[i2]]),
                None => Triangle::new(p[0], p[1], p[2]),
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit_square_positions() -> Vec<Vec3> {
        vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y]
    }

    #[test]
    fn a_valid_mesh_yields_its_triangles_sharing_vertices() {
        let mesh =
            TriangleMesh::new(unit_square_positions(), None, vec![[0, 1, 2], [0, 2, 3]]).unwrap();
        let triangles: Vec<Triangle> = mesh.triangles().collect();
        assert_eq!(triangles.len(), 2);
        assert_eq!(triangles[0].p[2], triangles[1].p[1]);
        assert_eq!(
            triangles[1].p,
            [Vec3::ZERO, Vec3::new(1.0, 1.0, 0.0), Vec3::Y]
        );
        assert!(triangles.iter().all(|t| t.normals.is_none()));
    }

    #[test]
    fn vertex_normals_are_passed_on() {
        let normals = vec![Vec3::Z; 4];
        let mesh =
            TriangleMesh::new(unit_square_positions(), Some(normals), vec![[0, 1, 2]]).unwrap();
        let triangle = mesh.triangles().next().unwrap();
        assert_eq!(triangle.normals, Some([Vec3::Z; 3]));
    }

    #[test]
    fn out_of_range_indices_are_reported() {
        let error = TriangleMesh::new(unit_square_positions(), None, vec![[0, 1, 2], [2, 4, 0]])
            .unwrap_err();
        assert_eq!(
            error,
            MeshError::IndexOutOfRange {
                triangle: 1,
                index: 4,
                vertex_count: 4
            }
        );
        assert_eq!(
            error.to_string(),
            "triangle 1 refers to vertex 4, but the mesh has 4 vertices"
        );
    }

    #[test]
    fn normal_count_must_match() {
        let error =
            TriangleMesh::new(unit_square_positions(), Some(vec![Vec3::Z]), vec![]).unwrap_err();
        assert_eq!(
            error,
            MeshError::NormalCountMismatch {
                positions: 4,
                normals: 1
            }
        );
    }
}
