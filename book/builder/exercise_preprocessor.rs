//! The book's side of the exercises: stubs on the page, no markers anywhere.
//!
//! Two things happen to every chapter, after mdBook's own `links` preprocessor has expanded the
//! `{{#include}}`s:
//!
//! - a line `{{#exercise path/to/file.rs:anchor}}` becomes a Rust code block showing that
//!   anchor with its solution replaced by `todo!()`, cut out as in the student edition;
//! - solution marker lines are dropped, so a solution shown with `{{#include file.rs:anchor}}`
//!   reads as plain code.
//!
//! Both leave fenced code blocks alone where that matters: a `{{#exercise}}` line inside a fence
//! is shown as written (that is how a page documents the syntax). A page that needs to show the
//! markers themselves says so with the comment [`KEEP_MARKERS`].

use std::path::Path;

use anyhow::{Context, Result, bail};
use mdbook_driver::book::Book;
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};

use crate::solution_markers::{self, Marker};

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
        let mut problems = Vec::new();
        book.for_each_chapter_mut(|chapter| {
            let Some(path) = &chapter.path else { return };
            let page_dir = src_dir.join(path.parent().unwrap_or(Path::new("")));
            match render_page(&chapter.content, &page_dir) {
                Ok(content) => chapter.content = content,
                Err(error) => problems.push(format!("{}: {error:#}", path.display())),
            }
        });
        if !problems.is_empty() {
            bail!("{}", problems.join("\n"));
        }
        Ok(book)
    }
}

/// One page with its exercises expanded and its marker lines dropped. Paths in `{{#exercise}}`
/// are relative to `page_dir`, like those of `{{#include}}`.
pub fn render_page(content: &str, page_dir: &Path) -> Result<String> {
    let keep_markers = content.contains(KEEP_MARKERS);
    let mut out = String::with_capacity(content.len());
    let mut open_fence: Option<Fence> = None;
    for line in content.lines() {
        let trimmed = line.trim_start();
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
    let stub =
        solution_markers::book_stub(&source, anchor).with_context(|| format!("in {path}"))?;
    Ok(format!("```rust\n{stub}\n```\n"))
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
            "Try it:\n\n```rust\npub fn reflect(x: f32) -> f32 {\n    todo!()\n}\n```\n\nDone.\n"
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
    fn strips_markers_from_included_solutions() {
        let page = format!("```rust\n{OPTICS}```\n");
        let rendered = render_page(&page, Path::new(".")).unwrap();
        assert!(rendered.contains("{\n    -x\n}"), "{rendered}");
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
