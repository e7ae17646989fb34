//! Tests of the scene loader.

mod animation;
mod any_uv;
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
mod old_versions;
mod parameter_textures;
mod spectra;
mod textures;
mod transforms;
mod uv_parameterisations;
mod warnings;

use std::path::Path;

use super::{LoadedDescription, SceneError, parse_description};

/// The configuration of the readers' property tests: `SCENE_FUZZ_CASES` cases (256 by
/// default) drawn from the seed `SCENE_FUZZ_SEED` (a fixed one by default, so that a run is
/// repeatable and CI never fails by the luck of the draw; set another seed to explore), with
/// a shrunk failure printed and nothing written into the source tree.
pub(crate) fn property_config() -> proptest::prelude::ProptestConfig {
    let number = |name: &str| std::env::var(name).ok().and_then(|v| v.parse().ok());
    proptest::prelude::ProptestConfig {
        cases: number("SCENE_FUZZ_CASES").map_or(256, |n: u64| n as u32),
        rng_seed: proptest::test_runner::RngSeed::Fixed(
            number("SCENE_FUZZ_SEED").unwrap_or(20_261_203),
        ),
        failure_persistence: None,
        ..proptest::prelude::ProptestConfig::default()
    }
}

/// The scene of `body` (see [`scene_with`]) read as if from `dir`; a loading error fails the
/// test with its message.
fn scene_in(dir: &Path, body: &str) -> common::scene::Scene {
    super::parse_scene(&scene_with(body), &dir.join("scene.xml"), &[])
        .unwrap_or_else(|e| panic!("{e}"))
        .scene
}

/// The error that reading the scene of `body` from `dir` must give.
fn error_in(dir: &Path, body: &str) -> String {
    super::parse_scene(&scene_with(body), &dir.join("scene.xml"), &[])
        .map(|_| ())
        .unwrap_err()
        .to_string()
}

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
