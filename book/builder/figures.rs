//! Every chapter's figures, regenerated before each build of the site.
//!
//! Figures are outputs of the chapters' code, never hand-made files: a page always shows what
//! the code it explains produces today. Each chapter writes its figures into its own directory
//! `book/src/figures/<chapter id>/`, and its page refers to them relatively, e.g.
//! `![](figures/ch01/spheres.png)`.

use std::path::Path;

use anyhow::{Context, Result};

/// A chapter's figure writer: fills `out_dir` with PNG and CSV files. With `quick` set it makes
/// small, fast versions (for CI and for checking a page's layout); otherwise full quality.
#[cfg(feature = "figures")]
pub type WriteFigures = fn(out_dir: &Path, quick: bool) -> Result<()>;

/// The chapters with figures, in book order: a chapter id (its figure directory) and its
/// package, whose binary writes the same figures (`figures --out DIR [--quick]`). A new chapter
/// registers its figures by adding one line here and one to [`WRITERS`].
pub const CHAPTERS: &[(&str, &str)] = &[
    ("ch01", "ch01-whitted"),
    ("ch02", "ch02-monte-carlo"),
    ("ch03", "ch03-anti-aliasing"),
    ("ch04", "ch04-depth-of-field"),
    ("ch05", "ch05-motion-blur"),
    ("ch06", "ch06-fuzzy-reflections"),
    ("ch07", "ch07-soft-shadows"),
    ("ch08", "ch08-path-tracing"),
    ("ch09", "ch09-materials"),
    ("ch10", "ch10-optimal-mis"),
    ("ch11", "ch11-path-guiding"),
];

/// Each chapter's figure writer, in the order of [`CHAPTERS`]. Only the `figures` feature
/// links the chapters into the builder: without it (the student edition's default), the tools
/// around the exercises start without compiling any chapter.
#[cfg(feature = "figures")]
const WRITERS: &[WriteFigures] = &[
    ch01_whitted::lab::figures::write_all,
    ch02_monte_carlo::lab::figures::write_all,
    ch03_anti_aliasing::lab::figures::write_all,
    ch04_depth_of_field::lab::figures::write_all,
    ch05_motion_blur::lab::figures::write_all,
    ch06_fuzzy_reflections::lab::figures::write_all,
    ch07_soft_shadows::lab::figures::write_all,
    ch08_path_tracing::lab::figures::write_all,
    ch09_materials::lab::figures::write_all,
    ch10_optimal_mis::lab::figures::write_all,
    ch11_path_guiding::lab::figures::write_all,
];

/// The name of the table of every figure's cost, beside the chapters' folders.
pub const COST_TABLE: &str = "figure-times.md";

/// Regenerates every chapter's figures under `figures_dir`, starting each chapter from an empty
/// directory so that no figure the code no longer makes lingers on a page.
#[cfg(feature = "figures")]
pub fn regenerate_all(figures_dir: &Path, quick: bool) -> Result<()> {
    let quality = if quick { "quick" } else { "full quality" };
    for ((chapter, _), write_all) in CHAPTERS.iter().zip(WRITERS) {
        let out_dir = figures_dir.join(chapter);
        println!("Figures of {chapter} ({quality}) -> {}", out_dir.display());
        let started = std::time::Instant::now();

        if out_dir.exists() {
            std::fs::remove_dir_all(&out_dir)
                .with_context(|| format!("cannot clear {}", out_dir.display()))?;
        }
        std::fs::create_dir_all(&out_dir)
            .with_context(|| format!("cannot create {}", out_dir.display()))?;
        write_all(&out_dir, quick).with_context(|| format!("figures of {chapter} failed"))?;

        println!("  done in {:.1} s", started.elapsed().as_secs_f64());
    }
    write_cost_table(figures_dir)
}

/// Writes [`COST_TABLE`] from the chapters' folders under `figures_dir`.
pub fn write_cost_table(figures_dir: &Path) -> Result<()> {
    let table = cost_table(figures_dir)?;
    workbench::output::write_text(&figures_dir.join(COST_TABLE), &table)
        .context("cannot write the table of figure times")
}

/// What every figure of this run cost, from each chapter's `figure-times.csv`: a Markdown
/// table for the speed appendix, one row per figure and a total per chapter, so that the
/// expensive figures are named on every build. Beside each time stands the figure's quality
/// where its error-against-time runs measure one: the smallest RMSE against their reference,
/// which a cheaper reference or fewer samples would raise. Other figures say "not measured"
/// (a gallery has no reference; the comparison with Mitsuba 3 reports its own numbers).
fn cost_table(figures_dir: &Path) -> Result<String> {
    let mut table = String::from(
        "| chapter | figure | seconds | smallest RMSE against its reference |\n|---|---|---:|---:|\n",
    );
    let mut total = 0.0;
    for (chapter, _) in CHAPTERS {
        let mut chapter_total = 0.0;
        for cost in workbench::figure_set::read_times(&figures_dir.join(chapter))? {
            let rmse = cost
                .rmse
                .map(|rmse| format!("{rmse:.2e}"))
                .unwrap_or_else(|| "not measured".to_string());
            table += &format!(
                "| {chapter} | {} | {:.2} | {rmse} |\n",
                cost.figure, cost.seconds
            );
            chapter_total += cost.seconds;
        }
        table += &format!(
            "| **{chapter}** | **all of the chapter's figures** | **{chapter_total:.2}** | |\n"
        );
        total += chapter_total;
    }
    table += &format!("| **all** | **every figure of the book** | **{total:.2}** | |\n");
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;
    use workbench::figure_set::TIMES_FILE;

    #[cfg(feature = "figures")]
    #[test]
    fn every_chapter_has_its_writer() {
        assert_eq!(CHAPTERS.len(), WRITERS.len());
    }

    #[test]
    fn the_cost_table_lists_every_figure_and_the_totals() {
        let dir = tempfile::tempdir().unwrap();
        for (index, (chapter, _)) in CHAPTERS.iter().enumerate() {
            std::fs::create_dir_all(dir.path().join(chapter)).unwrap();
            let csv = format!(
                "figure,seconds,rmse\nthe gallery,{}.3,\nthe plot,0.5,1.25e-3\n",
                index + 1
            );
            std::fs::write(dir.path().join(chapter).join(TIMES_FILE), csv).unwrap();
        }
        let table = cost_table(dir.path()).unwrap();
        assert!(
            table.contains("| ch01 | the gallery | 1.30 | not measured |"),
            "{table}"
        );
        assert!(
            table.contains("| ch01 | the plot | 0.50 | 1.25e-3 |"),
            "{table}"
        );
        assert!(
            table.contains("| **ch01** | **all of the chapter's figures** | **1.80** | |"),
            "{table}"
        );
        // 1.3 + 2.3 + ... and a half for each chapter.
        let n = CHAPTERS.len() as f64;
        let total = n * (n + 1.0) / 2.0 + 0.8 * n;
        assert!(
            table.contains(&format!(
                "| **every figure of the book** | **{total:.2}** | |"
            )),
            "{table}"
        );
        assert_eq!(table.lines().count(), 2 + CHAPTERS.len() * 3 + 1);
    }
}
