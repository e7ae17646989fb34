//! `ch08-path-tracing`: path-trace a scene file with the lecture's materials, or write the
//! chapter's figures.

use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::LectureMaterials;
use ch08_path_tracing::lab::CAPABILITIES;
use ch08_path_tracing::lab::cli::{PathMaterials, run_render};
use ch08_path_tracing::lab::figures;
use common::scene::Scene;
use std::process::ExitCode;
use workbench::capabilities::Capabilities;

/// The lecture's materials, the rest of a file's stood in for or refused.
#[derive(Debug)]
struct Lecture;

impl PathMaterials for Lecture {
    const CAPABILITIES: Capabilities = CAPABILITIES;
    type Materials = LectureMaterials;

    fn of(_: &Scene, fuzz: FuzzMethod) -> LectureMaterials {
        LectureMaterials { fuzz }
    }
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Path-trace a scene file (--scene FILE.xml).");
    binary.run(run_render::<Lecture>, figures::write_all)
}
