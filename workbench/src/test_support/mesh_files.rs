//! Writers of PLY and `.serialized` meshes, for tests: the readers are checked against files
//! these write from known meshes, and chapters' tests render scenes that use them.

use std::io::Write;

use flate2::Compression;
use flate2::write::ZlibEncoder;

use common::geometry::TriangleMesh;

/// How a PLY file stores its records.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlyEncoding {
    /// Numbers as text, a record per line.
    Ascii,
    /// `binary_little_endian`.
    LittleEndian,
    /// `binary_big_endian`.
    BigEndian,
}

/// The choices a PLY writer has beyond the mesh itself.
#[derive(Clone, Debug)]
pub struct PlyStyle {
    /// How records are stored.
    pub encoding: PlyEncoding,
    /// The names of the texture coordinates: `("u", "v")`, `("s", "t")`, ...
    pub uv_names: (&'static str, &'static str),
    /// The face list's property name: `vertex_indices` or `vertex_index`.
    pub indices_name: &'static str,
    /// The list's count and index types, e.g. `("uchar", "int")`.
    pub list_types: (&'static str, &'static str),
    /// Positions written as `double` rather than `float`.
    pub double_positions: bool,
    /// A vertex property and a whole element the reader must skip.
    pub extras: bool,
}

impl PlyStyle {
    /// `float` positions, `u`/`v`, `vertex_indices` as `uchar` and `int`, nothing extra.
    pub fn plain(encoding: PlyEncoding) -> Self {
        Self {
            encoding,
            uv_names: ("u", "v"),
            indices_name: "vertex_indices",
            list_types: ("uchar", "int"),
            double_positions: false,
            extras: false,
        }
    }
}

/// One value in a PLY record, written as its declared type.
enum Value {
    Float(f32),
    Double(f64),
    Integer(&'static str, i64),
}

/// The bytes of a PLY file holding `mesh`. `faces` overrides the mesh's triangles with
/// polygons of any size (to test fans).
pub fn write_ply(mesh: &TriangleMesh, faces: Option<&[Vec<u32>]>, style: &PlyStyle) -> Vec<u8> {
    let format = match style.encoding {
        PlyEncoding::Ascii => "ascii",
        PlyEncoding::LittleEndian => "binary_little_endian",
        PlyEncoding::BigEndian => "binary_big_endian",
    };
    let position_type = if style.double_positions {
        "double"
    } else {
        "float"
    };
    let mut header = format!(
        "ply\nformat {format} 1.0\ncomment written by the workbook's tests\n\
         element vertex {}\n",
        mesh.positions.len()
    );
    for axis in ["x", "y", "z"] {
        header += &format!("property {position_type} {axis}\n");
    }
    if style.extras {
        header += "property uchar confidence\n";
    }
    if mesh.normals.is_some() {
        header += "property float nx\nproperty float ny\nproperty float nz\n";
    }
    if mesh.uvs.is_some() {
        let (u, v) = style.uv_names;
        header += &format!("property float {u}\nproperty float {v}\n");
    }
    if style.extras {
        header += "element material 2\nproperty list uchar float weights\nproperty int id\n";
    }
    let polygons: Vec<Vec<u32>> = match faces {
        Some(faces) => faces.to_vec(),
        None => mesh.indices.iter().map(|t| t.to_vec()).collect(),
    };
    let (count_type, index_type) = style.list_types;
    header += &format!(
        "element face {}\nproperty list {count_type} {index_type} {}\n",
        polygons.len(),
        style.indices_name
    );
    if style.extras {
        header += "property uchar flags\n";
    }
    header += "end_header\n";

    let mut records: Vec<Vec<Value>> = Vec::new();
    for (i, p) in mesh.positions.iter().enumerate() {
        let mut record: Vec<Value> = p
            .to_array()
            .iter()
            .map(|&x| {
                if style.double_positions {
                    Value::Double(f64::from(x))
                } else {
                    Value::Float(x)
                }
            })
            .collect();
        if style.extras {
            record.push(Value::Integer("uchar", (i % 200) as i64));
        }
        if let Some(normals) = &mesh.normals {
            record.extend(normals[i].to_array().map(Value::Float));
        }
        if let Some(uvs) = &mesh.uvs {
            record.extend(uvs[i].to_array().map(Value::Float));
        }
        records.push(record);
    }
    if style.extras {
        for id in 0..2 {
            records.push(vec![
                Value::Integer("uchar", 2),
                Value::Float(0.5),
                Value::Float(-1.0),
                Value::Integer("int", id),
            ]);
        }
    }
    for polygon in &polygons {
        let mut record = vec![Value::Integer(count_type, polygon.len() as i64)];
        record.extend(
            polygon
                .iter()
                .map(|&i| Value::Integer(index_type, i64::from(i))),
        );
        if style.extras {
            record.push(Value::Integer("uchar", 7));
        }
        records.push(record);
    }

    let mut bytes = header.into_bytes();
    for record in records {
        match style.encoding {
            PlyEncoding::Ascii => {
                let words: Vec<String> = record
                    .iter()
                    .map(|value| match value {
                        Value::Float(x) => format!("{x}"),
                        Value::Double(x) => format!("{x}"),
                        Value::Integer(_, i) => format!("{i}"),
                    })
                    .collect();
                bytes.extend(words.join(" ").bytes());
                bytes.push(b'\n');
            }
            PlyEncoding::LittleEndian | PlyEncoding::BigEndian => {
                let big = style.encoding == PlyEncoding::BigEndian;
                for value in record {
                    bytes.extend(binary(&value, big));
                }
            }
        }
    }
    bytes
}

fn binary(value: &Value, big: bool) -> Vec<u8> {
    macro_rules! bytes {
        ($x:expr) => {
            if big {
                $x.to_be_bytes().to_vec()
            } else {
                $x.to_le_bytes().to_vec()
            }
        };
    }
    match *value {
        Value::Float(x) => bytes!(x),
        Value::Double(x) => bytes!(x),
        Value::Integer(kind, i) => match kind {
            "char" => bytes!(i as i8),
            "uchar" => bytes!(i as u8),
            "short" => bytes!(i as i16),
            "ushort" => bytes!(i as u16),
            "int" => bytes!(i as i32),
            "uint" => bytes!(i as u32),
            other => panic!("no integer type {other}"),
        },
    }
}

/// The choices a `.serialized` writer has beyond the meshes.
#[derive(Clone, Copy, Debug)]
pub struct SerializedStyle {
    /// 3 or 4.
    pub version: u16,
    /// Numbers as `f64` rather than `f32`.
    pub double_precision: bool,
    /// Vertex colours the reader must skip.
    pub colours: bool,
}

/// The bytes of a `.serialized` file holding `meshes`, with the dictionary at its end.
pub fn write_serialized(meshes: &[TriangleMesh], style: SerializedStyle) -> Vec<u8> {
    let payloads: Vec<Vec<u8>> = meshes
        .iter()
        .enumerate()
        .map(|(number, mesh)| serialized_payload(mesh, number, style))
        .collect();
    serialized_file(&payloads, style.version)
}

/// What the zlib stream of one mesh holds, uncompressed.
pub fn serialized_payload(mesh: &TriangleMesh, number: usize, style: SerializedStyle) -> Vec<u8> {
    let mut flags = if style.double_precision {
        0x2000u32
    } else {
        0x1000
    };
    flags |= if mesh.normals.is_some() { 0x1 } else { 0 };
    flags |= if mesh.uvs.is_some() { 0x2 } else { 0 };
    flags |= if style.colours { 0x8 } else { 0 };
    let mut data = flags.to_le_bytes().to_vec();
    if style.version == 4 {
        data.extend(format!("mesh {number}").bytes());
        data.push(0);
    }
    data.extend((mesh.positions.len() as u64).to_le_bytes());
    data.extend((mesh.indices.len() as u64).to_le_bytes());
    let mut floats = |values: &mut dyn Iterator<Item = f32>| {
        for x in values {
            if style.double_precision {
                data.extend(f64::from(x).to_le_bytes());
            } else {
                data.extend(x.to_le_bytes());
            }
        }
    };
    floats(&mut mesh.positions.iter().flat_map(|p| p.to_array()));
    if let Some(normals) = &mesh.normals {
        floats(&mut normals.iter().flat_map(|n| n.to_array()));
    }
    if let Some(uvs) = &mesh.uvs {
        floats(&mut uvs.iter().flat_map(|t| t.to_array()));
    }
    if style.colours {
        floats(&mut mesh.positions.iter().flat_map(|_| [0.25, 0.5, 1.0]));
    }
    for triangle in &mesh.indices {
        for &i in triangle {
            data.extend(i.to_le_bytes());
        }
    }
    data
}

/// A `.serialized` file of the given uncompressed mesh streams: each compressed behind its
/// header, then the dictionary of offsets.
pub fn serialized_file(payloads: &[Vec<u8>], version: u16) -> Vec<u8> {
    let mut bytes = Vec::new();
    let mut offsets = Vec::new();
    for payload in payloads {
        offsets.push(bytes.len() as u64);
        bytes.extend(0x041Cu16.to_le_bytes());
        bytes.extend(version.to_le_bytes());
        let mut encoder = ZlibEncoder::new(Vec::new(), Compression::default());
        encoder.write_all(payload).expect("writing to memory");
        bytes.extend(encoder.finish().expect("writing to memory"));
    }
    for offset in offsets {
        if version == 4 {
            bytes.extend(offset.to_le_bytes());
        } else {
            bytes.extend((offset as u32).to_le_bytes());
        }
    }
    bytes.extend((payloads.len() as u32).to_le_bytes());
    bytes
}
