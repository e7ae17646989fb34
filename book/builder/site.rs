//! The site: mdBook with the exercise and KaTeX preprocessors, built as a library.
//!
//! mdBook runs in-process, so building the book needs nothing installed beyond cargo. The two
//! extra preprocessors are registered in code; mdBook appends them after its built-in ones
//! (`index`, then `links`), so they see every `{{#include}}` already expanded.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use mdbook_driver::MDBook;
use mdbook_katex::preprocess::KatexProcessor;
use mdbook_preprocessor::Preprocessor;

use crate::exercise_preprocessor::ExercisePreprocessor;
use crate::{katex_offline, mdbook_log, offline_check, page_shape, prose_numbers};

/// Builds the book whose `book.toml` is in `book_dir`; returns the path of its front page.
pub fn build(book_dir: &Path) -> Result<PathBuf> {
    build_with(book_dir, None::<ExercisePreprocessor>)
}

/// Builds the book with one more preprocessor run after the exercises and before KaTeX.
///
/// The lab report (`progress --site`) uses it to set the student's figures beside the
/// reference ones; taking any preprocessor keeps the site unaware of the lab report, which
/// sits above it.
pub fn build_with(book_dir: &Path, extra: Option<impl Preprocessor + 'static>) -> Result<PathBuf> {
    // A number typed into a page fails the build before anything is written.
    prose_numbers::check(book_dir.parent().unwrap_or(book_dir), &book_dir.join("src"))?;
    // So does a chapter page without its diagram, its questions or its way to the primer.
    page_shape::check(&book_dir.join("src"))?;
    let mut book = MDBook::load(book_dir)
        .with_context(|| format!("cannot load the book in {}", book_dir.display()))?;
    katex_offline::configure(&mut book.config)?;
    book.with_preprocessor(ExercisePreprocessor);
    if let Some(extra) = extra {
        book.with_preprocessor(extra);
    }
    book.with_preprocessor(KatexProcessor);

    let problems_before = mdbook_log::problems_so_far();
    book.build().context("mdBook could not build the site")?;
    let problems = mdbook_log::problems_so_far() - problems_before;
    if problems > 0 {
        bail!("{problems} problem(s) would leave broken pages; see the messages above");
    }

    let site_dir = book.build_dir_for("html");
    katex_offline::copy_fonts_and_licence(book_dir, &site_dir)?;
    offline_check::ensure_offline(&site_dir)?;
    Ok(site_dir.join("index.html"))
}
