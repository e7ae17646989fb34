//! `check-exercises`: proves that every listed exercise is a real exercise.
//!
//! An exercise is sound when its check command
//! - fails on the student edition: the stub really leaves work to do, and the check tests it;
//! - passes on the workspace: the solution really solves it.
//!
//! Before running any check, the student edition must compile, or every check would fail for
//! the wrong reason. The edition and its build live under `target/student/`, in fixed places,
//! so repeated runs reuse the compiled dependencies instead of piling up copies.

use std::path::Path;
use std::process::{Command, Stdio};

use anyhow::{Context, Result, bail};

use crate::exercise_list::{Exercise, LIST_PATH};
use crate::student_edition;
use crate::workspace;

/// What one run of a check command did.
struct Outcome {
    passed: bool,
    output: String,
}

/// Checks every exercise both ways and prints a table; fails on any surprise.
pub fn run(root: &Path, exercises: &[Exercise]) -> Result<()> {
    if exercises.is_empty() {
        // Still worth one look: a solution marker nobody listed would leak to students.
        student_edition::plan(root, exercises, &[])?;
        println!("No exercises are listed in {LIST_PATH}, so there is nothing to check.");
        println!("(No stray solution markers either.)");
        return Ok(());
    }

    let student_dir = workspace::target_dir(root).join("student");
    let edition = student_dir.join("edition");
    let edition_target = student_dir.join("target");

    println!("Writing the student edition to {}", edition.display());
    let files = student_edition::write(root, exercises, &edition, true)?;
    println!("  {files} files, {} exercise(s) stubbed", exercises.len());
    write_quick_build_config(&edition)?;

    build_edition(&edition, &edition_target, exercises)?;

    println!();
    println!(
        "{:<28} {:<28} {:<28}",
        "exercise", "student edition (must fail)", "workspace (must pass)"
    );
    let mut surprises = Vec::new();
    for exercise in exercises {
        let stub = run_check(&exercise.check, &edition, Some(&edition_target))?;
        let solution = run_check(&exercise.check, root, None)?;
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
        println!("\nAll {} exercise(s) behave.", exercises.len());
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

/// Settings for this check's own build of the student edition, written into the edition's
/// `.cargo/config.toml` (which overrides the manifest's profiles): the checks are small unit
/// tests, so the dependencies are compiled without optimisation or debug information, which
/// shortens the check's largest step, a second build of every dependency. The edition handed
/// to students (`book student`) keeps the workspace's settings.
const QUICK_BUILD_CONFIG: &str = "\
# Written by `book check-exercises` for its own build of the student edition.
[profile.dev]
debug = false

[profile.dev.package.\"*\"]
opt-level = 0
";

fn write_quick_build_config(edition: &Path) -> Result<()> {
    let dir = edition.join(".cargo");
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let path = dir.join("config.toml");
    std::fs::write(&path, QUICK_BUILD_CONFIG)
        .with_context(|| format!("cannot write {}", path.display()))
}

/// Compiles, with all their targets, the student edition's packages that hold exercises.
///
/// Only those packages can break: a stub changes a function's body, never its signature, so
/// nothing that depends on them notices. They and their dependencies are also exactly what the
/// checks need, so nothing is built that the checks would not build anyway.
fn build_edition(edition: &Path, target: &Path, exercises: &[Exercise]) -> Result<()> {
    let mut args = vec!["build", "--all-targets"];
    let mut packages: Vec<&str> = exercises.iter().map(|e| e.chapter.as_str()).collect();
    packages.sort_unstable();
    packages.dedup();
    for package in packages {
        args.extend(["-p", package]);
    }
    println!(
        "Compiling it: cargo {} (target dir {})",
        args.join(" "),
        target.display()
    );
    let status = Command::new("cargo")
        .args(&args)
        .current_dir(edition)
        .env("CARGO_TARGET_DIR", target)
        .stdin(Stdio::null())
        .status()
        .context("cannot run cargo")?;
    if !status.success() {
        bail!(
            "the student edition does not compile (errors above): every stub must leave its \
             crate compiling, so students start from code that builds"
        );
    }
    Ok(())
}

/// Runs `check` through `sh -c` in `dir`, quietly, keeping its output for the report.
fn run_check(check: &str, dir: &Path, target: Option<&Path>) -> Result<Outcome> {
    let mut command = Command::new("sh");
    command
        .arg("-c")
        .arg(check)
        .current_dir(dir)
        .stdin(Stdio::null());
    if let Some(target) = target {
        command.env("CARGO_TARGET_DIR", target);
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
