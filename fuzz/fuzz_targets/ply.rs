//! Any bytes given to the PLY reader: an error or a mesh that passes validation, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    if let Ok(mesh) = workbench::scene_file::parse_ply(bytes) {
        mesh.validate().expect("a mesh the reader returns is valid");
        assert!(mesh.triangles().all(|t| t.p.iter().all(|p| p.is_finite())));
    }
});
