//! No answer in the prose before its exercise: a solution's key expression, written as a
//! formula or as inline code, may not appear on a page before the exercise that asks for it.
//!
//! [`solution_leaks`](crate::exercise_preprocessor::solution_leaks) finds a whole line of a
//! solution's code on a page. An answer is given away just as well by a formula in the prose,
//! `$\mathbf{u} - 3(\mathbf{u}\cdot\mathbf{v})\mathbf{w}$`, which no line of code matches.
//! So each exercise of `book/exercises.toml` may list its *giveaways*: the key expressions of
//! its solution as a page might write them,
//!
//! ```toml
//! [[exercise.giveaway]]
//! written = 'u - 3 (u \cdot v) w'
//! ```
//!
//! and this check fails the build when one of them appears, in any spelling that
//! [`normalized`] makes equal, on a page before the exercise's `{{#exercise}}` line: earlier in
//! the book, or higher on its own page. After the exercise (in its folded solution, in a later
//! chapter's recap) the formula is the student's own and may be written out. The student
//! edition's list has no giveaways (they are answers too), so a student's site skips this check.
//!
//! The student edition ships the workspace's code too, tests and later chapters included, and
//! a student stuck on an exercise reads it. So [`in_code`] fails the build when a giveaway
//! appears in any Rust file outside a solution region (which the edition cuts out): in a doc
//! comment, in a test that computes its expected answer the student's way, or in a later
//! chapter that writes the formula again instead of calling the exercise's function.

use std::path::Path;

use anyhow::{Context, Result};

use crate::exercise_list::Exercise;

/// One page: its path as mdBook names it and its text with the includes expanded and the
/// exercise lines still in place.
pub struct Page<'a> {
    /// The page's path in `book/src`, for messages.
    pub name: String,
    /// Its text.
    pub text: &'a str,
}

/// Every giveaway found before its exercise, as `page:line: ...` messages naming the exercise
/// and the expression; `pages` in the book's order. `is_home(line, exercise)` says whether a
/// page line is the `{{#exercise}}` line of `exercise`.
pub fn check(
    pages: &[Page],
    exercises: &[Exercise],
    is_home: impl Fn(&str, &Exercise) -> bool,
) -> Vec<String> {
    let mut problems = Vec::new();
    for exercise in exercises.iter().filter(|e| !e.giveaway.is_empty()) {
        // The exercise's home: the first page and line showing it; none if no page does.
        let home = pages.iter().enumerate().find_map(|(index, page)| {
            page.text
                .lines()
                .position(|line| is_home(line, exercise))
                .map(|line| (index, line))
        });
        for (index, page) in pages.iter().enumerate() {
            let before: Vec<&str> = match home {
                Some((home_page, _)) if index > home_page => continue,
                Some((home_page, line)) if index == home_page => {
                    page.text.lines().take(line).collect()
                }
                _ => page.text.lines().collect(),
            };
            let prose = outside_solutions(&before);
            for giveaway in &exercise.giveaway {
                if let Some(line) = find(&prose, &giveaway.written) {
                    let place = match home {
                        Some(_) => "before the exercise",
                        None => "and no page shows the exercise",
                    };
                    problems.push(format!(
                        "{}:{line}: states `{}`, the answer of {}, {place}: let the page derive \
                         the idea and the exercise ask for the expression (it may appear after \
                         the exercise, in its solution)",
                        page.name, giveaway.written, exercise.name
                    ));
                }
            }
        }
    }
    problems
}

/// The folders of the workspace whose Rust code the student edition ships.
const SHIPPED_CODE: &[&str] = &[
    "chapters",
    "common",
    "workbench",
    "tests",
    "book/builder",
    "fuzz",
    "web",
];

/// Every giveaway in the workspace's shipped Rust code outside solution regions, as
/// `file:line: ...` messages naming the exercise and the expression.
pub fn in_code(workspace: &Path, exercises: &[Exercise]) -> Result<Vec<String>> {
    let mut files = Vec::new();
    for folder in SHIPPED_CODE {
        files.extend(crate::workspace::rust_files_under(&workspace.join(folder))?);
    }
    files.sort();
    let mut problems = Vec::new();
    for file in files {
        let text = std::fs::read_to_string(&file)
            .with_context(|| format!("reading {}", file.display()))?;
        let name = file
            .strip_prefix(workspace)
            .unwrap_or(&file)
            .display()
            .to_string();
        problems.extend(in_source(&name, &text, exercises));
    }
    Ok(problems)
}

/// The giveaways in one Rust file's `text` outside its solution regions.
fn in_source(name: &str, text: &str, exercises: &[Exercise]) -> Vec<String> {
    let lines: Vec<&str> = text.lines().collect();
    let code = outside_solutions(&lines);
    let mut problems = Vec::new();
    for exercise in exercises {
        for giveaway in &exercise.giveaway {
            if let Some(line) = find(&code, &giveaway.written) {
                problems.push(format!(
                    "{name}:{line}: states `{}`, the answer of {}, in code the student edition \
                     ships: call the exercise's function, check a test's result by its \
                     properties or by numbers worked out beforehand, and let a comment ask \
                     rather than tell",
                    giveaway.written, exercise.name
                ));
            }
        }
    }
    problems
}

/// The lines of `lines`, numbered from 1, leaving out solution regions of included code (the
/// page shows them as `todo!()`) and folded solution blocks.
fn outside_solutions<'a>(lines: &[&'a str]) -> Vec<(usize, &'a str)> {
    let mut kept = Vec::new();
    let mut hidden = false;
    for (index, line) in lines.iter().enumerate() {
        let trimmed = line.trim();
        if trimmed == "// BEGIN SOLUTION" || trimmed.starts_with("<details class=\"solution\"") {
            hidden = true;
        } else if trimmed == "// END SOLUTION" || (hidden && trimmed == "</details>") {
            hidden = false;
        } else if !hidden {
            kept.push((index + 1, *line));
        }
    }
    kept
}

/// The line (from 1) on which `expression` appears in `lines`, normalized; an expression
/// broken over lines (a display formula) counts from the line where it starts.
fn find(lines: &[(usize, &str)], expression: &str) -> Option<usize> {
    let wanted = normalized(expression);
    if wanted.is_empty() {
        return None;
    }
    // Join the lines, remembering where each starts in the normalized text.
    let mut text = String::new();
    let mut starts = Vec::with_capacity(lines.len());
    for (number, line) in lines {
        starts.push((text.len(), *number));
        text.push_str(&normalized(line));
    }
    let at = text.find(&wanted)?;
    starts
        .iter()
        .rev()
        .find(|(start, _)| *start <= at)
        .map(|(_, number)| *number)
}

/// TeX control words that change how a symbol looks, not what it says.
const DECORATIONS: &[&str] = &[
    "\\left",
    "\\right",
    "\\bigl",
    "\\bigr",
    "\\big",
    "\\mathbf",
    "\\boldsymbol",
    "\\mathrm",
    "\\mathit",
    "\\operatorname",
    "\\text",
    "\\vec",
    "\\hat",
    "\\displaystyle",
    "\\quad",
    "\\,",
    "\\;",
    "\\!",
];

/// `text` as the check compares it: lower case, without spaces, braces, dollar signs,
/// backticks, the TeX decorations above or any sign of a product (`\cdot`, `\times`, `*`,
/// `·`, `×`: a product is as often written by juxtaposition), with `\dfrac`/`\tfrac` as
/// `\frac`. So `$2(\mathbf{d}\cdot\mathbf{n})$`, `` `2*(d*n)` `` and `2(d n)` read alike.
pub fn normalized(text: &str) -> String {
    let mut text = text.to_lowercase();
    for decoration in DECORATIONS {
        // A control word only where it ends: `\hat` but not the `\hat` of `\hatch`.
        text = remove_control_word(&text, decoration);
    }
    text = text
        .replace("\\dfrac", "\\frac")
        .replace("\\tfrac", "\\frac")
        .replace("\\cdot", "")
        .replace("\\times", "");
    text.chars()
        .filter(|c| !c.is_whitespace() && !matches!(c, '{' | '}' | '$' | '`' | '*' | '·' | '×'))
        .collect()
}

/// `text` without the control word `word`, where it is not the start of a longer one.
fn remove_control_word(text: &str, word: &str) -> String {
    let ends_in_letter = word.chars().last().is_some_and(|c| c.is_ascii_alphabetic());
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(word) {
        let after = &rest[at + word.len()..];
        let longer = ends_in_letter && after.starts_with(|c: char| c.is_ascii_alphabetic());
        out.push_str(&rest[..at]);
        if longer {
            out.push_str(word);
        }
        rest = after;
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exercise_list::parse;

    const LIST: &str = r#"
[[exercise]]
name = "ch01-lever"
chapter = "ch01-whitted"
file = "chapters/ch01-whitted/src/optics.rs"
anchor = "lever"
check = "cargo test"
hint = "Which arm is longer?"

[[exercise.giveaway]]
written = 'u - 3 (u \cdot v) w'
"#;

    fn is_home(line: &str, exercise: &Exercise) -> bool {
        line.trim() == format!("{{{{#exercise {}}}}}", exercise.anchor)
    }

    fn problems(pages: &[(&str, &str)]) -> Vec<String> {
        let exercises = parse(LIST).unwrap();
        let pages: Vec<_> = pages
            .iter()
            .map(|(name, text)| Page {
                name: name.to_string(),
                text,
            })
            .collect();
        check(&pages, &exercises, is_home)
    }

    #[test]
    fn spellings_of_one_formula_read_alike() {
        let formula = normalized(r"$\mathbf{u} - 3\,(\mathbf{u}\cdot\mathbf{v})\,\mathbf{w}$");
        assert_eq!(formula, "u-3(uv)w");
        assert_eq!(normalized("`u - 3 (u * v) w`"), formula);
        assert_eq!(normalized(r"\left(\hat{n}\right)"), "(n)");
        assert_eq!(normalized(r"\hatch"), r"\hatch");
        assert_eq!(normalized(r"\dfrac{1}{2}"), r"\frac12");
    }

    #[test]
    fn a_formula_before_its_exercise_is_named_with_page_and_line() {
        let page = "# Levers\n\nThe arm is\n$$\n\\mathbf{u} - 3(\\mathbf{u} \\cdot \
                    \\mathbf{v})\\,\\mathbf{w}\n$$\n\n{{#exercise lever}}\n";
        let found = problems(&[("ch01.md", page)]);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0].starts_with("ch01.md:5: states"), "{found:?}");
        assert!(found[0].contains("ch01-lever"), "{found:?}");

        // On an earlier page too.
        let earlier = problems(&[("intro.md", "Here: `u - 3*(u*v)*w`."), ("ch01.md", page)]);
        assert!(
            earlier.iter().any(|p| p.starts_with("intro.md:1:")),
            "{earlier:?}"
        );
    }

    #[test]
    fn after_the_exercise_or_folded_the_formula_is_allowed() {
        let after = "# Levers\n\n{{#exercise lever}}\n\nSo $u - 3(u\\cdot v)w$ it is.\n";
        assert!(problems(&[("ch01.md", after)]).is_empty());
        let later_page = "Recall $u - 3(u\\cdot v)w$.";
        assert!(problems(&[("ch01.md", after), ("ch08.md", later_page)]).is_empty());
        let folded = "<details class=\"solution\"><summary>Solution</summary>\n\n\
                      u - 3 (u * v) w\n\n</details>\n{{#exercise lever}}\n";
        assert!(problems(&[("ch01.md", folded)]).is_empty());
        let included = "```rust\n// BEGIN SOLUTION\nu - 3.0 * (u * v) * w\n// END SOLUTION\n```\n";
        assert!(problems(&[("ch01.md", included), ("ch01b.md", after)]).is_empty());
    }

    #[test]
    fn code_outside_solutions_may_not_state_a_giveaway() {
        let exercises = parse(LIST).unwrap();
        let solved = "fn lever(u: V, v: V, w: V) -> V {\n    // BEGIN SOLUTION\n    \
                      u - 3 * (u * v) * w\n    // END SOLUTION\n}\n";
        assert!(in_source("a.rs", solved, &exercises).is_empty());
        let test = format!(
            "{solved}\n#[test]\nfn t() {{\n    let expected =\n        u - 3 * (u * v) * w;\n}}\n"
        );
        let found = in_source("a.rs", &test, &exercises);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0].starts_with("a.rs:10: states"), "{found:?}");
        assert!(found[0].contains("ch01-lever"), "{found:?}");
        let doc = "/// The arm is $u - 3(u\\cdot v)w$.\n";
        assert_eq!(in_source("b.rs", doc, &exercises).len(), 1);
    }

    #[test]
    fn the_workspace_code_states_no_giveaway_outside_its_solutions() {
        let workspace = crate::workspace::root();
        let exercises = crate::exercise_list::load(&workspace).unwrap();
        assert!(exercises.iter().any(|e| !e.giveaway.is_empty()));
        let problems = in_code(&workspace, &exercises).unwrap();
        assert!(problems.is_empty(), "{}", problems.join("\n"));
    }

    #[test]
    fn without_its_exercise_on_any_page_the_formula_may_appear_nowhere() {
        let found = problems(&[("ch09.md", "Recall $u - 3(u\\cdot v)w$.")]);
        assert!(found[0].contains("no page shows the exercise"), "{found:?}");
    }
}
