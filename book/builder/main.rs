//! The workbook's builder: figures and site, and the tools around the exercises.
//!
//! - `cargo run --release -p book [-- --quick]` regenerates every chapter's figures, then builds
//!   the site into `book/site/`.
//! - `cargo run -p book -- exercises` lists the exercises with their checks and hints.
//! - `cargo run -p book -- student --out DIR` writes the student edition into `DIR`.
//! - `cargo run -p book -- check-exercises` proves every exercise fails as a stub and passes as
//!   solved, in order, and refuses its recorded wrong answers (CI runs it).
//! - `cargo run -p book -- progress` (in the student edition) lists what is done and what next.
//! - `cargo run -p book -- checkpoint NAME [--from WORKBOOK]` puts one reference solution back,
//!   from the edition's sealed solutions or from the workbook.
//! - `cargo run -p book -- check-prose` finds numbers typed into the pages that a run measured
//!   (the site build runs it too).
//! - `cargo run -p book --features browser -- check-site` opens every page of the built site in
//!   headless Chromium, offline, and fails on broken images, links and formulas, script errors,
//!   or a search that finds nothing; it leaves a screenshot of every page (CI runs it).
//! - `cargo run --release -p book --features browser -- bench-demos` times every live demo in
//!   headless Chromium (a benchmark: it reports, it does not fail on a time).

mod check_exercises;
mod checkpoint;
#[cfg(feature = "browser")]
mod demo_bench;
#[cfg(feature = "browser")]
mod demo_check;
mod demos;
mod exercise_calls;
mod exercise_list;
mod exercise_needs;
mod exercise_preprocessor;
mod figure_refs;
mod figures;
mod giveaways;
mod katex_offline;
mod lab_report;
#[cfg(feature = "browser")]
mod lab_report_check;
mod mdbook_log;
mod mutants;
mod offline_check;
mod page_shape;
mod progress;
mod prose_numbers;
mod sealed_solutions;
mod site;
#[cfg(feature = "browser")]
mod site_check;
mod solution_markers;
mod student_edition;
mod workspace;

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::Result;
use clap::{Parser, Subcommand};

/// Builds the workbook's figures and site, and manages its exercises.
#[derive(Parser)]
#[command(args_conflicts_with_subcommands = true)]
struct Cli {
    /// Make small, fast figures (as CI does) instead of full-quality ones.
    #[arg(long)]
    quick: bool,

    #[command(subcommand)]
    task: Option<Task>,
}

#[derive(Subcommand)]
enum Task {
    /// Write the student edition: the workspace with every exercise's solution cut out.
    Student {
        /// Where to write it; must be empty or missing.
        #[arg(long)]
        out: PathBuf,
        /// Delete what `--out` holds first.
        #[arg(long)]
        force: bool,
        /// Hand it out with its solutions sealed: `checkpoint` then works from the edition
        /// alone, while its site and its sources still show none (without this flag the
        /// edition holds no solution, and `checkpoint` needs the workbook).
        #[arg(long)]
        sealed_solutions: bool,
    },
    /// List the exercises in order, with the command that checks each and its hint.
    Exercises,
    /// Check that every exercise fails on the student edition and passes on the workspace, and
    /// that every recorded wrong answer fails its check with the recorded words.
    CheckExercises {
        /// Only these exercises (by name, repeatable); the student edition still stubs all.
        #[arg(long, value_name = "NAME")]
        only: Vec<String>,
        /// Only try the wrong answers (quicker while writing a check's messages).
        #[arg(long)]
        wrong_answers_only: bool,
        /// Write each exercise's measured `needs` into the list instead of failing when they
        /// differ from what it says.
        #[arg(long, conflicts_with = "wrong_answers_only")]
        write_needs: bool,
        /// Instead of the usual proof, try up to N small slips of each solution that nobody
        /// recorded (an operator swapped, a root or a constant lost) and fail if any makes a
        /// check crash in the workbook's code or hang (slow: about a minute a round).
        #[arg(long, value_name = "N", conflicts_with_all = ["wrong_answers_only", "write_needs"])]
        mutants: Option<usize>,
    },
    /// Run every exercise's check and list the exercises as done or to do, with the next one.
    Progress {
        /// Also build your own site: the book with your figures beside the reference ones.
        #[arg(long)]
        site: bool,
        /// With --site: render your figures at full quality (slower) instead of quick ones.
        #[arg(long, requires = "site")]
        full: bool,
    },
    /// Find numbers in the pages' prose that should come from a generated file, and chapter
    /// pages without a diagram, questions to check yourself or links to the primer (the site
    /// build runs these checks first).
    CheckProse,
    /// Put reference solutions back, to go on: one exercise, the stubs of a chapter, or the
    /// stubs among what one check needs (your versions are saved first).
    #[command(group(clap::ArgGroup::new("what").required(true).args(["name", "needs"])))]
    Checkpoint {
        /// An exercise, as `exercises` names it (`ch01-refract`), or a chapter
        /// (`ch04-depth-of-field`, or `ch04`): every exercise of it you have not written.
        name: Option<String>,
        /// Every exercise this exercise's check runs that you have not written, so that the
        /// check can run: `--needs ch08-path-loop`.
        #[arg(long, value_name = "NAME", conflicts_with = "name")]
        needs: Option<String>,
        /// The workbook: the repository with the solutions, from which this edition was made
        /// [default: the solutions sealed in this edition, if it was handed out with them].
        #[arg(long, value_name = "PATH")]
        from: Option<PathBuf>,
    },
    /// Walk a student's path to their lab report, as CI does: a fresh student edition with
    /// chapters 01 and 02 checkpointed runs `progress --site`, and its site must show their
    /// figures beside the reference ones and pass `check-site` (needs the workbook's figures
    /// built first).
    CheckLabReport {
        /// Where to write a screenshot of every page [default: lab-report-screenshots/ in
        /// cargo's target directory].
        #[arg(long, value_name = "DIR")]
        screenshots: Option<PathBuf>,
    },
    /// Time every live demo of the built site in headless Chromium: its first frame, its first
    /// complete pass and its target samples per pixel (a benchmark; pin it to one core with
    /// `taskset -c 0` to measure as on a small machine).
    BenchDemos {
        /// The built site [default: book/site].
        #[arg(long, value_name = "DIR")]
        site: Option<PathBuf>,
        /// Also write the table of times, in Markdown, to this file.
        #[arg(long, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// Open every page of the built site in headless Chromium (offline, from disk) and fail on
    /// a broken image, an image without alt text, a broken link or anchor, a formula KaTeX
    /// could not typeset, a console error or uncaught exception, or a search with no results.
    CheckSite {
        /// The built site [default: book/site].
        #[arg(long, value_name = "DIR")]
        site: Option<PathBuf>,
        /// Where to write a screenshot of every page [default: site-screenshots/ in cargo's
        /// target directory].
        #[arg(long, value_name = "DIR")]
        screenshots: Option<PathBuf>,
        /// Only list images without alt text instead of failing on them (until every page's
        /// figures have alt text, issue 20; this flag goes away then).
        #[arg(long)]
        no_alt_check: bool,
        /// The word typed into the search box of index.html, which must find something.
        #[arg(long, default_value = "Fresnel")]
        search: String,
    },
}

fn main() -> Result<()> {
    let cli = Cli::parse();
    let root = workspace::root();
    match cli.task {
        None => build_book(&root, cli.quick),
        Some(Task::Student {
            out,
            force,
            sealed_solutions,
        }) => {
            let exercises = exercise_list::load(&root)?;
            let files = student_edition::write(&root, &exercises, &out, force)?;
            println!(
                "Wrote the student edition to {}: {files} files, {} exercise(s) stubbed.",
                out.display(),
                exercises.len()
            );
            if sealed_solutions {
                let path = student_edition::seal_solutions(&root, &exercises, &out)?;
                println!(
                    "With the solutions sealed in {}: `checkpoint` works without the workbook.",
                    path.display()
                );
            } else {
                println!(
                    "Without solutions: `checkpoint` needs the workbook (`--from PATH`); \
                     `--sealed-solutions` hands the edition out with them sealed."
                );
            }
            if lab_report::ship_reference_figures(&root, &out)? {
                println!(
                    "With the workbook's figures in {}, for the student's own site \
                     (`progress --site`).",
                    lab_report::REFERENCE_DIR
                );
            } else {
                println!(
                    "Without reference figures: build the workbook's site first \
                     (`cargo run --release -p book`) for the student's site to compare with."
                );
            }
            Ok(())
        }
        Some(Task::Exercises) => {
            let exercises = exercise_list::load(&root)?;
            print_exercises(&exercises);
            if !exercise_list::is_student_edition(&root, &exercises) {
                print_shares(&exercise_list::shares(&root, &exercises)?);
            }
            Ok(())
        }
        Some(Task::Progress { site, full }) => {
            let exercises = exercise_list::load(&root)?;
            println!(
                "Running every exercise's check. The first check of a chapter compiles the \
                 chapter (and the first one, its dependencies) first: that takes a few minutes \
                 on a 2-core machine; after that a chapter's checks take seconds."
            );
            let statuses = progress::statuses(&root, &exercises)?;
            print!("{}", progress::report(&exercises, &statuses));
            if site {
                mdbook_log::install();
                let quality = lab_report::Quality {
                    full,
                    release: !cfg!(debug_assertions),
                };
                let front_page = lab_report::build(&root, &exercises, &statuses, quality)?;
                println!("\nYour site: open {}", front_page.display());
            }
            Ok(())
        }
        Some(Task::CheckProse) => {
            prose_numbers::check(&root, &root.join("book").join("src"))?;
            page_shape::check(&root.join("book").join("src"))?;
            println!(
                "No page's prose holds a number that is not listed in {}, and every chapter \
                 page has its diagram, its questions and its links to the primer.",
                prose_numbers::ALLOWED_PATH
            );
            Ok(())
        }
        Some(Task::Checkpoint { name, needs, from }) => {
            let exercises = exercise_list::load(&root)?;
            let target = match (name, needs) {
                (Some(name), None) => checkpoint::Target::named(&name, &exercises)?,
                (None, Some(needs)) => checkpoint::Target::NeedsOf(needs),
                _ => unreachable!("clap takes exactly one"),
            };
            let source = match &from {
                Some(workbook) => checkpoint::Source::workbook(workbook)?,
                None => checkpoint::Source::sealed(&root)?,
            };
            let outcome = checkpoint::run(&root, &exercises, &target, &source)?;
            print!(
                "{}",
                checkpoint_report(&target, &outcome, &exercises, from.as_deref())
            );
            Ok(())
        }
        Some(Task::CheckExercises {
            only,
            wrong_answers_only,
            write_needs,
            mutants,
        }) => {
            let exercises = exercise_list::load(&root)?;
            if let Some(unknown) = only
                .iter()
                .find(|n| !exercises.iter().any(|e| &e.name == *n))
            {
                anyhow::bail!("--only {unknown}: there is no such exercise in book/exercises.toml");
            }
            let selected = |e: &exercise_list::Exercise| only.is_empty() || only.contains(&e.name);
            match mutants {
                Some(most) => mutants::run(&root, &exercises, &selected, most),
                None => check_exercises::run(
                    &root,
                    &exercises,
                    &selected,
                    wrong_answers_only,
                    write_needs,
                ),
            }
        }
        Some(Task::CheckLabReport { screenshots }) => {
            let screenshots = screenshots
                .unwrap_or_else(|| workspace::target_dir(&root).join("lab-report-screenshots"));
            check_lab_report(&root, &screenshots)
        }
        Some(Task::BenchDemos { site, out }) => {
            bench_demos(&site.unwrap_or_else(|| root.join("book").join("site")), out)
        }
        Some(Task::CheckSite {
            site,
            screenshots,
            no_alt_check,
            search,
        }) => {
            let site = site.unwrap_or_else(|| root.join("book").join("site"));
            let screenshots = screenshots
                .unwrap_or_else(|| workspace::target_dir(&root).join("site-screenshots"));
            check_site(site, screenshots, !no_alt_check, search)
        }
    }
}

#[cfg(feature = "browser")]
fn check_lab_report(root: &Path, screenshots: &Path) -> Result<()> {
    lab_report_check::run(root, screenshots)
}

/// Without the browser driver, `check-lab-report` says how to build it in.
#[cfg(not(feature = "browser"))]
fn check_lab_report(_root: &Path, _screenshots: &Path) -> Result<()> {
    anyhow::bail!(
        "check-lab-report opens the student's site in headless Chromium, and this build of the \
         book leaves the browser driver out: run `cargo run -p book --features browser -- \
         check-lab-report`"
    )
}

/// Times the demos and prints the table (and writes it whole to `out`, if given).
#[cfg(feature = "browser")]
fn bench_demos(site: &Path, out: Option<PathBuf>) -> Result<()> {
    println!(
        "Timing every live demo of {} in headless Chromium ...",
        site.display()
    );
    let times = demo_bench::run(site)?;
    let table = demo_bench::table(&times);
    println!("{table}");
    if let Some(out) = out {
        workspace::write_whole(&out, &table)?;
    }
    Ok(())
}

/// Without the browser driver, `bench-demos` says how to build it in.
#[cfg(not(feature = "browser"))]
fn bench_demos(_site: &Path, _out: Option<PathBuf>) -> Result<()> {
    anyhow::bail!(
        "bench-demos drives headless Chromium, and this build of the book leaves the browser \
         driver out: run `cargo run --release -p book --features browser -- bench-demos`"
    )
}

/// Without the browser driver, `check-site` says how to build it in.
#[cfg(not(feature = "browser"))]
fn check_site(
    _site: PathBuf,
    _screenshots: PathBuf,
    _alt_check: bool,
    _search: String,
) -> Result<()> {
    anyhow::bail!(
        "check-site drives headless Chromium, and this build of the book leaves the browser \
         driver out (it is the slowest part to compile): run `cargo run -p book --features \
         browser -- check-site`"
    )
}

/// Runs the browser check and prints what it found; fails if anything is wrong.
#[cfg(feature = "browser")]
fn check_site(site: PathBuf, screenshots: PathBuf, alt_check: bool, search: String) -> Result<()> {
    let options = &site_check::Options {
        site,
        screenshots,
        alt_check,
        search_word: Some(search),
        demos_may_wait: false,
    };
    let started = Instant::now();
    println!(
        "Opening every page of {} in headless Chromium, offline ...",
        options.site.display()
    );
    let outcome = site_check::run(options)?;
    for skipped in &outcome.skipped {
        println!("Skipped {}: {}.", skipped.page, skipped.why);
    }
    if let Some(count) = outcome.search_results {
        println!(
            "Search for \"{}\" showed {count} result(s).",
            options.search_word.as_deref().unwrap_or_default()
        );
    }
    println!(
        "Screenshots of {} page(s) in {}",
        outcome.pages.len(),
        options.screenshots.display()
    );
    if !outcome.notes.is_empty() {
        println!(
            "\n{} image(s) without alt text (not failing: --no-alt-check):",
            outcome.notes.len()
        );
        for note in &outcome.notes {
            println!("  {note}");
        }
    }
    let seconds = started.elapsed().as_secs_f64();
    if !outcome.problems.is_empty() {
        println!("\n{} problem(s):", outcome.problems.len());
        for problem in &outcome.problems {
            println!("  {problem}");
        }
        let pages: std::collections::BTreeSet<&str> =
            outcome.problems.iter().map(|p| p.page.as_str()).collect();
        anyhow::bail!(
            "the site has {} problem(s) on {} page(s), listed above (checked in {seconds:.1} s)",
            outcome.problems.len(),
            pages.len()
        );
    }
    println!(
        "All {} page(s) load cleanly: every image, link, anchor and formula (checked in \
         {seconds:.1} s).",
        outcome.pages.len()
    );
    Ok(())
}

/// Figures first, then the site that shows them.
fn build_book(root: &Path, quick: bool) -> Result<()> {
    let started = Instant::now();
    let book_dir = root.join("book");
    mdbook_log::install();

    let figures_dir = book_dir.join("src").join("figures");
    regenerate_figures(&figures_dir, quick)?;
    // No page may show a figure the writers did not write (a broken image, a missing table).
    let chapters: Vec<&str> = figures::CHAPTERS.iter().map(|(id, _)| *id).collect();
    figure_refs::check(&book_dir.join("src"), &figures_dir, &chapters)?;
    demos::build(root, &book_dir.join("src"))?;

    println!("Building the site with mdBook and KaTeX ...");
    let front_page = site::build(&book_dir)?;
    println!(
        "Site ready in {:.1} s: open {}",
        started.elapsed().as_secs_f64(),
        front_page.display()
    );
    Ok(())
}

/// What a checkpoint did, and what to run next.
fn checkpoint_report(
    target: &checkpoint::Target,
    outcome: &checkpoint::Outcome,
    exercises: &[exercise_list::Exercise],
    from: Option<&Path>,
) -> String {
    let mut text = String::new();
    for restored in &outcome.restored {
        text += &format!(
            "Put the reference solution of {} into {} (your version is saved in {}).\n",
            restored.name,
            restored.file.display(),
            restored.saved.display()
        );
    }
    if !outcome.already.is_empty() {
        text += &format!(
            "Already the reference solution: {}.\n",
            outcome.already.join(", ")
        );
    }
    if !outcome.kept.is_empty() {
        text += &format!(
            "Kept as you wrote them: {} (`checkpoint NAME{}` replaces one).\n",
            outcome.kept.join(", "),
            from.map_or(String::new(), |from| format!(" --from {}", from.display()))
        );
    }
    let check = |name: &str| {
        exercises
            .iter()
            .find(|e| e.name == name)
            .map_or(String::new(), |e| e.check.clone())
    };
    match target {
        checkpoint::Target::Exercise(name) => {
            text += &format!("Its check should pass now: {}\n", check(name));
        }
        checkpoint::Target::Chapter(chapter) => {
            if outcome.restored.is_empty() && outcome.already.is_empty() {
                text += &format!("Every exercise of {chapter} is yours; nothing was put in.\n");
            }
        }
        checkpoint::Target::NeedsOf(name) => {
            let needs = exercises
                .iter()
                .find(|e| &e.name == name)
                .map_or(0, |e| e.needs.len());
            if needs == 0 {
                text += &format!("{name}'s check runs no other exercise; nothing to put in.\n");
            }
            text += &format!("Now its check runs your {name}: {}\n", check(name));
        }
    }
    text
}

#[cfg(feature = "figures")]
fn regenerate_figures(figures_dir: &Path, quick: bool) -> Result<()> {
    figures::regenerate_all(figures_dir, quick)
}

/// Without the chapters linked in, there is nothing to render the figures with.
#[cfg(not(feature = "figures"))]
fn regenerate_figures(_figures_dir: &Path, _quick: bool) -> Result<()> {
    anyhow::bail!(
        "this build of the book leaves the chapters out (the student edition's default, so that \
         `exercises`, `progress` and `checkpoint` start without compiling them). Your own site, \
         with your figures beside the reference ones, is built by `cargo run -p book -- \
         progress --site`; the book with every chapter's figures by `cargo run --release -p book \
         --features figures`"
    )
}

fn print_exercises(exercises: &[exercise_list::Exercise]) {
    if exercises.is_empty() {
        println!(
            "No exercises are listed in {} yet.",
            exercise_list::LIST_PATH
        );
        return;
    }
    println!("Exercises, in the order of the book:\n");
    for (number, exercise) in exercises.iter().enumerate() {
        println!(
            "{:>2}. {}  ({}, {}, anchor `{}`)",
            number + 1,
            exercise.name,
            exercise.chapter,
            exercise.file.display(),
            exercise.anchor
        );
        println!("    check: {}", exercise.check);
        if !exercise.needs.is_empty() {
            println!(
                "    needs: {} (its check runs their code too)",
                exercise.needs.join(", ")
            );
        }
        for (index, line) in exercise.hint.trim().lines().enumerate() {
            let label = if index == 0 { "hint: " } else { "      " };
            println!("    {label}{line}");
        }
        println!();
    }
}

/// For authors: how the exercises are spread over the chapters.
fn print_shares(shares: &[exercise_list::ChapterShare]) {
    println!("Per chapter (lines of solution; the capstone is the largest exercise):");
    for share in shares {
        println!(
            "  {:<24} {:>2} exercises {:>4} lines   capstone {} ({} lines)",
            share.chapter, share.exercises, share.lines, share.capstone, share.capstone_lines
        );
    }
    let exercises: usize = shares.iter().map(|s| s.exercises).sum();
    let lines: usize = shares.iter().map(|s| s.lines).sum();
    println!("  {:<24} {exercises:>2} exercises {lines:>4} lines", "all");
}
