//! What each exercise's check needs: the other exercises whose code it runs.
//!
//! A student stuck on a check that runs an exercise not written yet should learn which, before
//! the check runs into its stub. So the list says it (`needs`), the tools show it, and
//! `checkpoint --needs` puts those exercises in. The list is only worth trusting if it is
//! measured: `check-exercises` runs every check once with every solution marked
//! ([`crate::exercise_calls`]) and refuses a list whose `needs` differ from what ran, or, with
//! `--write-needs`, writes what ran into it.

use std::collections::HashMap;
use std::path::Path;

use anyhow::{Context, Result, bail};

use crate::exercise_calls::MarkedRun;
use crate::exercise_list::{Exercise, LIST_PATH};

/// The exercises other than `exercise` whose code its check ran, in the list's order.
pub fn measured<'e>(exercise: &Exercise, run: &MarkedRun, all: &'e [Exercise]) -> Vec<&'e str> {
    all.iter()
        .filter(|other| other.name != exercise.name && run.ran.contains(&other.name))
        .map(|other| other.name.as_str())
        .collect()
}

/// One exercise whose listed `needs` are not what its check ran.
pub struct Mismatch {
    pub name: String,
    pub listed: Vec<String>,
    pub measured: Vec<String>,
}

impl Mismatch {
    /// The line the list should hold.
    pub fn line(&self) -> String {
        needs_line(&self.measured)
    }
}

/// Every selected exercise (with a run that passed) whose `needs` differ from its run.
pub fn mismatches(
    exercises: &[Exercise],
    selected: &dyn Fn(&Exercise) -> bool,
    runs: &HashMap<String, MarkedRun>,
) -> Vec<Mismatch> {
    exercises
        .iter()
        .filter(|exercise| selected(exercise))
        .filter_map(|exercise| {
            let run = runs.get(&exercise.name).filter(|run| run.passed)?;
            let measured: Vec<String> = measured(exercise, run, exercises)
                .into_iter()
                .map(str::to_owned)
                .collect();
            (measured != exercise.needs).then(|| Mismatch {
                name: exercise.name.clone(),
                listed: exercise.needs.clone(),
                measured,
            })
        })
        .collect()
}

/// Proves every selected exercise's `needs` are what its check ran; with `write`, writes the
/// measured ones into the list at `root` instead of failing.
pub fn prove(
    root: &Path,
    exercises: &[Exercise],
    selected: &dyn Fn(&Exercise) -> bool,
    runs: &HashMap<String, MarkedRun>,
    write: bool,
) -> Result<()> {
    println!("\nNeeds: each check runs the code of exactly the exercises its `needs` names");
    let wrong = mismatches(exercises, selected, runs);
    if wrong.is_empty() {
        let with_needs = exercises
            .iter()
            .filter(|e| selected(e) && !e.needs.is_empty())
            .count();
        println!(
            "Every listed `needs` is what its check ran ({with_needs} exercise(s) need others)."
        );
        return Ok(());
    }
    for mismatch in &wrong {
        println!(
            "{:<28} lists [{}], its check ran [{}]",
            mismatch.name,
            mismatch.listed.join(", "),
            mismatch.measured.join(", ")
        );
    }
    if write {
        let path = root.join(LIST_PATH);
        let text =
            std::fs::read_to_string(&path).with_context(|| format!("cannot read {LIST_PATH}"))?;
        let rewritten = write_needs(&text, &wrong)?;
        workbench::output::write_text(&path, &rewritten)
            .with_context(|| format!("cannot write {LIST_PATH}"))?;
        println!(
            "Wrote the {} measured `needs` into {LIST_PATH}.",
            wrong.len()
        );
        return Ok(());
    }
    let lines: Vec<String> = wrong
        .iter()
        .map(|m| format!("  {}: {}", m.name, m.line()))
        .collect();
    bail!(
        "{} exercise(s) list other `needs` than their checks run; in {LIST_PATH}, write:\n{}\n\
         (or run check-exercises with --write-needs)",
        wrong.len(),
        lines.join("\n")
    )
}

/// `needs = ["a", "b"]`, or the empty list.
fn needs_line(needs: &[String]) -> String {
    let quoted: Vec<String> = needs.iter().map(|need| format!("{need:?}")).collect();
    format!("needs = [{}]", quoted.join(", "))
}

/// The list `text` with each mismatched exercise's `needs` line replaced by the measured one
/// (put just after its `check` line when it has none; left out when it needs nothing). Checked
/// by reading it back.
pub fn write_needs(text: &str, mismatches: &[Mismatch]) -> Result<String> {
    let mut out: Vec<String> = Vec::new();
    let mut current: Option<&Mismatch> = None;
    for line in text.lines() {
        let trimmed = line.trim();
        if trimmed.starts_with("[[") {
            current = None;
        }
        if let Some(name) = trimmed
            .strip_prefix("name = ")
            .map(|value| value.trim_matches('"'))
            && out
                .iter()
                .rev()
                .find(|l| !l.trim().is_empty())
                .map(|l| l.trim())
                == Some("[[exercise]]")
        {
            current = mismatches.iter().find(|m| m.name == name);
        }
        let Some(mismatch) = current else {
            out.push(line.to_owned());
            continue;
        };
        if trimmed.starts_with("needs = ") {
            continue; // dropped here, written after `check`
        }
        out.push(line.to_owned());
        if trimmed.starts_with("check = ") && !mismatch.measured.is_empty() {
            out.push(mismatch.line());
        }
    }
    let mut rewritten = out.join("\n");
    if text.ends_with('\n') {
        rewritten.push('\n');
    }
    let read_back = crate::exercise_list::parse(&rewritten)
        .context("the exercise list with its new `needs` does not read back")?;
    for mismatch in mismatches {
        let written = read_back.iter().find(|e| e.name == mismatch.name);
        if written.is_none_or(|e| e.needs != mismatch.measured) {
            bail!(
                "{LIST_PATH}: could not write the `needs` of {} (its `check` line must be one \
                 line)",
                mismatch.name
            );
        }
    }
    Ok(rewritten)
}

#[cfg(test)]
mod tests {
    use super::*;

    const LIST: &str = "[[exercise]]\nname = \"a\"\nchapter = \"c\"\nfile = \"f.rs\"\nanchor = \"a\"\n\
                        check = \"true\"\nhint = \"h\"\n\n[[exercise]]\nname = \"b\"\nchapter = \"c\"\n\
                        file = \"f.rs\"\nanchor = \"b\"\ncheck = \"true\"\nneeds = [\"x\"]\nhint = \"h\"\n\n\
                        [[exercise.wrong]]\nmistake = \"m\"\ncode = \"\"\"\nname = \"a\"\n\"\"\"\nsays = \"s\"\n";

    fn run(ran: &[&str]) -> MarkedRun {
        MarkedRun {
            passed: true,
            output: String::new(),
            ran: ran.iter().map(|name| (*name).to_owned()).collect(),
        }
    }

    #[test]
    fn a_list_that_says_other_needs_than_ran_is_caught_and_rewritten() {
        let exercises = crate::exercise_list::parse(LIST).unwrap();
        let runs = HashMap::from([
            ("a".to_owned(), run(&["a"])),
            ("b".to_owned(), run(&["b", "a"])),
        ]);
        let wrong = mismatches(&exercises, &|_| true, &runs);
        assert_eq!(wrong.len(), 1);
        assert_eq!(wrong[0].name, "b");
        assert_eq!(wrong[0].line(), "needs = [\"a\"]");
        let rewritten = write_needs(LIST, &wrong).unwrap();
        assert!(
            rewritten.contains("check = \"true\"\nneeds = [\"a\"]\nhint"),
            "{rewritten}"
        );
        // The wrong answer's code, which holds a `name = ` line, is left alone.
        assert!(rewritten.contains("code = \"\"\"\nname = \"a\"\n\"\"\""));
        let read = crate::exercise_list::parse(&rewritten).unwrap();
        assert!(mismatches(&read, &|_| true, &runs).is_empty());
        // Needing nothing takes the line out.
        let none = HashMap::from([("a".to_owned(), run(&["a"])), ("b".to_owned(), run(&["b"]))]);
        let emptied = write_needs(LIST, &mismatches(&exercises, &|_| true, &none)).unwrap();
        assert!(!emptied.contains("needs"), "{emptied}");
    }

    #[test]
    fn a_failed_run_measures_nothing() {
        let exercises = crate::exercise_list::parse(LIST).unwrap();
        let mut failed = run(&["b"]);
        failed.passed = false;
        let runs = HashMap::from([("b".to_owned(), failed)]);
        assert!(mismatches(&exercises, &|_| true, &runs).is_empty());
    }
}
