//! `check-lab-report`: walks the student's path to their own site, as CI does, and opens the
//! result in the browser.
//!
//! It writes a fresh student edition (with the workbook's figures, which must have been built:
//! CI's site step builds them, and with its solutions sealed), puts the reference solutions of
//! chapters 01 and 02 in with `checkpoint` from the edition's sealed solutions alone, runs the edition's own `progress --site`, and then requires that the pages
//! set the student's figures of chapters 01 and 02 beside the reference ones, that a later
//! chapter says it is not finished, and that `check-site` finds nothing wrong with the site.
//! Nothing in the workbook's own build exercises that path, so without this check it breaks
//! unseen.
//!
//! The edition is written where `check-exercises` writes its own, `target/student/edition/`,
//! and built as that one is (sharing the workspace's build directory, its chapters compiled
//! with settings of their own, see [`check_exercises::separate_crates_config`]): the libraries
//! are not compiled again, and after `check-exercises` (as in CI) the compiler's incremental
//! caches of the chapters, which hold the sources' absolute paths, serve this edition too. A
//! fresh place would compile every chapter from scratch (about a minute more on two cores).

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Instant;

use anyhow::{Context, Result, bail};

use crate::check_exercises::{self, EditionBuild};
use crate::checkpoint::{self, Target};
use crate::site_check;
use crate::{exercise_list, lab_report, student_edition, workspace};

/// The chapters the check finishes by checkpoint, and one it leaves for later.
const FINISHED: &[(&str, &str)] = &[("ch01-whitted", "ch01"), ("ch02-monte-carlo", "ch02")];
const UNFINISHED_PAGE: &str = "ch03-anti-aliasing.html";

/// Runs the whole path; fails naming what is wrong.
pub fn run(root: &Path, screenshots: &Path) -> Result<()> {
    let started = Instant::now();
    let exercises = exercise_list::load(root)?;
    let student_dir = workspace::target_dir(root).join("student");
    let edition = student_dir.join("edition");
    println!("Writing a student edition to {}", edition.display());
    student_edition::write(root, &exercises, &edition, true)?;
    // Handed out with sealed solutions, so that the checkpoints below come from the edition
    // alone, as a student's would.
    student_edition::seal_solutions(root, &exercises, &edition)?;
    if !lab_report::ship_reference_figures(root, &edition)? {
        bail!(
            "the workbook has no figures built, so the lab report would have nothing to compare \
             with: build the site first (`cargo run -p book -- --quick`)"
        );
    }
    check_exercises::write_config(
        &edition,
        &check_exercises::separate_crates_config(check_exercises::workspace_incremental()),
    )?;

    let student_list = exercise_list::load(&edition)?;
    let sealed = checkpoint::Source::sealed(&edition)?;
    for (chapter, _) in FINISHED {
        let target = Target::Chapter((*chapter).to_owned());
        let outcome = checkpoint::run(&edition, &student_list, &target, &sealed)?;
        println!(
            "checkpoint {chapter}: put in {} exercise(s)",
            outcome.restored.len()
        );
    }

    println!("Running `cargo run -p book -- progress --site` in the edition ...");
    let build = EditionBuild {
        target_dir: student_dir.join("target"),
        build_dir: workspace::target_dir(root),
        wrong_answers: None,
    };
    let mut command = Command::new("cargo");
    command
        .args(["run", "-p", "book", "--", "progress", "--site"])
        .current_dir(&edition)
        .stdin(Stdio::null());
    build.apply(&mut command);
    let output = command
        .output()
        .context("cannot run cargo in the edition")?;
    let printed = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    if !output.status.success() {
        bail!("`progress --site` failed in the student edition:\n{printed}");
    }
    // What the student would have seen, for the log: where the time went, what is done.
    for line in printed.lines().filter(|line| {
        line.starts_with("Checking the exercises")
            || line.starts_with("Your figures of")
            || line.contains("exercises done")
    }) {
        println!("  {line}");
    }
    for (_, id) in FINISHED {
        if !printed.contains(&format!("Your figures of {id} ->")) {
            bail!("`progress --site` did not render the student's figures of {id}:\n{printed}");
        }
    }
    println!(
        "  built in {:.0} s; checking its pages",
        started.elapsed().as_secs_f64()
    );

    let site = edition.join("book").join("site");
    let page = |name: &str| {
        std::fs::read_to_string(site.join(name)).with_context(|| format!("cannot read {name}"))
    };
    let first = page("ch01-whitted.html")?;
    for wanted in [
        "class=\"lab-report\"",
        "src=\"figures/ch01/",
        "src=\"figures/reference/ch01/",
        "<figcaption>Yours</figcaption>",
        "<figcaption>Reference</figcaption>",
        "Each figure of this chapter is rendered by your code",
    ] {
        if !first.contains(wanted) {
            bail!("the lab report's ch01-whitted.html lacks `{wanted}`");
        }
    }
    let later = page(UNFINISHED_PAGE)?;
    if !later.contains("Not finished yet") || later.contains("class=\"lab-report\"") {
        bail!("the lab report's {UNFINISHED_PAGE} does not say its chapter is not finished");
    }

    let options = site_check::Options {
        site,
        screenshots: screenshots.to_path_buf(),
        alt_check: true,
        search_word: Some("Fresnel".to_owned()),
        demos_may_wait: true,
    };
    let outcome = site_check::run(&options)?;
    if !outcome.problems.is_empty() {
        let problems: Vec<String> = outcome.problems.iter().map(|p| p.to_string()).collect();
        bail!(
            "the student's site has {} problem(s):\n  {}",
            problems.len(),
            problems.join("\n  ")
        );
    }
    println!(
        "The lab report of an edition with {} checkpointed shows the student's figures beside \
         the reference ones, and its {} page(s) load cleanly in the browser (screenshots in {}; \
         {:.0} s in all).",
        FINISHED
            .iter()
            .map(|(chapter, _)| *chapter)
            .collect::<Vec<_>>()
            .join(" and "),
        outcome.pages.len(),
        screenshots.display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}
