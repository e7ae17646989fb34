//! Which exercises each check runs: learned by running every check once on the solutions, with
//! a mark put first in every exercise's solution that writes the exercise's name to a file the
//! first time its code runs in a process.
//!
//! `check-exercises` needs this twice. A check that runs no exercise listed after its own
//! passes with those exercises stubbed just as it passes with them solved: until a stub is
//! called, the code that runs is the same. So the exercises can be done in order when no check
//! runs a later exercise, which one run of every check shows, where stubbing the later
//! exercises of each chapter in turn took a build per exercise of the longest chapter. And a
//! wrong answer put in for one exercise can change the outcome of another exercise's check
//! only if that check runs it, so the wrong answers can be tried side by side in rounds where
//! no check runs another answer of the round, and a check that does not refuse its answer is
//! a real surprise, never a neighbour's doing.

use std::collections::{BTreeSet, HashMap};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use anyhow::{Context, Result, bail};
use rayon::prelude::*;

use crate::exercise_list::Exercise;
use crate::progress;

/// The environment variable that names the file a marked exercise writes its name to.
pub const CALLS_FILE_VARIABLE: &str = "WORKBOOK_EXERCISE_CALLS";

/// The statement put first in `exercise`'s solution. The first time the code runs in a
/// process, it appends the exercise's name to the file named by [`CALLS_FILE_VARIABLE`], when
/// there is one; every later run costs one atomic load. Child processes inherit the variable,
/// so a check that runs a chapter's binary is followed into it.
pub fn call_mark(exercise: &Exercise) -> String {
    let line = format!("{}\n", exercise.name);
    format!(
        "{{ static MARKED: std::sync::Once = std::sync::Once::new(); MARKED.call_once(|| {{ \
         if let Some(path) = std::env::var_os({CALLS_FILE_VARIABLE:?}) {{ \
         if let Ok(mut file) = std::fs::OpenOptions::new().create(true).append(true).open(path) \
         {{ let _ = std::io::Write::write_all(&mut file, {line:?}.as_bytes()); }} }} }}); }}"
    )
}

/// Runs a check that is not of the usual form, as it is, with [`CALLS_FILE_VARIABLE`] set to
/// the given file: whether it passed, and what it printed.
pub type RunOther<'a> = dyn Fn(&str, &Path) -> Result<(bool, String)> + Sync + 'a;

/// One check's run on the marked solutions: whether it passed, what it printed, and the names
/// of the exercises whose code ran.
pub struct MarkedRun {
    pub passed: bool,
    pub output: String,
    pub ran: BTreeSet<String>,
}

/// The test binary of each package's library built by a `cargo test --no-run
/// --message-format=json` whose standard output is `json`, by package name.
pub fn library_test_binaries(json: &str) -> HashMap<String, (PathBuf, PathBuf)> {
    let mut binaries = HashMap::new();
    for line in json.lines() {
        let Ok(message) = serde_json::from_str::<serde_json::Value>(line) else {
            continue;
        };
        if message["reason"] != "compiler-artifact" || message["profile"]["test"] != true {
            continue;
        }
        let is_library = message["target"]["kind"]
            .as_array()
            .is_some_and(|kinds| kinds.iter().any(|kind| kind == "lib"));
        let (Some(executable), Some(manifest), Some(id)) = (
            message["executable"].as_str(),
            message["manifest_path"].as_str(),
            message["package_id"].as_str(),
        ) else {
            continue;
        };
        if !is_library {
            continue;
        }
        let dir = Path::new(manifest)
            .parent()
            .map_or_else(PathBuf::new, Path::to_path_buf);
        binaries.insert(package_name(id), (PathBuf::from(executable), dir));
    }
    binaries
}

/// A package's name from cargo's id for it: `path+file:///w/dir#name@0.1.0`, or
/// `path+file:///w/name#0.1.0` when the folder is named after the package, or the older
/// `name 0.1.0 (path+file:///w/name)`.
fn package_name(id: &str) -> String {
    if let Some((url, version)) = id.split_once('#') {
        match version.split_once('@') {
            Some((name, _)) => name.to_owned(),
            None => url.rsplit('/').next().unwrap_or(url).to_owned(),
        }
    } else {
        id.split_whitespace().next().unwrap_or(id).to_owned()
    }
}

/// Runs each check of `exercises` in the copy (already built, its library test binaries in
/// `binaries`), each in processes of its own with a file of its own for the marks in
/// `marks_dir`, as many side by side as there are cores. A check of the usual form runs its
/// package's test binary with its filter, as `cargo test` would, from the package's folder;
/// any other runs as it is, through `run_other` with the variable to set.
pub fn run_marked(
    exercises: &[&Exercise],
    binaries: &HashMap<String, (PathBuf, PathBuf)>,
    marks_dir: &Path,
    run_other: &RunOther<'_>,
) -> Result<Vec<MarkedRun>> {
    std::fs::create_dir_all(marks_dir)
        .with_context(|| format!("cannot create {}", marks_dir.display()))?;
    exercises
        .par_iter()
        .map(|exercise| {
            let marks = marks_dir.join(format!("{}.txt", exercise.name));
            run_one(exercise, binaries, &marks, run_other)
        })
        .collect()
}

fn run_one(
    exercise: &Exercise,
    binaries: &HashMap<String, (PathBuf, PathBuf)>,
    marks: &Path,
    run_other: &RunOther<'_>,
) -> Result<MarkedRun> {
    if marks.exists() {
        std::fs::remove_file(marks)
            .with_context(|| format!("cannot remove {}", marks.display()))?;
    }
    let (passed, output) = match progress::standard_check(&exercise.check) {
        Some((package, filter)) => {
            let Some((binary, dir)) = binaries.get(package) else {
                bail!(
                    "{}: the build made no test binary for the library of {package}",
                    exercise.name
                );
            };
            let output = Command::new(binary)
                .arg(filter)
                .current_dir(dir)
                .env(CALLS_FILE_VARIABLE, marks)
                .env("CARGO_MANIFEST_DIR", dir)
                .stdin(Stdio::null())
                .output()
                .with_context(|| format!("cannot run {}", binary.display()))?;
            let text = format!(
                "{}{}",
                String::from_utf8_lossy(&output.stdout),
                String::from_utf8_lossy(&output.stderr)
            );
            let results = progress::test_results(&text);
            if progress::picked_by(&results, filter).is_empty() {
                (false, format!("no test's name contains `{filter}`\n{text}"))
            } else {
                (output.status.success(), text)
            }
        }
        None => run_other(&exercise.check, marks)?,
    };
    let ran = match std::fs::read_to_string(marks) {
        Ok(text) => text.lines().map(str::to_owned).collect(),
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => BTreeSet::new(),
        Err(error) => {
            return Err(error).with_context(|| format!("cannot read {}", marks.display()));
        }
    };
    Ok(MarkedRun {
        passed,
        output,
        ran,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn package_names_are_read_from_every_form_of_cargos_ids() {
        assert_eq!(
            package_name("path+file:///w/chapters/ch01-whitted#0.1.0"),
            "ch01-whitted"
        );
        assert_eq!(
            package_name("path+file:///w/tests#workbook-tests@0.1.0"),
            "workbook-tests"
        );
        assert_eq!(
            package_name("ch01-whitted 0.1.0 (path+file:///w/chapters/ch01-whitted)"),
            "ch01-whitted"
        );
    }

    #[test]
    fn only_library_test_binaries_are_kept() {
        let json = [
            r#"{"reason":"compiler-artifact","package_id":"path+file:///w/a#0.1.0","manifest_path":"/w/a/Cargo.toml","target":{"kind":["lib"]},"profile":{"test":true},"executable":"/t/a-1"}"#,
            r#"{"reason":"compiler-artifact","package_id":"path+file:///w/a#0.1.0","manifest_path":"/w/a/Cargo.toml","target":{"kind":["lib"]},"profile":{"test":false},"executable":null}"#,
            r#"{"reason":"compiler-artifact","package_id":"path+file:///w/b#0.1.0","manifest_path":"/w/b/Cargo.toml","target":{"kind":["bin"]},"profile":{"test":true},"executable":"/t/b-1"}"#,
            "not json",
        ]
        .join("\n");
        let binaries = library_test_binaries(&json);
        assert_eq!(binaries.len(), 1);
        assert_eq!(
            binaries["a"],
            (PathBuf::from("/t/a-1"), PathBuf::from("/w/a"))
        );
    }
}
