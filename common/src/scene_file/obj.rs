//! Wavefront OBJ meshes: the positions, normals and faces of a triangle mesh.
//!
//! Only what a renderer of this workbook needs is read: `v x y z`, `vn x y z` and faces `f`
//! whose corners are `v`, `v/vt`, `v//vn` or `v/vt/vn` (1-based, or negative to count back
//! from the last vertex read). A polygon with more than three corners is split into a fan of
//! triangles. Texture coordinates, groups, materials and smoothing groups are skipped.

use crate::geometry::TriangleMesh;
use glam::Vec3;
use std::collections::HashMap;
use std::path::Path;

/// Reads the OBJ file at `path`. Errors name the file and, for bad content, the line.
pub fn load_obj(path: &Path) -> Result<TriangleMesh, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the mesh {}: {e}", path.display()))?;
    parse_obj(&text).map_err(|e| format!("{}:{e}", path.display()))
}

/// Parses OBJ text. An error starts with its line number.
pub fn parse_obj(text: &str) -> Result<TriangleMesh, String> {
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    // Corners that share a position and a normal share a vertex of the mesh.
    let mut vertex_of: HashMap<(usize, Option<usize>), u32> = HashMap::new();
    let mut mesh_positions = Vec::new();
    let mut mesh_normals = Vec::new();
    let mut indices = Vec::new();
    let mut every_corner_has_a_normal = true;
    for (number, line) in text.lines().enumerate() {
        let line_number = number + 1;
        let error = |message: String| format!("{line_number}: {message}");
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => positions.push(vector(words, "a vertex `v x y z`").map_err(error)?),
            Some("vn") => normals.push(vector(words, "a normal `vn x y z`").map_err(error)?),
            Some("f") => {
                let mut corners = Vec::new();
                for word in words {
                    let (p, n) = corner(word, positions.len(), normals.len()).map_err(error)?;
                    every_corner_has_a_normal &= n.is_some();
                    let next = mesh_positions.len() as u32;
                    let vertex = *vertex_of.entry((p, n)).or_insert_with(|| {
                        mesh_positions.push(positions[p]);
                        mesh_normals.push(n.map_or(Vec3::ZERO, |n| normals[n]));
                        next
                    });
                    corners.push(vertex);
                }
                if corners.len() < 3 {
                    return Err(error(format!(
                        "a face needs at least 3 corners, this one has {}",
                        corners.len()
                    )));
                }
                for i in 1..corners.len() - 1 {
                    indices.push([corners[0], corners[i], corners[i + 1]]);
                }
            }
            _ => {} // comments, texture coordinates, groups, materials: not needed here
        }
    }
    if indices.is_empty() {
        return Err("0: the mesh has no faces".to_string());
    }
    let normals = (every_corner_has_a_normal).then_some(mesh_normals);
    TriangleMesh::new(mesh_positions, normals, indices).map_err(|e| format!("0: {e}"))
}

fn vector<'a>(mut words: impl Iterator<Item = &'a str>, expected: &str) -> Result<Vec3, String> {
    let mut next = || -> Result<f32, String> {
        let word = words.next().ok_or_else(|| format!("expected {expected}"))?;
        let value: f32 = word
            .parse()
            .map_err(|_| format!("`{word}` is not a number in {expected}"))?;
        if value.is_finite() {
            Ok(value)
        } else {
            Err(format!("`{word}` is not finite in {expected}"))
        }
    };
    Ok(Vec3::new(next()?, next()?, next()?))
}

/// A face corner `v`, `v/vt`, `v//vn` or `v/vt/vn` as 0-based position and normal indices.
fn corner(
    word: &str,
    position_count: usize,
    normal_count: usize,
) -> Result<(usize, Option<usize>), String> {
    let mut parts = word.split('/');
    let position = index(parts.next().unwrap_or(""), position_count, "vertex", word)?;
    let _texture = parts.next();
    let normal = match parts.next() {
        Some(n) if !n.is_empty() => Some(index(n, normal_count, "normal", word)?),
        _ => None,
    };
    Ok((position, normal))
}

fn index(text: &str, count: usize, what: &str, corner: &str) -> Result<usize, String> {
    let value: i64 = text
        .parse()
        .map_err(|_| format!("`{corner}` is not a face corner (v, v/vt, v//vn or v/vt/vn)"))?;
    let resolved = if value > 0 {
        value - 1
    } else {
        count as i64 + value
    };
    if value == 0 || resolved < 0 || resolved >= count as i64 {
        return Err(format!(
            "face corner `{corner}` refers to {what} {value}, but only {count} were read so far"
        ));
    }
    Ok(resolved as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quad_with_normals_becomes_two_triangles() {
        let text = "# a unit square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n";
        let mesh = parse_obj(text).unwrap();
        assert_eq!(mesh.indices, vec![[0, 1, 2], [0, 2, 3]]);
        assert_eq!(mesh.positions.len(), 4);
        assert_eq!(mesh.normals.as_ref().unwrap()[2], Vec3::Z);
    }

    #[test]
    fn negative_indices_count_back_and_missing_normals_mean_flat_shading() {
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3/1 -2/2 -1/3\n";
        let mesh = parse_obj(text).unwrap();
        assert_eq!(mesh.indices, vec![[0, 1, 2]]);
        assert!(mesh.normals.is_none());
    }

    #[test]
    fn bad_meshes_are_refused_with_their_line() {
        let cases = [
            ("v 0 0\n", "1: expected a vertex"),
            ("v 0 0 x\n", "1: `x` is not a number"),
            (
                "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n",
                "5: face corner `4` refers to vertex 4",
            ),
            ("v 0 0 0\nf 1 1\n", "2: a face needs at least 3 corners"),
            (
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n",
                "refers to normal 1",
            ),
            ("v 0 0 0\nf 0 1 1\n", "refers to vertex 0"),
            ("v 0 0 0\n", "no faces"),
            ("v nan 0 0\n", "not finite"),
        ];
        for (text, expected) in cases {
            let error = parse_obj(text).unwrap_err();
            assert!(
                error.contains(expected),
                "{text:?}: expected `{expected}` in `{error}`"
            );
        }
    }

    #[test]
    fn a_missing_file_is_named() {
        let error = load_obj(Path::new("no/such/mesh.obj")).unwrap_err();
        assert!(error.contains("no/such/mesh.obj"), "{error}");
    }
}
