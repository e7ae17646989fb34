//! `ch08-path-tracing`: path-trace a scene file with the lecture's materials, or write the
//! chapter's figures.

use ch08_path_tracing::LectureMaterials;
use ch08_path_tracing::lab::CAPABILITIES;
use ch08_path_tracing::lab::cli::{RenderCommand, run_render};
use ch08_path_tracing::lab::figures;
use std::process::ExitCode;

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Path-trace a scene file (--scene FILE.xml).");
    binary.run(
        |command: RenderCommand| {
            run_render(command, &CAPABILITIES, |_, fuzz| LectureMaterials { fuzz })
        },
        figures::write_all,
    )
}
