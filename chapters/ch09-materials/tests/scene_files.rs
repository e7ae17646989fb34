//! `render` renders every scene file of the workbook: chapter 08's path tracer computes every
//! effect of chapters 01 to 07, and this crate's materials are every material a file names, so
//! each chapter's scenes must render here too, tiny, to a finite image with no non-finite
//! sample, or be refused with the reason listed in [`REFUSED`].
//!
//! The files are found, not listed, so a new scene is tested as soon as it is added, and a
//! scene that starts to be refused fails until its reason is written down here.

use rayon::prelude::*;
use std::path::{Path, PathBuf};

mod support;
use support::render_tiny;

/// Scene files `render` refuses, by file name, with what its message must say. None: every
/// feature of the subset (motion, lenses, lobes, area and point lights) is the path tracer's.
const REFUSED: &[(&str, &str)] = &[];

/// Every `.xml` file under `chapters/*/scenes/`, at any depth outside `parts/` folders, sorted.
fn scene_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, files: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            // `parts/` holds pieces that other scene files include, not scenes of their own.
            if path.is_dir() && !path.ends_with("parts") {
                walk(&path, files);
            } else if path.extension().is_some_and(|e| e == "xml") {
                files.push(path);
            }
        }
    }
    let chapters = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
    let mut files = Vec::new();
    for chapter in std::fs::read_dir(chapters).unwrap() {
        let scenes = chapter.unwrap().path().join("scenes");
        if scenes.is_dir() {
            walk(&scenes, &mut files);
        }
    }
    files.sort();
    files
}

#[test]
fn render_renders_every_scene_file_of_the_workbook() {
    let files = scene_files();
    let own = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/metals.xml");
    assert!(
        files.contains(&own),
        "the search finds the crate's own scenes"
    );
    let dir = tempfile::tempdir().unwrap();
    // The renders side by side, each in a folder of its own: each is a process of its own.
    let renders: Vec<_> = files
        .par_iter()
        .enumerate()
        .map(|(i, file)| {
            let out = dir.path().join(i.to_string());
            std::fs::create_dir(&out).unwrap();
            render_tiny(file, &out)
        })
        .collect();
    let mut refused = Vec::new();
    for (file, render) in files.iter().zip(renders) {
        let name = file.file_name().unwrap().to_str().unwrap();
        let reason = REFUSED.iter().find(|(n, _)| *n == name).map(|(_, r)| *r);
        match (render, reason) {
            (Ok(image), None) => {
                assert_eq!((image.width, image.height), (16, 12), "{name}");
                assert!(
                    image.pixels.iter().all(|p| p.is_finite()),
                    "{name}: a pixel is not finite"
                );
            }
            (Ok(_), Some(reason)) => panic!("{name} rendered, but is listed as refused: {reason}"),
            (Err(message), Some(reason)) => {
                assert!(message.contains(reason), "{name}: {message}");
                refused.push(name);
            }
            (Err(message), None) => panic!("{name} is refused: {message}"),
        }
    }
    eprintln!(
        "{} scene files: {} rendered, refused: {refused:?}",
        files.len(),
        files.len() - refused.len()
    );
    assert_eq!(refused.len(), REFUSED.len(), "every listed refusal exists");
}
