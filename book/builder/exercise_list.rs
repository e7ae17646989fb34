//! The ordered list of exercises, `book/exercises.toml`, and the checks that keep it honest.
//!
//! The list is the single place that says which anchors are exercises, in which order students
//! meet them, and which one command proves an exercise solved. Every tool in this package reads
//! it through [`load`], which refuses a list with a broken entry: a wrong path or anchor would
//! otherwise surface much later, as a solution leaking into the student edition or a check that
//! can never pass.

use std::collections::HashMap;
use std::path::{Component, Path, PathBuf};

use anyhow::{Context, Result, bail};
use serde::Deserialize;

use crate::solution_markers::{self, MarkerError};

/// Where the list lives, relative to the workspace root.
pub const LIST_PATH: &str = "book/exercises.toml";

/// One exercise, as written in the list.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Exercise {
    /// Unique name, chapter first: `ch01-reflect`.
    pub name: String,
    /// The package the exercise belongs to: `ch01-whitted`.
    pub chapter: String,
    /// The source file holding it, relative to the workspace root.
    pub file: PathBuf,
    /// The mdBook anchor around it in that file.
    pub anchor: String,
    /// The one shell command, run from the workspace root, that passes once it is solved.
    pub check: String,
    /// A nudge for the stuck. Its first line doubles as the message of the student's stub.
    pub hint: String,
    /// The other exercises whose code the check runs, in the list's order: the check cannot
    /// pass until they are written too. `check-exercises` measures the set and refuses a list
    /// that says otherwise, so the student can trust it (`exercises` and `progress` show it,
    /// `checkpoint --needs` puts them in).
    #[serde(default)]
    pub needs: Vec<String>,
    /// Plausible wrong answers, each of which the check must refuse with its own words.
    #[serde(default)]
    pub wrong: Vec<WrongAnswer>,
    /// The solution's key expressions as a page might write them (a formula, inline code): no
    /// page may state one before the exercise (see `giveaways`).
    #[serde(default)]
    pub giveaway: Vec<Giveaway>,
}

/// A key expression of an exercise's solution, which no page may state before the exercise.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Giveaway {
    /// The expression as TeX or code: `u - 3 (u \cdot v) w`. Spaces, braces, `\mathbf` and
    /// the like do not matter (see `giveaways::normalized`).
    pub written: String,
}

/// A plausible wrong answer to an exercise: code that stands where the solution stands, and
/// the words the exercise's check must print when it refuses it (a check that fails without
/// saying what is wrong does not teach).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WrongAnswer {
    /// The mistake, in a few words: `r = u instead of sqrt(u)`.
    pub mistake: String,
    /// The code put in place of the solution region, indented as the region is.
    pub code: String,
    /// Words the failing check must print (case-insensitive).
    pub says: String,
}

impl Exercise {
    /// The message of the stub that replaces the solution in the student edition.
    pub fn todo_message(&self) -> String {
        match self
            .hint
            .lines()
            .map(str::trim)
            .find(|line| !line.is_empty())
        {
            Some(hint) => format!("{}: {hint}", self.name),
            None => self.name.clone(),
        }
    }
}

/// The file's shape: a sequence of `[[exercise]]` tables, possibly none.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ExerciseFile {
    #[serde(default, rename = "exercise")]
    exercises: Vec<Exercise>,
}

/// Reads and validates the workspace's exercise list, in order.
pub fn load(workspace: &Path) -> Result<Vec<Exercise>> {
    let path = workspace.join(LIST_PATH);
    let text =
        std::fs::read_to_string(&path).with_context(|| format!("cannot read {LIST_PATH}"))?;
    let exercises = parse(&text)?;
    let problems = validate(workspace, &exercises);
    if !problems.is_empty() {
        bail!(
            "{LIST_PATH} has {} problem(s):\n  {}",
            problems.len(),
            problems.join("\n  ")
        );
    }
    Ok(exercises)
}

/// Parses the list without looking at any source file.
pub fn parse(text: &str) -> Result<Vec<Exercise>> {
    let file: ExerciseFile =
        toml::from_str(text).with_context(|| format!("{LIST_PATH} is not valid"))?;
    Ok(file.exercises)
}

/// Every problem with the list, each naming its entry; empty if there are none.
pub fn validate(workspace: &Path, exercises: &[Exercise]) -> Vec<String> {
    let mut problems = Vec::new();
    let mut first_entry_named: HashMap<&str, usize> = HashMap::new();
    // Where an exercise's anchor has no solution region; in a student edition none has one.
    let mut without_solution: Vec<String> = Vec::new();

    for (index, exercise) in exercises.iter().enumerate() {
        let entry = index + 1;
        let label = format!("exercise #{entry} `{}`", exercise.name);
        let mut complain = |problem: String| problems.push(format!("{label}: {problem}"));

        for (field, value) in [
            ("name", &exercise.name),
            ("chapter", &exercise.chapter),
            ("anchor", &exercise.anchor),
            ("check", &exercise.check),
        ] {
            if value.trim().is_empty() {
                complain(format!("`{field}` is empty"));
            }
        }
        if let Some(first) = first_entry_named.insert(&exercise.name, entry) {
            complain(format!("the name is already used by exercise #{first}"));
        }

        if !is_inside_workspace(&exercise.file) {
            complain(format!(
                "`file` must be a relative path inside the workspace, not `{}`",
                exercise.file.display()
            ));
            continue;
        }
        let source = match std::fs::read_to_string(workspace.join(&exercise.file)) {
            Ok(source) => source,
            Err(error) => {
                complain(format!(
                    "cannot read `{}`: {error}",
                    exercise.file.display()
                ));
                continue;
            }
        };
        let lines: Vec<&str> = source.lines().collect();
        match solution_markers::locate(&lines, &exercise.anchor) {
            Ok(_) => {}
            Err(MarkerError::NoSolution { .. }) => without_solution.push(format!(
                "{label}: in `{}`, the anchor `{}` holds no solution region",
                exercise.file.display(),
                exercise.anchor
            )),
            Err(error) => complain(format!("in `{}`, {error}", exercise.file.display())),
        }
        for (position, need) in exercise.needs.iter().enumerate() {
            match exercises.iter().position(|other| &other.name == need) {
                None => complain(format!("`needs` names `{need}`, which is not listed")),
                Some(at) if at >= index => complain(format!(
                    "`needs` names `{need}`, which is not listed before it: the exercises must \
                     be doable in order"
                )),
                Some(_) if exercise.needs[..position].contains(need) => {
                    complain(format!("`needs` names `{need}` twice"))
                }
                Some(_) => {}
            }
        }
        for (number, wrong) in exercise.wrong.iter().enumerate() {
            for (field, value) in [
                ("mistake", &wrong.mistake),
                ("code", &wrong.code),
                ("says", &wrong.says),
            ] {
                if value.trim().is_empty() {
                    complain(format!("wrong answer #{}: `{field}` is empty", number + 1));
                }
            }
        }
    }
    // In a student edition every solution has been cut out (or written by the student).
    if without_solution.len() < exercises.len() {
        problems.extend(without_solution);
    }
    problems
}

/// How many lines the solution of `exercise` has (between its markers), in the workbook at
/// `root`.
pub fn solution_size(root: &Path, exercise: &Exercise) -> Result<usize> {
    let source = std::fs::read_to_string(root.join(&exercise.file))
        .with_context(|| format!("cannot read {}", exercise.file.display()))?;
    let lines = solution_markers::solution_lines(&source, &exercise.anchor)
        .with_context(|| format!("{}: {}", exercise.name, exercise.file.display()))?;
    Ok(lines.len())
}

/// One chapter's share of the exercises: how many, how many lines of solution, and its
/// largest exercise (the capstone, where the student writes the chapter's central routine).
#[derive(Debug)]
pub struct ChapterShare {
    pub chapter: String,
    pub exercises: usize,
    pub lines: usize,
    pub capstone: String,
    pub capstone_lines: usize,
}

/// Every chapter's share, in the list's order.
pub fn shares(root: &Path, exercises: &[Exercise]) -> Result<Vec<ChapterShare>> {
    let mut shares: Vec<ChapterShare> = Vec::new();
    for exercise in exercises {
        let lines = solution_size(root, exercise)?;
        let index = match shares.iter().position(|s| s.chapter == exercise.chapter) {
            Some(index) => index,
            None => {
                shares.push(ChapterShare {
                    chapter: exercise.chapter.clone(),
                    exercises: 0,
                    lines: 0,
                    capstone: String::new(),
                    capstone_lines: 0,
                });
                shares.len() - 1
            }
        };
        let share = &mut shares[index];
        share.exercises += 1;
        share.lines += lines;
        if lines > share.capstone_lines {
            share.capstone = exercise.name.clone();
            share.capstone_lines = lines;
        }
    }
    Ok(shares)
}

/// Whether the workspace at `root` is a student edition: no listed exercise has its solution
/// region (the workbook has every one).
pub fn is_student_edition(root: &Path, exercises: &[Exercise]) -> bool {
    !exercises.is_empty()
        && exercises.iter().all(|exercise| {
            std::fs::read_to_string(root.join(&exercise.file)).is_ok_and(|source| {
                let lines: Vec<&str> = source.lines().collect();
                matches!(
                    solution_markers::locate(&lines, &exercise.anchor),
                    Err(MarkerError::NoSolution { .. } | MarkerError::AnchorNotFound { .. })
                )
            })
        })
}

/// Whether the workspace at `root` is a student edition, by its own list: the workbook's own
/// tests that measure or guard the solutions have nothing to look at there.
#[cfg(test)]
pub fn holds_no_solutions(root: &Path) -> bool {
    load(root).is_ok_and(|exercises| is_student_edition(root, &exercises))
}

/// Whether `path` is relative and never climbs out with `..`.
fn is_inside_workspace(path: &Path) -> bool {
    path.components().all(|c| matches!(c, Component::Normal(_)))
        && path.components().next().is_some()
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOURCE: &str = "// ANCHOR: reflect\nfn reflect() {\n    // BEGIN SOLUTION\n    ()\n    // END SOLUTION\n}\n// ANCHOR_END: reflect\n";

    fn entry(name: &str, file: &str, anchor: &str) -> String {
        format!(
            "[[exercise]]\nname = \"{name}\"\nchapter = \"ch01-whitted\"\nfile = \"{file}\"\nanchor = \"{anchor}\"\ncheck = \"cargo test -p ch01-whitted\"\nhint = \"\"\"\nMirror it.\nThen normalise.\"\"\"\n"
        )
    }

    fn workspace_with_source() -> tempfile::TempDir {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(dir.path().join("src")).unwrap();
        std::fs::write(dir.path().join("src/optics.rs"), SOURCE).unwrap();
        dir
    }

    #[test]
    fn wrong_answers_are_read_and_checked() {
        let dir = workspace_with_source();
        let text = format!(
            "{}[[exercise.wrong]]\nmistake = \"no sign\"\ncode = \"x\"\nsays = \"the sign\"\n\
             [[exercise.wrong]]\nmistake = \"nothing said\"\ncode = \"y\"\nsays = \" \"\n",
            entry("ch01-reflect", "src/optics.rs", "reflect")
        );
        let exercises = parse(&text).unwrap();
        assert_eq!(exercises[0].wrong.len(), 2);
        assert_eq!(exercises[0].wrong[0].says, "the sign");
        let problems = validate(dir.path(), &exercises);
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(
            problems[0].contains("wrong answer #2: `says` is empty"),
            "{problems:?}"
        );
    }

    #[test]
    fn needs_name_earlier_exercises_once() {
        let dir = workspace_with_source();
        let text = format!(
            "{}{}needs = [\"ch01-a\", \"ch01-a\", \"ch01-c\", \"ch01-none\", \"ch01-b\"]\n{}",
            entry("ch01-a", "src/optics.rs", "reflect"),
            entry("ch01-b", "src/optics.rs", "reflect"),
            entry("ch01-c", "src/optics.rs", "reflect"),
        );
        let exercises = parse(&text).unwrap();
        assert_eq!(exercises[1].needs.len(), 5);
        let problems = validate(dir.path(), &exercises).join("\n");
        assert!(
            problems.contains("`ch01-b`: `needs` names `ch01-a` twice"),
            "{problems}"
        );
        assert!(problems.contains("`needs` names `ch01-c`, which is not listed before it"));
        assert!(problems.contains("`needs` names `ch01-none`, which is not listed"));
        assert!(problems.contains("`needs` names `ch01-b`, which is not listed before it"));
        assert!(!problems.contains("names `ch01-a`, which"), "{problems}");
    }

    #[test]
    fn an_empty_list_is_fine() {
        assert!(parse("# nothing yet\n").unwrap().is_empty());
    }

    #[test]
    fn unknown_fields_are_rejected() {
        let text = format!("{}typo = 1\n", entry("a", "src/optics.rs", "reflect"));
        assert!(parse(&text).is_err());
    }

    #[test]
    fn a_good_entry_validates() {
        let dir = workspace_with_source();
        let exercises = parse(&entry("ch01-reflect", "src/optics.rs", "reflect")).unwrap();
        assert_eq!(validate(dir.path(), &exercises), Vec::<String>::new());
        assert_eq!(exercises[0].todo_message(), "ch01-reflect: Mirror it.");
    }

    #[test]
    fn problems_name_their_entry() {
        let dir = workspace_with_source();
        let text = [
            entry("ch01-reflect", "src/optics.rs", "reflect"),
            entry("ch01-reflect", "src/optics.rs", "refract"),
            entry("ch01-missing", "src/nowhere.rs", "reflect"),
            entry("ch01-escape", "../optics.rs", "reflect"),
        ]
        .concat();
        let problems = validate(dir.path(), &parse(&text).unwrap());
        assert_eq!(problems.len(), 4, "{problems:#?}");
        assert!(
            problems[0]
                .starts_with("exercise #2 `ch01-reflect`: the name is already used by exercise #1")
        );
        assert!(problems[1].starts_with(
            "exercise #2 `ch01-reflect`: in `src/optics.rs`, there is no `ANCHOR: refract`"
        ));
        assert!(
            problems[2].starts_with("exercise #3 `ch01-missing`: cannot read `src/nowhere.rs`")
        );
        assert!(
            problems[3].starts_with("exercise #4 `ch01-escape`: `file` must be a relative path")
        );
    }

    #[test]
    fn a_student_edition_validates_but_a_workbook_missing_one_solution_does_not() {
        let dir = workspace_with_source();
        std::fs::write(
            dir.path().join("src/stub.rs"),
            "// ANCHOR: refract\nfn refract() {\n    todo!()\n}\n// ANCHOR_END: refract\n",
        )
        .unwrap();
        let both = [
            entry("ch01-reflect", "src/optics.rs", "reflect"),
            entry("ch01-refract", "src/stub.rs", "refract"),
        ]
        .concat();
        let problems = validate(dir.path(), &parse(&both).unwrap());
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(
            problems[0].contains("holds no solution region"),
            "{problems:?}"
        );
        let stubbed_only = parse(&entry("ch01-refract", "src/stub.rs", "refract")).unwrap();
        assert!(validate(dir.path(), &stubbed_only).is_empty());
        assert!(is_student_edition(dir.path(), &stubbed_only));
        assert!(!is_student_edition(dir.path(), &parse(&both).unwrap()));
    }

    /// The crates after the lecture, whose pages go beyond it.
    const BEYOND_THE_LECTURE: &[&str] =
        &["ch09-materials", "ch10-optimal-mis", "ch11-path-guiding"];

    /// The promise of the exercise set: every chapter's student writes at least four
    /// exercises, one of them the chapter's central routine (a capstone of 25 lines or more),
    /// and the whole set covers the lecture (40 exercises, 900 lines of solution at least).
    #[test]
    fn every_chapter_has_four_exercises_and_a_capstone() {
        let root = crate::workspace::root();
        if holds_no_solutions(&root) {
            return; // a student edition: the solutions, which this measures, are to be written
        }
        let exercises = load(&root).unwrap();
        let shares = shares(&root, &exercises).unwrap();
        let chapters: Vec<&str> = shares.iter().map(|s| s.chapter.as_str()).collect();
        for chapter in crate::figures::CHAPTERS.iter().map(|(id, _)| *id) {
            assert!(
                chapters.iter().any(|c| c.starts_with(chapter)),
                "{chapter} has no exercise"
            );
        }
        for share in &shares {
            // The promise is the lecture's: the page beyond it has an exercise or two.
            if BEYOND_THE_LECTURE.contains(&share.chapter.as_str()) {
                continue;
            }
            assert!(share.exercises >= 4, "{share:?}: fewer than four exercises");
            assert!(
                share.capstone_lines >= 25,
                "{share:?}: no capstone of 25 lines"
            );
        }
        let lines: usize = shares.iter().map(|s| s.lines).sum();
        assert!(exercises.len() >= 40, "{} exercises", exercises.len());
        assert!(lines >= 900, "{lines} lines of solution");
        for exercise in &exercises {
            assert!(
                exercise.wrong.len() >= 2,
                "{}: fewer than two recorded wrong answers",
                exercise.name
            );
        }
    }
}
