//! `ch10-optimal-mis`: render the light reaching what the camera sees straight from the
//! lights, the light and BSDF samples combined by a heuristic or optimally (`--mis`), or write
//! the figures of the page "Optimal multiple importance sampling".

use ch10_optimal_mis::lab::{cli, figures};
use std::process::ExitCode;

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!(
        "Render a scene file's direct light (--scene FILE.xml), its light and BSDF samples combined by --mis optimal|power|balance."
    );
    binary.run(cli::run_render, figures::write_all)
}
