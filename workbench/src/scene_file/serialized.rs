//! Mitsuba's `.serialized` meshes (versions 3 and 4, the ones Mitsuba 0.6 wrote and Mitsuba 3
//! reads), as Mitsuba 3's `serialized` shape reads them.
//!
//! A file holds one or more meshes. Each starts with two little-endian `u16`s, the format
//! identifier `0x041C` and the version, followed by a zlib stream that holds, little-endian:
//!
//! - a `u32` of flags: `0x0001` vertex normals, `0x0002` texture coordinates, `0x0008` vertex
//!   colours, `0x0010` face normals, `0x1000` single and `0x2000` double precision;
//! - in version 4, the mesh's name, ended by a zero byte;
//! - `u64` vertex and triangle counts `V` and `F`;
//! - `3 V` positions, then `3 V` normals, `2 V` texture coordinates and `3 V` colours where the
//!   flags say so, each a `f32` or, with `0x2000`, a `f64`;
//! - `3 F` `u32` vertex indices.
//!
//! The file ends with a dictionary: the byte offset of each mesh (`u64` in version 4, `u32` in
//! version 3), then the number of meshes as a `u32`. `shape_index` picks the mesh; the first
//! is read without the dictionary, as Mitsuba does.
//!
//! Colours are read and dropped. The face-normals flag is ignored, as Mitsuba 3 ignores it in
//! these versions: the scene's `face_normals` decides. Texture coordinates are kept as stored.
//! Nothing is reserved ahead of a count the file declares: arrays grow as their bytes are
//! inflated, so a made-up count ends in an error when the stream runs out, not in a huge
//! allocation.

use super::bounded_read::{MESH_FILE_LIMIT, read_bytes};
use std::io::Read;
use std::path::Path;

use flate2::read::ZlibDecoder;
use glam::{Vec2, Vec3};

use common::geometry::TriangleMesh;

/// The format identifier at the start of every mesh.
const MAGIC: u16 = 0x041C;
const HAS_NORMALS: u32 = 0x0001;
const HAS_TEXCOORDS: u32 = 0x0002;
const HAS_COLORS: u32 = 0x0008;
const DOUBLE_PRECISION: u32 = 0x2000;
/// The longest mesh name read before giving up on finding its end.
const MAX_NAME_BYTES: usize = 1 << 16;
/// How many values are inflated at a time.
const CHUNK: usize = 1 << 14;

/// Reads mesh number `shape_index` of the `.serialized` file at `path`. Errors name the file.
pub fn load_serialized(path: &Path, shape_index: u32) -> Result<TriangleMesh, String> {
    let bytes = read_bytes(path, "mesh", MESH_FILE_LIMIT)?;
    parse_serialized(&bytes, shape_index)
        .map_err(|e| format!("{} (shape {shape_index}): {e}", path.display()))
}

/// Parses mesh number `shape_index` of the bytes of a `.serialized` file.
pub fn parse_serialized(bytes: &[u8], shape_index: u32) -> Result<TriangleMesh, String> {
    let (magic, version) = header(bytes, 0)?;
    if magic != MAGIC {
        return Err(format!(
            "not a serialized mesh: it starts with {magic:#06x}, not {MAGIC:#06x}"
        ));
    }
    if version != 3 && version != 4 {
        return Err(format!(
            "serialized meshes of version {version} are not read (only versions 3 and 4)"
        ));
    }
    let start = if shape_index == 0 {
        0
    } else {
        shape_offset(bytes, version, shape_index)?
    };
    header(bytes, start)?; // Mitsuba skips it unread; it must at least be there.
    let mut stream = Inflated {
        decoder: ZlibDecoder::new(&bytes[start + 4..]),
    };
    read_mesh(&mut stream, version).map_err(|e| format!("in the mesh at byte {start}: {e}"))
}

/// The two `u16`s at `at`.
fn header(bytes: &[u8], at: usize) -> Result<(u16, u16), String> {
    match bytes.get(at..at.saturating_add(4)) {
        Some(&[a, b, c, d]) => Ok((u16::from_le_bytes([a, b]), u16::from_le_bytes([c, d]))),
        _ => Err(format!(
            "the file is {} bytes long; a mesh header at byte {at} does not fit",
            bytes.len()
        )),
    }
}

/// Where mesh `shape_index` starts, from the dictionary at the end of the file.
fn shape_offset(bytes: &[u8], version: u16, shape_index: u32) -> Result<usize, String> {
    let too_short = || "the file is too short to end with a dictionary of meshes".to_string();
    let count_at = bytes.len().checked_sub(4).ok_or_else(too_short)?;
    let count = u32::from_le_bytes(bytes[count_at..].try_into().map_err(|_| too_short())?);
    if shape_index >= count {
        return Err(format!(
            "shape_index {shape_index} is out of range: the file holds {count} meshes"
        ));
    }
    let from_end = u64::from(count - shape_index);
    let entry_size: u64 = if version >= 4 { 8 } else { 4 };
    let entry_at = (count_at as u64)
        .checked_sub(from_end * entry_size)
        .ok_or_else(|| format!("the file is too short for a dictionary of {count} meshes"))?
        as usize;
    let entry = &bytes[entry_at..entry_at + entry_size as usize];
    let offset = match *entry {
        [a, b, c, d] => u64::from(u32::from_le_bytes([a, b, c, d])),
        _ => u64::from_le_bytes(entry.try_into().map_err(|_| too_short())?),
    };
    usize::try_from(offset)
        .ok()
        .filter(|&o| o < count_at)
        .ok_or_else(|| {
            format!("the dictionary puts mesh {shape_index} at byte {offset}, beyond the file")
        })
}

/// The inflated stream of one mesh.
struct Inflated<'a> {
    decoder: ZlibDecoder<&'a [u8]>,
}

impl Inflated<'_> {
    fn bytes<const N: usize>(&mut self, what: &str) -> Result<[u8; N], String> {
        let mut buffer = [0; N];
        self.decoder
            .read_exact(&mut buffer)
            .map_err(|e| stream_error(e, what))?;
        Ok(buffer)
    }

    fn u32(&mut self, what: &str) -> Result<u32, String> {
        self.bytes(what).map(u32::from_le_bytes)
    }

    fn u64(&mut self, what: &str) -> Result<u64, String> {
        self.bytes(what).map(u64::from_le_bytes)
    }

    /// `count` records of `size` bytes each, decoded one by one; the vector grows only as the
    /// bytes arrive.
    fn records<T>(
        &mut self,
        count: u64,
        size: usize,
        what: &str,
        mut decode: impl FnMut(&[u8]) -> T,
    ) -> Result<Vec<T>, String> {
        let mut values = Vec::new();
        let mut buffer = vec![0; CHUNK * size];
        let mut left = count;
        while left > 0 {
            let n = left.min(CHUNK as u64) as usize;
            let chunk = &mut buffer[..n * size];
            self.decoder.read_exact(chunk).map_err(|e| {
                stream_error(e, &format!("{what} (read {} of {count})", values.len()))
            })?;
            values.extend(chunk.chunks_exact(size).map(&mut decode));
            left -= n as u64;
        }
        Ok(values)
    }

    /// `count` vectors of `N` floats, each `f32` or `f64`.
    fn vectors<const N: usize>(
        &mut self,
        count: u64,
        double: bool,
        what: &str,
    ) -> Result<Vec<[f32; N]>, String> {
        let scalar = if double { 8 } else { 4 };
        self.records(count, N * scalar, what, |record| {
            std::array::from_fn(|i| {
                let bytes = &record[i * scalar..(i + 1) * scalar];
                match *bytes {
                    [a, b, c, d] => f32::from_le_bytes([a, b, c, d]),
                    _ => f64::from_le_bytes(bytes.try_into().unwrap_or_default()) as f32,
                }
            })
        })
    }

    /// The version 4 name: bytes up to a zero.
    fn name(&mut self) -> Result<(), String> {
        for _ in 0..MAX_NAME_BYTES {
            if self.bytes::<1>("the mesh's name")? == [0] {
                return Ok(());
            }
        }
        Err(format!(
            "the mesh's name has no end within {MAX_NAME_BYTES} bytes"
        ))
    }
}

fn stream_error(error: std::io::Error, what: &str) -> String {
    if error.kind() == std::io::ErrorKind::UnexpectedEof {
        format!("the compressed data end before {what}")
    } else {
        format!("the compressed data are broken before {what}: {error}")
    }
}

fn read_mesh(stream: &mut Inflated, version: u16) -> Result<TriangleMesh, String> {
    let flags = stream.u32("the flags")?;
    if version == 4 {
        stream.name()?;
    }
    let vertex_count = stream.u64("the vertex count")?;
    let face_count = stream.u64("the triangle count")?;
    if vertex_count > u64::from(u32::MAX) {
        return Err(format!(
            "the mesh has {vertex_count} vertices; at most {} can be indexed",
            u32::MAX
        ));
    }
    let double = flags & DOUBLE_PRECISION != 0;
    let positions = stream.vectors::<3>(vertex_count, double, "the positions")?;
    let normals = if flags & HAS_NORMALS != 0 {
        Some(stream.vectors::<3>(vertex_count, double, "the normals")?)
    } else {
        None
    };
    let uvs = if flags & HAS_TEXCOORDS != 0 {
        Some(stream.vectors::<2>(vertex_count, double, "the texture coordinates")?)
    } else {
        None
    };
    if flags & HAS_COLORS != 0 {
        stream.vectors::<3>(vertex_count, double, "the vertex colours")?;
    }
    let indices = stream.records(face_count, 12, "the triangles", |record| {
        std::array::from_fn(|i| {
            u32::from_le_bytes([
                record[4 * i],
                record[4 * i + 1],
                record[4 * i + 2],
                record[4 * i + 3],
            ])
        })
    })?;

    let finite = |values: &[[f32; 3]], what: &str| match values
        .iter()
        .position(|v| !v.iter().all(|x| x.is_finite()))
    {
        Some(i) => Err(format!(
            "vertex {i} has a non-finite {what} {:?}",
            values[i]
        )),
        None => Ok(()),
    };
    finite(&positions, "position")?;
    if let Some(normals) = &normals {
        finite(normals, "normal")?;
    }
    if let Some(uvs) = &uvs {
        let padded: Vec<[f32; 3]> = uvs.iter().map(|&[u, v]| [u, v, 0.0]).collect();
        finite(&padded, "texture coordinate")?;
    }
    if indices.is_empty() {
        return Err("the mesh has no triangles".to_string());
    }
    TriangleMesh::new(
        positions.into_iter().map(Vec3::from_array).collect(),
        normals.map(|n| n.into_iter().map(Vec3::from_array).collect()),
        indices,
    )
    .and_then(|mesh| mesh.with_uvs(uvs.map(|t| t.into_iter().map(Vec2::from_array).collect())))
    .map_err(|e| e.to_string())
}
