//! Scene files written by other people, which the workbook cannot ship: every file under the
//! folder `REAL_SCENES` names (Mitsuba 3's documentation scenes, say, from its data
//! repository) must either render, tiny, to a finite image with no non-finite sample, or be refused with a message that
//! names the file, line and column: never a panic, never a broken image. Ignored by default:
//!
//! ```text
//! REAL_SCENES=/path/to/mitsuba-data/docs/scenes cargo test -p ch09-materials \
//!     --test real_scenes -- --ignored --nocapture
//! ```
//!
//! It prints one line per file and a count of the reasons for refusal, the list of what to
//! read next.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

mod support;
use support::render_tiny;

/// Every `.xml` file under `folder` that may be a whole scene: one with a `<sensor>` or an
/// `<include>` (a part meant only to be included has neither), sorted.
fn scenes_under(folder: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut folders = vec![folder.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "xml")
                && std::fs::read_to_string(&path)
                    .is_ok_and(|text| text.contains("<sensor") || text.contains("<include"))
            {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

/// The reason of a refusal without its place: the part after `error: file:line:column: `.
fn reason(message: &str) -> String {
    let first = message.lines().next().unwrap_or_default();
    let first = first.strip_prefix("error: ").unwrap_or(first);
    let after_place = first.splitn(4, ':').nth(3).unwrap_or(first);
    after_place.trim().chars().take(90).collect()
}

#[test]
#[ignore = "needs scene files written by others (set REAL_SCENES to their folder)"]
fn real_scene_files_render_or_are_refused_with_their_place() {
    let Ok(folder) = std::env::var("REAL_SCENES") else {
        panic!("set REAL_SCENES to a folder of Mitsuba 3 scene files");
    };
    let out = tempfile::tempdir().unwrap();
    let mut rendered = 0;
    let mut refusals: BTreeMap<String, usize> = BTreeMap::new();
    for scene in scenes_under(Path::new(&folder)) {
        let result = render_tiny(&scene, out.path());
        let name = scene.strip_prefix(&folder).unwrap_or(&scene).display();
        match result {
            Ok(pixels) => {
                assert!(
                    pixels.pixels.iter().all(|p| p.is_finite()),
                    "{name}: a pixel is not finite"
                );
                rendered += 1;
                eprintln!("rendered  {name}");
            }
            Err(stderr) => {
                let message = stderr
                    .lines()
                    .find(|line| line.starts_with("error"))
                    .unwrap_or(&stderr)
                    .to_string();
                assert!(
                    message.contains(".xml:"),
                    "{name}: the refusal does not name the file: {message}"
                );
                eprintln!("refused   {name}: {}", reason(&message));
                *refusals.entry(reason(&message)).or_default() += 1;
            }
        }
    }
    eprintln!("\n{rendered} rendered; refusals by reason:");
    let mut by_count: Vec<_> = refusals.into_iter().collect();
    by_count.sort_by_key(|(_, count)| std::cmp::Reverse(*count));
    for (reason, count) in by_count {
        eprintln!("{count:4}  {reason}");
    }
}
