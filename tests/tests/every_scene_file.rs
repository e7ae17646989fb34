//! Every chapter's `render --scene` on every scene file shipped in the workspace: each one
//! renders, or is refused with the line and column of the element that needs a later chapter,
//! and that chapter's name. A refusal that names no position, or no chapter, fails.

use rayon::prelude::*;
use std::path::{Path, PathBuf};
use workbook_tests::binaries::{RENDERING_CHAPTERS, run_chapter};

/// Every `.xml` scene under `chapters/*/scenes/` and the suite's own good scenes.
fn shipped_scene_files() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut dirs: Vec<PathBuf> = std::fs::read_dir(root.join("chapters"))
        .expect("the chapters directory")
        .map(|entry| entry.expect("an entry").path().join("scenes"))
        .collect();
    dirs.push(root.join("workbench/tests/scenes"));
    dirs.push(root.join("tests/scenes"));
    let mut files: Vec<PathBuf> = dirs
        .iter()
        .filter_map(|dir| std::fs::read_dir(dir).ok())
        .flatten()
        .map(|entry| entry.expect("an entry").path())
        .filter(|path| path.extension().is_some_and(|e| e == "xml"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_chapter_renders_or_refuses_every_shipped_scene_with_its_line_and_chapter() {
    let files = shipped_scene_files();
    assert!(files.len() >= 20, "only {} scene files found", files.len());
    let out_dir = tempfile::tempdir().unwrap();
    let runs: Vec<_> = RENDERING_CHAPTERS
        .iter()
        .flat_map(|chapter| files.iter().map(move |file| (chapter, file)))
        .collect();
    // Side by side, one thread each (each run is a process of its own), each writing an image
    // of its own.
    let outcomes: Vec<Result<(), Option<String>>> = runs
        .par_iter()
        .enumerate()
        .map(|(i, (chapter, file))| {
            let out = out_dir.path().join(format!("{i}.pfm"));
            let args = [
                "render",
                "--scene",
                file.to_str().unwrap(),
                "--spp",
                "1",
                "--width",
                "8",
                "--height",
                "6",
                "--threads",
                "1",
                "--out",
                out.to_str().unwrap(),
            ];
            let run = run_chapter(chapter, &args);
            if run.status.success() {
                return Ok(());
            }
            // A refusal: "FILE: line L, column C: WHAT; LESSON in chapter NN (package); ..."
            let stderr = String::from_utf8_lossy(&run.stderr);
            let names_position = stderr.contains(": line ") && stderr.contains(", column ");
            let names_chapter = stderr.contains("in chapter 0");
            let explained = names_position && names_chapter && !stderr.contains("panicked");
            Err((!explained).then(|| format!("{chapter} {}: {stderr}", file.display())))
        })
        .collect();
    let rendered = outcomes.iter().filter(|outcome| outcome.is_ok()).count();
    let problems: Vec<String> = outcomes
        .into_iter()
        .filter_map(|outcome| outcome.err().flatten())
        .collect();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    // The renderer of real scene files (ch09-materials) renders every one of them.
    assert!(rendered >= files.len(), "only {rendered} renders");
}
