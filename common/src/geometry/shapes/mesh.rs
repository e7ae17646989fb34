//! Indexed triangle meshes, as loaded from model files.

use glam::{Vec2, Vec3};

use super::triangle::Triangle;

/// A triangle mesh: shared vertex positions (and optionally normals and texture coordinates)
/// and, for each triangle, the indices of its three vertices.
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
    /// Three indices into `positions` (and `normals` and `uvs`) per triangle.
    pub indices: Vec<[u32; 3]>,
    /// Texture coordinates, one per position. A triangle interpolates them into its hits'
    /// `uv`; without them its `uv` is the barycentric `(b1, b2)`, as in Mitsuba 3.
    pub uvs: Option<Vec<Vec2>>,
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
    /// There are texture coordinates, but not exactly one per position.
    #[error("the mesh has {positions} positions but {uvs} texture coordinates")]
    UvCountMismatch {
        /// How many positions there are.
        positions: usize,
        /// How many texture coordinates there are.
        uvs: usize,
    },
}

impl TriangleMesh {
    /// How many triangles use each edge, in either direction; an edge is named by its two
    /// vertex indices, the smaller first. A closed mesh uses every edge exactly twice, which
    /// is how tests and figures tell a closed model from one with holes.
    pub fn edge_uses(&self) -> std::collections::HashMap<(u32, u32), usize> {
        let mut uses = std::collections::HashMap::new();
        for &[a, b, c] in &self.indices {
            for (p, q) in [(a, b), (b, c), (c, a)] {
                *uses.entry((p.min(q), p.max(q))).or_insert(0) += 1;
            }
        }
        uses
    }

    /// A mesh without texture coordinates, checked with [`validate`](Self::validate).
    pub fn new(
        positions: Vec<Vec3>,
        normals: Option<Vec<Vec3>>,
        indices: Vec<[u32; 3]>,
    ) -> Result<Self, MeshError> {
        let mesh = Self {
            positions,
            normals,
            indices,
            uvs: None,
        };
        mesh.validate()?;
        Ok(mesh)
    }

    /// The same mesh with texture coordinates `uvs` (or none), checked again.
    pub fn with_uvs(self, uvs: Option<Vec<Vec2>>) -> Result<Self, MeshError> {
        let mesh = Self { uvs, ..self };
        mesh.validate()?;
        Ok(mesh)
    }

    /// Checks that every index names an existing vertex and that normals and texture
    /// coordinates, if present, match the positions one to one.
    pub fn validate(&self) -> Result<(), MeshError> {
        if let Some(uvs) = &self.uvs
            && uvs.len() != self.positions.len()
        {
            return Err(MeshError::UvCountMismatch {
                positions: self.positions.len(),
                uvs: uvs.len(),
            });
        }
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

    // ANCHOR: recompute_vertex_normals
    /// Gives the mesh smooth vertex normals: at each vertex, the mean of the unit normals of
    /// the triangles around it, each weighted by the triangle's angle at that vertex (Thürmer
    /// and Wüthrich, "Computing vertex normals from polygonal facets", 1998; Mitsuba 3 does the
    /// same for a mesh whose file has no normals).
    ///
    /// Weighting by angle rather than by area makes the result independent of how a face is
    /// split into triangles. A normal points to the side from which the triangle's corners
    /// run counter-clockwise. Degenerate triangles add nothing; a vertex with no
    /// non-degenerate triangle gets `+x`, as in Mitsuba, so that no normal is NaN.
    pub fn recompute_vertex_normals(&mut self) {
        let mut sums = vec![Vec3::ZERO; self.positions.len()];
        for corners in &self.indices {
            let p = corners.map(|i| self.positions[i as usize]);
            let Some(n) = (p[1] - p[0]).cross(p[2] - p[0]).try_normalize() else {
                continue;
            };
            for k in 0..3 {
                let to_next = (p[(k + 1) % 3] - p[k]).normalize_or_zero();
                let to_previous = (p[(k + 2) % 3] - p[k]).normalize_or_zero();
                let angle = to_next.dot(to_previous).clamp(-1.0, 1.0).acos();
                sums[corners[k] as usize] += angle * n;
            }
        }
        self.normals = Some(
            sums.into_iter()
                .map(|sum| sum.try_normalize().unwrap_or(Vec3::X))
                .collect(),
        );
    }
    // ANCHOR_END: recompute_vertex_normals

    /// The mesh's triangles, with vertex normals and texture coordinates if the mesh has them.
    ///
    /// # Panics
    ///
    /// If the mesh is malformed; a mesh made with [`new`](Self::new), or one that passed
    /// [`validate`](Self::validate), is not.
    pub fn triangles(&self) -> impl Iterator<Item = Triangle> + '_ {
        self.indices.iter().map(|corners| {
            let [i0, i1, i2] = corners.map(|i| i as usize);
            let p = [self.positions[i0], self.positions[i1], self.positions[i2]];
            let triangle = match &self.normals {
                Some(n) => Triangle::with_normals(p, [n[i0], n[i1], n[i2]]),
                None => Triangle::new(p[0], p[1], p[2]),
            };
            match &self.uvs {
                Some(uv) => triangle.with_uvs([uv[i0], uv[i1], uv[i2]]),
                None => triangle,
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
    fn recomputed_normals_weigh_each_triangle_by_its_angle() {
        // Two faces meeting along the x axis: a flat one in z = 0 and one sloping down at 45
        // degrees. Vertex 0 sees the sloping face with a right angle and the flat one with 45
        // degrees, so its normal leans 2 : 1 towards the sloping face's.
        let positions = vec![
            Vec3::ZERO,                 // 0: on the shared edge
            Vec3::X,                    // 1: on the shared edge
            Vec3::new(0.0, -1.0, -1.0), // 2: down the sloping face
            Vec3::new(1.0, 1.0, 0.0),   // 3: on the flat face, 45 degrees off at vertex 0
        ];
        let mut mesh = TriangleMesh::new(positions, None, vec![[0, 2, 1], [0, 1, 3]]).unwrap();
        mesh.recompute_vertex_normals();
        let normals = mesh.normals.as_ref().unwrap();
        let face = |a: usize, b: usize, c: usize| {
            let p = &mesh.positions;
            (p[b] - p[a]).cross(p[c] - p[a]).normalize()
        };
        let (steep, shallow) = (face(0, 2, 1), face(0, 1, 3));
        let angle = |k: usize, a: usize, b: usize| {
            let p = &mesh.positions;
            (p[a] - p[k])
                .normalize()
                .dot((p[b] - p[k]).normalize())
                .acos()
        };
        let expected = (angle(0, 2, 1) * steep + angle(0, 1, 3) * shallow).normalize();
        assert!((angle(0, 2, 1) - std::f32::consts::FRAC_PI_2).abs() < 1e-6);
        assert!((angle(0, 1, 3) - std::f32::consts::FRAC_PI_4).abs() < 1e-6);
        assert!((normals[0] - expected).length() < 1e-6, "{:?}", normals[0]);
        // Vertices 2 and 3 touch one face each: their normal is that face's.
        assert!((normals[2] - steep).length() < 1e-6);
        assert!((normals[3] - shallow).length() < 1e-6);
        // Both faces point up, away from the ground below the roof.
        assert!(normals.iter().all(|n| n.z > 0.0 && n.is_normalized()));
    }

    #[test]
    fn degenerate_triangles_give_no_nan_normals() {
        let positions = vec![Vec3::ZERO, Vec3::X, 2.0 * Vec3::X, Vec3::Y];
        // A zero-area triangle on the line y = 0; vertex 3 belongs to no triangle at all.
        let mut mesh = TriangleMesh::new(positions, None, vec![[0, 1, 2]]).unwrap();
        mesh.recompute_vertex_normals();
        assert_eq!(mesh.normals.unwrap(), vec![Vec3::X; 4]);
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
    fn texture_coordinates_are_passed_on_and_must_match_the_positions() {
        let square = TriangleMesh::new(unit_square_positions(), None, vec![[0, 2, 3]]).unwrap();
        let uvs: Vec<Vec2> = unit_square_positions()
            .iter()
            .map(|p| p.truncate())
            .collect();
        let mesh = square.clone().with_uvs(Some(uvs)).unwrap();
        let triangle = mesh.triangles().next().unwrap();
        assert_eq!(triangle.uvs, Some([Vec2::ZERO, Vec2::ONE, Vec2::Y]));
        assert_eq!(
            square.with_uvs(Some(vec![Vec2::ZERO])).unwrap_err(),
            MeshError::UvCountMismatch {
                positions: 4,
                uvs: 1
            }
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
