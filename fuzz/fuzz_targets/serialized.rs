//! Any bytes given to the serialized mesh reader: an error or a mesh that passes validation,
//! never a panic. The bytes are read as a file (its first and second mesh), and also as the
//! inflated stream of a one-mesh file of version 3 and of version 4, so that the fuzzer's
//! mutations reach the mesh reader instead of stopping at zlib's checks.
#![no_main]

use std::io::Write;

use flate2::Compression;
use flate2::write::ZlibEncoder;
use libfuzzer_sys::fuzz_target;

fn check(file: &[u8], shape_index: u32) {
    if let Ok(mesh) = workbench::scene_file::parse_serialized(file, shape_index) {
        mesh.validate().expect("a mesh the reader returns is valid");
        assert!(mesh.triangles().all(|t| t.p.iter().all(|p| p.is_finite())));
    }
}

/// A file holding one mesh whose inflated stream is `payload`.
fn one_mesh_file(payload: &[u8], version: u16) -> Vec<u8> {
    let mut file = vec![0x1C, 0x04];
    file.extend(version.to_le_bytes());
    let mut encoder = ZlibEncoder::new(file, Compression::fast());
    encoder.write_all(payload).expect("writing to memory");
    let mut file = encoder.finish().expect("writing to memory");
    if version == 4 {
        file.extend(0u64.to_le_bytes());
    } else {
        file.extend(0u32.to_le_bytes());
    }
    file.extend(1u32.to_le_bytes());
    file
}

fuzz_target!(|bytes: &[u8]| {
    check(bytes, 0);
    check(bytes, 1);
    for version in [3, 4] {
        check(&one_mesh_file(bytes, version), 0);
    }
});
