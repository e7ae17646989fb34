//! `ch11-path-guiding`: path-trace a scene file with its directions guided by what earlier
//! iterations learnt (`--guiding`), or write the figures of the page "Path guiding".

use ch11_path_guiding::lab::{cli, figures};
use std::process::ExitCode;

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!(
        "Path-trace a scene file (--scene FILE.xml), its directions guided by --guiding off|radiance|variance."
    );
    binary.run(cli::run_render, figures::write_all)
}
