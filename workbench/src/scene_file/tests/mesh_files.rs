//! The PLY and `.serialized` readers: exact round trips of meshes written in every encoding,
//! clear errors for broken and hostile files, and no panic on mutated ones.

use glam::{Vec2, Vec3};
use proptest::collection::vec;
use proptest::prelude::*;

use crate::scene_file::{parse_ply, parse_serialized};
use crate::test_support::mesh_files::{
    PlyEncoding, PlyStyle, SerializedStyle, serialized_file, serialized_payload, write_ply,
    write_serialized,
};
use common::geometry::TriangleMesh;

const ENCODINGS: [PlyEncoding; 3] = [
    PlyEncoding::Ascii,
    PlyEncoding::LittleEndian,
    PlyEncoding::BigEndian,
];

/// A unit square in z = 0 with normals +z and texture coordinates equal to x and y.
fn square() -> TriangleMesh {
    let positions = vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
    let uvs = positions.iter().map(|p| p.truncate()).collect();
    TriangleMesh::new(
        positions,
        Some(vec![Vec3::Z; 4]),
        vec![[0, 1, 2], [0, 2, 3]],
    )
    .and_then(|mesh| mesh.with_uvs(Some(uvs)))
    .unwrap()
}

fn without_extras(mut mesh: TriangleMesh, normals: bool, uvs: bool) -> TriangleMesh {
    if !normals {
        mesh.normals = None;
    }
    if !uvs {
        mesh.uvs = None;
    }
    mesh
}

#[test]
fn ply_meshes_read_back_in_every_encoding_and_naming() {
    let uv_names = [("u", "v"), ("s", "t"), ("texture_u", "texture_v")];
    let list_types = [("uchar", "int"), ("uchar", "uint"), ("int", "ushort")];
    for encoding in ENCODINGS {
        for (k, (normals, uvs)) in [(false, false), (true, false), (false, true), (true, true)]
            .into_iter()
            .enumerate()
        {
            let mesh = without_extras(square(), normals, uvs);
            let style = PlyStyle {
                uv_names: uv_names[k % 3],
                list_types: list_types[k % 3],
                indices_name: ["vertex_indices", "vertex_index"][k % 2],
                double_positions: k % 2 == 1,
                extras: k >= 2,
                ..PlyStyle::plain(encoding)
            };
            let bytes = write_ply(&mesh, None, &style);
            assert_eq!(parse_ply(&bytes).unwrap(), mesh, "{style:?}");
        }
    }
}

#[test]
fn ply_polygons_become_fans() {
    let positions = (0..5)
        .map(|k| {
            let angle = k as f32 * std::f32::consts::TAU / 5.0;
            Vec3::new(angle.cos(), angle.sin(), 0.0)
        })
        .collect();
    let mesh = TriangleMesh::new(positions, None, vec![]).unwrap();
    let faces = [vec![0, 1, 2, 3, 4], vec![4, 3, 2]];
    for encoding in ENCODINGS {
        let read = parse_ply(&write_ply(&mesh, Some(&faces), &PlyStyle::plain(encoding))).unwrap();
        assert_eq!(
            read.indices,
            vec![[0, 1, 2], [0, 2, 3], [0, 3, 4], [4, 3, 2]]
        );
    }
}

/// A PLY header for `vertices` float `x y z` vertices and `faces` faces, then `body`.
fn ply(format: &str, vertices: &str, faces: &str, body: &[u8]) -> Vec<u8> {
    let mut bytes = format!(
        "ply\nformat {format} 1.0\nelement vertex {vertices}\nproperty float x\n\
         property float y\nproperty float z\nelement face {faces}\n\
         property list uchar int vertex_indices\nend_header\n"
    )
    .into_bytes();
    bytes.extend(body);
    bytes
}

#[test]
fn broken_and_hostile_ply_files_are_refused_with_the_reason() {
    let triangle = b"0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    assert!(parse_ply(&ply("ascii", "3", "1", triangle)).is_ok());
    let mut binary_triangle = Vec::new();
    for x in [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
        binary_triangle.extend(x.to_le_bytes());
    }
    binary_triangle.push(3);
    for i in [0i32, 1, 2] {
        binary_triangle.extend(i.to_le_bytes());
    }
    let little = |vertices: &str, faces: &str, body: &[u8]| {
        ply("binary_little_endian", vertices, faces, body)
    };
    assert!(parse_ply(&little("3", "1", &binary_triangle)).is_ok());
    let cases: Vec<(Vec<u8>, &str)> = vec![
        (b"not a mesh".to_vec(), "not a PLY header"),
        (
            little("4000000000000", "1", &binary_triangle),
            "declares 4000000000000 `vertex` records",
        ),
        (
            little("3", "1", &binary_triangle[..30]),
            "more than the 30 bytes after it",
        ),
        (
            little("3", "1", &binary_triangle[..38]),
            "in the `face` element (its data start at byte",
        ),
        (
            ply("ascii", "3", "1", b"0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
            "face 0 refers to vertex 3, but the mesh has 3 vertices",
        ),
        (
            ply("ascii", "3", "1", b"0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n"),
            "face 0 refers to vertex -1",
        ),
        (
            little("3", "1", &{
                let mut nan = binary_triangle.clone();
                nan[16..20].copy_from_slice(&f32::NAN.to_le_bytes());
                nan
            }),
            "vertex 1 has a non-finite position",
        ),
        (
            ply("ascii", "3", "1", b"0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
            "in the `vertex` element",
        ),
        (
            ply("ascii", "3", "1", b"0 0 0\n1 0 0\n0 1 0\n2 0 1\n"),
            "face 0 has 2 corners",
        ),
        (ply("ascii", "3", "0", b"0 0 0\n1 0 0\n0 1 0\n"), "no faces"),
        (
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
              end_header\n0 0\n"
                .to_vec(),
            "no `z` property",
        ),
        (
            b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
              property float z\nend_header\n0 0 0\n"
                .to_vec(),
            "no `face` element",
        ),
        (
            b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
              property float z\nelement face 1\nproperty list uchar float vertex_indices\n\
              end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"
                .to_vec(),
            "in the `face` element",
        ),
    ];
    for (bytes, expected) in cases {
        let error = parse_ply(&bytes).unwrap_err();
        assert!(
            error.contains(expected),
            "{:?}: expected `{expected}` in `{error}`",
            String::from_utf8_lossy(&bytes)
        );
    }
}

#[test]
fn ascii_ply_files_from_other_tools_are_read() {
    // Windows line ends, `obj_info`, comments, runs of spaces and trailing blanks.
    let text = "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info tool 1\r\n\
                element vertex 3\r\nproperty float x\r\nproperty float y\r\n\
                property float z\r\nelement face 1\r\nproperty list uchar int vertex_index\r\n\
                end_header\r\n0  0 0 \r\n1 0   0\r\n0 1 0\r\n3 0 1 2 \r\n";
    let mesh = parse_ply(text.as_bytes()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(mesh.positions, vec![Vec3::ZERO, Vec3::X, Vec3::Y]);
    assert_eq!(mesh.indices, vec![[0, 1, 2]]);
}

#[test]
fn a_binary_element_without_properties_costs_nothing_however_many_it_claims() {
    let mut bytes = b"ply\nformat binary_little_endian 1.0\nelement nothing 18446744073709551615\n\
                      element vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
                      element face 1\nproperty list uchar uint vertex_indices\nend_header\n"
        .to_vec();
    for x in [0.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
        bytes.extend(x.to_le_bytes());
    }
    bytes.push(3);
    for i in [0u32, 1, 2] {
        bytes.extend(i.to_le_bytes());
    }
    assert_eq!(parse_ply(&bytes).unwrap().indices, vec![[0, 1, 2]]);
}

const SERIALIZED_STYLES: [SerializedStyle; 4] = [
    SerializedStyle {
        version: 3,
        double_precision: false,
        colours: false,
    },
    SerializedStyle {
        version: 4,
        double_precision: false,
        colours: true,
    },
    SerializedStyle {
        version: 3,
        double_precision: true,
        colours: true,
    },
    SerializedStyle {
        version: 4,
        double_precision: true,
        colours: false,
    },
];

#[test]
fn serialized_meshes_read_back_by_shape_index() {
    for style in SERIALIZED_STYLES {
        let meshes = [
            square(),
            without_extras(square(), false, true),
            without_extras(square(), true, false),
            without_extras(square(), false, false),
        ];
        let bytes = write_serialized(&meshes, style);
        for (index, mesh) in meshes.iter().enumerate() {
            assert_eq!(
                &parse_serialized(&bytes, index as u32).unwrap(),
                mesh,
                "{style:?}, mesh {index}"
            );
        }
    }
}

#[test]
fn broken_and_hostile_serialized_files_are_refused_with_the_reason() {
    let style = SERIALIZED_STYLES[1];
    let good = write_serialized(&[square(), square()], style);
    let payload = serialized_payload(&square(), 0, style);
    // Version 4: flags (4), name "mesh 0\0" (7), then the counts.
    let counts_at = 4 + 7;
    let with_counts = |vertices: u64, faces: u64| {
        let mut payload = payload.clone();
        payload[counts_at..counts_at + 8].copy_from_slice(&vertices.to_le_bytes());
        payload[counts_at + 8..counts_at + 16].copy_from_slice(&faces.to_le_bytes());
        serialized_file(&[payload], 4)
    };
    let mut index_out_of_range = payload.clone();
    let last = index_out_of_range.len() - 4;
    index_out_of_range[last..].copy_from_slice(&4u32.to_le_bytes());
    let mut nan_position = payload.clone();
    nan_position[counts_at + 16..counts_at + 20].copy_from_slice(&f32::NAN.to_le_bytes());
    let mut version_5 = good.clone();
    version_5[2] = 5;
    let mut far_offset = good.clone();
    let dictionary = far_offset.len() - 4 - 8;
    far_offset[dictionary..dictionary + 8].copy_from_slice(&u64::MAX.to_le_bytes());
    let cases: Vec<(Vec<u8>, u32, &str)> = vec![
        (
            b"PK\x03\x04 not a mesh".to_vec(),
            0,
            "not a serialized mesh",
        ),
        (vec![0x1C], 0, "does not fit"),
        (version_5, 0, "version 5 are not read"),
        (
            good.clone(),
            2,
            "shape_index 2 is out of range: the file holds 2 meshes",
        ),
        (far_offset, 1, "beyond the file"),
        (good[..good.len() / 3].to_vec(), 0, "the compressed data"),
        (
            with_counts(1 << 40, 2),
            0,
            "at most 4294967295 can be indexed",
        ),
        (
            with_counts(4, u64::MAX),
            0,
            "before the triangles (read 0 of 18446744073709551615)",
        ),
        (
            with_counts(4_000_000_000, 2),
            0,
            "before the positions (read 0 of 4000000000)",
        ),
        (
            serialized_file(&[index_out_of_range], 4),
            0,
            "triangle 1 refers to vertex 4",
        ),
        (
            serialized_file(&[nan_position], 4),
            0,
            "vertex 0 has a non-finite position",
        ),
        (
            {
                // The zlib header names no known compression method.
                let mut broken = good.clone();
                broken[4] ^= 0xFF;
                broken
            },
            0,
            "the compressed data",
        ),
    ];
    for (bytes, index, expected) in cases {
        let error = parse_serialized(&bytes, index).unwrap_err();
        assert!(
            error.contains(expected),
            "shape {index}: expected `{expected}` in `{error}`"
        );
    }
}

/// Meshes found locally in a copy of Mitsuba's data repository, when `MITSUBA_MESHES` names
/// a directory of its `.ply` and `.serialized` files; nothing otherwise (the files are not the
/// workbook's to ship).
#[test]
fn mitsubas_own_meshes_load_when_present() {
    let Some(directory) = std::env::var_os("MITSUBA_MESHES") else {
        return;
    };
    let mut loaded = 0;
    for entry in std::fs::read_dir(directory).unwrap() {
        let path = entry.unwrap().path();
        let mesh = match path.extension().and_then(|e| e.to_str()) {
            Some("ply") => crate::scene_file::load_ply(&path),
            Some("serialized") => {
                // Every mesh of the file, up to the first index out of range.
                let mut index = 1;
                while let Ok(mesh) = crate::scene_file::load_serialized(&path, index) {
                    mesh.validate().unwrap();
                    index += 1;
                }
                eprintln!("{}: {index} meshes", path.display());
                crate::scene_file::load_serialized(&path, 0)
            }
            _ => continue,
        };
        let mesh = mesh.unwrap_or_else(|e| panic!("{e}"));
        eprintln!(
            "{}: {} vertices, {} triangles, normals {}, uvs {}",
            path.display(),
            mesh.positions.len(),
            mesh.indices.len(),
            mesh.normals.is_some(),
            mesh.uvs.is_some()
        );
        loaded += 1;
    }
    assert!(loaded > 0);
}

/// Our readers against Mitsuba 3's own, when `MITSUBA_MESH_DUMPS` names a directory of JSON
/// files, each what Mitsuba loaded from one mesh file (`file`, `kind`, `shape_index`, and its
/// `positions`, `faces`, `normals` and `uvs` as flat arrays, as `mi.traverse` gives them); nothing
/// otherwise. The positions, triangles and texture coordinates must be the same `f32`s, and
/// normals the same directions where the file has them (Mitsuba computes them where it has
/// none). `mitsuba_mesh_dump.py` beside this file writes the dumps.
#[test]
fn mitsuba_reads_the_same_meshes_when_its_dumps_are_present() {
    let Some(directory) = std::env::var_os("MITSUBA_MESH_DUMPS") else {
        return;
    };
    let mut compared = 0;
    for entry in std::fs::read_dir(directory).unwrap() {
        let text = std::fs::read_to_string(entry.unwrap().path()).unwrap();
        let dump: serde_json::Value = serde_json::from_str(&text).unwrap();
        let numbers = |key: &str| -> Vec<f64> {
            dump[key]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        };
        let path = std::path::Path::new(dump["file"].as_str().unwrap());
        let mesh = match dump["kind"].as_str().unwrap() {
            "ply" => crate::scene_file::load_ply(path),
            _ => crate::scene_file::load_serialized(
                path,
                dump["shape_index"].as_u64().unwrap() as u32,
            ),
        }
        .unwrap();
        let label = format!("{} {}", path.display(), dump["shape_index"]);
        let same = |ours: &[f64], theirs: &[f64], what: &str| {
            assert_eq!(ours.len(), theirs.len(), "{label}: how many {what}");
            // As `f32`s: Mitsuba's Python binding hands out some values as doubles a
            // fraction of an `f32` step away from the `f32` it holds.
            if let Some(i) = (0..ours.len()).find(|&i| ours[i] as f32 != theirs[i] as f32) {
                panic!(
                    "{label}: {what}[{i}] is {} here and {} in Mitsuba",
                    ours[i], theirs[i]
                );
            }
        };
        let flat3 = |v: &[Vec3]| -> Vec<f64> {
            v.iter().flat_map(|p| p.to_array().map(f64::from)).collect()
        };
        same(&flat3(&mesh.positions), &numbers("positions"), "positions");
        let faces: Vec<f64> = mesh.indices.iter().flat_map(|t| t.map(f64::from)).collect();
        same(&faces, &numbers("faces"), "faces");
        let uvs: Vec<f64> = mesh
            .uvs
            .iter()
            .flatten()
            .flat_map(|t| t.to_array().map(f64::from))
            .collect();
        same(&uvs, &numbers("uvs"), "uvs");
        if let Some(normals) = &mesh.normals {
            let theirs = numbers("normals");
            // Mitsuba keeps them unit length; here placing the mesh normalises them.
            let unit: Vec<Vec3> = normals.iter().map(|n| n.normalize_or_zero()).collect();
            let ours = flat3(&unit);
            assert_eq!(ours.len(), theirs.len(), "{label}");
            let worst = ours
                .iter()
                .zip(&theirs)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            assert!(worst < 1e-6, "{label}: normals differ by {worst}");
        }
        eprintln!("{label}: the same as Mitsuba's");
        compared += 1;
    }
    assert!(compared > 0);
}

fn finite() -> impl Strategy<Value = f32> {
    any::<f32>().prop_filter("finite", |x| x.is_finite())
}

fn vec3() -> impl Strategy<Value = Vec3> {
    [finite(), finite(), finite()].prop_map(Vec3::from_array)
}

/// A mesh of up to 12 vertices and 16 triangles, with or without normals and texture
/// coordinates, of any finite numbers.
fn any_mesh() -> impl Strategy<Value = TriangleMesh> {
    (1..12usize, any::<bool>(), any::<bool>())
        .prop_flat_map(|(n, normals, uvs)| {
            let uv = [finite(), finite()].prop_map(Vec2::from_array);
            (
                vec(vec3(), n),
                vec(vec3(), n).prop_map(move |v| normals.then_some(v)),
                vec(uv, n).prop_map(move |v| uvs.then_some(v)),
                vec([0..n as u32, 0..n as u32, 0..n as u32], 1..16),
            )
        })
        .prop_map(|(positions, normals, uvs, indices)| {
            TriangleMesh::new(positions, normals, indices)
                .and_then(|mesh| mesh.with_uvs(uvs))
                .unwrap()
        })
}

fn ply_style() -> impl Strategy<Value = PlyStyle> {
    (
        prop::sample::select(ENCODINGS.to_vec()),
        prop::sample::select(vec![("u", "v"), ("s", "t"), ("texture_u", "texture_v")]),
        prop::sample::select(vec!["vertex_indices", "vertex_index"]),
        prop::sample::select(vec![
            ("uchar", "int"),
            ("uchar", "uint"),
            ("char", "uchar"),
            ("ushort", "short"),
            ("uint", "uint"),
        ]),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(
            |(encoding, uv_names, indices_name, list_types, double_positions, extras)| PlyStyle {
                encoding,
                uv_names,
                indices_name,
                list_types,
                double_positions,
                extras,
            },
        )
}

fn serialized_style() -> impl Strategy<Value = SerializedStyle> {
    (3..=4u16, any::<bool>(), any::<bool>()).prop_map(|(version, double_precision, colours)| {
        SerializedStyle {
            version,
            double_precision,
            colours,
        }
    })
}

/// A triangle's corners: positions, normals and texture coordinates.
type Corners = ([Vec3; 3], Option<[Vec3; 3]>, Option<[Vec2; 3]>);

fn corners(mesh: &TriangleMesh) -> Vec<Corners> {
    mesh.triangles().map(|t| (t.p, t.normals, t.uvs)).collect()
}

/// The same corners, texture coordinates equal up to a rounding (`1 - (1 - v)` need not be
/// `v` exactly).
fn same_corners(a: &[Corners], b: &[Corners]) -> bool {
    let close =
        |u: &Vec2, w: &Vec2| (*u - *w).abs().max_element() <= 1e-7 * (1.0 + w.abs().max_element());
    a.len() == b.len()
        && a.iter().zip(b).all(|(x, y)| {
            x.0 == y.0
                && x.1 == y.1
                && match (x.2, y.2) {
                    (Some(u), Some(w)) => u.iter().zip(&w).all(|(u, w)| close(u, w)),
                    (u, w) => u == w,
                }
        })
}

/// One change to a file's bytes.
#[derive(Clone, Debug)]
enum Mutation {
    Replace(usize, u8),
    Delete(usize),
    Insert(usize, u8),
    Truncate(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::Replace(i, b)),
        2 => any::<usize>().prop_map(Mutation::Delete),
        2 => (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::Insert(i, b)),
        1 => any::<usize>().prop_map(Mutation::Truncate),
    ]
}

fn mutate(mut bytes: Vec<u8>, mutations: &[Mutation]) -> Vec<u8> {
    for mutation in mutations {
        let at = |i: usize| i % (bytes.len() + 1);
        match *mutation {
            Mutation::Replace(i, b) if !bytes.is_empty() => {
                let i = i % bytes.len();
                bytes[i] = b;
            }
            Mutation::Delete(i) if !bytes.is_empty() => {
                let i = i % bytes.len();
                bytes.remove(i);
            }
            Mutation::Insert(i, b) => bytes.insert(at(i), b),
            Mutation::Truncate(i) => bytes.truncate(at(i)),
            _ => {}
        }
    }
    bytes
}

/// A mesh a reader returns must be usable: valid indices and counts, finite positions.
fn assert_usable(result: Result<TriangleMesh, String>) -> Result<(), TestCaseError> {
    if let Ok(mesh) = result {
        prop_assert_eq!(mesh.validate(), Ok(()));
        prop_assert!(mesh.positions.iter().all(|p| p.is_finite()));
        prop_assert!(!mesh.indices.is_empty());
    }
    Ok(())
}

proptest! {
    #![proptest_config(super::property_config())]

    #[test]
    fn any_mesh_survives_a_ply_round_trip(mesh in any_mesh(), style in ply_style()) {
        let bytes = write_ply(&mesh, None, &style);
        prop_assert_eq!(parse_ply(&bytes), Ok(mesh));
    }

    #[test]
    fn any_meshes_survive_a_serialized_round_trip(
        meshes in vec(any_mesh(), 1..4),
        style in serialized_style(),
        pick in any::<prop::sample::Index>(),
    ) {
        let bytes = write_serialized(&meshes, style);
        let index = pick.index(meshes.len());
        prop_assert_eq!(parse_serialized(&bytes, index as u32), Ok(meshes[index].clone()));
    }

    #[test]
    fn any_mesh_survives_an_obj_round_trip(mesh in any_mesh()) {
        // Written with one index for position, texture coordinate and normal, v flipped as
        // Mitsuba reads it back; the reader numbers vertices in the order faces use them, so
        // the triangles' corners are compared, not the vertex arrays.
        let mut text = String::new();
        for p in &mesh.positions {
            text += &format!("v {} {} {}\n", p.x, p.y, p.z);
        }
        for t in mesh.uvs.iter().flatten() {
            text += &format!("vt {} {}\n", t.x, 1.0 - t.y);
        }
        for n in mesh.normals.iter().flatten() {
            text += &format!("vn {} {} {}\n", n.x, n.y, n.z);
        }
        for triangle in &mesh.indices {
            text += "f";
            for i in triangle.map(|i| i + 1) {
                text += &match (mesh.uvs.is_some(), mesh.normals.is_some()) {
                    (false, false) => format!(" {i}"),
                    (true, false) => format!(" {i}/{i}"),
                    (false, true) => format!(" {i}//{i}"),
                    (true, true) => format!(" {i}/{i}/{i}"),
                };
            }
            text += "\n";
        }
        let read = crate::scene_file::parse_obj(&text).map_err(TestCaseError::fail)?;
        prop_assert_eq!(read.indices.len(), mesh.indices.len());
        // `1 - (1 - v)` is `v` only where no digit is lost on the way (not for v = 18802118,
        // say, where floats are 2 apart): the flip is expected as floats compute it.
        let flipped_twice = TriangleMesh {
            uvs: mesh.uvs.clone().map(|uvs| {
                uvs.into_iter().map(|t| Vec2::new(t.x, 1.0 - (1.0 - t.y))).collect()
            }),
            ..mesh.clone()
        };
        prop_assert!(same_corners(&corners(&read), &corners(&flipped_twice)));
    }

    #[test]
    fn mutated_ply_files_load_a_usable_mesh_or_fail(
        mesh in any_mesh(),
        style in ply_style(),
        mutations in vec(mutation(), 1..6),
    ) {
        assert_usable(parse_ply(&mutate(write_ply(&mesh, None, &style), &mutations)))?;
    }

    #[test]
    fn mutated_serialized_files_load_a_usable_mesh_or_fail(
        mesh in any_mesh(),
        style in serialized_style(),
        mutations in vec(mutation(), 1..6),
        inside_the_stream in any::<bool>(),
    ) {
        // Bytes changed in the compressed stream mostly break it; changed before compression
        // they reach the mesh reader.
        let bytes = if inside_the_stream {
            let payload = mutate(serialized_payload(&mesh, 0, style), &mutations);
            serialized_file(&[payload, serialized_payload(&mesh, 1, style)], style.version)
        } else {
            mutate(write_serialized(&[mesh.clone(), mesh], style), &mutations)
        };
        assert_usable(parse_serialized(&bytes, 0))?;
        assert_usable(parse_serialized(&bytes, 1))?;
    }
}
