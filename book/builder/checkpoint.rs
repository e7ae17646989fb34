//! `checkpoint NAME --from PATH`: puts the reference solution of one exercise back into the
//! student's copy, so that a student stuck on it can go on to the next.
//!
//! The student's own attempt is not lost: the lines it replaces are saved first, under
//! `target/checkpoints/`, and the command says where.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::exercise_list::{self, Exercise, LIST_PATH};
use crate::solution_markers::{self, Marker};
use crate::workspace;

/// What the checkpoint did, for the student.
#[derive(Debug)]
pub struct Restored {
    /// The file that now holds the reference solution, relative to the student's workspace.
    pub file: PathBuf,
    /// Where the student's own version of the exercise was saved.
    pub saved: PathBuf,
}

/// Puts the reference solution of exercise `name`, read from the workbook at `workbook`, into
/// the student's workspace at `root`.
pub fn run(root: &Path, exercises: &[Exercise], name: &str, workbook: &Path) -> Result<Restored> {
    let exercise = exercises.iter().find(|e| e.name == name).with_context(|| {
        format!("there is no exercise `{name}` in {LIST_PATH} (`cargo run -p book -- exercises` lists them)")
    })?;
    let reference = reference_lines(workbook, exercise)?;

    let path = root.join(&exercise.file);
    let source = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", exercise.file.display()))?;
    let lines: Vec<&str> = source.lines().collect();
    let body = solution_markers::anchor_body(&lines, &exercise.anchor).with_context(|| {
        format!(
            "{} has lost the comment lines `// ANCHOR: {anchor}` and `// ANCHOR_END: {anchor}` \
             around the exercise, so it cannot tell which lines to replace; put them back, or \
             copy the function by hand from {}",
            exercise.file.display(),
            workbook.join(&exercise.file).display(),
            anchor = exercise.anchor
        )
    })?;
    if lines[body.clone()]
        .iter()
        .any(|line| Marker::of_line(line).is_some())
    {
        bail!(
            "`{name}` in {} still has its solution markers: this is the workbook, not a student \
             edition, and the exercise is solved already",
            exercise.file.display()
        );
    }

    // The student's attempt first, so nothing is lost even if the next write fails.
    let saved_dir = workspace::target_dir(root).join("checkpoints");
    std::fs::create_dir_all(&saved_dir)
        .with_context(|| format!("cannot create {}", saved_dir.display()))?;
    let saved = saved_dir.join(format!("{name}.rs"));
    let mut attempt = lines[body.clone()].join("\n");
    attempt.push('\n');
    std::fs::write(&saved, attempt).with_context(|| format!("cannot write {}", saved.display()))?;

    let mut out: Vec<&str> = lines[..body.start].to_vec();
    out.extend(reference.iter().map(String::as_str));
    out.extend(&lines[body.end..]);
    let mut text = out.join("\n");
    if source.ends_with('\n') {
        text.push('\n');
    }
    write_whole(&path, &text)?;
    Ok(Restored {
        file: exercise.file.clone(),
        saved,
    })
}

/// The reference solution of `exercise` as the workbook at `workbook` has it: the lines inside
/// its anchor, without the solution markers.
fn reference_lines(workbook: &Path, exercise: &Exercise) -> Result<Vec<String>> {
    let list = exercise_list::load(workbook).with_context(|| {
        format!(
            "--from {}: this is not the workbook (the repository with the solutions)",
            workbook.display()
        )
    })?;
    if exercise_list::is_student_edition(workbook, &list) {
        bail!(
            "--from {}: this is a student edition, which holds no solutions; give the path of \
             the workbook itself",
            workbook.display()
        );
    }
    let reference = list
        .iter()
        .find(|e| e.name == exercise.name)
        .with_context(|| {
            format!(
                "--from {}: the workbook there has no exercise `{}` (is it another version of the \
                 workbook?)",
                workbook.display(),
                exercise.name
            )
        })?;
    let path = workbook.join(&reference.file);
    let source = std::fs::read_to_string(&path)
        .with_context(|| format!("cannot read {}", path.display()))?;
    let lines: Vec<&str> = source.lines().collect();
    solution_markers::locate(&lines, &reference.anchor)
        .with_context(|| format!("{}: exercise `{}`", path.display(), exercise.name))?;
    let body = solution_markers::anchor_body(&lines, &reference.anchor)?;
    Ok(lines[body]
        .iter()
        .filter(|line| Marker::of_line(line).is_none())
        .map(|line| (*line).to_owned())
        .collect())
}

/// Writes `text` to `path` whole or not at all: into a file beside it, then renamed over it.
fn write_whole(path: &Path, text: &str) -> Result<()> {
    let temporary = path.with_extension("rs.checkpoint");
    std::fs::write(&temporary, text)
        .with_context(|| format!("cannot write {}", temporary.display()))?;
    std::fs::rename(&temporary, path).with_context(|| format!("cannot replace {}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    // Built from escaped strings so that no marker sits at the start of a line of this file.
    const SOLVED: &str = "use x::Y;\n\n// ANCHOR: reflect\npub fn reflect(d: f32) -> f32 {\n    // BEGIN SOLUTION\n    -d\n    // END SOLUTION\n}\n// ANCHOR_END: reflect\n";
    const STUB: &str = "use x::Y;\n\n// ANCHOR: reflect\npub fn reflect(d: f32) -> f32 {\n    let _ = &d; // mine\n    todo!(\"ch01-reflect: hint\")\n}\n// ANCHOR_END: reflect\n";
    const LIST: &str = "[[exercise]]\nname = \"ch01-reflect\"\nchapter = \"ch01-whitted\"\nfile = \"src/optics.rs\"\nanchor = \"reflect\"\ncheck = \"true\"\nhint = \"hint\"\n";

    fn workspace(source: &str) -> tempfile::TempDir {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(dir.path().join("src")).unwrap();
        std::fs::create_dir_all(dir.path().join("book")).unwrap();
        std::fs::write(dir.path().join("src/optics.rs"), source).unwrap();
        std::fs::write(dir.path().join(LIST_PATH), LIST).unwrap();
        dir
    }

    #[test]
    fn the_reference_solution_replaces_the_stub_and_the_attempt_is_kept() {
        let workbook = workspace(SOLVED);
        let student = workspace(STUB);
        let exercises = exercise_list::load(student.path()).unwrap();
        let restored = run(student.path(), &exercises, "ch01-reflect", workbook.path()).unwrap();
        let now = std::fs::read_to_string(student.path().join(&restored.file)).unwrap();
        assert_eq!(
            now,
            "use x::Y;\n\n// ANCHOR: reflect\npub fn reflect(d: f32) -> f32 {\n    -d\n}\n// ANCHOR_END: reflect\n"
        );
        let kept = std::fs::read_to_string(&restored.saved).unwrap();
        assert!(kept.contains("// mine"), "{kept}");
        // The list still reads as a student edition's.
        assert!(exercise_list::is_student_edition(
            student.path(),
            &exercises
        ));
    }

    #[test]
    fn a_student_edition_is_no_workbook_and_the_workbook_is_no_student() {
        let student = workspace(STUB);
        let other = workspace(STUB);
        let exercises = exercise_list::load(student.path()).unwrap();
        let error = run(student.path(), &exercises, "ch01-reflect", other.path()).unwrap_err();
        assert!(
            format!("{error:#}").contains("holds no solutions"),
            "{error:#}"
        );

        let workbook = workspace(SOLVED);
        let error = run(workbook.path(), &exercises, "ch01-reflect", workbook.path()).unwrap_err();
        assert!(format!("{error:#}").contains("solved already"), "{error:#}");

        let error = run(student.path(), &exercises, "ch01-nothing", workbook.path()).unwrap_err();
        assert!(
            format!("{error:#}").contains("no exercise `ch01-nothing`"),
            "{error:#}"
        );
        let nowhere = student.path().join("no-such-dir");
        let error = run(student.path(), &exercises, "ch01-reflect", &nowhere).unwrap_err();
        assert!(
            format!("{error:#}").contains("not the workbook"),
            "{error:#}"
        );
    }

    #[test]
    fn lost_anchor_lines_are_named() {
        let workbook = workspace(SOLVED);
        let student = workspace(STUB);
        let exercises = exercise_list::load(student.path()).unwrap();
        std::fs::write(
            student.path().join("src/optics.rs"),
            "pub fn reflect(d: f32) -> f32 {\n    d\n}\n",
        )
        .unwrap();
        let error = run(student.path(), &exercises, "ch01-reflect", workbook.path()).unwrap_err();
        assert!(
            format!("{error:#}").contains("ANCHOR: reflect"),
            "{error:#}"
        );
    }
}
