//! What every chapter page holds besides its lecture: the way to the primer, a diagram of its
//! geometry, and questions to check yourself.
//!
//! A student meets a symbol or a word in the middle of chapter 06 and needs the one place that
//! defines it; a page explaining a lens needs a drawing of the lens, not only a paragraph; and a
//! student who cannot tell whether they understood needs questions with answers they can fold
//! open after predicting. This check fails the build when a chapter page (`chNN-*.md`) lacks
//! one of them, naming the page and what is missing:
//!
//! - the line pointing to the primer, the notation and the glossary, before the first section;
//! - at least one diagram, an image under `figures/chNN/diagrams/` with alt text;
//! - a `## Check yourself` section before `## Exercises`, holding three to five questions, each
//!   answered in a folded `<details>` block with a `<summary>`.

use std::path::Path;

use anyhow::{Context, Result, bail};

/// The pages every chapter page must link to before its first section.
const REFERENCE_PAGES: [&str; 3] = ["primer.md", "notation.md", "glossary.md"];

/// The heading of the questions' section.
const CHECK_YOURSELF: &str = "## Check yourself";

/// How many questions the section holds, at least and at most.
const QUESTIONS: std::ops::RangeInclusive<usize> = 3..=5;

/// Checks every chapter page of `book_src`; fails naming each page and what it lacks.
pub fn check(book_src: &Path) -> Result<()> {
    let mut problems = Vec::new();
    let mut entries: Vec<_> = std::fs::read_dir(book_src)
        .with_context(|| format!("cannot list {}", book_src.display()))?
        .collect::<Result<_, _>>()
        .with_context(|| format!("cannot list {}", book_src.display()))?;
    entries.sort_by_key(|entry| entry.file_name());
    for entry in entries {
        let name = entry.file_name().to_string_lossy().into_owned();
        if !is_chapter_page(&name) {
            continue;
        }
        let text = std::fs::read_to_string(entry.path())
            .with_context(|| format!("cannot read {}", entry.path().display()))?;
        for problem in problems_of(&name, &text) {
            problems.push(format!("book/src/{name}: {problem}"));
        }
    }
    if !problems.is_empty() {
        bail!(
            "chapter pages without what every chapter page holds:\n  {}",
            problems.join("\n  ")
        );
    }
    Ok(())
}

/// Whether `name` is a chapter's page: `ch`, two digits, a dash, `.md`.
fn is_chapter_page(name: &str) -> bool {
    let bytes = name.as_bytes();
    name.ends_with(".md")
        && bytes.len() > 5
        && name.starts_with("ch")
        && bytes[2].is_ascii_digit()
        && bytes[3].is_ascii_digit()
        && bytes[4] == b'-'
}

/// What the page `name` with `text` lacks, in words; empty when it has everything.
fn problems_of(name: &str, text: &str) -> Vec<String> {
    let mut problems = Vec::new();
    let lines: Vec<&str> = prose_lines(text);

    let first_section = lines
        .iter()
        .position(|line| line.starts_with("## "))
        .unwrap_or(lines.len());
    let opening = lines[..first_section].join("\n");
    let missing: Vec<_> = REFERENCE_PAGES
        .iter()
        .filter(|page| !opening.contains(&format!("]({page}")))
        .collect();
    if !missing.is_empty() {
        problems.push(format!(
            "no link to {} before its first section (the line that sends a reader to the \
             words and symbols the page uses)",
            missing
                .iter()
                .map(|page| page.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }

    let chapter = &name[..4];
    let diagrams = diagram_images(&lines, chapter);
    if diagrams.is_empty() {
        problems.push(format!(
            "no diagram: no image under figures/{chapter}/diagrams/ (geometry drawn from the \
             chapter's code by its lab/diagrams.rs)"
        ));
    }
    for (line, path) in diagrams.iter().filter(|(_, alt)| alt.trim().is_empty()) {
        problems.push(format!(
            "line {line}: the diagram {path} has no alt text saying what it shows"
        ));
    }

    problems.extend(check_yourself_problems(&lines));
    problems
}

/// The page's lines outside fenced code blocks (a code block's `## ` is not a heading); lines
/// inside a fence are kept as empty lines, so that numbers still count from 1 in the file.
fn prose_lines(text: &str) -> Vec<&str> {
    let mut in_fence = false;
    text.lines()
        .map(|line| {
            let fence = line.trim_start().starts_with("```");
            if fence {
                in_fence = !in_fence;
            }
            if fence || in_fence { "" } else { line }
        })
        .collect()
}

/// The diagram images of `chapter` on the page: `(line number, alt text)` pairs, the alt text
/// standing where the path should be when it is missing: `![](path)` yields `(n, "")`.
fn diagram_images(lines: &[&str], chapter: &str) -> Vec<(usize, String)> {
    let folder = format!("](figures/{chapter}/diagrams/");
    let mut found = Vec::new();
    for (index, line) in lines.iter().enumerate() {
        let mut rest = *line;
        while let Some(start) = rest.find("![") {
            let after = &rest[start + 2..];
            let Some(close) = after.find("](") else { break };
            let alt = &after[..close];
            let target = &after[close..];
            if target.starts_with(&folder) {
                found.push((index + 1, alt.to_owned()));
            }
            rest = &after[close..];
        }
    }
    found
}

/// What is wrong with the page's "Check yourself" section, if anything.
fn check_yourself_problems(lines: &[&str]) -> Vec<String> {
    let Some(start) = lines
        .iter()
        .position(|line| line.trim_end() == CHECK_YOURSELF)
    else {
        return vec![format!(
            "no `{CHECK_YOURSELF}` section (three to five questions to predict before running, \
             each with its answer folded in <details>)"
        )];
    };
    let end = lines[start + 1..]
        .iter()
        .position(|line| line.starts_with("## "))
        .map_or(lines.len(), |offset| start + 1 + offset);
    let mut problems = Vec::new();
    let exercises = lines
        .iter()
        .position(|line| line.trim_end() == "## Exercises");
    if exercises.is_some_and(|exercises| exercises < start) {
        problems.push(format!(
            "`{CHECK_YOURSELF}` comes after `## Exercises`; its questions belong before them"
        ));
    }
    let section = &lines[start..end];
    let opened = section
        .iter()
        .filter(|line| line.trim_start().starts_with("<details"))
        .count();
    let closed = section
        .iter()
        .filter(|line| line.contains("</details>"))
        .count();
    let summaries = section
        .iter()
        .filter(|line| line.contains("<summary>"))
        .count();
    if opened != closed || summaries != opened {
        problems.push(format!(
            "line {}: `{CHECK_YOURSELF}` opens {opened} <details>, closes {closed} and has \
             {summaries} <summary>: each answer is one <details> with one <summary>",
            start + 1
        ));
    }
    if !QUESTIONS.contains(&opened) {
        problems.push(format!(
            "line {}: `{CHECK_YOURSELF}` has {opened} folded answers; it needs {} to {} \
             questions, each with its answer",
            start + 1,
            QUESTIONS.start(),
            QUESTIONS.end()
        ));
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;

    const ANSWER: &str = "<details>\n<summary>Answer</summary>\n\nBecause.\n\n</details>\n";

    fn page(opening: &str, diagram: &str, questions: usize) -> String {
        let mut text = format!("# Chapter\n\n{opening}\n\nIntro.\n\n## The idea\n\n{diagram}\n\n");
        text.push_str("```rust\n## not a heading\n```\n\n## Check yourself\n\n");
        for _ in 0..questions {
            text.push_str("What happens?\n\n");
            text.push_str(ANSWER);
            text.push('\n');
        }
        text.push_str("## Exercises\n\nWork.\n");
        text
    }

    const OPENING: &str = "> New words and symbols: the [primer](primer.md), the \
                           [notation](notation.md) and the [glossary](glossary.md).";
    const DIAGRAM: &str = "![A lens and its focus](figures/ch04/diagrams/thin-lens.svg)";

    #[test]
    fn a_complete_page_passes() {
        assert_eq!(
            problems_of("ch04-x.md", &page(OPENING, DIAGRAM, 3)),
            [] as [String; 0]
        );
        assert_eq!(
            problems_of("ch04-x.md", &page(OPENING, DIAGRAM, 5)),
            [] as [String; 0]
        );
    }

    #[test]
    fn each_missing_part_is_named() {
        let no_links = problems_of("ch04-x.md", &page("Intro.", DIAGRAM, 3));
        assert_eq!(no_links.len(), 1, "{no_links:?}");
        assert!(no_links[0].contains("primer.md, notation.md, glossary.md"));

        let other_chapter = problems_of("ch05-x.md", &page(OPENING, DIAGRAM, 3));
        assert!(
            other_chapter[0].contains("figures/ch05/diagrams/"),
            "{other_chapter:?}"
        );

        let render_only = "![A render](figures/ch04/apertures.png)";
        assert!(problems_of("ch04-x.md", &page(OPENING, render_only, 3))[0].contains("no diagram"));

        let no_alt = problems_of(
            "ch04-x.md",
            &page(OPENING, "![](figures/ch04/diagrams/a.svg)", 3),
        );
        assert_eq!(no_alt.len(), 1, "{no_alt:?}");
        assert!(no_alt[0].contains("no alt text"));

        let too_few = problems_of("ch04-x.md", &page(OPENING, DIAGRAM, 2));
        assert!(too_few[0].contains("has 2 folded answers"), "{too_few:?}");
        let too_many = problems_of("ch04-x.md", &page(OPENING, DIAGRAM, 6));
        assert!(too_many[0].contains("has 6 folded answers"), "{too_many:?}");
    }

    #[test]
    fn the_links_must_come_before_the_first_section() {
        let late = page("Intro.", DIAGRAM, 3)
            .replace("## The idea\n", &format!("## The idea\n{OPENING}\n"));
        assert!(problems_of("ch04-x.md", &late)[0].contains("before its first section"));
    }

    #[test]
    fn a_missing_section_or_an_unclosed_answer_is_named() {
        let text = page(OPENING, DIAGRAM, 3).replace("## Check yourself", "## Questions");
        assert!(problems_of("ch04-x.md", &text)[0].contains("no `## Check yourself` section"));

        let unclosed = page(OPENING, DIAGRAM, 3).replacen("</details>", "", 1);
        let problems = problems_of("ch04-x.md", &unclosed);
        assert!(
            problems[0].contains("opens 3 <details>, closes 2"),
            "{problems:?}"
        );

        let late = page(OPENING, DIAGRAM, 3)
            .replace("## Check yourself", "## Placeholder")
            .replace(
                "## Exercises\n\nWork.\n",
                "## Exercises\n\nWork.\n\n## Check yourself\n\n",
            );
        let problems = problems_of("ch04-x.md", &late);
        assert!(
            problems.iter().any(|p| p.contains("after `## Exercises`")),
            "{problems:?}"
        );
    }

    #[test]
    fn only_chapter_pages_are_checked() {
        assert!(is_chapter_page("ch04-depth-of-field.md"));
        assert!(is_chapter_page("ch10-x.md"));
        assert!(!is_chapter_page("primer.md"));
        assert!(!is_chapter_page("chapter-x.md"));
        assert!(!is_chapter_page("ch04.md"));
    }
}
