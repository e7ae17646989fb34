//! Tests of the scene loader.

mod animation;
mod broken_files;
mod cornell;
mod environment_map;
mod files_and_references;
mod masks;
mod materials;
mod mesh_files;
mod mesh_scenes;
mod model;
mod never_panics;
mod parameter_textures;
mod spectra;
mod textures;
mod transforms;
mod uv_parameterisations;
mod warnings;

use std::path::Path;

use super::{LoadedDescription, SceneError, parse_description};

/// Wraps `body` in a scene with a minimal sensor. The body starts on **line 2**, so a broken
/// element on the body's first line is reported on line 2.
fn scene_with(body: &str) -> String {
    format!(
        "<scene version=\"3.0.0\">\n{body}\n<sensor type=\"perspective\"><float name=\"fov\" \
         value=\"40\"/></sensor>\n</scene>"
    )
}

/// Parses what `text` describes as if it came from `test.xml`.
fn parse(text: &str) -> Result<LoadedDescription, SceneError> {
    parse_description(text, Path::new("test.xml"), &[])
}
