//! The student edition: the workspace with every exercise's solution cut out.
//!
//! It is a plain copy of the source tree in which each listed exercise's solution region has
//! become a `todo!("<name>: <hint>")` line. Everything is worked out in memory first, so a
//! broken exercise or a stray marker stops the run before a single file is written.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::exercise_list::{Exercise, LIST_PATH};
use crate::solution_markers::{self, Cut};
use crate::workspace;

/// One file of the student edition.
pub enum EditionFile {
    /// Copied as it is (permissions included, so scripts stay executable).
    Copy(PathBuf),
    /// A Rust source with its solutions cut out.
    Rewritten(PathBuf, String),
}

impl EditionFile {
    /// Where the file goes, relative to the edition's root.
    pub fn path(&self) -> &Path {
        match self {
            EditionFile::Copy(path) | EditionFile::Rewritten(path, _) => path,
        }
    }
}

/// Works out every file of the student edition without writing anything.
///
/// Fails, listing every problem at once, if a listed exercise's file is not among the sources
/// or any `.rs` file has a solution marker outside the listed exercises.
pub fn plan(
    root: &Path,
    exercises: &[Exercise],
    leave_out: &[PathBuf],
) -> Result<Vec<EditionFile>> {
    let mut cuts_by_file: BTreeMap<&Path, Vec<Cut<'_>>> = BTreeMap::new();
    for exercise in exercises {
        cuts_by_file.entry(&exercise.file).or_default().push(Cut {
            anchor: &exercise.anchor,
            message: exercise.todo_message(),
        });
    }

    let sources = workspace::source_files(root)?;
    let mut problems = Vec::new();
    for file in cuts_by_file.keys() {
        if !sources.iter().any(|source| source == file) {
            problems.push(format!(
                "{}: holds an exercise but is not a source file (ignored by git?)",
                file.display()
            ));
        }
    }

    let mut edition = Vec::with_capacity(sources.len());
    for file in sources {
        if leave_out.iter().any(|dir| file.starts_with(dir)) {
            continue;
        }
        if file == Path::new(LIST_PATH) {
            let list = std::fs::read_to_string(root.join(&file))
                .with_context(|| format!("cannot read {LIST_PATH}"))?;
            edition.push(EditionFile::Rewritten(file, without_wrong_answers(&list)?));
            continue;
        }
        if file == Path::new(STUDENT_README) {
            continue; // it becomes the edition's README.md, below
        }
        if file == Path::new("README.md") && root.join(STUDENT_README).is_file() {
            let readme = std::fs::read_to_string(root.join(STUDENT_README))
                .with_context(|| format!("cannot read {STUDENT_README}"))?;
            edition.push(EditionFile::Rewritten(file, readme));
            continue;
        }
        if file == Path::new(BOOK_MANIFEST) {
            let manifest = std::fs::read_to_string(root.join(&file))
                .with_context(|| format!("cannot read {BOOK_MANIFEST}"))?;
            edition.push(EditionFile::Rewritten(
                file,
                without_default_figures(&manifest)?,
            ));
            continue;
        }
        if file.extension().is_none_or(|ext| ext != "rs") {
            edition.push(EditionFile::Copy(file));
            continue;
        }
        let source = std::fs::read_to_string(root.join(&file))
            .with_context(|| format!("cannot read {}", file.display()))?;
        let cuts = cuts_by_file
            .get(file.as_path())
            .map_or(&[][..], Vec::as_slice);
        match solution_markers::student_source(&source, cuts) {
            // Nothing to cut and no stray marker: the file is copied byte for byte.
            Ok(_) if cuts.is_empty() => edition.push(EditionFile::Copy(file)),
            Ok(student) => edition.push(EditionFile::Rewritten(file, student)),
            Err(errors) => problems.extend(
                errors
                    .into_iter()
                    .map(|error| format!("{}: {error}", file.display())),
            ),
        }
    }

    for package in packages_with_exercises(exercises) {
        let script = package.join("build.rs");
        if !edition.iter().any(|file| file.path() == script) {
            edition.push(EditionFile::Rewritten(script, FIRST_BUILD_NOTE.to_owned()));
        }
    }

    if !problems.is_empty() {
        bail!(
            "cannot make the student edition, {} problem(s):\n  {}\n\
             (every solution region must belong to an exercise listed in {LIST_PATH})",
            problems.len(),
            problems.join("\n  ")
        );
    }
    Ok(edition)
}

/// The workbook's README for students, which becomes the edition's `README.md` (the workbook's
/// own is for its maintainers).
pub const STUDENT_README: &str = "book/student-README.md";

/// The builder's manifest, whose default features the edition changes.
const BOOK_MANIFEST: &str = "book/Cargo.toml";

/// The line of [`BOOK_MANIFEST`] that links every chapter into the builder by default.
const DEFAULT_FIGURES: &str = "default = [\"figures\"]";

/// The builder's manifest as the student gets it: without the chapters by default, so that
/// `exercises`, `progress` and `checkpoint` start without compiling the student's chapters
/// (each chapter's first compile takes minutes, and one after an edit rebuilds the chapters
/// after it). The lab report renders with the chapters' own binaries instead.
fn without_default_figures(manifest: &str) -> Result<String> {
    let lines: Vec<&str> = manifest.lines().collect();
    if lines
        .iter()
        .filter(|line| line.trim() == DEFAULT_FIGURES)
        .count()
        != 1
    {
        bail!("{BOOK_MANIFEST}: expected one line `{DEFAULT_FIGURES}` to turn off for students");
    }
    let mut out = String::with_capacity(manifest.len() + 200);
    for line in lines {
        if line.trim() == DEFAULT_FIGURES {
            out.push_str(
                "# The student edition: the tools start without compiling the chapters (written \
                 by\n# `book student`; the workbook has `default = [\"figures\"]`).\ndefault = []\n",
            );
        } else {
            out.push_str(line);
            out.push('\n');
        }
    }
    Ok(out)
}

/// The build script the student edition gives each package that holds exercises. It runs once,
/// before the chapter's first compile (cargo runs a build script again only when the script
/// changes), and says why that compile takes a while, before it starts. It writes to the
/// terminal itself: cargo would keep a `cargo::warning` and repeat it on every later build,
/// compiled or not. Without a terminal (CI, an editor's background build) it says nothing.
const FIRST_BUILD_NOTE: &str = "\
//! Written by `book student`: a note on this chapter's first compile, which takes a while.
use std::io::Write;

fn main() {
    println!(\"cargo::rerun-if-changed=build.rs\");
    let terminal = if cfg!(windows) { \"CONOUT$\" } else { \"/dev/tty\" };
    if let Ok(mut terminal) = std::fs::OpenOptions::new().write(true).open(terminal) {
        let package = std::env::var(\"CARGO_PKG_NAME\").unwrap_or_default();
        let _ = writeln!(
            terminal,
            \"\\r      Note: compiling {package} for the first time (the very first check also \\
             compiles the libraries it uses): a few minutes on a 2-core machine; after that a \\
             check takes seconds.\"
        );
    }
}
";

/// The directories of the packages that hold exercises, in the list's order: the part of each
/// exercise's file before its `src/`.
fn packages_with_exercises(exercises: &[Exercise]) -> Vec<PathBuf> {
    let mut packages: Vec<PathBuf> = Vec::new();
    for exercise in exercises {
        let package = exercise
            .file
            .ancestors()
            .find(|dir| dir.file_name().is_some_and(|name| name == "src"))
            .and_then(Path::parent);
        if let Some(package) = package
            && !packages.iter().any(|known| known == package)
        {
            packages.push(package.to_path_buf());
        }
    }
    packages
}

/// The exercise list as the student gets it: without the recorded wrong answers, whose
/// mistakes would give the right answers away, and without the giveaways (the solutions' key
/// expressions). Checked by reading it back: the same exercises, none with a wrong answer or a
/// giveaway left.
fn without_wrong_answers(list: &str) -> Result<String> {
    let mut out = String::with_capacity(list.len());
    let mut skipping = false;
    for line in list.lines() {
        let trimmed = line.trim();
        if trimmed == "[[exercise.wrong]]" || trimmed == "[[exercise.giveaway]]" {
            skipping = true;
            continue;
        }
        if trimmed.starts_with("[[") {
            skipping = false;
        }
        if !skipping {
            out.push_str(line);
            out.push('\n');
        }
    }
    let before = crate::exercise_list::parse(list)?;
    let after = crate::exercise_list::parse(&out)
        .context("the exercise list without its wrong answers does not read back")?;
    let same = before.len() == after.len()
        && before
            .iter()
            .zip(&after)
            .all(|(a, b)| a.name == b.name && a.hint == b.hint);
    let left = |exercise: &Exercise| !exercise.wrong.is_empty() || !exercise.giveaway.is_empty();
    if !same || after.iter().any(left) {
        bail!("{LIST_PATH}: its wrong answers could not be taken out cleanly");
    }
    Ok(out)
}

/// Writes the student edition into `out`.
///
/// `out` must be empty or missing; with `force`, whatever it holds is deleted first (but never
/// when `out` is the workspace or contains it). If `out` lies inside the workspace, it is left
/// out of the copy, so an earlier edition is never copied into the next.
pub fn write(root: &Path, exercises: &[Exercise], out: &Path, force: bool) -> Result<usize> {
    let (root, out, leave_out) = copy_places(root, out)?;
    let edition = plan(&root, exercises, &leave_out)?;
    prepare_empty_dir(&out, force)?;
    write_files(&root, &out, &edition)?;
    Ok(edition.len())
}

/// Seals the reference solutions of `exercises`, read from the workbook at `root`, into the
/// edition at `out` (see [`crate::sealed_solutions`]); returns the sealed file's path.
pub fn seal_solutions(root: &Path, exercises: &[Exercise], out: &Path) -> Result<PathBuf> {
    use crate::sealed_solutions::{SEALED_PATH, collect, seal};
    let sealed = seal(&collect(root, exercises)?)?;
    let path = out.join(SEALED_PATH);
    workspace::write_whole(&path, &sealed)?;
    Ok(path)
}

/// Writes a plain copy of the workspace's sources into `out`, solutions and all, replacing
/// what `out` held: where `check-exercises` tries the recorded wrong answers.
pub fn write_copy(root: &Path, out: &Path) -> Result<usize> {
    let (root, out, leave_out) = copy_places(root, out)?;
    let files: Vec<EditionFile> = workspace::source_files(&root)?
        .into_iter()
        .filter(|file| !leave_out.iter().any(|dir| file.starts_with(dir)))
        .map(EditionFile::Copy)
        .collect();
    prepare_empty_dir(&out, true)?;
    write_files(&root, &out, &files)?;
    Ok(files.len())
}

/// The workspace and the copy's directory as absolute paths, and what of the workspace the
/// copy must leave out: the copy itself, when it lies inside. A copy that is the workspace, or
/// contains it, is refused.
fn copy_places(root: &Path, out: &Path) -> Result<(PathBuf, PathBuf, Vec<PathBuf>)> {
    let out = absolute(out)?;
    let root = absolute(root)?;
    if root.starts_with(&out) {
        bail!(
            "{} is the workspace or contains it; choose another directory",
            out.display()
        );
    }
    let leave_out = out
        .strip_prefix(&root)
        .map(Path::to_path_buf)
        .into_iter()
        .collect();
    Ok((root, out, leave_out))
}

/// Writes `files` of the workspace at `root` into `out`. A file copied as it is keeps its
/// modification time: a build directory shared with the workspace then finds a crate copied
/// whole (`common`) as fresh as the workspace's build of it, instead of compiling it again.
fn write_files(root: &Path, out: &Path, files: &[EditionFile]) -> Result<()> {
    for file in files {
        let destination = out.join(file.path());
        if let Some(parent) = destination.parent() {
            std::fs::create_dir_all(parent)
                .with_context(|| format!("cannot create {}", parent.display()))?;
        }
        match file {
            EditionFile::Copy(path) => copy_with_time(&root.join(path), &destination),
            EditionFile::Rewritten(_, text) => std::fs::write(&destination, text),
        }
        .with_context(|| format!("cannot write {}", destination.display()))?;
    }
    Ok(())
}

/// Copies `from` to `to` with its modification time.
fn copy_with_time(from: &Path, to: &Path) -> std::io::Result<()> {
    std::fs::copy(from, to)?;
    let modified = std::fs::metadata(from)?.modified()?;
    std::fs::File::options()
        .write(true)
        .open(to)?
        .set_modified(modified)
}

fn prepare_empty_dir(out: &Path, force: bool) -> Result<()> {
    let holds_something = match std::fs::read_dir(out) {
        Ok(mut entries) => entries.next().is_some(),
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => false,
        Err(error) => {
            return Err(error).with_context(|| format!("cannot look into {}", out.display()));
        }
    };
    if holds_something {
        if !force {
            bail!(
                "{} is not empty; pass --force to replace what it holds",
                out.display()
            );
        }
        std::fs::remove_dir_all(out).with_context(|| format!("cannot empty {}", out.display()))?;
    }
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))
}

fn absolute(path: &Path) -> Result<PathBuf> {
    std::path::absolute(path).with_context(|| format!("cannot resolve {}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exercise_list;

    const OPTICS: &str = "// ANCHOR: reflect\npub fn reflect(x: f32) -> f32 {\n    // BEGIN SOLUTION\n    -x\n    // END SOLUTION\n}\n// ANCHOR_END: reflect\n";
    const LIST: &str = "[[exercise]]\nname = \"ch01-reflect\"\nchapter = \"ch01-whitted\"\nfile = \"src/optics.rs\"\nanchor = \"reflect\"\ncheck = \"true\"\nhint = \"Flip the sign.\"\n";

    fn workspace(files: &[(&str, &str)]) -> tempfile::TempDir {
        let dir = tempfile::tempdir().unwrap();
        for (path, text) in files {
            let path = dir.path().join(path);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, text).unwrap();
        }
        dir
    }

    #[test]
    fn writes_stubs_and_copies_the_rest() {
        let ws = workspace(&[("src/optics.rs", OPTICS), ("README.md", "hi\n")]);
        let exercises = exercise_list::parse(LIST).unwrap();
        let out = tempfile::tempdir().unwrap();
        let written = write(ws.path(), &exercises, out.path(), false).unwrap();
        // The two files, and the package's build script with its note on the first build.
        assert_eq!(written, 3);
        let note = std::fs::read_to_string(out.path().join("build.rs")).unwrap();
        assert!(
            note.contains("compiling {package} for the first time"),
            "{note}"
        );
        assert!(!note.contains("cargo::warning"), "{note}");
        let stubbed = std::fs::read_to_string(out.path().join("src/optics.rs")).unwrap();
        assert!(
            stubbed.contains(
                "{\n    let _ = &x; // the inputs, until your code uses them\n    ::common::exercise::todo(\"ch01-reflect: Flip the sign.\")\n}"
            ),
            "{stubbed}"
        );
        assert_eq!(
            std::fs::read_to_string(out.path().join("README.md")).unwrap(),
            "hi\n"
        );
    }

    #[test]
    fn the_student_gets_their_own_readme_and_a_builder_without_the_chapters() {
        let manifest = "[features]\ndefault = [\"figures\"]\nfigures = [\"dep:ch01\"]\n";
        let ws = workspace(&[
            ("src/optics.rs", OPTICS),
            ("README.md", "For maintainers\n"),
            (STUDENT_README, "For students\n"),
            (BOOK_MANIFEST, manifest),
        ]);
        let exercises = exercise_list::parse(LIST).unwrap();
        let out = tempfile::tempdir().unwrap();
        write(ws.path(), &exercises, out.path(), true).unwrap();
        let read = |path: &str| std::fs::read_to_string(out.path().join(path)).unwrap();
        assert_eq!(read("README.md"), "For students\n");
        assert!(!out.path().join(STUDENT_README).exists());
        let student_manifest = read(BOOK_MANIFEST);
        assert!(
            student_manifest.contains("\ndefault = []\n"),
            "{student_manifest}"
        );
        assert!(student_manifest.contains("figures = [\"dep:ch01\"]"));
        let parsed: toml::Table = toml::from_str(&student_manifest).unwrap();
        assert_eq!(
            parsed["features"]["default"].as_array().map(Vec::len),
            Some(0)
        );
        // A manifest without the line is an error, not a silent copy.
        assert!(without_default_figures("[features]\n").is_err());
    }

    #[test]
    fn refuses_a_non_empty_directory_without_force() {
        let ws = workspace(&[("src/optics.rs", OPTICS)]);
        let exercises = exercise_list::parse(LIST).unwrap();
        let out = workspace(&[("old.txt", "")]);
        let error = write(ws.path(), &exercises, out.path(), false).unwrap_err();
        assert!(error.to_string().contains("not empty"), "{error}");
        write(ws.path(), &exercises, out.path(), true).unwrap();
        assert!(!out.path().join("old.txt").exists());
    }

    #[test]
    fn refuses_to_replace_the_workspace() {
        let ws = workspace(&[("src/optics.rs", OPTICS)]);
        let error = write(ws.path(), &[], ws.path(), true).unwrap_err();
        assert!(error.to_string().contains("contains it"), "{error}");
        assert!(ws.path().join("src/optics.rs").exists());
    }

    #[test]
    fn reports_markers_in_unlisted_files() {
        let ws = workspace(&[("src/optics.rs", OPTICS)]);
        let error = plan(ws.path(), &[], &[]).err().unwrap();
        let message = error.to_string();
        assert!(message.contains("2 problem(s)"), "{message}");
        assert!(
            message.contains("src/optics.rs: `// BEGIN SOLUTION` on line 3"),
            "{message}"
        );
    }

    #[test]
    fn leaves_out_an_edition_inside_the_workspace() {
        let ws = workspace(&[("src/lib.rs", ""), ("student/src/lib.rs", "")]);
        let edition = plan(ws.path(), &[], &[PathBuf::from("student")]).unwrap();
        let paths: Vec<&Path> = edition.iter().map(EditionFile::path).collect();
        assert_eq!(paths, [Path::new("src/lib.rs")]);
    }

    #[test]
    fn the_students_list_keeps_its_exercises_but_not_their_wrong_answers_or_giveaways() {
        let list = format!(
            "{LIST}\n[[exercise.wrong]]\nmistake = \"no sign change\"\ncode = \"\"\"\nx\n\"\"\"\nsays = \"flip\"\n\n\
             [[exercise.giveaway]]\nwritten = 'u - 3 (u \\cdot v) w'\n\n{}",
            LIST.replace("ch01-reflect", "ch01-other")
        );
        assert_eq!(exercise_list::parse(&list).unwrap()[0].giveaway.len(), 1);
        let stripped = without_wrong_answers(&list).unwrap();
        assert!(!stripped.contains("no sign change"), "{stripped}");
        assert!(!stripped.contains("cdot"), "{stripped}");
        let exercises = exercise_list::parse(&stripped).unwrap();
        assert_eq!(exercises.len(), 2);
        assert!(exercises.iter().all(|exercise| exercise.wrong.is_empty()));
        assert!(
            exercises
                .iter()
                .all(|exercise| exercise.giveaway.is_empty())
        );
    }
}
