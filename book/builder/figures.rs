//! Every chapter's figures, regenerated before each build of the site.
//!
//! Figures are outputs of the chapters' code, never hand-made files: a page always shows what
//! the code it explains produces today. Each chapter writes its figures into its own directory
//! `book/src/figures/<chapter id>/`, and its page refers to them relatively, e.g.
//! `![](figures/ch01/spheres.png)`.

use std::path::Path;
use std::time::Instant;

use anyhow::{Context, Result};

/// A chapter's figure writer: fills `out_dir` with PNG and CSV files. With `quick` set it makes
/// small, fast versions (for CI and for checking a page's layout); otherwise full quality.
pub type WriteFigures = fn(out_dir: &Path, quick: bool) -> Result<()>;

/// The chapters with figures, in book order: a chapter id (its figure directory) and its writer.
/// A new chapter registers its figures by adding one line here.
pub const CHAPTERS: &[(&str, WriteFigures)] = &[
    ("ch01", ch01_whitted::figures::write_all),
    ("ch02", ch02_monte_carlo::figures::write_all),
    ("ch03", ch03_anti_aliasing::figures::write_all),
    ("ch04", ch04_depth_of_field::figures::write_all),
    ("ch05", ch05_motion_blur::figures::write_all),
    ("ch06", ch06_fuzzy_reflections::figures::write_all),
    ("ch07", ch07_soft_shadows::figures::write_all),
    ("ch08", ch08_path_tracing::figures::write_all),
];

/// Regenerates every chapter's figures under `figures_dir`, starting each chapter from an empty
/// directory so that no figure the code no longer makes lingers on a page.
pub fn regenerate_all(figures_dir: &Path, quick: bool) -> Result<()> {
    let quality = if quick { "quick" } else { "full quality" };
    for (chapter, write_all) in CHAPTERS {
        let out_dir = figures_dir.join(chapter);
        println!("Figures of {chapter} ({quality}) -> {}", out_dir.display());
        let started = Instant::now();

        if out_dir.exists() {
            std::fs::remove_dir_all(&out_dir)
                .with_context(|| format!("cannot clear {}", out_dir.display()))?;
        }
        std::fs::create_dir_all(&out_dir)
            .with_context(|| format!("cannot create {}", out_dir.display()))?;
        write_all(&out_dir, quick).with_context(|| format!("figures of {chapter} failed"))?;

        println!("  done in {:.1} s", started.elapsed().as_secs_f64());
    }
    Ok(())
}
