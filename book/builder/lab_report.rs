//! `progress --site`: the student's own site, like a lab report. Each chapter whose exercises
//! (and those of every chapter before it) are done gets its figures rendered by the student's
//! code, and the pages show them beside the reference figures; a chapter not done yet shows the
//! reference figures alone, saying so.
//!
//! The reference figures are the workbook's, copied into the student edition by `book student`
//! (into [`REFERENCE_DIR`]) when the workbook's site had been built.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};
use mdbook_driver::book::Book;
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};

use crate::exercise_list::Exercise;
use crate::figures;
use crate::progress::Status;

/// Where a student edition keeps the workbook's figures, relative to the workspace root.
pub const REFERENCE_DIR: &str = "book/reference-figures";
/// Where the site finds them, relative to the book's `src/`.
const REFERENCE_IN_SITE: &str = "reference-figures";

/// Renders the figures of every chapter the student has finished, puts the reference figures
/// beside them, and builds the site; returns the path of its front page.
pub fn build(
    root: &Path,
    exercises: &[Exercise],
    statuses: &[Status],
    full: bool,
) -> Result<PathBuf> {
    let reference = root.join(REFERENCE_DIR);
    if !reference.is_dir() {
        bail!(
            "this edition has no reference figures ({REFERENCE_DIR} is missing), so there is \
             nothing to put your figures beside: write the student edition again from a workbook \
             whose site has been built (`cargo run --release -p book` there first)"
        );
    }
    let book_dir = root.join("book");
    let figures_dir = book_dir.join("src").join("figures");
    let mut yours = Vec::new();
    for (chapter, write_all) in figures::CHAPTERS {
        let out_dir = figures_dir.join(chapter);
        if out_dir.exists() {
            std::fs::remove_dir_all(&out_dir)
                .with_context(|| format!("cannot clear {}", out_dir.display()))?;
        }
        std::fs::create_dir_all(&out_dir)
            .with_context(|| format!("cannot create {}", out_dir.display()))?;
        let ready = exercises
            .iter()
            .zip(statuses)
            .filter(|(exercise, _)| chapter_id(&exercise.chapter) <= *chapter)
            .all(|(_, status)| *status == Status::Done);
        let rendered = ready && {
            println!("Your figures of {chapter} -> {}", out_dir.display());
            // The student's code renders them; a panic in it must not lose the site.
            let quick = !full;
            match std::panic::catch_unwind(|| write_all(&out_dir, quick)) {
                Ok(Ok(())) => true,
                Ok(Err(error)) => {
                    println!("  failed ({error:#}); the page shows the reference figures");
                    false
                }
                Err(_) => {
                    println!("  your code panicked; the page shows the reference figures");
                    false
                }
            }
        };
        if rendered {
            yours.push(chapter.to_string());
        } else {
            copy_dir(&reference.join(chapter), &out_dir)?;
        }
    }
    let in_site = book_dir.join("src").join(REFERENCE_IN_SITE);
    if in_site.exists() {
        std::fs::remove_dir_all(&in_site)
            .with_context(|| format!("cannot clear {}", in_site.display()))?;
    }
    copy_dir(&reference, &in_site)?;
    crate::site::build_with(&book_dir, Some(LabReport { yours }))
}

/// Copies the workbook's built figures into the student edition at `edition`, for the
/// student's site to set beside theirs; `false` if the workbook has no figures built.
pub fn ship_reference_figures(root: &Path, edition: &Path) -> Result<bool> {
    let built = root.join("book").join("src").join("figures");
    let any = std::fs::read_dir(&built).is_ok_and(|mut entries| entries.next().is_some());
    if any {
        copy_dir(&built, &edition.join(REFERENCE_DIR))?;
    }
    Ok(any)
}

/// The figure directory's name of a chapter's package: `ch03` for `ch03-anti-aliasing`.
fn chapter_id(package: &str) -> &str {
    package.split('-').next().unwrap_or(package)
}

fn copy_dir(from: &Path, to: &Path) -> Result<()> {
    std::fs::create_dir_all(to).with_context(|| format!("cannot create {}", to.display()))?;
    let Ok(entries) = std::fs::read_dir(from) else {
        return Ok(()); // a chapter without reference figures
    };
    for entry in entries {
        let path = entry?.path();
        let target = to.join(path.file_name().expect("an entry has a name"));
        if path.is_dir() {
            copy_dir(&path, &target)?;
        } else {
            std::fs::copy(&path, &target)
                .with_context(|| format!("cannot copy {}", path.display()))?;
        }
    }
    Ok(())
}

/// The preprocessor that sets the student's figures beside the reference ones.
pub struct LabReport {
    /// The chapters (figure directories: `ch01`) whose figures the student's code rendered.
    pub yours: Vec<String>,
}

impl Preprocessor for LabReport {
    fn name(&self) -> &str {
        "lab-report"
    }

    fn run(&self, _context: &PreprocessorContext, mut book: Book) -> Result<Book> {
        book.for_each_chapter_mut(|chapter| {
            chapter.content = self.page(&chapter.content);
        });
        Ok(book)
    }
}

impl LabReport {
    /// `page` with every figure image shown as yours beside the reference, or marked as the
    /// reference.
    fn page(&self, page: &str) -> String {
        let mut out = String::with_capacity(page.len());
        let mut rest = page;
        while let Some((before, alt, path, after)) = next_figure(rest) {
            out.push_str(before);
            let chapter = path.split('/').nth(1).unwrap_or("");
            let file = path.split_once('/').map_or(path, |(_, file)| file);
            if self.yours.iter().any(|yours| yours == chapter) {
                out.push_str(&format!(
                    "<span class=\"lab-report\"><span><img src=\"{path}\" alt=\"{alt} (yours)\" \
                     width=\"49%\"><br>Yours</span> <span><img src=\"{REFERENCE_IN_SITE}/{file}\" \
                     alt=\"{alt} (reference)\" width=\"49%\"><br>Reference</span></span>"
                ));
            } else {
                out.push_str(&format!(
                    "![{alt} (reference)]({path})<br>*Reference figure: yours appears here once \
                     the exercises up to chapter {} are done.*",
                    chapter.trim_start_matches("ch")
                ));
            }
            rest = after;
        }
        out.push_str(rest);
        out
    }
}

/// The first `![alt](figures/...)` in `text`: what comes before it, its alt text and path, and
/// what comes after it.
fn next_figure(text: &str) -> Option<(&str, &str, &str, &str)> {
    let mut from = 0;
    while let Some(offset) = text[from..].find("![") {
        let start = from + offset;
        let close = text[start..].find("](figures/")?;
        let alt = &text[start + 2..start + close];
        let path_start = start + close + 2;
        if !alt.contains(['\n', ']'])
            && let Some(end) = text[path_start..].find(')')
        {
            let path = &text[path_start..path_start + end];
            return Some((&text[..start], alt, path, &text[path_start + end + 1..]));
        }
        from = start + 2;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finished_chapters_show_both_figures_and_the_others_the_reference() {
        let report = LabReport {
            yours: vec!["ch01".into()],
        };
        let page = "See ![The spheres](figures/ch01/spheres.png) and\n\
                    ![Blur](figures/ch05/street.png).\n";
        let shown = report.page(page);
        assert!(
            shown.starts_with("See <span class=\"lab-report\">"),
            "{shown}"
        );
        assert!(shown.contains("src=\"figures/ch01/spheres.png\" alt=\"The spheres (yours)\""));
        assert!(
            shown.contains("src=\"reference-figures/ch01/spheres.png\""),
            "{shown}"
        );
        assert!(
            shown.contains("![Blur (reference)](figures/ch05/street.png)<br>*Reference figure: yours appears here once the exercises up to chapter 05 are done.*."),
            "{shown}"
        );
    }

    #[test]
    fn other_images_and_text_are_left_alone() {
        let report = LabReport { yours: vec![] };
        let page = "![logo](theme/logo.png) and [a link](figures/ch01/x.csv) ![";
        assert_eq!(report.page(page), page);
        assert_eq!(chapter_id("ch03-anti-aliasing"), "ch03");
    }
}
