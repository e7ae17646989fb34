//! `progress`: runs every exercise's check and lists the exercises, in order, as done or to do,
//! with the next one's file and hint.
//!
//! Checks of the usual form, `cargo test -p PACKAGE --lib FILTER`, are run one package at a
//! time: one `cargo test -p PACKAGE --lib exercise_` runs every check of the package, and an
//! exercise is done when every test its filter picks passed (as its own command would say).
//! Any other check command is run as it is.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Stdio};

use anyhow::{Context, Result};

use crate::exercise_list::Exercise;

/// Where an exercise stands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Status {
    Done,
    ToDo,
    /// Its package did not compile, so its check could not run.
    DoesNotCompile,
}

/// The prefix every standard check's filter starts with.
pub const CHECK_PREFIX: &str = "exercise_";

/// The package and test filter of a check of the usual form.
pub fn standard_check(check: &str) -> Option<(&str, &str)> {
    match check.split_whitespace().collect::<Vec<_>>().as_slice() {
        ["cargo", "test", "-p", package, "--lib", filter] if filter.starts_with(CHECK_PREFIX) => {
            Some((package, filter))
        }
        _ => None,
    }
}

/// The outcome of every test a `cargo test` run printed (`test path::name ... ok`).
pub fn test_results(output: &str) -> Vec<(String, bool)> {
    output
        .lines()
        .filter_map(|line| {
            let rest = line.strip_prefix("test ")?;
            let (name, verdict) = rest.split_once(" ... ")?;
            match verdict.trim() {
                "ok" => Some((name.to_owned(), true)),
                "FAILED" => Some((name.to_owned(), false)),
                _ => None,
            }
        })
        .collect()
}

/// The results among `results` of the tests a check's `filter` picks: as `cargo test`'s
/// filter, every test whose name contains it.
pub fn picked_by<'r>(results: &'r [(String, bool)], filter: &str) -> Vec<&'r (String, bool)> {
    results
        .iter()
        .filter(|(name, _)| name.contains(filter))
        .collect()
}

/// The status of each exercise, in the list's order, running the checks in `root`.
pub fn statuses(root: &Path, exercises: &[Exercise]) -> Result<Vec<Status>> {
    let mut by_package: BTreeMap<&str, Vec<usize>> = BTreeMap::new();
    let mut statuses = vec![Status::ToDo; exercises.len()];
    let mut package_order: Vec<&str> = Vec::new();
    for (index, exercise) in exercises.iter().enumerate() {
        match standard_check(&exercise.check) {
            Some((package, _)) => {
                if !by_package.contains_key(package) {
                    package_order.push(package);
                }
                by_package.entry(package).or_default().push(index);
            }
            None => {
                println!("Checking {} ...", exercise.name);
                let (passed, _) = run(root, &["sh", "-c", &exercise.check])?;
                statuses[index] = if passed { Status::Done } else { Status::ToDo };
            }
        }
    }
    for package in package_order {
        print!("Checking the exercises of {package} ... ");
        let _ = std::io::Write::flush(&mut std::io::stdout());
        let started = std::time::Instant::now();
        let (_, output) = run(
            root,
            &[
                "cargo",
                "test",
                "-p",
                package,
                "--lib",
                CHECK_PREFIX,
                "--",
                "--test-threads=2",
            ],
        )?;
        let results = test_results(&output);
        let compiled = output.contains("running ");
        println!(
            "{} in {:.0} s",
            if compiled { "ran" } else { "does not compile" },
            started.elapsed().as_secs_f64()
        );
        for &index in &by_package[package] {
            let (_, filter) = standard_check(&exercises[index].check).expect("standard");
            let picked = picked_by(&results, filter);
            statuses[index] = if !compiled {
                Status::DoesNotCompile
            } else if !picked.is_empty() && picked.iter().all(|(_, passed)| *passed) {
                Status::Done
            } else {
                Status::ToDo
            };
        }
    }
    Ok(statuses)
}

/// Runs `command` in `root`, its progress shown, its output kept.
fn run(root: &Path, command: &[&str]) -> Result<(bool, String)> {
    let output = Command::new(command[0])
        .args(&command[1..])
        .current_dir(root)
        .stdin(Stdio::null())
        .output()
        .with_context(|| format!("cannot run `{}`", command.join(" ")))?;
    Ok((
        output.status.success(),
        format!(
            "{}{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        ),
    ))
}

/// The report: every exercise with its status, then what to do next.
pub fn report(exercises: &[Exercise], statuses: &[Status]) -> String {
    let done = statuses.iter().filter(|s| **s == Status::Done).count();
    let mut text = format!("\n{done} of {} exercises done.\n\n", exercises.len());
    let next = statuses.iter().position(|s| *s != Status::Done);
    let not_done = |exercise: &Exercise| -> Vec<String> {
        exercise
            .needs
            .iter()
            .filter(|need| {
                exercises
                    .iter()
                    .zip(statuses)
                    .any(|(other, status)| &other.name == *need && *status != Status::Done)
            })
            .cloned()
            .collect()
    };
    for (index, (exercise, status)) in exercises.iter().zip(statuses).enumerate() {
        let missing = not_done(exercise);
        let word = match status {
            Status::Done => "done".to_owned(),
            Status::ToDo if !missing.is_empty() => {
                format!("to do (its check needs {} too)", missing.join(", "))
            }
            Status::ToDo => "to do".to_owned(),
            Status::DoesNotCompile => "to do (its chapter does not compile)".to_owned(),
        };
        let arrow = if Some(index) == next {
            "   <- next"
        } else {
            ""
        };
        text.push_str(&format!(
            "{:>3}. {:<34} {word}{arrow}\n",
            index + 1,
            exercise.name
        ));
    }
    match next {
        None => text.push_str("\nEvery exercise is done.\n"),
        Some(index) => {
            let exercise = &exercises[index];
            text.push_str(&format!(
                "\nNext: {} in {} (the function under `// ANCHOR: {}`)\n  check: {}\n",
                exercise.name,
                exercise.file.display(),
                exercise.anchor,
                exercise.check
            ));
            for (number, line) in exercise.hint.trim().lines().enumerate() {
                let label = if number == 0 { "hint: " } else { "      " };
                text.push_str(&format!("  {label}{line}\n"));
            }
            if !exercise.needs.is_empty() {
                text.push_str(&format!(
                    "  needs: {} (its check runs their code too)\n",
                    exercise.needs.join(", ")
                ));
            }
            let missing = not_done(exercise);
            if !missing.is_empty() {
                text.push_str(&format!(
                    "Its check cannot pass until {} {} done too: do {}, or put the reference \
                     solutions in with `cargo run -p book -- checkpoint --needs {}` (with \
                     `--from <the workbook>` if your edition has no sealed solutions).\n",
                    missing.join(", "),
                    if missing.len() == 1 { "is" } else { "are" },
                    if missing.len() == 1 { "it" } else { "them" },
                    exercise.name
                ));
            }
            text.push_str(&format!(
                "Stuck? `cargo run -p book -- checkpoint {}` puts the reference solution in \
                 (your version is kept), so you can go on; add `--from <the workbook>` if your \
                 edition has no sealed solutions.\n",
                exercise.name
            ));
        }
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exercise(name: &str, check: &str) -> Exercise {
        Exercise {
            name: name.into(),
            chapter: "ch01-whitted".into(),
            file: "chapters/ch01-whitted/src/optics.rs".into(),
            anchor: "reflect".into(),
            check: check.into(),
            hint: "Which part changes?\nAnd which does not?".into(),
            needs: Vec::new(),
            wrong: Vec::new(),
            giveaway: Vec::new(),
        }
    }

    #[test]
    fn standard_checks_are_recognised() {
        assert_eq!(
            standard_check("cargo test -p ch01-whitted --lib exercise_reflect"),
            Some(("ch01-whitted", "exercise_reflect"))
        );
        assert_eq!(
            standard_check("cargo test -p ch01-whitted exercise_reflect"),
            None
        );
        assert_eq!(standard_check("sh check.sh"), None);
    }

    #[test]
    fn test_lines_are_read() {
        let output = "running 3 tests\ntest optics::tests::exercise_reflect_a ... ok\n\
                      test optics::tests::exercise_refract ... FAILED\n\
                      test optics::tests::exercise_slow ... ignored\n";
        assert_eq!(
            test_results(output),
            vec![
                ("optics::tests::exercise_reflect_a".to_owned(), true),
                ("optics::tests::exercise_refract".to_owned(), false),
            ]
        );
    }

    #[test]
    fn the_report_points_at_the_first_exercise_not_done() {
        let exercises = [
            exercise("ch01-reflect", "true"),
            exercise("ch01-refract", "false"),
            exercise("ch01-fresnel", "false"),
        ];
        let text = report(&exercises, &[Status::Done, Status::ToDo, Status::ToDo]);
        assert!(text.contains("1 of 3 exercises done"), "{text}");
        assert!(
            text.contains("ch01-refract                       to do   <- next"),
            "{text}"
        );
        assert!(text.contains("Next: ch01-refract in chapters/ch01-whitted/src/optics.rs"));
        assert!(text.contains("hint: Which part changes?\n        And which does not?"));
        assert!(text.contains("checkpoint ch01-refract` puts"), "{text}");
        let all = report(&exercises[..1], &[Status::Done]);
        assert!(all.contains("Every exercise is done."), "{all}");
    }

    #[test]
    fn the_report_names_what_a_check_needs_that_is_not_done() {
        let mut exercises = [
            exercise("ch01-reflect", "true"),
            exercise("ch01-refract", "false"),
            exercise("ch01-fresnel", "false"),
        ];
        exercises[2].needs = vec!["ch01-reflect".into(), "ch01-refract".into()];
        let statuses = [Status::Done, Status::ToDo, Status::ToDo];
        let text = report(&exercises, &statuses);
        assert!(
            text.contains(
                "ch01-fresnel                       to do (its check needs ch01-refract too)"
            ),
            "{text}"
        );
        let skipped = report(&exercises, &[Status::ToDo, Status::ToDo, Status::ToDo]);
        assert!(
            skipped.contains("needs ch01-reflect, ch01-refract too)"),
            "{skipped}"
        );
        // Skipping ahead: the next one is the first not done, and its needs are named.
        exercises.swap(0, 2);
        exercises[2].needs.clear();
        let next = report(&exercises, &[Status::ToDo, Status::Done, Status::ToDo]);
        assert!(
            next.contains("  needs: ch01-reflect, ch01-refract (its check runs their code too)"),
            "{next}"
        );
        assert!(
            next.contains("until ch01-reflect is done too: do it, or put the reference solutions in with `cargo run -p book -- checkpoint --needs ch01-fresnel"),
            "{next}"
        );
    }
}
