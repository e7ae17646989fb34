//! `check-exercises`: proves that every listed exercise is a real exercise.
//!
//! An exercise is sound when its check command
//! - fails on the student edition: the stub really leaves work to do, and the check tests it;
//! - passes on the workspace: the solution really solves it.
//!
//! Before running any check, the student edition must compile, or every check would fail for
//! the wrong reason. The edition lives under `target/student/`, in a fixed place, and its build
//! shares the workspace's build directory: the dependencies are compiled once, for the
//! workspace's tests, and the edition reuses them. The edition's own crates are built with
//! other settings (see [`separate_crates_config`]), so cargo files them under other names than
//! the workspace's, and its binaries go to a target directory of their own.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use anyhow::{Context, Result, bail};

use crate::exercise_calls::{self, MarkedRun};
use crate::exercise_list::{Exercise, LIST_PATH, WrongAnswer};
use crate::exercise_needs;
use crate::progress;
use crate::solution_markers;
use crate::student_edition;
use crate::workspace;

/// What one run of a check command did.
struct Outcome {
    passed: bool,
    output: String,
}

/// Checks every `selected` exercise both ways and prints a table, then tries their recorded
/// wrong answers (only those with `wrong_answers_only`); fails on any surprise.
pub fn run(
    root: &Path,
    exercises: &[Exercise],
    selected: &dyn Fn(&Exercise) -> bool,
    wrong_answers_only: bool,
    write_needs: bool,
) -> Result<()> {
    if exercises.is_empty() {
        // Still worth one look: a solution marker nobody listed would leak to students.
        student_edition::plan(root, exercises, &[])?;
        println!("No exercises are listed in {LIST_PATH}, so there is nothing to check.");
        println!("(No stray solution markers either.)");
        return Ok(());
    }

    let started = std::time::Instant::now();
    let target_dir = workspace::target_dir(root);
    let student_dir = target_dir.join("student");
    let chosen: Vec<Exercise> = exercises.iter().filter(|e| selected(e)).cloned().collect();
    if wrong_answers_only {
        let mut trial = Trial::in_workspace(root)?;
        let runs = trial.run_marked(&chosen, exercises)?;
        return prove_wrong_answers(&mut trial, &chosen, &runs);
    }
    let edition = student_dir.join("edition");
    let edition_build = EditionBuild {
        target_dir: student_dir.join("target"),
        build_dir: target_dir,
        wrong_answers: None,
    };

    println!("Writing the student edition to {}", edition.display());
    let files = student_edition::write(root, exercises, &edition, true)?;
    println!("  {files} files, {} exercise(s) stubbed", exercises.len());
    write_config(&edition, &separate_crates_config(workspace_incremental()))?;

    build_edition(&edition, &edition_build, &chosen)?;

    println!();
    println!(
        "{:<28} {:<28} {:<28}",
        "exercise", "student edition (must fail)", "workspace (must pass)"
    );
    let mut surprises = Vec::new();
    let all: Vec<&Exercise> = chosen.iter().collect();
    let stubs = run_checks(&all, &[], &edition, Some(&edition_build))?;
    let solutions = run_checks(&all, &[], root, None)?;
    for ((exercise, stub), solution) in chosen.iter().zip(stubs).zip(solutions) {
        println!(
            "{:<28} {:<28} {:<28}",
            exercise.name,
            verdict(&stub, false),
            verdict(&solution, true)
        );
        if stub.passed {
            surprises.push((exercise, "passes on the student edition", stub));
        }
        if !solution.passed {
            surprises.push((exercise, "fails on the workspace", solution));
        }
    }

    if surprises.is_empty() {
        println!(
            "\nAll {} exercise(s) behave ({:.0} s so far).",
            chosen.len(),
            started.elapsed().as_secs_f64()
        );
        let mut trial = Trial::over_edition(root, edition, edition_build, exercises);
        let runs = trial.run_marked(&chosen, exercises)?;
        prove_in_order(exercises, selected, &runs)?;
        exercise_needs::prove(root, exercises, selected, &runs, write_needs)?;
        println!("({:.0} s so far)", started.elapsed().as_secs_f64());
        prove_wrong_answers(&mut trial, &chosen, &runs)?;
        println!(
            "check-exercises took {:.0} s.",
            started.elapsed().as_secs_f64()
        );
        return Ok(());
    }
    for (exercise, what, outcome) in &surprises {
        println!(
            "\n--- {} {what}: `{}` printed (last lines):",
            exercise.name, exercise.check
        );
        println!("{}", last_lines(&outcome.output, 30));
    }
    bail!(
        "{} surprise(s): each check must fail on the student edition and pass on the workspace",
        surprises.len()
    )
}

/// Proves that every recorded wrong answer fails its exercise's check, and that the check
/// says so in the recorded words.
///
/// The answers are tried in a copy of the workspace (the student edition with its solutions
/// put back, or a fresh copy when only the wrong answers are checked), all solutions in place
/// but the ones being tried, in rounds: round `r` puts in the `r`-th wrong answer of every
/// exercise that has one. A round chooses its answers as its checks run, in the copy
/// [`Trial::run_marked`] built with every answer in it (or, where that copy did not compile,
/// costs one build of the changed crates), never one build per answer.
/// A check may run the code of another exercise with an answer in the same round (`runs` says
/// which exercises each check runs); one that then does not refuse its own answer as recorded
/// is tried again, in rounds where no check runs the code of another answer of the round,
/// before it counts. The copy's crates have names of their own in the shared build directory
/// (see [`separate_crates_config`] and [`TRIALS_CONFIG`]).
fn prove_wrong_answers(
    trial: &mut Trial<'_>,
    exercises: &[Exercise],
    runs: &HashMap<String, MarkedRun>,
) -> Result<()> {
    let rounds = exercises.iter().map(|e| e.wrong.len()).max().unwrap_or(0);
    if rounds == 0 {
        println!("No wrong answers are recorded in {LIST_PATH}.");
        return Ok(());
    }
    println!(
        "\nTrying the recorded wrong answers in {}",
        trial.copy.display()
    );
    println!("{:<28} {:<40} {:<20}", "exercise", "wrong answer", "check");
    // Whether `check`'s check runs the code of `other`.
    let runs_code_of = |check: &Exercise, other: &Exercise| {
        check.name != other.name
            && runs
                .get(&check.name)
                .is_some_and(|run| run.ran.contains(&other.name))
    };
    let mut tried = 0;
    let mut surprises = Vec::new();
    let mut again = Vec::new();
    for round in 0..rounds {
        let in_round: Vec<(&Exercise, &WrongAnswer)> = exercises
            .iter()
            .filter_map(|e| e.wrong.get(round).map(|wrong| (e, wrong)))
            .collect();
        for (exercise, wrong, outcome) in trial.wrong_answers(&in_round)? {
            tried += 1;
            let disturbed = in_round
                .iter()
                .any(|(other, _)| runs_code_of(exercise, other));
            if refused(wrong, &outcome) {
                print_verdict(exercise, wrong, &outcome, "");
            } else if disturbed {
                print_verdict(exercise, wrong, &outcome, ", tried again alone");
                again.push((exercise, wrong));
            } else {
                print_verdict(exercise, wrong, &outcome, "");
                surprises.push((exercise, wrong, outcome));
            }
        }
    }
    // Alone: no check of a round runs the code of another answer of the round.
    while !again.is_empty() {
        let mut in_round: Vec<(&Exercise, &WrongAnswer)> = Vec::new();
        again.retain(|&(exercise, wrong)| {
            let apart = in_round.iter().all(|(other, _)| {
                other.name != exercise.name
                    && !runs_code_of(exercise, other)
                    && !runs_code_of(other, exercise)
            });
            if apart {
                in_round.push((exercise, wrong));
            }
            !apart
        });
        for (exercise, wrong, outcome) in trial.wrong_answers(&in_round)? {
            print_verdict(exercise, wrong, &outcome, " (alone)");
            if !refused(wrong, &outcome) {
                surprises.push((exercise, wrong, outcome));
            }
        }
    }
    if surprises.is_empty() {
        println!("\nAll {tried} wrong answer(s) fail their checks with the recorded words.");
        return Ok(());
    }
    for (exercise, wrong, outcome) in &surprises {
        println!(
            "\n--- {} with the wrong answer \"{}\" should fail saying \"{}\"; `{}` printed (last lines):",
            exercise.name, wrong.mistake, wrong.says, exercise.check
        );
        println!("{}", last_lines(&outcome.output, 30));
    }
    bail!(
        "{} wrong answer(s) not refused as recorded: a check must fail on each and say what is wrong",
        surprises.len()
    )
}

/// The copy of the workspace where stubs and wrong answers are put in place of solutions, and
/// the files it holds that differ from the workspace's. Its crates are built with settings of
/// their own, so they have names of their own in the shared build directory.
pub struct Trial<'a> {
    root: &'a Path,
    copy: PathBuf,
    build: EditionBuild,
    changed: Vec<PathBuf>,
    /// Whether the copy's exercises are now switches among their wrong answers (see
    /// [`Trial::run_marked`]), so that trying a wrong answer needs no build.
    switched: bool,
    /// The packages whose libraries that build compiled, which every run of checks selects.
    built: Vec<String>,
}

impl<'a> Trial<'a> {
    /// A fresh copy of the workspace at `root`, in its build directory's `student/`, where the
    /// wrong answers and the mutants are tried.
    pub fn in_workspace(root: &'a Path) -> Result<Self> {
        Self::new(root, &workspace::target_dir(root).join("student"))
    }

    /// Writes a fresh copy of the workspace, every solution in place: for checking the wrong
    /// answers alone, without the student edition.
    fn new(root: &'a Path, student_dir: &Path) -> Result<Self> {
        let copy = student_dir.join("trials");
        student_edition::write_copy(root, &copy)?;
        write_config(&copy, TRIALS_CONFIG)?;
        Ok(Self {
            root,
            copy,
            build: EditionBuild {
                target_dir: student_dir.join("trials-target"),
                build_dir: workspace::target_dir(root),
                wrong_answers: None,
            },
            changed: Vec::new(),
            switched: false,
            built: Vec::new(),
        })
    }

    /// Takes over the student edition at `edition`, already built with `build`, for the trials:
    /// putting back the solutions of its exercise files makes it the workspace as far as the
    /// checks can tell (it differs only in the notes its build scripts print and in an
    /// exercise list without wrong answers, which no check reads). Its crates, compiled
    /// incrementally, are then rebuilt in seconds per round, where a fresh copy would compile
    /// `common` and every chapter once more.
    fn over_edition(
        root: &'a Path,
        edition: PathBuf,
        build: EditionBuild,
        exercises: &[Exercise],
    ) -> Self {
        let mut changed: Vec<PathBuf> = Vec::new();
        for exercise in exercises {
            if !changed.contains(&exercise.file) {
                changed.push(exercise.file.clone());
            }
        }
        Self {
            root,
            copy: edition,
            build,
            changed,
            switched: false,
            built: Vec::new(),
        }
    }

    /// Puts each `(exercise, code)` in, `code` standing where the exercise's solution stands,
    /// after putting back every file the last round changed.
    pub fn put_in(&mut self, splices: &[(&Exercise, String)]) -> Result<()> {
        self.put_back()?;
        for (exercise, code) in splices {
            self.rewrite(exercise, |source| {
                solution_markers::splice_code(source, &exercise.anchor, code)
            })?;
        }
        Ok(())
    }

    /// Puts back, from the workspace, every file the copy's exercises were changed in.
    fn put_back(&mut self) -> Result<()> {
        self.switched = false;
        for file in self.changed.drain(..) {
            std::fs::copy(self.root.join(&file), self.copy.join(&file))
                .with_context(|| format!("cannot restore {}", file.display()))?;
        }
        Ok(())
    }

    /// Rewrites the copy's file of `exercise` with `edit`, and remembers to put it back.
    fn rewrite(
        &mut self,
        exercise: &Exercise,
        edit: impl FnOnce(&str) -> Result<String, solution_markers::MarkerError>,
    ) -> Result<()> {
        let path = self.copy.join(&exercise.file);
        let source = std::fs::read_to_string(&path)
            .with_context(|| format!("cannot read {}", path.display()))?;
        let edited = edit(&source)
            .with_context(|| format!("{}: {}", exercise.name, exercise.file.display()))?;
        std::fs::write(&path, edited)
            .with_context(|| format!("cannot write {}", path.display()))?;
        if !self.changed.contains(&exercise.file) {
            self.changed.push(exercise.file.clone());
        }
        Ok(())
    }

    /// Puts every solution of `all` back with a mark first in it ([`exercise_calls`]), builds
    /// the copy's libraries with their tests, and runs each check of `chosen` once, each in
    /// processes of its own: what each check does and which exercises' code it runs, by name.
    ///
    /// Each solution is put back as the last arm of a switch among the exercise's recorded
    /// wrong answers ([`solution_markers::switch_solution`]), which runs the solution unless
    /// [`WRONG_ANSWERS_VARIABLE`] chooses another arm: the wrong answers are then tried with
    /// this one build instead of one build per round (about 25 s a round on two cores with cold
    /// caches). Should that copy not compile, the solutions are put back marked only, and each
    /// round of wrong answers is built apart.
    pub fn run_marked(
        &mut self,
        chosen: &[Exercise],
        all: &[Exercise],
    ) -> Result<HashMap<String, MarkedRun>> {
        let chosen: Vec<&Exercise> = chosen.iter().collect();
        let packages = standard_packages(&chosen);
        let mut binaries = HashMap::new();
        for switched in [true, false] {
            self.put_back()?;
            for exercise in all {
                self.rewrite(exercise, |source| {
                    let mark = exercise_calls::call_mark(exercise);
                    if !switched {
                        return solution_markers::mark_solution(source, &exercise.anchor, &mark);
                    }
                    let wrong: Vec<&str> = exercise.wrong.iter().map(|w| w.code.as_str()).collect();
                    let choice = choice_of(&exercise.name);
                    solution_markers::switch_solution(
                        source,
                        &exercise.anchor,
                        &mark,
                        &choice,
                        &wrong,
                    )
                })?;
            }
            if packages.is_empty() {
                break;
            }
            match self.compile_library_tests(&packages)? {
                Compiled::Binaries(built) => {
                    binaries = built;
                    self.switched = switched;
                    self.built = packages.iter().map(|p| (*p).to_owned()).collect();
                    break;
                }
                Compiled::Errors { text, .. } if switched => println!(
                    "The copy with every exercise a switch among its wrong answers does not \
                     compile, so each round of wrong answers will be built apart (slower); \
                     the compiler said:\n{}",
                    last_lines(&text, 30)
                ),
                Compiled::Errors { command, text, .. } => bail!(
                    "the copy at {} with every solution marked does not compile (`{command}`):\n{}",
                    self.copy.display(),
                    last_lines(&text, 30)
                ),
            }
        }
        let run_other = |check: &str, marks: &Path| -> Result<(bool, String)> {
            let marks = marks.to_string_lossy().replace('\'', "'\\''");
            let command = format!("{}='{marks}' {check}", exercise_calls::CALLS_FILE_VARIABLE);
            let outcome = run_check(&command, &self.copy, Some(&self.build))?;
            Ok((outcome.passed, outcome.output))
        };
        let marks_dir = self.build.target_dir.join("exercise-calls");
        let runs = exercise_calls::run_marked(&chosen, &binaries, &marks_dir, &run_other)?;
        Ok(chosen
            .iter()
            .map(|exercise| exercise.name.clone())
            .zip(runs)
            .collect())
    }

    /// Compiles the library tests of `packages` in the copy as it now stands: their test
    /// binaries, or where the compiler found errors.
    pub fn compile_library_tests(&self, packages: &[&str]) -> Result<Compiled> {
        let (mut command, args) = compile_library_tests(
            &self.copy,
            &self.build,
            packages,
            &["--message-format=json"],
        );
        let output = command
            .output()
            .with_context(|| format!("cannot run cargo in {}", self.copy.display()))?;
        let json = String::from_utf8_lossy(&output.stdout);
        if output.status.success() {
            return Ok(Compiled::Binaries(exercise_calls::library_test_binaries(
                &json,
            )));
        }
        let mut places = Vec::new();
        let mut text = String::new();
        for line in json.lines() {
            let Ok(message) = serde_json::from_str::<serde_json::Value>(line) else {
                continue;
            };
            if message["reason"] != "compiler-message" || message["message"]["level"] != "error" {
                continue;
            }
            if let Some(rendered) = message["message"]["rendered"].as_str() {
                text.push_str(rendered);
            }
            let spans = message["message"]["spans"]
                .as_array()
                .cloned()
                .unwrap_or_default();
            for span in spans {
                if let (Some(file), Some(line)) =
                    (span["file_name"].as_str(), span["line_start"].as_u64())
                {
                    places.push((PathBuf::from(file), line as usize));
                }
            }
        }
        text.push_str(&String::from_utf8_lossy(&output.stderr));
        Ok(Compiled::Errors {
            command: format!("cargo {}", args.join(" ")),
            places,
            text,
        })
    }

    /// The workspace the copy is of.
    pub fn root(&self) -> &Path {
        self.root
    }

    /// The copy's folder.
    pub fn copy_dir(&self) -> &Path {
        &self.copy
    }

    /// Puts the `answers` in and runs each one's check.
    fn wrong_answers<'e>(
        &mut self,
        answers: &[(&'e Exercise, &'e WrongAnswer)],
    ) -> Result<Vec<(&'e Exercise, &'e WrongAnswer, Outcome)>> {
        let exercises: Vec<&Exercise> = answers.iter().map(|(exercise, _)| *exercise).collect();
        let outcomes = if self.switched {
            // Chosen as the checks run: nothing to build.
            let pairs: Vec<String> = answers
                .iter()
                .map(|(exercise, wrong)| {
                    let index = exercise
                        .wrong
                        .iter()
                        .position(|recorded| std::ptr::eq(recorded, *wrong))
                        .expect("a wrong answer of its exercise");
                    format!("{}={}", exercise.name, index + 1)
                })
                .collect();
            self.build.wrong_answers = Some(pairs.join(" "));
            let built: Vec<&str> = self.built.iter().map(String::as_str).collect();
            let outcomes = run_checks(&exercises, &built, &self.copy, Some(&self.build));
            self.build.wrong_answers = None;
            outcomes?
        } else {
            let splices: Vec<(&Exercise, String)> = answers
                .iter()
                .map(|(exercise, wrong)| (*exercise, wrong.code.clone()))
                .collect();
            self.put_in(&splices)?;
            run_checks(&exercises, &[], &self.copy, Some(&self.build))?
        };
        Ok(answers
            .iter()
            .zip(outcomes)
            .map(|(&(exercise, wrong), outcome)| (exercise, wrong, outcome))
            .collect())
    }
}

/// What compiling a copy's library tests gave.
pub enum Compiled {
    /// Each package's library test binary and folder.
    Binaries(HashMap<String, (PathBuf, PathBuf)>),
    /// The compiler's errors: the cargo command, the places (file relative to the copy, line)
    /// its messages point at, and the messages.
    Errors {
        command: String,
        places: Vec<(PathBuf, usize)>,
        text: String,
    },
}

/// Proves the promise that the exercises can be done in order: each exercise's check passes
/// once it and the exercises before it are solved, while the ones after it are still stubs.
/// A check that calls a later exercise would leave the student stuck.
///
/// Each check has run once with every solution in place and marked (`runs`): one that passed
/// there and ran no exercise listed after its own passes with those exercises stubbed too,
/// since the code it runs is the same until a stub is called. One that ran a later exercise
/// fails for the student, with that exercise's `todo!`.
fn prove_in_order(
    exercises: &[Exercise],
    selected: &dyn Fn(&Exercise) -> bool,
    runs: &HashMap<String, MarkedRun>,
) -> Result<()> {
    println!(
        "\nIn order: each check, run once with every solution in place, runs no exercise listed \
         after its own"
    );
    let mut proved = 0;
    let mut stuck = Vec::new();
    for (index, exercise) in exercises.iter().enumerate() {
        let Some(run) = runs.get(&exercise.name).filter(|_| selected(exercise)) else {
            continue;
        };
        let after = &exercises[index + 1..];
        let later_in_chapter = after
            .iter()
            .filter(|later| later.chapter == exercise.chapter)
            .count();
        let runs_later: Vec<&str> = after
            .iter()
            .filter(|later| run.ran.contains(&later.name))
            .map(|later| later.name.as_str())
            .collect();
        if !run.passed {
            println!(
                "{:<28} FAILS with every solution in place (and marked)",
                exercise.name
            );
            stuck.push((
                exercise,
                "fails with every solution in place".to_owned(),
                run,
            ));
        } else if !run.ran.contains(&exercise.name) {
            // It failed on its stub, so it runs its exercise: the mark did not work.
            println!("{:<28} ran no marked code", exercise.name);
            stuck.push((
                exercise,
                format!(
                    "left no mark of its own exercise, whose stub it fails on: the marks ({}) \
                     were not written, so nothing is known of what the checks run",
                    exercise_calls::CALLS_FILE_VARIABLE
                ),
                run,
            ));
        } else if !runs_later.is_empty() {
            println!(
                "{:<28} FAILS with the later exercises stubbed: it runs {}",
                exercise.name,
                runs_later.join(", ")
            );
            stuck.push((
                exercise,
                format!(
                    "runs {}, listed after it: a student doing them in order would be stuck here, \
                     at that exercise's todo! (does the check, or the code it runs, call it?)",
                    runs_later.join(", ")
                ),
                run,
            ));
        } else if later_in_chapter > 0 {
            println!(
                "{:<28} passes with {later_in_chapter} later exercise(s) of its chapter stubbed \
                 (it runs none of them)",
                exercise.name
            );
            proved += 1;
        }
    }
    if stuck.is_empty() {
        println!(
            "All {proved} exercise(s) that have later ones in their chapter can be done in order."
        );
        return Ok(());
    }
    for (exercise, why, run) in &stuck {
        println!(
            "\n--- {}'s check {why}; `{}` printed (last lines):",
            exercise.name, exercise.check
        );
        println!("{}", last_lines(&run.output, 30));
    }
    bail!(
        "{} exercise(s) cannot be done in order: a check may call only the exercises before it",
        stuck.len()
    )
}

/// Whether the check refused the wrong answer in its recorded words.
fn refused(wrong: &WrongAnswer, outcome: &Outcome) -> bool {
    !outcome.passed
        && outcome
            .output
            .to_lowercase()
            .contains(&wrong.says.to_lowercase())
}

fn print_verdict(exercise: &Exercise, wrong: &WrongAnswer, outcome: &Outcome, note: &str) {
    let verdict = match (outcome.passed, refused(wrong, outcome)) {
        (true, _) => "passed (SURPRISE)",
        (false, true) => "failed, said it (ok)",
        (false, false) => "failed, silent (SURPRISE)",
    };
    println!(
        "{:<28} {:<40} {verdict}{note}",
        exercise.name, wrong.mistake
    );
}

/// Settings of the copy in which stubs and wrong answers are tried: other debug settings than
/// the workspace's and the student edition's, so its crates get names of their own in the
/// shared build directory.
const TRIALS_CONFIG: &str = "\
# Written by `book check-exercises` for its trials: the workspace's crates get names
# of their own in the shared build directory; dependencies are shared.
[profile.dev]
debug = \"limited\"
incremental = true
";

/// Settings for this check's own build of the student edition, written into the edition's
/// `.cargo/config.toml` (which overrides the manifest's profiles).
///
/// Cargo names a workspace crate's compiled files after its name, version, settings and its
/// path *relative to the workspace*, which are the same in the edition as in the workspace. In
/// a shared build directory the two copies of a crate would then be one: a check on the
/// workspace could run the student's stub. Building the edition's chapters without debug
/// information (the workspace keeps line tables) gives them names of their own. The
/// dependencies are configured by `[profile.dev.package."*"]`, which this leaves alone, so
/// they keep the workspace's names and are shared; so does `common`, which holds no exercise
/// and is copied with its files' times (see `student_edition::write`): it keeps the
/// workspace's debug setting and, with `workspace_incremental`, the incremental compilation
/// the workspace's build had, so that the edition uses the `common` the workspace's tests
/// compiled instead of compiling it once more. The chapters are compiled incrementally: the
/// trials change a few function bodies per round, which rustc's caches rebuild in seconds.
/// The edition handed to students (`book student`) keeps the workspace's settings.
pub fn separate_crates_config(workspace_incremental: bool) -> String {
    format!(
        "# Written by `book check-exercises` for its own build of the student edition: the \
         chapters\n\
         # get names of their own in the shared build directory; `common`, `workbench` and the \
         dependencies are\n\
         # shared with the workspace's build.\n\
         [profile.dev]\n\
         debug = false\n\
         incremental = true\n\
         \n\
         [profile.dev.package.common]\n\
         debug = \"{WORKSPACE_DEV_DEBUG}\"\n\
         incremental = {workspace_incremental}\n\
         \n\
         [profile.dev.package.workbench]\n\
         debug = \"{WORKSPACE_DEV_DEBUG}\"\n\
         incremental = {workspace_incremental}\n"
    )
}

/// The workspace's `[profile.dev]` debug setting (a test holds it to the manifest).
const WORKSPACE_DEV_DEBUG: &str = "line-tables-only";

/// Whether the workspace's own builds in this process's environment are incremental: as
/// `CARGO_INCREMENTAL` says, else as the dev profile's default (the manifest sets none).
pub fn workspace_incremental() -> bool {
    std::env::var("CARGO_INCREMENTAL").map_or(true, |value| value != "0")
}

/// Writes `config` as the `.cargo/config.toml` of the copy at `dir`.
pub fn write_config(edition: &Path, config: &str) -> Result<()> {
    let dir = edition.join(".cargo");
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let path = dir.join("config.toml");
    std::fs::write(&path, config).with_context(|| format!("cannot write {}", path.display()))
}

/// Where cargo puts the student edition's build.
pub struct EditionBuild {
    /// Final artifacts (binaries), kept apart from the workspace's.
    pub target_dir: PathBuf,
    /// Intermediate artifacts: the workspace's own build directory, so that the dependencies
    /// compiled for the workspace are reused rather than compiled a second time.
    pub build_dir: PathBuf,
    /// The wrong answers a copy's switches choose (see [`WRONG_ANSWERS_VARIABLE`]), if any.
    pub wrong_answers: Option<String>,
}

/// The environment variable that chooses, in a copy whose exercises are switches
/// ([`solution_markers::switch_solution`]), which recorded wrong answer each exercise runs:
/// `NAME=K` pairs (K counted from 1), separated by spaces; an exercise not named runs its
/// solution.
pub const WRONG_ANSWERS_VARIABLE: &str = "WORKBOOK_WRONG_ANSWERS";

/// The expression a switch of exercise `name` matches on: the number that
/// [`WRONG_ANSWERS_VARIABLE`] gives it, 0 if none, read once per process.
fn choice_of(name: &str) -> String {
    format!(
        "{{ static WRONG_ANSWER: std::sync::OnceLock<usize> = std::sync::OnceLock::new(); \
         *WRONG_ANSWER.get_or_init(|| std::env::var({WRONG_ANSWERS_VARIABLE:?}).ok().and_then(\
         |pairs| pairs.split_whitespace().find_map(|pair| pair.strip_prefix({prefix:?})?.parse().ok())\
         ).unwrap_or(0)) }}",
        prefix = format!("{name}=")
    )
}

impl EditionBuild {
    /// Points `command`'s cargo at this build. A build directory the caller chose
    /// (`CARGO_BUILD_BUILD_DIR`) is inherited as it is: the workspace's build used it too.
    /// Which crates are compiled incrementally is the copy's configuration's to say, so the
    /// caller's `CARGO_INCREMENTAL`, which would say it for every crate, is left out. (The
    /// trials change a few function bodies per round and rebuild every chapter that holds
    /// one: about 20 s per round on a 2-core machine from scratch, about 2 s with rustc's
    /// incremental caches.)
    pub fn apply(&self, command: &mut Command) {
        command.env("CARGO_TARGET_DIR", &self.target_dir);
        command.env_remove("CARGO_INCREMENTAL");
        match &self.wrong_answers {
            Some(pairs) => command.env(WRONG_ANSWERS_VARIABLE, pairs),
            None => command.env_remove(WRONG_ANSWERS_VARIABLE),
        };
        if std::env::var_os("CARGO_BUILD_BUILD_DIR").is_none() {
            command.env("CARGO_BUILD_BUILD_DIR", &self.build_dir);
        }
    }
}

/// Compiles the libraries of the student edition's packages that hold exercises.
///
/// Only those libraries can break: a stub changes a function's body, never its signature, so
/// nothing that calls it notices, neither the package's binaries, benchmarks and tests nor
/// the packages that depend on it; and a stub's warnings (a variable the stub leaves unused,
/// code after its `todo!`) are the library's own. The libraries are compiled with their unit
/// tests, which is all the checks run, and as the checks compile them: `cargo test` turns on
/// the dev-dependencies' features, so a `cargo build` of the same libraries would compile
/// `common` and every chapter once more. Building every target as well would compile each
/// binary, benchmark and integration test of the edition and could find nothing more.
fn build_edition(edition: &Path, build: &EditionBuild, exercises: &[Exercise]) -> Result<()> {
    let mut packages: Vec<&str> = exercises.iter().map(|e| e.chapter.as_str()).collect();
    packages.sort_unstable();
    packages.dedup();
    let (mut command, args) = compile_library_tests(edition, build, &packages, &[]);
    println!(
        "Compiling it: cargo {} (target dir {})",
        args.join(" "),
        build.target_dir.display()
    );
    command.stdout(Stdio::inherit()).stderr(Stdio::piped());
    let output = command.output().context("cannot run cargo")?;
    let messages = String::from_utf8_lossy(&output.stderr);
    eprint!("{messages}");
    if !output.status.success() {
        bail!(
            "the student edition does not compile (errors above): every stub must leave its \
             crate compiling, so students start from code that builds"
        );
    }
    let warned: Vec<&str> = messages
        .lines()
        .filter(|line| line.starts_with("warning: `") && line.contains(" generated "))
        .collect();
    if !warned.is_empty() {
        bail!(
            "the student edition compiles with warnings ({}): a stub must leave no warning, or \
             students learn to ignore them",
            warned.join("; ")
        );
    }
    Ok(())
}

/// `cargo test --no-run --lib` of `packages` in the copy at `dir`, with `also`, as the checks
/// compile them (with [`AS_THE_WORKSPACE_TESTS`]) and pointed at `build`; and its arguments.
fn compile_library_tests<'a>(
    dir: &Path,
    build: &EditionBuild,
    packages: &[&'a str],
    also: &[&'a str],
) -> (Command, Vec<&'a str>) {
    let mut args = vec!["test", "--no-run", "--lib"];
    args.extend(also);
    for package in packages {
        args.extend(["-p", package]);
    }
    args.extend(AS_THE_WORKSPACE_TESTS.split(' '));
    let mut command = Command::new("cargo");
    command.args(&args).current_dir(dir).stdin(Stdio::null());
    build.apply(&mut command);
    (command, args)
}

/// The packages of the checks of the usual form among `exercises`, each once, in order.
fn standard_packages<'e>(exercises: &[&'e Exercise]) -> Vec<&'e str> {
    let mut packages: Vec<&str> = Vec::new();
    for exercise in exercises {
        if let Some((package, _)) = progress::standard_check(&exercise.check)
            && !packages.contains(&package)
        {
            packages.push(package);
        }
    }
    packages
}

/// Runs the checks of `exercises` in `dir` and returns their outcomes in the same order. The
/// packages `also` are built and tested with theirs (and their outcomes left out), so that a
/// run selects the packages an earlier build selected: cargo compiles a chapter again when
/// another selection gives it other features.
///
/// Checks of the usual form (`cargo test -p PACKAGE --lib exercise_...`) are run together: an
/// exercise's check passes when every test its filter picks passed, and its output is what
/// those tests printed. That is what its own command would report, at the cost of one cargo
/// run, which compiles the packages side by side. In a copy (`build` given) that run tests the
/// packages with a check this time, with [`AS_THE_WORKSPACE_TESTS`], so a round rebuilds the
/// chapters it tests, not every chapter that depends on one it changed. In the workspace it
/// tests what the README's test command tests ([`WORKSPACE_SELECTION`]), which has compiled it
/// all before (in CI, the step before). If that run compiled nothing (one package's code
/// does not build), each package is run on its own, so one package's error is not blamed on
/// the others. Other checks run as they are.
fn run_checks(
    exercises: &[&Exercise],
    also: &[&str],
    dir: &Path,
    build: Option<&EditionBuild>,
) -> Result<Vec<Outcome>> {
    let mut outcomes: Vec<Option<Outcome>> = exercises.iter().map(|_| None).collect();
    let mut packages = standard_packages(exercises);
    for &package in also {
        if !packages.contains(&package) {
            packages.push(package);
        }
    }
    for (index, exercise) in exercises.iter().enumerate() {
        if progress::standard_check(&exercise.check).is_none() {
            outcomes[index] = Some(run_check(&exercise.check, dir, build)?);
        }
    }
    let mut runs: Vec<(&str, Outcome)> = Vec::new();
    if !packages.is_empty() {
        let selection = match build {
            // The workspace itself: built as the README's test command builds it, so that the
            // run compiles nothing that command compiled (fewer packages or features would
            // unify their dependencies' features otherwise, and compile `common` and every
            // chapter again). Only the exercises' tests run, whatever the packages.
            None => WORKSPACE_SELECTION.to_owned(),
            Some(_) => {
                packages
                    .iter()
                    .map(|p| format!("-p {p} "))
                    .collect::<String>()
                    + AS_THE_WORKSPACE_TESTS
            }
        };
        let command = format!(
            "cargo test --no-fail-fast {selection} --lib {} 2>&1",
            progress::CHECK_PREFIX
        );
        let joint = run_check(&command, dir, build)?;
        if let Some(sections) = package_sections(&joint.output, &packages) {
            runs = sections;
        }
    }
    if runs.is_empty() {
        for &package in &packages {
            let also = if build.is_some() {
                AS_THE_WORKSPACE_TESTS
            } else {
                ""
            };
            let command = format!(
                "cargo test -p {package} {also} --lib {}",
                progress::CHECK_PREFIX
            );
            runs.push((package, run_check(&command, dir, build)?));
        }
    }
    for (package, run) in &runs {
        let compiled = run.output.contains("\nrunning ");
        let results = progress::test_results(&run.output);
        let printed = failure_sections(&run.output);
        for (index, exercise) in exercises.iter().enumerate() {
            let Some((this_package, filter)) = progress::standard_check(&exercise.check) else {
                continue;
            };
            if this_package != *package {
                continue;
            }
            let picked = progress::picked_by(&results, filter);
            outcomes[index] = Some(if !compiled {
                Outcome {
                    passed: false,
                    output: run.output.clone(),
                }
            } else if picked.is_empty() {
                Outcome {
                    passed: false,
                    output: format!("no test's name contains `{filter}`"),
                }
            } else {
                let mut output = String::new();
                for (name, passed) in &picked {
                    output.push_str(&format!(
                        "test {name} ... {}\n",
                        if *passed { "ok" } else { "FAILED" }
                    ));
                    if let Some((_, text)) = printed.iter().find(|(failed, _)| failed == name) {
                        output.push_str(text);
                    }
                }
                Outcome {
                    passed: picked.iter().all(|(_, passed)| *passed),
                    output,
                }
            });
        }
    }
    Ok(outcomes
        .into_iter()
        .map(|outcome| outcome.expect("every exercise ran"))
        .collect())
}

/// The packages and features of the README's test command (`cargo test --workspace
/// --all-features`), with which the checks run on the workspace.
const WORKSPACE_SELECTION: &str = "--workspace --all-features";

/// Added to the chapters that a build of the student edition or of a trial copy selects, so
/// that their dependencies are compiled with the features the README's test command gave
/// them, and are shared with its build instead of compiled once more (cargo unifies a
/// dependency's features over the packages selected), whichever chapters are selected: `book`
/// depends on every chapter and on the site's crates, and `--all-features` turns on its
/// browser; it has no library, so `--lib` compiles nothing of it. (The chapters' own
/// dev-dependencies add no features to what `book` asks for; were that to change, a round
/// would compile more, not check less.)
const AS_THE_WORKSPACE_TESTS: &str = "-p book --all-features";

/// Splits the output of one `cargo test` run over several packages' libraries (stdout and
/// stderr as one stream) into each package's part: from the line where cargo starts its test
/// binary to the next such line; the parts of packages not in `packages` are left out. `None`
/// unless every package of `packages` has exactly one part, as when something did not compile.
fn package_sections<'p>(output: &str, packages: &[&'p str]) -> Option<Vec<(&'p str, Outcome)>> {
    let mut sections: Vec<(Option<&'p str>, String)> = Vec::new();
    for line in output.lines() {
        if let Some(binary) = line
            .trim_start()
            .strip_prefix("Running unittests ")
            .and_then(|rest| rest.rsplit_once('/'))
            .map(|(_, file)| file.trim_end_matches(')'))
        {
            // The binary is named after the crate and a hash: `ch01_whitted-0123abcd`. Other
            // packages' parts are split off and left out.
            let crate_name = binary.rsplit_once('-').map_or(binary, |(name, _)| name);
            let package = packages
                .iter()
                .find(|package| package.replace('-', "_") == crate_name)
                .copied();
            sections.push((package, String::new()));
        } else if let Some((_, text)) = sections.last_mut() {
            text.push_str(line);
            text.push('\n');
        }
    }
    let every_one_once = packages
        .iter()
        .all(|package| sections.iter().filter(|(p, _)| *p == Some(package)).count() == 1);
    every_one_once.then(|| {
        sections
            .into_iter()
            .filter_map(|(package, text)| Some((package?, text)))
            .map(|(package, text)| {
                let passed = text.contains("\ntest result: ok.");
                (
                    package,
                    Outcome {
                        passed,
                        output: format!("\n{text}"),
                    },
                )
            })
            .collect()
    })
}

/// What each failed test printed: the `---- NAME stdout ----` sections of a `cargo test` run.
fn failure_sections(output: &str) -> Vec<(String, String)> {
    let mut sections: Vec<(String, String)> = Vec::new();
    let mut current: Option<usize> = None;
    for line in output.lines() {
        if let Some(name) = line
            .strip_prefix("---- ")
            .and_then(|rest| rest.strip_suffix(" stdout ----"))
        {
            sections.push((name.to_owned(), String::new()));
            current = Some(sections.len() - 1);
        } else if line == "failures:" {
            current = None;
        } else if let Some(index) = current {
            sections[index].1.push_str(line);
            sections[index].1.push('\n');
        }
    }
    sections
}

/// Runs `check` through `sh -c` in `dir`, quietly, keeping its output for the report.
fn run_check(check: &str, dir: &Path, build: Option<&EditionBuild>) -> Result<Outcome> {
    let mut command = Command::new("sh");
    command
        .arg("-c")
        .arg(check)
        .current_dir(dir)
        .stdin(Stdio::null());
    if let Some(build) = build {
        build.apply(&mut command);
    }
    let output = command
        .output()
        .with_context(|| format!("cannot run `{check}` in {}", dir.display()))?;
    Ok(Outcome {
        passed: output.status.success(),
        output: format!(
            "{}{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        ),
    })
}

fn verdict(outcome: &Outcome, should_pass: bool) -> String {
    let what = if outcome.passed { "passed" } else { "failed" };
    let ok = if outcome.passed == should_pass {
        "ok"
    } else {
        "SURPRISE"
    };
    format!("{what} ({ok})")
}

fn last_lines(text: &str, count: usize) -> String {
    let lines: Vec<&str> = text.lines().collect();
    lines[lines.len().saturating_sub(count)..].join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exercise(name: &str, chapter: &str) -> Exercise {
        Exercise {
            name: name.into(),
            chapter: chapter.into(),
            file: format!("chapters/{chapter}/src/lib.rs").into(),
            anchor: name.into(),
            check: format!("cargo test -p {chapter} --lib exercise_{name}"),
            hint: "Which part changes?".into(),
            needs: Vec::new(),
            wrong: Vec::new(),
            giveaway: Vec::new(),
        }
    }

    fn ran(names: &[&str]) -> MarkedRun {
        MarkedRun {
            passed: true,
            output: String::new(),
            ran: names.iter().map(|name| (*name).to_owned()).collect(),
        }
    }

    #[test]
    fn a_check_that_runs_a_later_exercise_cannot_be_done_in_order() {
        let exercises = [
            exercise("a1", "a"),
            exercise("a2", "a"),
            exercise("b1", "b"),
        ];
        let all = |_: &Exercise| true;
        let in_order = HashMap::from([
            ("a1".to_owned(), ran(&["a1"])),
            ("a2".to_owned(), ran(&["a2", "a1"])),
            ("b1".to_owned(), ran(&["b1", "a2"])),
        ]);
        assert!(prove_in_order(&exercises, &all, &in_order).is_ok());
        let mut stuck = in_order;
        stuck.insert("a1".to_owned(), ran(&["a1", "a2"]));
        let error = prove_in_order(&exercises, &all, &stuck).unwrap_err();
        assert!(format!("{error}").contains("1 exercise(s) cannot be done in order"));
        // Not selected, not proved either way.
        assert!(prove_in_order(&exercises, &|e: &Exercise| e.name != "a1", &stuck).is_ok());
    }

    #[test]
    fn a_check_that_left_no_mark_of_its_own_exercise_fails_the_proof() {
        let exercises = [exercise("a1", "a"), exercise("a2", "a")];
        let runs = HashMap::from([("a1".to_owned(), ran(&[])), ("a2".to_owned(), ran(&["a2"]))]);
        assert!(prove_in_order(&exercises, &|_| true, &runs).is_err());
        let mut failed = ran(&["a1"]);
        failed.passed = false;
        let runs = HashMap::from([("a1".to_owned(), failed), ("a2".to_owned(), ran(&["a2"]))]);
        assert!(prove_in_order(&exercises, &|_| true, &runs).is_err());
    }

    /// The `debug` setting of `[profile.dev]` in a TOML document (`None` if it sets none).
    fn dev_debug(document: &str) -> Option<toml::Value> {
        let value: toml::Table = toml::from_str(document).expect("valid TOML");
        value.get("profile")?.get("dev")?.get("debug").cloned()
    }

    /// If the workspace's test builds ever drop their line tables, the edition's crates would
    /// share the workspace's names in the build directory, and the checks on the workspace
    /// could run the students' stubs. Then the edition needs another distinguishing setting.
    #[test]
    fn the_editions_crates_are_built_with_other_settings_than_the_workspaces() {
        let manifest = std::fs::read_to_string(workspace::root().join("Cargo.toml")).unwrap();
        let workspace = dev_debug(&manifest);
        assert_eq!(
            workspace,
            Some(toml::Value::String(WORKSPACE_DEV_DEBUG.into())),
            "common is shared with the workspace's build only with the workspace's debug setting"
        );
        let manifest_table: toml::Table = toml::from_str(&manifest).unwrap();
        assert!(
            manifest_table["profile"]["dev"]
                .get("incremental")
                .is_none(),
            "workspace_incremental takes the dev profile's default"
        );
        let config = separate_crates_config(false);
        let edition = dev_debug(&config).expect("the edition sets debug");
        let config_table: toml::Table = toml::from_str(&config).unwrap();
        let common = &config_table["profile"]["dev"]["package"]["common"];
        assert_eq!(common["debug"].as_str(), Some(WORKSPACE_DEV_DEBUG));
        assert_eq!(common["incremental"].as_bool(), Some(false));
        assert_eq!(edition, toml::Value::Boolean(false));
        let same = match &workspace {
            None => false, // the default for dev is full debug information
            Some(toml::Value::Boolean(on)) => !on,
            Some(toml::Value::Integer(level)) => *level == 0,
            Some(toml::Value::String(level)) => level == "none",
            Some(other) => panic!("unexpected debug setting {other}"),
        };
        assert!(
            !same,
            "the workspace's [profile.dev] debug is {workspace:?}"
        );
        // The copy for wrong answers differs from both.
        let wrong = dev_debug(TRIALS_CONFIG).expect("the copy sets debug");
        assert_eq!(wrong, toml::Value::String("limited".into()));
        assert_ne!(Some(&wrong), workspace.as_ref());
        assert_ne!(wrong, edition);
    }

    #[test]
    fn a_joint_run_is_split_by_package() {
        let output = "   Compiling ch01-whitted v0.1.0\n    Finished `test` profile\n     \
                      Running unittests src/lib.rs (target/debug/deps/ch01_whitted-0a1b)\n\n\
                      running 1 test\ntest a::exercise_x ... ok\n\ntest result: ok. 1 passed\n     \
                      Running unittests src/lib.rs (target/debug/deps/ch02_monte_carlo-9f8e)\n\n\
                      running 1 test\ntest b::exercise_y ... FAILED\n\nfailures:\n\n\
                      ---- b::exercise_y stdout ----\nthe sign is wrong\n\ntest result: FAILED.\n";
        let sections = package_sections(output, &["ch01-whitted", "ch02-monte-carlo"]).unwrap();
        assert_eq!(sections.len(), 2);
        assert_eq!(sections[0].0, "ch01-whitted");
        assert!(sections[0].1.passed);
        assert!(sections[0].1.output.contains("exercise_x"));
        assert!(!sections[0].1.output.contains("exercise_y"));
        assert_eq!(sections[1].0, "ch02-monte-carlo");
        assert!(!sections[1].1.passed);
        assert!(sections[1].1.output.contains("the sign is wrong"));
        // A run over the whole workspace: the other packages' parts are left out.
        let second_only = package_sections(output, &["ch02-monte-carlo"]).unwrap();
        assert_eq!(second_only.len(), 1);
        assert_eq!(second_only[0].0, "ch02-monte-carlo");
        assert!(!second_only[0].1.output.contains("exercise_x"));
        // A package that did not get as far as its tests: no split, each is run on its own.
        assert!(package_sections(output, &["ch01-whitted", "ch03-anti-aliasing"]).is_none());
        let first_only = &output[..output.rfind("     Running").unwrap()];
        assert!(package_sections(first_only, &["ch01-whitted", "ch02-monte-carlo"]).is_none());
        assert!(package_sections("error: could not compile", &["ch01-whitted"]).is_none());
    }

    #[test]
    fn each_failed_test_keeps_what_it_printed() {
        let output = "running 2 tests\ntest a::exercise_x ... FAILED\ntest a::exercise_y ... FAILED\n\n\
                      failures:\n\n---- a::exercise_x stdout ----\nthe sign is wrong\n\n\
                      ---- a::exercise_y stdout ----\nno interface\n\nfailures:\n    a::exercise_x\n";
        let sections = failure_sections(output);
        assert_eq!(sections.len(), 2);
        assert_eq!(sections[0].0, "a::exercise_x");
        assert!(sections[0].1.contains("the sign is wrong"));
        assert!(!sections[0].1.contains("no interface"));
        assert!(sections[1].1.contains("no interface"));
        assert!(!sections[1].1.contains("exercise_x"));
    }
}
