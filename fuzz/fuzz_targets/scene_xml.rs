//! Any text given to the scene file reader, as if it were a file in a directory that does not
//! exist (so a mesh it names cannot be read): an error or a scene, never a panic.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    let file = Path::new("/nonexistent/fuzz/scene.xml");
    let _ = workbench::scene_file::parse_scene(text, file, &[]);
});
