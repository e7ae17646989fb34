//! `ch09-materials`: path-trace a real scene file with every material it names (Mitsuba 3's
//! metals, plastic, masks, thin and tinted glass, the microfacet models), or write the figures
//! of the page "Beyond the lecture: Mitsuba's materials".

use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::lab::cli::{PathMaterials, run_render};
use ch09_materials::SceneMaterials;
use ch09_materials::lab::CAPABILITIES;
use ch09_materials::lab::figures;
use common::scene::Scene;
use std::process::ExitCode;
use workbench::capabilities::Capabilities;

/// Every material a scene file names.
#[derive(Debug)]
struct Every;

impl PathMaterials for Every {
    const CAPABILITIES: Capabilities = CAPABILITIES;
    type Materials = SceneMaterials;

    fn of(scene: &Scene, fuzz: FuzzMethod) -> SceneMaterials {
        SceneMaterials::of(scene, fuzz)
    }
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!(
        "Path-trace a scene file (--scene FILE.xml) with every material it names."
    );
    binary.run(run_render::<Every>, figures::write_all)
}
