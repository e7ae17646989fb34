//! PLY meshes (the Stanford polygon format), as Mitsuba 3's `ply` shape reads them.
//!
//! The file's header and records are read by the `ply-rs-bw` crate: it reads ASCII and both
//! binary byte orders, is fuzzed and checked with Miri by its maintainers, forbids `unsafe`, and
//! caps what it reserves ahead of a declared count (so a header that promises a billion
//! vertices costs no memory until they arrive). This module picks the mesh out of what it reads:
//!
//! - the `vertex` element's `x`, `y`, `z`; `nx`, `ny`, `nz` if all three are there; texture
//!   coordinates from `texture_u`/`texture_v`, else `s`/`t`, else `u`/`v` (Mitsuba's order),
//!   kept as they are (Mitsuba's `flip_tex_coords` is `false` for PLY);
//! - the `face` element's `vertex_indices` (or `vertex_index`) list, of any integer type; a
//!   polygon with more than three corners becomes a fan of triangles;
//! - every other element and property is skipped.
//!
//! Before any record is read, the sizes the header declares are checked against the bytes that
//! follow it, so a short file or a made-up count is an error that says so, and reading never
//! loops over records that cannot be there.

use super::bounded_read::{MESH_FILE_LIMIT, read_bytes};
use std::io::Cursor;
use std::path::Path;

use glam::{Vec2, Vec3};
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{
    ElementDef, Encoding, Header, Property, PropertyAccess, PropertyAccessResult, PropertyType,
    ScalarType,
};

use common::geometry::TriangleMesh;

/// Reads the PLY file at `path`. Errors name the file.
pub fn load_ply(path: &Path) -> Result<TriangleMesh, String> {
    let bytes = read_bytes(path, "mesh", MESH_FILE_LIMIT)?;
    parse_ply(&bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// Parses the bytes of a PLY file.
pub fn parse_ply(bytes: &[u8]) -> Result<TriangleMesh, String> {
    let mut reader = Reader::new(Cursor::new(bytes));
    let header = Parser::<Skipped>::new()
        .read_header(&mut reader)
        .map_err(|e| format!("not a PLY header: {e}"))?;
    let data_start = reader.get_ref().position();
    check_declared_sizes(&header, bytes.len() as u64 - data_start)?;

    let mut vertices: Option<Vec<PlyVertex>> = None;
    let mut faces: Option<Vec<PlyFace>> = None;
    for element in header.elements.values() {
        let at = reader.get_ref().position();
        let context = |e: ply_rs_bw::parser::ParseError| {
            let place = match header.encoding {
                Encoding::Ascii => String::new(),
                _ => format!(" (its data start at byte {at})"),
            };
            format!("in the `{}` element{place}: {e}", element.name)
        };
        match element.name.as_str() {
            "vertex" => {
                vertices = Some(
                    Parser::<PlyVertex>::new()
                        .read_payload_for_element(&mut reader, element, &header)
                        .map_err(context)?,
                );
            }
            "face" => {
                faces = Some(
                    Parser::<PlyFace>::new()
                        .read_payload_for_element(&mut reader, element, &header)
                        .map_err(context)?,
                );
            }
            // A binary element without properties has no bytes to read, however many
            // records it claims.
            _ if element.properties.is_empty() && header.encoding != Encoding::Ascii => {}
            _ => {
                Parser::<Skipped>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(context)?;
            }
        }
    }
    let vertex_element = header.elements.get("vertex");
    let vertices = vertices.ok_or("the file has no `vertex` element")?;
    let faces = faces.ok_or("the file has no `face` element")?;
    mesh_of(vertex_element, &vertices, &faces)
}

/// Refuses a header whose records cannot fit in the `available` bytes after it, and a vertex
/// or face element without the properties a mesh needs.
fn check_declared_sizes(header: &Header, available: u64) -> Result<(), String> {
    let mut needed: u64 = 0;
    for element in header.elements.values() {
        let smallest_record = match header.encoding {
            // A line per record, with at least its newline.
            Encoding::Ascii => 1,
            _ => element
                .properties
                .values()
                .map(|p| smallest_binary_size(&p.data_type))
                .sum(),
        };
        needed = needed.saturating_add((element.count as u64).saturating_mul(smallest_record));
        if needed > available {
            return Err(format!(
                "the header declares {} `{}` records, more than the {available} bytes after it \
                 can hold",
                element.count, element.name
            ));
        }
    }
    if let Some(vertex) = header.elements.get("vertex") {
        for name in ["x", "y", "z"] {
            if !vertex.properties.contains_key(name) {
                return Err(format!("the `vertex` element has no `{name}` property"));
            }
        }
        if vertex.count > u32::MAX as usize {
            return Err(format!(
                "the mesh has {} vertices; at most {} can be indexed",
                vertex.count,
                u32::MAX
            ));
        }
    }
    if let Some(face) = header.elements.get("face")
        && face_indices_name(face).is_none()
    {
        return Err("the `face` element has no `vertex_indices` or `vertex_index` list".into());
    }
    Ok(())
}

/// The fewest bytes a binary record of this property takes: a scalar's size, or a list's count
/// alone (an empty list).
fn smallest_binary_size(data_type: &PropertyType) -> u64 {
    let size = |scalar: &ScalarType| match scalar {
        ScalarType::Char | ScalarType::UChar => 1,
        ScalarType::Short | ScalarType::UShort => 2,
        ScalarType::Int | ScalarType::UInt | ScalarType::Float => 4,
        ScalarType::Double => 8,
    };
    match data_type {
        PropertyType::Scalar(scalar) => size(scalar),
        PropertyType::List(count, _) => size(count),
    }
}

fn face_indices_name(face: &ElementDef) -> Option<&'static str> {
    ["vertex_indices", "vertex_index"]
        .into_iter()
        .find(|name| face.properties.contains_key(*name))
}

/// Where each vertex property a mesh uses is kept in [`PlyVertex::values`].
const VERTEX_PROPERTIES: [&str; 12] = [
    "x",
    "y",
    "z",
    "nx",
    "ny",
    "nz",
    "texture_u",
    "texture_v",
    "s",
    "t",
    "u",
    "v",
];

/// One vertex record: the value of each of [`VERTEX_PROPERTIES`] (0 when absent).
struct PlyVertex {
    values: [f32; 12],
}

impl PropertyAccess for PlyVertex {
    fn new() -> Self {
        Self { values: [0.0; 12] }
    }

    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        let Some(slot) = VERTEX_PROPERTIES.iter().position(|&p| p == name) else {
            return PropertyAccessResult::Ignored;
        };
        match property.to_f32_lossy() {
            Some(value) => {
                self.values[slot] = value;
                PropertyAccessResult::Set
            }
            None => PropertyAccessResult::UnsupportedType, // a list where a number belongs
        }
    }
}

/// One face record: its corners' vertex indices, as written (they may be negative).
struct PlyFace {
    corners: Vec<i64>,
}

impl PropertyAccess for PlyFace {
    fn new() -> Self {
        Self {
            corners: Vec::new(),
        }
    }

    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        if name != "vertex_indices" && name != "vertex_index" {
            return PropertyAccessResult::Ignored;
        }
        fn widen<T: Copy + Into<i64>>(values: Vec<T>) -> Vec<i64> {
            values.into_iter().map(Into::into).collect()
        }
        self.corners = match property {
            Property::ListChar(v) => widen(v),
            Property::ListUChar(v) => widen(v),
            Property::ListShort(v) => widen(v),
            Property::ListUShort(v) => widen(v),
            Property::ListInt(v) => widen(v),
            Property::ListUInt(v) => widen(v),
            _ => return PropertyAccessResult::UnsupportedType,
        };
        PropertyAccessResult::Set
    }
}

/// A record of an element the mesh does not use: nothing is kept.
struct Skipped;

impl PropertyAccess for Skipped {
    fn new() -> Self {
        Skipped
    }
}

/// The mesh of the records read, checked: finite numbers, indices in range, faces of at least
/// three corners.
fn mesh_of(
    vertex_element: Option<&ElementDef>,
    vertices: &[PlyVertex],
    faces: &[PlyFace],
) -> Result<TriangleMesh, String> {
    let has = |name: &str| vertex_element.is_some_and(|e| e.properties.contains_key(name));
    let slot = |name: &str| VERTEX_PROPERTIES.iter().position(|&p| p == name);
    let normal_slots = ["nx", "ny", "nz"]
        .iter()
        .all(|n| has(n))
        .then(|| [slot("nx"), slot("ny"), slot("nz")].map(Option::unwrap));
    let uv_slots = [("texture_u", "texture_v"), ("s", "t"), ("u", "v")]
        .into_iter()
        .find(|(u, v)| has(u) && has(v))
        .and_then(|(u, v)| Some([slot(u)?, slot(v)?]));

    let mut positions = Vec::with_capacity(vertices.len());
    let mut normals = normal_slots.map(|_| Vec::with_capacity(vertices.len()));
    let mut uvs = uv_slots.map(|_| Vec::with_capacity(vertices.len()));
    for (index, vertex) in vertices.iter().enumerate() {
        let v = &vertex.values;
        let finite = |values: &[f32], what: &str| {
            if values.iter().all(|x| x.is_finite()) {
                Ok(())
            } else {
                Err(format!("vertex {index} has a non-finite {what} {values:?}"))
            }
        };
        finite(&v[0..3], "position")?;
        positions.push(Vec3::new(v[0], v[1], v[2]));
        if let (Some(normals), Some(s)) = (normals.as_mut(), normal_slots) {
            let n = s.map(|s| v[s]);
            finite(&n, "normal")?;
            normals.push(Vec3::from_array(n));
        }
        if let (Some(uvs), Some([u, w])) = (uvs.as_mut(), uv_slots) {
            finite(&[v[u], v[w]], "texture coordinate")?;
            uvs.push(Vec2::new(v[u], v[w]));
        }
    }

    let vertex_count = positions.len();
    let mut indices = Vec::with_capacity(faces.len());
    for (number, face) in faces.iter().enumerate() {
        if face.corners.len() < 3 {
            return Err(format!(
                "face {number} has {} corners; a face needs at least 3",
                face.corners.len()
            ));
        }
        let mut corners = Vec::with_capacity(face.corners.len());
        for &corner in &face.corners {
            match u32::try_from(corner) {
                Ok(index) if (index as usize) < vertex_count => corners.push(index),
                _ => {
                    return Err(format!(
                        "face {number} refers to vertex {corner}, but the mesh has \
                         {vertex_count} vertices"
                    ));
                }
            }
        }
        for i in 1..corners.len() - 1 {
            indices.push([corners[0], corners[i], corners[i + 1]]);
        }
    }
    if indices.is_empty() {
        return Err("the mesh has no faces".to_string());
    }
    TriangleMesh::new(positions, normals, indices)
        .and_then(|mesh| mesh.with_uvs(uvs))
        .map_err(|e| e.to_string())
}
