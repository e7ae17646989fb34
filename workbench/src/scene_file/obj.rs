//! Wavefront OBJ meshes: the positions, normals, texture coordinates and faces of a triangle
//! mesh.
//!
//! Only what a renderer of this workbook needs is read: `v x y z`, `vn x y z`, `vt u v` and
//! faces `f` whose corners are `v`, `v/vt`, `v//vn` or `v/vt/vn` (1-based, or negative to count
//! back from the last one read). A polygon with more than three corners is split into a fan of
//! triangles. Groups, materials and smoothing groups are skipped.
//!
//! Texture coordinates follow Mitsuba 3's `obj` plugin (its default `flip_tex_coords`): `v` is
//! stored as `1 - v`, since most OBJ files put `v = 0` at the bottom of the image and Mitsuba's
//! textures put it at the top. The mesh has texture coordinates if any corner names one; a
//! corner without one gets `(0, 0)`, as in Mitsuba.

use super::bounded_read::{MESH_FILE_LIMIT, read_text};
use common::geometry::TriangleMesh;
use glam::{Vec2, Vec3};
use std::collections::HashMap;
use std::path::Path;

/// Reads the OBJ file at `path`. Errors name the file and, for bad content, the line.
pub fn load_obj(path: &Path) -> Result<TriangleMesh, String> {
    let text = read_text(path, "mesh", MESH_FILE_LIMIT)?;
    parse_obj(&text).map_err(|e| format!("{}:{e}", path.display()))
}

/// The position, texture coordinate and normal a face corner names, 0-based.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Corner {
    position: usize,
    uv: Option<usize>,
    normal: Option<usize>,
}

/// Parses OBJ text. An error starts with its line number.
pub fn parse_obj(text: &str) -> Result<TriangleMesh, String> {
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut uvs = Vec::new();
    // Corners that name the same position, texture coordinate and normal share a vertex.
    let mut vertex_of: HashMap<Corner, u32> = HashMap::new();
    let mut mesh_positions = Vec::new();
    let mut mesh_normals = Vec::new();
    let mut mesh_uvs = Vec::new();
    let mut indices = Vec::new();
    let mut every_corner_has_a_normal = true;
    let mut some_corner_has_a_uv = false;
    for (number, line) in text.lines().enumerate() {
        let line_number = number + 1;
        let error = |message: String| format!("{line_number}: {message}");
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => positions.push(vector(words, "a vertex `v x y z`").map_err(error)?),
            Some("vn") => normals.push(vector(words, "a normal `vn x y z`").map_err(error)?),
            Some("vt") => {
                let [u, v] = numbers(&mut words, "a texture coordinate `vt u v`").map_err(error)?;
                uvs.push(Vec2::new(u, 1.0 - v));
            }
            Some("f") => {
                let mut corners = Vec::new();
                for word in words {
                    let counts = [positions.len(), uvs.len(), normals.len()];
                    let corner = corner(word, counts).map_err(error)?;
                    every_corner_has_a_normal &= corner.normal.is_some();
                    some_corner_has_a_uv |= corner.uv.is_some();
                    let next = mesh_positions.len() as u32;
                    let vertex = *vertex_of.entry(corner).or_insert_with(|| {
                        mesh_positions.push(positions[corner.position]);
                        mesh_normals.push(corner.normal.map_or(Vec3::ZERO, |n| normals[n]));
                        mesh_uvs.push(corner.uv.map_or(Vec2::ZERO, |t| uvs[t]));
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
            _ => {} // comments, groups, materials: not needed here
        }
    }
    if indices.is_empty() {
        return Err("0: the mesh has no faces".to_string());
    }
    let normals = every_corner_has_a_normal.then_some(mesh_normals);
    let uvs = some_corner_has_a_uv.then_some(mesh_uvs);
    TriangleMesh::new(mesh_positions, normals, indices)
        .and_then(|mesh| mesh.with_uvs(uvs))
        .map_err(|e| format!("0: {e}"))
}

fn vector<'a>(mut words: impl Iterator<Item = &'a str>, expected: &str) -> Result<Vec3, String> {
    numbers(&mut words, expected).map(Vec3::from_array)
}

/// The next `N` words as finite numbers; any further words are left.
fn numbers<'a, const N: usize>(
    words: &mut impl Iterator<Item = &'a str>,
    expected: &str,
) -> Result<[f32; N], String> {
    let mut values = [0.0f32; N];
    for value in &mut values {
        let word = words.next().ok_or_else(|| format!("expected {expected}"))?;
        *value = word
            .parse()
            .map_err(|_| format!("`{word}` is not a number in {expected}"))?;
        if !value.is_finite() {
            return Err(format!("`{word}` is not finite in {expected}"));
        }
    }
    Ok(values)
}

/// A face corner `v`, `v/vt`, `v//vn` or `v/vt/vn`, given how many positions, texture
/// coordinates and normals were read so far.
fn corner(word: &str, [positions, uvs, normals]: [usize; 3]) -> Result<Corner, String> {
    let mut parts = word.split('/');
    let position = index(parts.next().unwrap_or(""), positions, "vertex", word)?;
    let mut optional = |count: usize, what: &str| match parts.next() {
        Some(text) if !text.is_empty() => index(text, count, what, word).map(Some),
        _ => Ok(None),
    };
    let uv = optional(uvs, "texture coordinate")?;
    let normal = optional(normals, "normal")?;
    Ok(Corner {
        position,
        uv,
        normal,
    })
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
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf -3/-3 -2/-2 -1/-1\n";
        let mesh = parse_obj(text).unwrap();
        assert_eq!(mesh.indices, vec![[0, 1, 2]]);
        assert!(mesh.normals.is_none());
    }

    #[test]
    fn texture_coordinates_are_read_with_v_flipped_as_mitsuba_does() {
        // A corner without `vt` gets (0, 0) once any corner has one.
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0.25 0.125\nvt 1 1 0\n\
                    f 1/1 2/2 3/1\nf 2 4 3\n";
        let mesh = parse_obj(text).unwrap();
        let uvs = mesh.uvs.as_ref().expect("texture coordinates");
        let uv_of = |position: Vec3| {
            let vertex = mesh.positions.iter().position(|&p| p == position).unwrap();
            uvs[vertex]
        };
        assert_eq!(uv_of(Vec3::ZERO), Vec2::new(0.25, 0.875));
        assert_eq!(uv_of(Vec3::X), Vec2::new(1.0, 0.0));
        assert_eq!(uv_of(Vec3::new(1.0, 1.0, 0.0)), Vec2::ZERO);
        // Positions 2 and 3 appear with and without `vt`: two vertices each.
        assert_eq!(mesh.positions.len(), 6);
        assert!(parse_obj("v 0 0 0\nf 1 1 1\n").unwrap().uvs.is_none());
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
            ("vt 0\n", "1: expected a texture coordinate"),
            (
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n",
                "5: face corner `2/2` refers to texture coordinate 2",
            ),
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
