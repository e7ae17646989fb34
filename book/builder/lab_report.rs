//! `progress --site`: the student's own site, like a lab report. Each chapter whose exercises
//! (and those of every chapter before it) are done gets its figures rendered by the student's
//! code, and the pages show them beside the reference figures, side by side at the same size;
//! a chapter not done yet shows the reference figures alone and says so, at the top of its page
//! and under each figure.
//!
//! The reference figures are the workbook's, copied into the student edition by `book student`
//! (into [`REFERENCE_DIR`]) when the workbook's site had been built. The student's figures are
//! rendered by each finished chapter's own binary (`figures --out DIR`), so this is the one
//! tool besides the checks that compiles the student's code, and only the chapters it renders.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use anyhow::{Context, Result, bail};
use mdbook_driver::book::Book;
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};

use crate::exercise_list::Exercise;
use crate::figures;
use crate::progress::Status;

/// Where a student edition keeps the workbook's figures, relative to the workspace root.
pub const REFERENCE_DIR: &str = "book/reference-figures";
/// Where the site finds them, relative to the book's `src/`: inside the generated `figures/`,
/// which the prose check leaves alone, as it leaves the student's own figures.
const REFERENCE_IN_SITE: &str = "figures/reference";

/// How the student's figures are rendered.
#[derive(Clone, Copy, Debug)]
pub struct Quality {
    /// Full-size figures instead of quick ones.
    pub full: bool,
    /// Build the chapters' binaries optimised (`--release`).
    pub release: bool,
}

/// Renders the figures of every chapter the student has finished, puts the reference figures
/// beside them, and builds the site; returns the path of its front page.
pub fn build(
    root: &Path,
    exercises: &[Exercise],
    statuses: &[Status],
    quality: Quality,
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
    let in_site = book_dir.join("src").join(REFERENCE_IN_SITE);
    replace_dir(&in_site)?;
    copy_dir(&reference, &in_site)?;
    let mut chapters = Vec::new();
    for &(chapter, package) in figures::CHAPTERS {
        let out_dir = figures_dir.join(chapter);
        replace_dir(&out_dir)?;
        let (done, total) = done_up_to(chapter, exercises, statuses);
        let rendered = done == total && {
            print!("Your figures of {chapter} -> {} ... ", out_dir.display());
            let _ = std::io::Write::flush(&mut std::io::stdout());
            let started = std::time::Instant::now();
            match render_figures(root, package, &out_dir, quality) {
                Ok(()) => {
                    println!("written in {:.0} s", started.elapsed().as_secs_f64());
                    true
                }
                Err(error) => {
                    println!("failed\n  {error:#}\n  The page shows the reference figures.");
                    replace_dir(&out_dir)?;
                    false
                }
            }
        };
        if !rendered {
            copy_dir(&reference.join(chapter), &out_dir)?;
        }
        chapters.push(ChapterReport {
            id: chapter.to_owned(),
            yours: rendered,
            done,
            total,
        });
    }
    // The cost of this run's figures, yours and the reference's, for the speed appendix.
    if figures::write_cost_table(&figures_dir).is_err() {
        let table = reference.join(figures::COST_TABLE);
        if table.is_file() {
            std::fs::copy(&table, figures_dir.join(figures::COST_TABLE))
                .with_context(|| format!("cannot copy {}", table.display()))?;
        }
    }
    // The demos run the student's code: an exercise not written yet shows as such in them.
    crate::demos::build(root, &book_dir.join("src"))?;
    crate::site::build_with(&book_dir, Some(LabReport { chapters }))
}

/// How many of the exercises of `chapter` and every chapter before it are done, of how many.
fn done_up_to(chapter: &str, exercises: &[Exercise], statuses: &[Status]) -> (usize, usize) {
    let up_to: Vec<&Status> = exercises
        .iter()
        .zip(statuses)
        .filter(|(exercise, _)| chapter_id(&exercise.chapter) <= chapter)
        .map(|(_, status)| status)
        .collect();
    let done = up_to.iter().filter(|s| ***s == Status::Done).count();
    (done, up_to.len())
}

/// Runs the chapter's own binary to write its figures: `cargo run -p PACKAGE -- figures --out
/// DIR`, quick unless `quality.full`. What it prints is kept and shown only if it fails.
fn render_figures(root: &Path, package: &str, out_dir: &Path, quality: Quality) -> Result<()> {
    let mut command = Command::new("cargo");
    command.args(["run", "-q", "-p", package]);
    if quality.release {
        command.arg("--release");
    }
    command.args(["--", "figures", "--out"]).arg(out_dir);
    if !quality.full {
        command.arg("--quick");
    }
    let output = command
        .current_dir(root)
        .stdin(Stdio::null())
        .output()
        .with_context(|| format!("cannot run cargo for {package}"))?;
    if !output.status.success() {
        let printed = String::from_utf8_lossy(&output.stderr);
        let lines: Vec<&str> = printed.lines().collect();
        bail!(
            "{package}'s figures failed with your code; its last words:\n    {}",
            lines[lines.len().saturating_sub(12)..].join("\n    ")
        );
    }
    Ok(())
}

/// Copies the workbook's built figures into the student edition at `edition`, for the
/// student's site to set beside theirs; `false` if the workbook has no figures built.
pub fn ship_reference_figures(root: &Path, edition: &Path) -> Result<bool> {
    let built = root.join("book").join("src").join("figures");
    let any = figures::CHAPTERS
        .iter()
        .any(|(chapter, _)| built.join(chapter).is_dir());
    if any {
        copy_dir(&built, &edition.join(REFERENCE_DIR))?;
    }
    Ok(any)
}

/// The figure directory's name of a chapter's package: `ch03` for `ch03-anti-aliasing`.
fn chapter_id(package: &str) -> &str {
    package.split('-').next().unwrap_or(package)
}

/// Makes `dir` an empty directory.
fn replace_dir(dir: &Path) -> Result<()> {
    if dir.exists() {
        std::fs::remove_dir_all(dir).with_context(|| format!("cannot clear {}", dir.display()))?;
    }
    std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))
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

/// Where one chapter stands in the lab report.
#[derive(Clone, Debug)]
pub struct ChapterReport {
    /// Its figure directory: `ch01`.
    pub id: String,
    /// Whether its figures on the site are the student's.
    pub yours: bool,
    /// Exercises done, of all those up to this chapter.
    pub done: usize,
    pub total: usize,
}

/// The preprocessor that sets the student's figures beside the reference ones.
pub struct LabReport {
    /// Every chapter with figures, in book order.
    pub chapters: Vec<ChapterReport>,
}

impl Preprocessor for LabReport {
    fn name(&self) -> &str {
        "lab-report"
    }

    fn run(&self, _context: &PreprocessorContext, mut book: Book) -> Result<Book> {
        book.for_each_chapter_mut(|chapter| {
            let page = chapter
                .path
                .as_deref()
                .and_then(Path::file_name)
                .map(|name| name.to_string_lossy().into_owned())
                .unwrap_or_default();
            chapter.content = self.page(&page, &chapter.content);
        });
        Ok(book)
    }
}

impl LabReport {
    fn chapter(&self, id: &str) -> Option<&ChapterReport> {
        self.chapters.iter().find(|chapter| chapter.id == id)
    }

    /// The page `file` (`ch04-depth-of-field.md`) with a note on where its chapter stands, and
    /// every figure shown as the student's beside the reference, or as the reference.
    fn page(&self, file: &str, page: &str) -> String {
        let mut out = String::with_capacity(page.len() + 1024);
        let mut lines = page.split_inclusive('\n').peekable();
        // The note goes after the page's title.
        if let Some(report) = self.chapter(chapter_id(file)) {
            while let Some(line) = lines.next_if(|line| !line.starts_with("# ")) {
                out.push_str(line);
            }
            if let Some(title) = lines.next() {
                out.push_str(title);
            }
            out.push_str(&format!("\n{}\n", self.note(report)));
        }
        for line in lines {
            self.line(line, &mut out);
        }
        out
    }

    /// The lab report's note at the top of a chapter's page.
    fn note(&self, report: &ChapterReport) -> String {
        let number = report.id.trim_start_matches("ch");
        let text = if report.yours {
            "<strong>Your lab report.</strong> Each figure of this chapter is rendered by your \
             code, on the left, beside the reference figure, on the right."
                .to_owned()
        } else {
            format!(
                "<strong>Your lab report.</strong> Not finished yet: {} of the {} exercises up to \
                 chapter {number} are done. The figures below are the reference ones; yours take \
                 their place once all are done (<code>cargo run -p book -- progress</code> says \
                 what is next).",
                report.done, report.total
            )
        };
        format!("<p class=\"lab-report-note\">{text}</p>\n")
    }

    /// One line of a page, its figures replaced, appended to `out`.
    fn line(&self, line: &str, out: &mut String) {
        let alone = next_figure(line).is_some_and(|(before, _, _, after)| {
            before.trim().is_empty() && after.trim().is_empty()
        });
        let mut rest = line;
        while let Some((before, alt, path, after)) = next_figure(rest) {
            out.push_str(before);
            let chapter = path.split('/').nth(1).unwrap_or("");
            let file = path.strip_prefix("figures/").unwrap_or(path);
            let reference = format!("{REFERENCE_IN_SITE}/{file}");
            let alt = alt.replace('"', "&quot;");
            let (tag, caption) = if alone {
                ("figure", "figcaption")
            } else {
                ("span", "span")
            };
            match self.chapter(chapter) {
                Some(report) if report.yours => out.push_str(&format!(
                    "<{tag} class=\"lab-report\"><{tag}><img src=\"{path}\" alt=\"{alt} (yours)\">\
                     <{caption}>Yours</{caption}></{tag}><{tag}><img src=\"{reference}\" \
                     alt=\"{alt} (reference)\"><{caption}>Reference</{caption}></{tag}></{tag}>"
                )),
                _ => out.push_str(&format!(
                    "<{tag} class=\"lab-report-pending\"><img src=\"{path}\" alt=\"{alt} \
                     (reference)\"><{caption}>Reference figure: yours appears here once the \
                     exercises up to chapter {} are done.</{caption}></{tag}>",
                    chapter.trim_start_matches("ch")
                )),
            }
            rest = after;
        }
        out.push_str(rest);
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

    fn report() -> LabReport {
        let chapter = |id: &str, yours: bool, done: usize| ChapterReport {
            id: id.into(),
            yours,
            done,
            total: 6,
        };
        LabReport {
            chapters: vec![chapter("ch01", true, 6), chapter("ch05", false, 4)],
        }
    }

    #[test]
    fn a_finished_chapter_shows_both_figures_side_by_side() {
        let page = "# Whitted\n\nText.\n\n![The \"spheres\"](figures/ch01/spheres.png)\n\nSee \
                    ![Blur](figures/ch05/street.png) inline.\n";
        let shown = report().page("ch01-whitted.md", page);
        assert!(
            shown.starts_with("# Whitted\n\n<p class=\"lab-report-note\"><strong>Your lab report.</strong> Each figure"),
            "{shown}"
        );
        assert!(
            shown.contains(
                "<figure class=\"lab-report\"><figure><img src=\"figures/ch01/spheres.png\" \
                 alt=\"The &quot;spheres&quot; (yours)\"><figcaption>Yours</figcaption></figure>\
                 <figure><img src=\"figures/reference/ch01/spheres.png\" alt=\"The \
                 &quot;spheres&quot; (reference)\"><figcaption>Reference</figcaption></figure></figure>\n"
            ),
            "{shown}"
        );
        // Inline, a figure of a chapter not done: spans, and the reason.
        assert!(
            shown.contains(
                "See <span class=\"lab-report-pending\"><img src=\"figures/ch05/street.png\" \
                 alt=\"Blur (reference)\"><span>Reference figure: yours appears here once the \
                 exercises up to chapter 05 are done.</span></span> inline.\n"
            ),
            "{shown}"
        );
    }

    #[test]
    fn an_unfinished_chapter_says_how_far_it_is() {
        let shown = report().page("ch05-motion-blur.md", "# Motion blur\n");
        assert!(
            shown.contains("Not finished yet: 4 of the 6 exercises up to chapter 05 are done."),
            "{shown}"
        );
    }

    #[test]
    fn other_pages_images_and_text_are_left_alone() {
        let page = "![logo](theme/logo.png) and [a link](figures/ch01/x.csv) ![";
        assert_eq!(report().page("introduction.md", page), page);
        assert_eq!(chapter_id("ch03-anti-aliasing"), "ch03");
    }

    #[test]
    fn only_the_exercises_up_to_a_chapter_count() {
        let exercise = |name: &str, chapter: &str| Exercise {
            name: name.into(),
            chapter: chapter.into(),
            file: "f.rs".into(),
            anchor: name.into(),
            check: "true".into(),
            hint: String::new(),
            needs: Vec::new(),
            wrong: Vec::new(),
            giveaway: Vec::new(),
        };
        let exercises = [
            exercise("a", "ch01-whitted"),
            exercise("b", "ch02-monte-carlo"),
            exercise("c", "ch03-anti-aliasing"),
        ];
        let statuses = [Status::Done, Status::Done, Status::ToDo];
        assert_eq!(done_up_to("ch02", &exercises, &statuses), (2, 2));
        assert_eq!(done_up_to("ch03", &exercises, &statuses), (2, 3));
    }
}
