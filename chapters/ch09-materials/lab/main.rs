//! `ch09-materials`: path-trace a real scene file with every material it names (Mitsuba 3's
//! metals, plastic, masks, thin and tinted glass, the microfacet models), or write the figures
//! of the page "Beyond the lecture: Mitsuba's materials".

use ch08_path_tracing::lab::cli::{RenderCommand, run_render};
use ch09_materials::SceneMaterials;
use ch09_materials::lab::CAPABILITIES;
use ch09_materials::lab::figures;
use std::process::ExitCode;

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!(
        "Path-trace a scene file (--scene FILE.xml) with every material it names."
    );
    binary.run(
        |command: RenderCommand| run_render(command, &CAPABILITIES, SceneMaterials::of),
        figures::write_all,
    )
}
