//! Any text given to the OBJ reader: an error or a mesh that passes validation, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    if let Ok(mesh) = workbench::scene_file::parse_obj(text) {
        mesh.validate().expect("a mesh the reader returns is valid");
    }
});
