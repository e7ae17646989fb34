//! Any bytes given to the serialized mesh reader, for the first and the second mesh of the
//! file: an error or a mesh that passes validation, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    for shape_index in [0, 1] {
        if let Ok(mesh) = common::scene_file::parse_serialized(bytes, shape_index) {
            mesh.validate().expect("a mesh the reader returns is valid");
            assert!(mesh.triangles().all(|t| t.p.iter().all(|p| p.is_finite())));
        }
    }
});
