//! `checkpoint`: puts reference solutions back into the student's copy, so that a student stuck
//! on an exercise, or skipping a chapter, can go on.
//!
//! - `checkpoint NAME`: one exercise, whatever it holds now;
//! - `checkpoint CHAPTER` (`ch04-depth-of-field` or `ch04`): every exercise of the chapter that
//!   is still a stub;
//! - `checkpoint --needs NAME`: every exercise whose code NAME's check runs (its `needs` in the
//!   list) that is still a stub, so that the check runs the student's own answer and nothing
//!   not written yet.
//!
//! The reference solutions come from the edition's own sealed solutions when the teacher handed
//! it out with them ([`crate::sealed_solutions`]), or from the workbook given with
//! `--from WORKBOOK`.
//!
//! An exercise the student has written is kept in the last two cases (the command names it, and
//! `checkpoint NAME` replaces it). The student's own attempt is never lost: the lines it
//! replaces are saved first, under `target/checkpoints/`, and the command says where. Nothing
//! here compiles anything: the tools read and write source files only.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::exercise_list::{self, Exercise, LIST_PATH};
use crate::sealed_solutions::{self, References};
use crate::solution_markers::{self, Marker};
use crate::workspace;

/// Where the reference solutions come from.
pub enum Source {
    /// The workbook (the repository with the solutions) at this path, with its exercise list.
    Workbook(PathBuf, Vec<Exercise>),
    /// The sealed solutions the edition was handed out with.
    Sealed(References),
}

impl Source {
    /// The workbook at `workbook`; an error unless it is one (with solutions).
    pub fn workbook(workbook: &Path) -> Result<Self> {
        Ok(Source::Workbook(
            workbook.to_owned(),
            workbook_exercises(workbook)?,
        ))
    }

    /// The sealed solutions of the edition at `root`; an error saying what to do when the
    /// edition was handed out without them.
    pub fn sealed(root: &Path) -> Result<Self> {
        match sealed_solutions::read(root)? {
            Some(references) => Ok(Source::Sealed(references)),
            None => bail!(
                "this edition was handed out without its solutions ({} is missing): ask your \
                 teacher for the workbook and give its path with `--from PATH`",
                sealed_solutions::SEALED_PATH
            ),
        }
    }

    /// Where a student can copy an exercise from by hand, in words.
    fn describe(&self, exercise: &Exercise) -> String {
        match self {
            Source::Workbook(workbook, _) => workbook.join(&exercise.file).display().to_string(),
            Source::Sealed(_) => "the solution on the exercise's page of the site".to_owned(),
        }
    }

    /// The reference lines of `exercise`.
    fn reference(&self, exercise: &Exercise) -> Result<Vec<String>> {
        match self {
            Source::Workbook(workbook, list) => reference_lines(workbook, list, exercise),
            Source::Sealed(references) => references.get(&exercise.name).cloned().with_context(|| {
                format!(
                    "the sealed solutions have no exercise `{}`: they belong to another version \
                     of the workbook than this edition's list",
                    exercise.name
                )
            }),
        }
    }
}

/// What to put back.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// One exercise, by name.
    Exercise(String),
    /// The stubs of one chapter, by package name.
    Chapter(String),
    /// The stubs among what one exercise's check runs.
    NeedsOf(String),
}

impl Target {
    /// What `NAME` means: an exercise, else a chapter (by package name or by its `chNN`
    /// prefix), else an error listing what it could have been.
    pub fn named(name: &str, exercises: &[Exercise]) -> Result<Self> {
        if exercises.iter().any(|e| e.name == name) {
            return Ok(Target::Exercise(name.to_owned()));
        }
        let chapter = exercises
            .iter()
            .map(|e| e.chapter.as_str())
            .find(|chapter| *chapter == name || chapter.split('-').next() == Some(name));
        match chapter {
            Some(chapter) => Ok(Target::Chapter(chapter.to_owned())),
            None => bail!(
                "there is no exercise or chapter `{name}` in {LIST_PATH} (`cargo run -p book -- \
                 exercises` lists them; a chapter is named like `ch04-depth-of-field` or `ch04`)"
            ),
        }
    }
}

/// One exercise whose reference solution was put in.
#[derive(Debug)]
pub struct Restored {
    /// The exercise's name.
    pub name: String,
    /// The file that now holds the reference solution, relative to the student's workspace.
    pub file: PathBuf,
    /// Where the student's own version of the exercise was saved.
    pub saved: PathBuf,
}

/// What a checkpoint did, for the student.
#[derive(Debug, Default)]
pub struct Outcome {
    /// The exercises put in, in the list's order.
    pub restored: Vec<Restored>,
    /// Exercises left as the student wrote them (not stubs), by name.
    pub kept: Vec<String>,
    /// Exercises that already held the reference solution, by name.
    pub already: Vec<String>,
}

/// Puts in the reference solutions `target` asks for, read from `source`, in the student's
/// workspace at `root`.
pub fn run(
    root: &Path,
    exercises: &[Exercise],
    target: &Target,
    source: &Source,
) -> Result<Outcome> {
    let mut outcome = Outcome::default();
    let chosen: Vec<&Exercise> = match target {
        Target::Exercise(name) => vec![find(exercises, name)?],
        Target::Chapter(chapter) => exercises.iter().filter(|e| &e.chapter == chapter).collect(),
        Target::NeedsOf(name) => {
            let exercise = find(exercises, name)?;
            exercise
                .needs
                .iter()
                .map(|need| find(exercises, need))
                .collect::<Result<_>>()?
        }
    };
    let only_stubs = !matches!(target, Target::Exercise(_));
    for exercise in chosen {
        let reference = source.reference(exercise)?;
        let path = root.join(&exercise.file);
        let text = std::fs::read_to_string(&path)
            .with_context(|| format!("cannot read {}", exercise.file.display()))?;
        let body = body_lines(&text, exercise, source)?;
        if body == reference {
            outcome.already.push(exercise.name.clone());
            continue;
        }
        if only_stubs && !is_stub(&body, exercise) {
            outcome.kept.push(exercise.name.clone());
            continue;
        }
        let saved = put_in(root, &path, &text, exercise, &reference)?;
        outcome.restored.push(Restored {
            name: exercise.name.clone(),
            file: exercise.file.clone(),
            saved,
        });
    }
    Ok(outcome)
}

fn find<'e>(exercises: &'e [Exercise], name: &str) -> Result<&'e Exercise> {
    exercises.iter().find(|e| e.name == name).with_context(|| {
        format!(
            "there is no exercise `{name}` in {LIST_PATH} (`cargo run -p book -- exercises` lists \
             them)"
        )
    })
}

/// Whether the anchor body `body` still holds the student edition's stub of `exercise`: a call
/// of `exercise::todo` naming it (or the `todo!` an older edition had), even if the student has
/// started writing around it.
pub fn is_stub(body: &[String], exercise: &Exercise) -> bool {
    let stub = format!("exercise::todo(\"{}", exercise.name);
    let old_stub = format!("todo!(\"{}", exercise.name);
    body.iter()
        .any(|line| line.contains(&stub) || line.contains(&old_stub))
}

/// The lines of `exercise`'s anchor in `source`, without the anchor comments.
fn body_lines(source: &str, exercise: &Exercise, from: &Source) -> Result<Vec<String>> {
    let lines: Vec<&str> = source.lines().collect();
    let body = solution_markers::anchor_body(&lines, &exercise.anchor).with_context(|| {
        format!(
            "{} has lost the comment lines `// ANCHOR: {anchor}` and `// ANCHOR_END: {anchor}` \
             around the exercise, so it cannot tell which lines to replace; put them back, or \
             copy the function by hand from {}",
            exercise.file.display(),
            from.describe(exercise),
            anchor = exercise.anchor
        )
    })?;
    if lines[body.clone()]
        .iter()
        .any(|line| Marker::of_line(line).is_some())
    {
        bail!(
            "`{}` in {} still has its solution markers: this is the workbook, not a student \
             edition, and the exercise is solved already",
            exercise.name,
            exercise.file.display()
        );
    }
    Ok(lines[body].iter().map(|line| (*line).to_owned()).collect())
}

/// Saves the student's lines of `exercise` under `target/checkpoints/`, then writes `source`
/// with the `reference` lines in their place; returns where the student's lines are.
fn put_in(
    root: &Path,
    path: &Path,
    source: &str,
    exercise: &Exercise,
    reference: &[String],
) -> Result<PathBuf> {
    let lines: Vec<&str> = source.lines().collect();
    let body = solution_markers::anchor_body(&lines, &exercise.anchor)?;
    // The student's attempt first, so nothing is lost even if the next write fails.
    let saved_dir = workspace::target_dir(root).join("checkpoints");
    std::fs::create_dir_all(&saved_dir)
        .with_context(|| format!("cannot create {}", saved_dir.display()))?;
    let saved = saved_dir.join(format!("{}.rs", exercise.name));
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
    crate::workspace::write_whole(path, &text)?;
    Ok(saved)
}

/// The workbook's exercise list; an error unless `workbook` is a workbook (with solutions).
fn workbook_exercises(workbook: &Path) -> Result<Vec<Exercise>> {
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
    Ok(list)
}

/// The reference solution of `exercise` as the workbook at `workbook` (whose list is `list`)
/// has it: the lines inside its anchor, without the solution markers.
fn reference_lines(workbook: &Path, list: &[Exercise], exercise: &Exercise) -> Result<Vec<String>> {
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
    sealed_solutions::reference_lines(&source, &reference.anchor)
        .with_context(|| format!("{}: exercise `{}`", path.display(), exercise.name))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`run`] with the reference solutions of the workbook at `workbook`.
    fn run_from(
        root: &Path,
        exercises: &[Exercise],
        target: &Target,
        workbook: &Path,
    ) -> Result<Outcome> {
        run(root, exercises, target, &Source::workbook(workbook)?)
    }

    /// A file with one exercise `name` whose body is `body`, built from escaped strings so that
    /// no marker sits at the start of a line of this file.
    fn source(name: &str, body: &str) -> String {
        format!(
            "use x::Y;\n\n// ANCHOR: {name}\npub fn {name}(d: f32) -> f32 {{\n{body}}}\n// ANCHOR_END: {name}\n"
        )
    }
    fn solved(name: &str) -> String {
        source(name, "    // BEGIN SOLUTION\n    -d\n    // END SOLUTION\n")
    }
    fn stub(name: &str) -> String {
        source(
            name,
            &format!("    let _ = &d; // mine\n    ::common::exercise::todo(\"{name}: hint\")\n"),
        )
    }
    fn entry(name: &str, chapter: &str, needs: &[&str]) -> String {
        let needs: Vec<String> = needs.iter().map(|n| format!("{n:?}")).collect();
        format!(
            "[[exercise]]\nname = \"{name}\"\nchapter = \"{chapter}\"\nfile = \"src/{name}.rs\"\n\
             anchor = \"{name}\"\ncheck = \"true\"\nneeds = [{}]\nhint = \"hint\"\n",
            needs.join(", ")
        )
    }

    /// Exercises `a` and `b` of chapter `ch01-one`, `c` of `ch02-two` needing both; each file
    /// solved or a stub as `solved` says.
    fn workspace(solved_ones: &[&str]) -> tempfile::TempDir {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(dir.path().join("src")).unwrap();
        std::fs::create_dir_all(dir.path().join("book")).unwrap();
        for name in ["a", "b", "c"] {
            let text = if solved_ones.contains(&name) {
                solved(name)
            } else {
                stub(name)
            };
            std::fs::write(dir.path().join(format!("src/{name}.rs")), text).unwrap();
        }
        let list = [
            entry("a", "ch01-one", &[]),
            entry("b", "ch01-one", &[]),
            entry("c", "ch02-two", &["a", "b"]),
        ]
        .join("\n");
        std::fs::write(dir.path().join(LIST_PATH), list).unwrap();
        dir
    }

    fn read(dir: &tempfile::TempDir, name: &str) -> String {
        std::fs::read_to_string(dir.path().join(format!("src/{name}.rs"))).unwrap()
    }

    fn names(restored: &[Restored]) -> Vec<&str> {
        restored.iter().map(|r| r.name.as_str()).collect()
    }

    #[test]
    fn the_reference_solution_replaces_the_stub_and_the_attempt_is_kept() {
        let workbook = workspace(&["a", "b", "c"]);
        let student = workspace(&[]);
        let exercises = exercise_list::load(student.path()).unwrap();
        let target = Target::named("a", &exercises).unwrap();
        let outcome = run_from(student.path(), &exercises, &target, workbook.path()).unwrap();
        assert_eq!(names(&outcome.restored), ["a"]);
        assert_eq!(
            read(&student, "a"),
            "use x::Y;\n\n// ANCHOR: a\npub fn a(d: f32) -> f32 {\n    -d\n}\n// ANCHOR_END: a\n"
        );
        let kept = std::fs::read_to_string(&outcome.restored[0].saved).unwrap();
        assert!(kept.contains("// mine"), "{kept}");
        // The list still reads as a student edition's.
        assert!(exercise_list::is_student_edition(
            student.path(),
            &exercises[1..]
        ));
        // Again: nothing to do, and the student's saved attempt is not overwritten.
        let again = run_from(student.path(), &exercises, &target, workbook.path()).unwrap();
        assert!(again.restored.is_empty());
        assert_eq!(again.already, ["a"]);
        let still = std::fs::read_to_string(&outcome.restored[0].saved).unwrap();
        assert!(still.contains("// mine"), "{still}");
    }

    #[test]
    fn a_chapter_puts_in_its_stubs_and_keeps_what_the_student_wrote() {
        let workbook = workspace(&["a", "b", "c"]);
        let student = workspace(&[]);
        let written = source("b", "    d * 2.0\n");
        std::fs::write(student.path().join("src/b.rs"), &written).unwrap();
        let exercises = exercise_list::load(student.path()).unwrap();
        for name in ["ch01-one", "ch01"] {
            assert_eq!(
                Target::named(name, &exercises).unwrap(),
                Target::Chapter("ch01-one".into())
            );
        }
        let target = Target::named("ch01", &exercises).unwrap();
        let outcome = run_from(student.path(), &exercises, &target, workbook.path()).unwrap();
        assert_eq!(names(&outcome.restored), ["a"]);
        assert_eq!(outcome.kept, ["b"]);
        assert_eq!(read(&student, "b"), written);
        assert!(read(&student, "c").contains("exercise::todo(\"c: hint\")"));
    }

    #[test]
    fn the_needs_of_a_check_are_put_in_but_not_its_own_exercise() {
        let workbook = workspace(&["a", "b", "c"]);
        let student = workspace(&[]);
        let exercises = exercise_list::load(student.path()).unwrap();
        let target = Target::NeedsOf("c".into());
        let outcome = run_from(student.path(), &exercises, &target, workbook.path()).unwrap();
        assert_eq!(names(&outcome.restored), ["a", "b"]);
        assert!(read(&student, "a").contains("    -d\n"));
        assert!(read(&student, "c").contains("exercise::todo(\"c: hint\")"));
        let error = Target::named("ch09", &exercises).unwrap_err();
        assert!(
            format!("{error:#}").contains("no exercise or chapter `ch09`"),
            "{error:#}"
        );
    }

    #[test]
    fn a_student_edition_is_no_workbook_and_the_workbook_is_no_student() {
        let student = workspace(&[]);
        let other = workspace(&[]);
        let exercises = exercise_list::load(student.path()).unwrap();
        let a = Target::Exercise("a".into());
        let error = run_from(student.path(), &exercises, &a, other.path()).unwrap_err();
        assert!(
            format!("{error:#}").contains("holds no solutions"),
            "{error:#}"
        );

        let workbook = workspace(&["a", "b", "c"]);
        let error = run_from(workbook.path(), &exercises, &a, workbook.path()).unwrap_err();
        assert!(format!("{error:#}").contains("solved already"), "{error:#}");

        let nothing = Target::Exercise("ch01-nothing".into());
        let error = run_from(student.path(), &exercises, &nothing, workbook.path()).unwrap_err();
        assert!(
            format!("{error:#}").contains("no exercise `ch01-nothing`"),
            "{error:#}"
        );
        let nowhere = student.path().join("no-such-dir");
        let error = run_from(student.path(), &exercises, &a, &nowhere).unwrap_err();
        assert!(
            format!("{error:#}").contains("not the workbook"),
            "{error:#}"
        );
    }

    #[test]
    fn sealed_solutions_put_in_what_the_workbook_would() {
        let workbook = workspace(&["a", "b", "c"]);
        let workbook_list = exercise_list::load(workbook.path()).unwrap();
        let sealed = sealed_solutions::seal(
            &sealed_solutions::collect(workbook.path(), &workbook_list).unwrap(),
        )
        .unwrap();
        let from_workbook = workspace(&[]);
        let from_seal = workspace(&[]);
        let exercises = exercise_list::load(from_seal.path()).unwrap();
        let chapter = Target::named("ch01", &exercises).unwrap();

        let error = Source::sealed(from_seal.path()).err().unwrap();
        assert!(
            format!("{error:#}").contains("handed out without its solutions"),
            "{error:#}"
        );
        let path = from_seal.path().join(sealed_solutions::SEALED_PATH);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, sealed).unwrap();
        let source = Source::sealed(from_seal.path()).unwrap();

        let outcome = run(from_seal.path(), &exercises, &chapter, &source).unwrap();
        run_from(from_workbook.path(), &exercises, &chapter, workbook.path()).unwrap();
        assert_eq!(names(&outcome.restored), ["a", "b"]);
        for file in ["src/a.rs", "src/b.rs", "src/c.rs"] {
            let read = |root: &Path| std::fs::read_to_string(root.join(file)).unwrap();
            assert_eq!(read(from_seal.path()), read(from_workbook.path()), "{file}");
        }
    }

    #[test]
    fn lost_anchor_lines_are_named() {
        let workbook = workspace(&["a", "b", "c"]);
        let student = workspace(&[]);
        let exercises = exercise_list::load(student.path()).unwrap();
        std::fs::write(
            student.path().join("src/a.rs"),
            "pub fn a(d: f32) -> f32 {\n    d\n}\n",
        )
        .unwrap();
        let error = run_from(
            student.path(),
            &exercises,
            &Target::Exercise("a".into()),
            workbook.path(),
        )
        .unwrap_err();
        assert!(format!("{error:#}").contains("ANCHOR: a"), "{error:#}");
    }

    #[test]
    fn a_stub_is_told_from_an_answer() {
        let exercises = exercise_list::parse(&entry("ch01-reflect", "c", &[])).unwrap();
        let lines = |text: &str| text.lines().map(str::to_owned).collect::<Vec<_>>();
        let exercise = &exercises[0];
        assert!(is_stub(
            &lines("    ::common::exercise::todo(\"ch01-reflect: hint\")"),
            exercise
        ));
        assert!(is_stub(
            &lines("let x = 1;\ncommon::exercise::todo(\"ch01-reflect\")"),
            exercise
        ));
        assert!(is_stub(
            &lines("    todo!(\"ch01-reflect: hint\")"),
            exercise
        ));
        assert!(!is_stub(&lines("    u - 3.0 * u.dot(v) * w"), exercise));
        assert!(!is_stub(&lines("    todo!()"), exercise));
    }
}
