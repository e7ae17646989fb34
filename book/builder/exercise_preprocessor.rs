//! The book's side of the exercises: stubs on the page, solutions only after their exercise.
//!
//! Three things happen to every chapter, after mdBook's own `links` preprocessor has expanded
//! the `{{#include}}`s:
//!
//! - a line `{{#exercise path/to/file.rs:anchor}}` becomes a Rust code block showing that
//!   anchor with its solution replaced by `todo!()`, cut out as in the student edition,
//!   followed by the solution in a collapsed "Solution" block;
//! - a solution region inside any other code block (an `{{#include}}` of code that holds an
//!   exercise) is shown as its `todo!()` too, so no page gives an answer away before its
//!   exercise; marker lines outside code blocks are dropped;
//! - a page that writes out a line of any exercise's solution outside its "Solution" block is
//!   an error naming the page, the exercise and the line ([`solution_leaks`]); so is a page
//!   that states a solution's key expression, as a formula or inline code, before the exercise
//!   ([`giveaways`]).
//!
//! Both leave fenced code blocks alone where that matters: a `{{#exercise}}` line inside a fence
//! is shown as written (that is how a page documents the syntax). A page that needs to show the
//! markers themselves says so with the comment [`KEEP_MARKERS`].

use std::path::Path;

use anyhow::{Context, Result, bail};
use mdbook_driver::book::{Book, BookItem};
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};

use crate::solution_markers::{self, Marker, MarkerError};
use crate::{exercise_list, giveaways};

/// A page containing this comment keeps its solution marker lines.
pub const KEEP_MARKERS: &str = "<!-- keep solution markers -->";

/// Registered with the builder's `MDBook` after the built-in preprocessors, so it sees pages with
/// their includes expanded.
pub struct ExercisePreprocessor;

impl Preprocessor for ExercisePreprocessor {
    fn name(&self) -> &str {
        "exercises"
    }

    fn run(&self, context: &PreprocessorContext, mut book: Book) -> Result<Book> {
        let src_dir = context.root.join(&context.config.book.src);
        let workspace = context.root.parent().unwrap_or(Path::new("."));
        let solutions = known_solutions(workspace)?;
        let mut problems = giveaways_before_their_exercises(&book, workspace)?;
        book.for_each_chapter_mut(|chapter| {
            let Some(path) = &chapter.path else { return };
            let page_dir = src_dir.join(path.parent().unwrap_or(Path::new("")));
            match render_page(&chapter.content, &page_dir) {
                Ok(content) => {
                    for leak in solution_leaks(&content, &solutions) {
                        problems.push(format!("{}: {leak}", path.display()));
                    }
                    chapter.content = content;
                }
                Err(error) => problems.push(format!("{}: {error:#}", path.display())),
            }
        });
        if !problems.is_empty() {
            bail!("{}", problems.join("\n"));
        }
        Ok(book)
    }
}

/// Every key expression of a solution that a page states before its exercise, or that the
/// shipped code states outside a solution (see [`giveaways`]), over the pages in the book's
/// order.
fn giveaways_before_their_exercises(book: &Book, workspace: &Path) -> Result<Vec<String>> {
    let exercises = exercise_list::load(workspace)?;
    let pages: Vec<giveaways::Page> = book
        .iter()
        .filter_map(|item| match item {
            BookItem::Chapter(chapter) => chapter.path.as_ref().map(|path| giveaways::Page {
                name: path.display().to_string(),
                text: &chapter.content,
            }),
            _ => None,
        })
        .collect();
    let mut problems = giveaways::check(&pages, &exercises, shows_exercise);
    problems.extend(giveaways::in_code(workspace, &exercises)?);
    Ok(problems)
}

/// Whether `line` is the `{{#exercise}}` line that shows `exercise`.
fn shows_exercise(line: &str, exercise: &exercise_list::Exercise) -> bool {
    exercise_directive(line)
        .and_then(|target| target.rsplit_once(':'))
        .is_some_and(|(path, anchor)| {
            anchor == exercise.anchor && Path::new(path).ends_with(&exercise.file)
        })
}

/// One page with its exercises expanded and its marker lines dropped. Paths in `{{#exercise}}`
/// are relative to `page_dir`, like those of `{{#include}}`.
pub fn render_page(content: &str, page_dir: &Path) -> Result<String> {
    let keep_markers = content.contains(KEEP_MARKERS);
    let mut out = String::with_capacity(content.len());
    let mut open_fence: Option<Fence> = None;
    let mut in_solution = false;
    for line in content.lines() {
        let trimmed = line.trim_start();
        if !keep_markers && open_fence.is_some() {
            // A solution region in shown code: its `todo!()`, as the student sees it.
            match Marker::of_line(line) {
                Some(Marker::Begin) => {
                    let indent = &line[..line.len() - trimmed.len()];
                    out.push_str(indent);
                    out.push_str(&solution_markers::todo_call(None));
                    out.push('\n');
                    in_solution = true;
                    continue;
                }
                Some(Marker::End) => {
                    in_solution = false;
                    continue;
                }
                None if in_solution => continue,
                None => {}
            }
        }
        if let Some(fence) = Fence::of_line(trimmed) {
            open_fence = match open_fence {
                None => Some(fence),
                Some(open) if fence.closes(open) => None,
                still_open => still_open,
            };
        } else if open_fence.is_none()
            && let Some(target) = exercise_directive(trimmed)
        {
            let indent = &line[..line.len() - trimmed.len()];
            let block = exercise_block(target, page_dir)
                .with_context(|| format!("in `{}`", trimmed.trim_end()))?;
            for block_line in block.lines() {
                out.push_str(indent);
                out.push_str(block_line);
                out.push('\n');
            }
            continue;
        }
        if keep_markers || Marker::of_line(line).is_none() {
            out.push_str(line);
            out.push('\n');
        }
    }
    if !content.ends_with('\n') {
        out.pop();
    }
    Ok(out)
}

/// A code fence: its character (backtick or tilde) and length.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Fence {
    char: char,
    len: usize,
    has_info: bool,
}

impl Fence {
    /// The fence `trimmed` (a line without its indentation) starts with, if any.
    fn of_line(trimmed: &str) -> Option<Fence> {
        let char = trimmed.chars().next().filter(|c| *c == '`' || *c == '~')?;
        let len = trimmed.len() - trimmed.trim_start_matches(char).len();
        (len >= 3).then(|| Fence {
            char,
            len,
            has_info: !trimmed[len..].trim().is_empty(),
        })
    }

    /// Whether this fence closes the block `open` started: same character, at least as long,
    /// and nothing after it (as CommonMark has it).
    fn closes(self, open: Fence) -> bool {
        self.char == open.char && self.len >= open.len && !self.has_info
    }
}

/// The `path:anchor` of a `{{#exercise path:anchor}}` line.
fn exercise_directive(line: &str) -> Option<&str> {
    let inner = line
        .trim_end()
        .strip_prefix("{{#exercise")?
        .strip_suffix("}}")?;
    inner.starts_with(char::is_whitespace).then(|| inner.trim())
}

/// The code block for `path:anchor`.
fn exercise_block(target: &str, page_dir: &Path) -> Result<String> {
    let Some((path, anchor)) = target.rsplit_once(':') else {
        bail!("name the anchor too: {{{{#exercise path/to/file.rs:anchor}}}}");
    };
    let file = page_dir.join(path);
    let source = std::fs::read_to_string(&file)
        .with_context(|| format!("cannot read {}", file.display()))?;
    let stub = match solution_markers::book_stub(&source, anchor) {
        // A student edition: the exercise as the student has it, and no solution to show.
        Err(MarkerError::NoSolution { .. }) => {
            let written = solution_markers::book_as_written(&source, anchor)
                .with_context(|| format!("in {path}"))?;
            return Ok(format!("```rust\n{written}\n```\n"));
        }
        stub => stub.with_context(|| format!("in {path}"))?,
    };
    let solution =
        solution_markers::book_solution(&source, anchor).with_context(|| format!("in {path}"))?;
    Ok(format!(
        "```rust\n{stub}\n```\n\n{SOLUTION_OPEN}\n\n```rust\n{solution}\n```\n\n{SOLUTION_CLOSE}\n"
    ))
}

/// Opens the collapsed block that shows an exercise's solution after the exercise.
const SOLUTION_OPEN: &str = "<details class=\"solution\"><summary>Solution</summary>";
/// Closes it.
const SOLUTION_CLOSE: &str = "</details>";

/// The solution lines of every listed exercise, each with its exercise's name, as
/// [`normalized`] compares them. Lines too short to be telling (a brace, `None`, `x`) are
/// left out, and so are lines that the workspace's code also holds outside any solution
/// (`let d2 = to_light.length_squared();` shows nothing away).
fn known_solutions(workspace: &Path) -> Result<Vec<(String, String)>> {
    let mut elsewhere = std::collections::HashSet::new();
    for dir in ["common", "workbench", "chapters"] {
        collect_code_outside_solutions(&workspace.join(dir), &mut elsewhere)?;
    }
    let mut known = Vec::new();
    for exercise in exercise_list::load(workspace)? {
        let file = workspace.join(&exercise.file);
        let source = std::fs::read_to_string(&file)
            .with_context(|| format!("cannot read {}", file.display()))?;
        let lines = match solution_markers::solution_lines(&source, &exercise.anchor) {
            // A student edition has no solutions to give away.
            Err(MarkerError::NoSolution { .. }) => continue,
            lines => lines.with_context(|| format!("in {}", exercise.file.display()))?,
        };
        for line in lines {
            let line = normalized(&line);
            if line.len() >= MIN_TELLING_LENGTH
                && !line.starts_with("//")
                && !elsewhere.contains(&line)
            {
                known.push((exercise.name.clone(), line));
            }
        }
    }
    Ok(known)
}

/// Every line of the `.rs` files under `dir` that is outside a solution region, normalized.
fn collect_code_outside_solutions(
    dir: &Path,
    lines: &mut std::collections::HashSet<String>,
) -> Result<()> {
    for path in crate::workspace::rust_files_under(dir)? {
        let source = std::fs::read_to_string(&path)
            .with_context(|| format!("cannot read {}", path.display()))?;
        let mut in_solution = false;
        for line in source.lines() {
            match Marker::of_line(line) {
                Some(Marker::Begin) => in_solution = true,
                Some(Marker::End) => in_solution = false,
                None if !in_solution => {
                    lines.insert(normalized(line));
                }
                None => {}
            }
        }
    }
    Ok(())
}

/// How many characters, spaces left out, a solution line needs to count as the solution's
/// own rather than any code's (`return None;`, `let mut sum = 0.0;`).
const MIN_TELLING_LENGTH: usize = 24;

/// A line with its spaces left out: a copy typed with other spacing is the same line.
fn normalized(line: &str) -> String {
    line.chars().filter(|c| !c.is_whitespace()).collect()
}

/// Every line of `page` outside its "Solution" blocks that is a line of a known solution:
/// an answer given away before (or without) its exercise.
pub fn solution_leaks(page: &str, solutions: &[(String, String)]) -> Vec<String> {
    let mut leaks = Vec::new();
    let mut in_solution_block = false;
    for line in page.lines() {
        let trimmed = line.trim();
        if trimmed == SOLUTION_OPEN {
            in_solution_block = true;
        } else if trimmed == SOLUTION_CLOSE {
            in_solution_block = false;
        } else if !in_solution_block {
            let shown = normalized(line);
            if let Some((name, _)) = solutions.iter().find(|(_, line)| *line == shown) {
                leaks.push(format!(
                    "`{trimmed}` is a line of the solution of {name}: show it only in the \
                     exercise's Solution block"
                ));
            }
        }
    }
    leaks
}

#[cfg(test)]
mod tests {
    use super::*;

    const OPTICS: &str = "// ANCHOR: reflect\npub fn reflect(x: f32) -> f32 {\n    // BEGIN SOLUTION\n    -x\n    // END SOLUTION\n}\n// ANCHOR_END: reflect\n";

    fn page_dir() -> tempfile::TempDir {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(dir.path().join("code")).unwrap();
        std::fs::write(dir.path().join("code/optics.rs"), OPTICS).unwrap();
        dir
    }

    #[test]
    fn expands_an_exercise_into_a_stub_block() {
        let dir = page_dir();
        let page = "Try it:\n\n{{#exercise code/optics.rs:reflect}}\n\nDone.\n";
        assert_eq!(
            render_page(page, dir.path()).unwrap(),
            "Try it:\n\n```rust\npub fn reflect(x: f32) -> f32 {\n    todo!()\n}\n```\n\n\
             <details class=\"solution\"><summary>Solution</summary>\n\n\
             ```rust\npub fn reflect(x: f32) -> f32 {\n    -x\n}\n```\n\n</details>\n\nDone.\n"
        );
    }

    #[test]
    fn a_student_edition_shows_the_exercise_as_written_and_no_solution() {
        let dir = page_dir();
        std::fs::write(
            dir.path().join("code/optics.rs"),
            "// ANCHOR: reflect\npub fn reflect(x: f32) -> f32 {\n    x * 2.0 // mine\n}\n// ANCHOR_END: reflect\n",
        )
        .unwrap();
        let page = "{{#exercise code/optics.rs:reflect}}\n";
        assert_eq!(
            render_page(page, dir.path()).unwrap(),
            "```rust\npub fn reflect(x: f32) -> f32 {\n    x * 2.0 // mine\n}\n```\n"
        );
    }

    #[test]
    fn indents_the_block_like_the_directive() {
        let dir = page_dir();
        let page = "1. Solve:\n\n   {{#exercise code/optics.rs:reflect}}";
        let rendered = render_page(page, dir.path()).unwrap();
        assert!(
            rendered.contains("\n   ```rust\n   pub fn reflect"),
            "{rendered}"
        );
        assert!(rendered.contains("\n       todo!()\n"), "{rendered}");
    }

    #[test]
    fn included_code_shows_the_stub_of_an_exercise_it_holds() {
        let page = format!("```rust\n{OPTICS}```\nBEGIN and END outside code:\n// END SOLUTION\n");
        let rendered = render_page(&page, Path::new(".")).unwrap();
        assert!(rendered.contains("{\n    todo!()\n}"), "{rendered}");
        assert!(!rendered.contains("-x"), "{rendered}");
        assert!(!rendered.contains("SOLUTION"), "{rendered}");
    }

    #[test]
    fn a_solution_written_out_on_a_page_is_found_but_not_in_its_block() {
        let solutions = vec![(
            "ch01-reflect".to_string(),
            normalized("u - 3.0 * u.dot(v) * w"),
        )];
        let page = "The answer:\n\n```rust\nu - 3.0*u.dot(v)*w\n```\n";
        let leaks = solution_leaks(page, &solutions);
        assert_eq!(leaks.len(), 1, "{leaks:?}");
        assert!(leaks[0].contains("ch01-reflect"), "{leaks:?}");
        let hidden = format!(
            "{SOLUTION_OPEN}\n\n```rust\nu - 3.0 * u.dot(v) * w\n```\n\n{SOLUTION_CLOSE}\n"
        );
        assert!(solution_leaks(&hidden, &solutions).is_empty());
    }

    /// The page with its `{{#include path}}` and `{{#include path:anchor}}` lines expanded as
    /// mdBook's `links` preprocessor expands them (anchor comment lines left out), so that
    /// the test sees what the site's build sees.
    fn expand_includes(page: &str, page_dir: &Path) -> String {
        let mut out = String::new();
        for line in page.lines() {
            let Some(target) = line
                .trim()
                .strip_prefix("{{#include ")
                .and_then(|rest| rest.strip_suffix("}}"))
            else {
                out.push_str(line);
                out.push('\n');
                continue;
            };
            let (path, anchor) = match target.trim().rsplit_once(':') {
                Some((path, anchor)) => (path, Some(anchor)),
                None => (target.trim(), None),
            };
            // Generated files (the figures' tables) hold no code.
            let Ok(source) = std::fs::read_to_string(page_dir.join(path)) else {
                continue;
            };
            let mut inside = anchor.is_none();
            for source_line in source.lines() {
                let name_after = |marker: &str| {
                    source_line
                        .split_once(marker)
                        .map(|(_, rest)| rest.trim().to_string())
                };
                if let Some(anchor) = anchor {
                    if name_after("ANCHOR_END:").as_deref() == Some(anchor) {
                        inside = false;
                    } else if name_after("ANCHOR:").as_deref() == Some(anchor) {
                        inside = true;
                        continue;
                    }
                }
                if inside
                    && !source_line.contains("ANCHOR:")
                    && !source_line.contains("ANCHOR_END:")
                {
                    out.push_str(source_line);
                    out.push('\n');
                }
            }
        }
        out
    }

    #[test]
    fn no_page_of_the_book_gives_a_solution_away() {
        let workspace = crate::workspace::root();
        if crate::exercise_list::holds_no_solutions(&workspace) {
            return; // a student edition: there is no solution to give away
        }
        let solutions = known_solutions(&workspace).unwrap();
        assert!(solutions.len() > 25, "{} solution lines", solutions.len());
        let src = workspace.join("book/src");
        let mut leaks = Vec::new();
        for entry in std::fs::read_dir(&src).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "md") {
                let page = expand_includes(&std::fs::read_to_string(&path).unwrap(), &src);
                let rendered = render_page(&page, &src).unwrap();
                for leak in solution_leaks(&rendered, &solutions) {
                    leaks.push(format!("{}: {leak}", path.display()));
                }
            }
        }
        assert!(leaks.is_empty(), "{}", leaks.join("\n"));
    }

    #[test]
    fn no_page_of_the_book_states_a_key_expression_before_its_exercise() {
        let workspace = crate::workspace::root();
        let exercises = exercise_list::load(&workspace).unwrap();
        let src = workspace.join("book/src");
        let summary = std::fs::read_to_string(src.join("SUMMARY.md")).unwrap();
        // The pages in the book's order, as SUMMARY.md lists them.
        let names: Vec<&str> = summary
            .split("](")
            .skip(1)
            .filter_map(|rest| rest.split_once(')').map(|(name, _)| name))
            .filter(|name| name.ends_with(".md"))
            .collect();
        assert!(names.len() > 10, "{names:?}");
        let texts: Vec<String> = names
            .iter()
            .map(|name| expand_includes(&std::fs::read_to_string(src.join(name)).unwrap(), &src))
            .collect();
        let pages: Vec<giveaways::Page> = names
            .iter()
            .zip(&texts)
            .map(|(name, text)| giveaways::Page {
                name: (*name).to_owned(),
                text,
            })
            .collect();
        let problems = giveaways::check(&pages, &exercises, shows_exercise);
        assert!(problems.is_empty(), "{}", problems.join("\n"));
    }

    #[test]
    fn keeps_markers_and_directives_where_the_page_documents_them() {
        let page = format!("{KEEP_MARKERS}\n```text\n{{{{#exercise x.rs:y}}}}\n{OPTICS}```\n");
        assert_eq!(render_page(&page, Path::new(".")).unwrap(), page);
    }

    #[test]
    fn a_longer_fence_can_show_a_shorter_one() {
        let page = "````markdown\n```rust\n```\n{{#exercise x.rs:y}}\n````\n";
        assert_eq!(render_page(page, Path::new(".")).unwrap(), page);
    }

    #[test]
    fn broken_exercises_are_errors() {
        let dir = page_dir();
        for (page, expected) in [
            ("{{#exercise code/optics.rs}}", "name the anchor too"),
            ("{{#exercise code/none.rs:reflect}}", "cannot read"),
            (
                "{{#exercise code/optics.rs:refract}}",
                "no `ANCHOR: refract`",
            ),
        ] {
            let error = format!("{:#}", render_page(page, dir.path()).unwrap_err());
            assert!(error.contains(expected), "{page}: {error}");
        }
    }
}
