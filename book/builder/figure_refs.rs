//! No page refers to a figure its chapter's figures do not write.
//!
//! Figures are generated, never committed ([`crate::figures`]), so a page that names a file the
//! figure writer stopped making (renamed, dropped, written only at full quality) would show a
//! broken image, or fail the build on an `{{#include}}`, only once someone builds the site, and
//! the quick build CI runs would miss a figure only the full one writes. [`problems`] compares
//! what the hand-written pages refer to under `figures/` (images, included tables and
//! sentences, CSVs, SVGs, links) with the files each chapter's writer has written, and names
//! the page, the line and the file for every reference with no file behind it. The site build
//! runs it on the figures it has just written; a test runs it on every chapter's quick figures.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

use anyhow::{Context, Result};

/// One reference of a page to a generated figure: `figures/<chapter>/<file>`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FigureRef {
    /// The line (from 1) it is on.
    pub line: usize,
    /// The chapter id, the folder below `figures/`: `ch10`.
    pub chapter: String,
    /// The file below the chapter's folder, `/` between folders: `diagrams/covered-and-left.svg`.
    pub file: String,
}

/// The files a page refers to below `figures/`, in order. Code is not a reference (a page may
/// show how a reference is written), except an `{{#include}}` directive, which mdBook expands
/// inside code blocks too (unless escaped with a backslash).
pub fn references(page: &str) -> Vec<FigureRef> {
    let mut found = Vec::new();
    let mut in_fence = false;
    for (index, line) in page.lines().enumerate() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("```") || trimmed.starts_with("~~~") {
            in_fence = !in_fence;
            continue;
        }
        let directive = trimmed.starts_with("{{#include") || trimmed.starts_with("{{#exercise");
        let text = if directive {
            line.to_string()
        } else if in_fence {
            continue;
        } else {
            without_code_spans(line)
        };
        for (chapter, file) in figure_paths(&text) {
            found.push(FigureRef {
                line: index + 1,
                chapter,
                file,
            });
        }
    }
    found
}

/// `line` with its inline code spans (between backticks) left out.
fn without_code_spans(line: &str) -> String {
    line.split('`').step_by(2).collect::<Vec<_>>().join(" ")
}

/// Every `figures/<chapter>/<file>` in `text` that starts a path (after `(`, a quote, a space
/// or the line's start, and not `src/figures/...`, the folder named in prose), as `(chapter,
/// file)`; an include's `:anchor` or a link's `#fragment` left out.
fn figure_paths(text: &str) -> Vec<(String, String)> {
    const PREFIX: &str = "figures/";
    let mut paths = Vec::new();
    let mut from = 0;
    while let Some(at) = text[from..].find(PREFIX).map(|at| at + from) {
        from = at + PREFIX.len();
        let starts_path = text[..at]
            .chars()
            .next_back()
            .is_none_or(|c| matches!(c, '(' | '"' | '\'' | ' ' | '='));
        if !starts_path || text[..at].ends_with("\\{{#include ") {
            continue;
        }
        let rest = &text[from..];
        let end = rest
            .find(|c: char| c.is_whitespace() || matches!(c, ')' | '"' | '\'' | '}' | '`' | '#'))
            .unwrap_or(rest.len());
        let path = &rest[..end];
        let path = path.split_once(':').map_or(path, |(file, _anchor)| file);
        let Some((chapter, file)) = path.split_once('/') else {
            continue;
        };
        // A placeholder such as `figures/<chapter id>/` names no file.
        if file.is_empty() || path.contains(['<', '>', '*']) {
            continue;
        }
        paths.push((chapter.to_string(), file.to_string()));
    }
    paths
}

/// The files under `dir`, each as its path below `dir` with `/` between folders.
pub fn files_under(dir: &Path) -> Result<BTreeSet<String>> {
    let mut files = BTreeSet::new();
    for path in crate::workspace::files_under(dir)? {
        let relative = path.strip_prefix(dir).unwrap_or(&path);
        let parts: Vec<_> = relative
            .components()
            .map(|c| c.as_os_str().to_string_lossy())
            .collect();
        files.insert(parts.join("/"));
    }
    Ok(files)
}

/// Every reference of `pages` (name and text) to a figure that `written` (each chapter id's
/// files) does not hold, as `page:line: ...` messages that name the file, the chapter and
/// what the chapter does write.
pub fn problems(
    pages: &[(String, String)],
    written: &BTreeMap<String, BTreeSet<String>>,
) -> Vec<String> {
    let mut problems = Vec::new();
    for (name, text) in pages {
        for reference in references(text) {
            let FigureRef {
                line,
                chapter,
                file,
            } = &reference;
            let Some(files) = written.get(chapter) else {
                problems.push(format!(
                    "{name}:{line}: refers to figures/{chapter}/{file}, but no chapter writes \
                     figures into figures/{chapter}/ (the chapters with figures are {})",
                    written.keys().cloned().collect::<Vec<_>>().join(", ")
                ));
                continue;
            };
            if !files.contains(file) {
                let listed = if files.is_empty() {
                    "nothing at all".to_string()
                } else {
                    files.iter().cloned().collect::<Vec<_>>().join(", ")
                };
                problems.push(format!(
                    "{name}:{line}: refers to figures/{chapter}/{file}, which {chapter}'s \
                     figures do not write: a renamed or dropped figure, or one written only \
                     at one quality? They write {listed}"
                ));
            }
        }
    }
    problems
}

/// The hand-written pages under `book_src` (every `.md` file but the generated `figures/`),
/// each as its path below `book_src` and its text, sorted by path.
pub fn pages(book_src: &Path) -> Result<Vec<(String, String)>> {
    let mut pages = Vec::new();
    for name in files_under(book_src)? {
        if name.starts_with("figures/") || !name.ends_with(".md") {
            continue;
        }
        let path = book_src.join(&name);
        let text = std::fs::read_to_string(&path)
            .with_context(|| format!("cannot read {}", path.display()))?;
        pages.push((name, text));
    }
    Ok(pages)
}

/// Fails, listing every problem, unless each figure the pages of `book_src` refer to is among
/// the files under `figures_dir/<chapter id>/` for the chapter ids given.
pub fn check(book_src: &Path, figures_dir: &Path, chapters: &[&str]) -> Result<()> {
    let mut written = BTreeMap::new();
    for chapter in chapters {
        let dir = figures_dir.join(chapter);
        let files = if dir.exists() {
            files_under(&dir)?
        } else {
            BTreeSet::new()
        };
        written.insert(chapter.to_string(), files);
    }
    let problems = problems(&pages(book_src)?, &written);
    if !problems.is_empty() {
        anyhow::bail!(
            "{} reference(s) to a figure that no figure writer wrote:\n{}",
            problems.len(),
            problems.join("\n")
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn refs(page: &str) -> Vec<(usize, String, String)> {
        references(page)
            .into_iter()
            .map(|r| (r.line, r.chapter, r.file))
            .collect()
    }

    #[test]
    fn images_includes_and_links_are_references_and_code_is_not() {
        let page = "# A page\n\
            ![The plot](figures/ch02/plot.png)\n\
            {{#include figures/ch02/table.md}}\n\
            <img src=\"figures/ch03/a.svg\" alt=\"a\">\n\
            See [the data](figures/ch02/data.csv#top) and `![x](figures/ch02/shown.png)`.\n\
            Written into `book/src/figures/<chapter id>/` and book/src/figures/ch02/x.png.\n\
            ```markdown\n\
            ![In a fence](figures/ch02/fenced.png)\n\
            {{#include figures/ch02/expanded.md}}\n\
            ```\n\
            \\{{#include figures/ch02/escaped.md}}\n\
            ![A diagram](figures/ch10/diagrams/d.svg)\n";
        assert_eq!(
            refs(page),
            [
                (2, "ch02".into(), "plot.png".into()),
                (3, "ch02".into(), "table.md".into()),
                (4, "ch03".into(), "a.svg".into()),
                (5, "ch02".into(), "data.csv".into()),
                (9, "ch02".into(), "expanded.md".into()),
                (12, "ch10".into(), "diagrams/d.svg".into()),
            ]
        );
    }

    #[test]
    fn a_figure_no_writer_wrote_is_named_with_page_line_and_chapter() {
        let written = BTreeMap::from([(
            "ch02".to_string(),
            BTreeSet::from(["plot.png".to_string(), "table.md".to_string()]),
        )]);
        let page = "![The plot](figures/ch02/plot.png)\n\
            {{#include figures/ch02/table.md}}\n\
            ![Gone](figures/ch02/renamed.png)\n\
            ![Elsewhere](figures/ch99/x.png)\n";
        let problems = problems(&[("ch02-page.md".to_string(), page.to_string())], &written);
        assert_eq!(problems.len(), 2, "{problems:?}");
        assert!(
            problems[0].starts_with("ch02-page.md:3: refers to figures/ch02/renamed.png")
                && problems[0].contains("ch02's figures do not write")
                && problems[0].contains("They write plot.png, table.md"),
            "{}",
            problems[0]
        );
        assert!(
            problems[1].starts_with("ch02-page.md:4: refers to figures/ch99/x.png")
                && problems[1].contains("no chapter writes figures into figures/ch99/"),
            "{}",
            problems[1]
        );
    }

    /// The promise itself: every chapter's quick figures, written into a fresh folder, hold
    /// every file a page of the book refers to (the full-quality figures write the same names:
    /// the site build checks them too, after writing them).
    ///
    /// Ignored in the suite: it writes every chapter's figures (about two minutes), and every
    /// site build, CI's included, runs the same check on the figures it has just written.
    /// `cargo test -p book --lib figure_refs -- --ignored` runs it alone.
    #[cfg(feature = "figures")]
    #[test]
    #[ignore = "the site build runs this check on the figures it writes (two minutes here)"]
    fn every_figure_a_page_refers_to_is_written_by_the_quick_figures() {
        let root = crate::workspace::root();
        let figures_dir = tempfile::tempdir().unwrap();
        crate::figures::regenerate_all(figures_dir.path(), true).unwrap();
        let chapters: Vec<&str> = crate::figures::CHAPTERS.iter().map(|(id, _)| *id).collect();
        if let Err(error) = check(
            &root.join("book").join("src"),
            figures_dir.path(),
            &chapters,
        ) {
            panic!("{error:#}");
        }
    }
}
