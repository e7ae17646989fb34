//! No answer in the prose before its exercise: a solution's key expression, written as a
//! formula or as inline code, may not appear on a page before the exercise that asks for it.
//!
//! [`solution_leaks`](crate::exercise_preprocessor::solution_leaks) finds a whole line of a
//! solution's code on a page. An answer is given away just as well by a formula in the prose,
//! `$\mathbf{d} - 2(\mathbf{d}\cdot\mathbf{n})\mathbf{n}$`, which no line of code matches. So
//! each exercise of `book/exercises.toml` may list its *giveaways*: the key expressions of its
//! solution as a page might write them,
//!
//! ```toml
//! [[exercise.giveaway]]
//! written = 'd - 2 (d \cdot n) n'
//! ```
//!
//! and this check fails the build when one of them appears, in any spelling that
//! [`normalized`] makes equal, on a page before the exercise's `{{#exercise}}` line: earlier in
//! the book, or higher on its own page. After the exercise (in its folded solution, in a later
//! chapter's recap) the formula is the student's own and may be written out. The student
//! edition's list has no giveaways (they are answers too), so a student's site skips this check.

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
name = "ch01-reflect"
chapter = "ch01-whitted"
file = "chapters/ch01-whitted/src/optics.rs"
anchor = "reflect"
check = "cargo test"
hint = "Which part changes?"

[[exercise.giveaway]]
written = 'd - 2 (d \cdot n) n'
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
        let formula = normalized(r"$\mathbf{d} - 2\,(\mathbf{d}\cdot\mathbf{n})\,\mathbf{n}$");
        assert_eq!(formula, "d-2(dn)n");
        assert_eq!(normalized("`d - 2 (d * n) n`"), formula);
        assert_eq!(normalized(r"\left(\hat{n}\right)"), "(n)");
        assert_eq!(normalized(r"\hatch"), r"\hatch");
        assert_eq!(normalized(r"\dfrac{1}{2}"), r"\frac12");
    }

    #[test]
    fn a_formula_before_its_exercise_is_named_with_page_and_line() {
        let page = "# Mirrors\n\nThe mirror direction is\n$$\n\\mathbf{d} - 2(\\mathbf{d} \\cdot \
                    \\mathbf{n})\\,\\mathbf{n}\n$$\n\n{{#exercise reflect}}\n";
        let found = problems(&[("ch01.md", page)]);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0].starts_with("ch01.md:5: states"), "{found:?}");
        assert!(found[0].contains("ch01-reflect"), "{found:?}");

        // On an earlier page too.
        let earlier = problems(&[("intro.md", "Here: `d - 2*(d*n)*n`."), ("ch01.md", page)]);
        assert!(
            earlier.iter().any(|p| p.starts_with("intro.md:1:")),
            "{earlier:?}"
        );
    }

    #[test]
    fn after_the_exercise_or_folded_the_formula_is_allowed() {
        let after = "# Mirrors\n\n{{#exercise reflect}}\n\nSo $d - 2(d\\cdot n)n$ it is.\n";
        assert!(problems(&[("ch01.md", after)]).is_empty());
        let later_page = "Recall $d - 2(d\\cdot n)n$.";
        assert!(problems(&[("ch01.md", after), ("ch08.md", later_page)]).is_empty());
        let folded = "<details class=\"solution\"><summary>Solution</summary>\n\n\
                      d - 2 (d * n) n\n\n</details>\n{{#exercise reflect}}\n";
        assert!(problems(&[("ch01.md", folded)]).is_empty());
        let included = "```rust\n// BEGIN SOLUTION\nd - 2.0 * (d * n) * n\n// END SOLUTION\n```\n";
        assert!(problems(&[("ch01.md", included), ("ch01b.md", after)]).is_empty());
    }

    #[test]
    fn without_its_exercise_on_any_page_the_formula_may_appear_nowhere() {
        let found = problems(&[("ch09.md", "Recall $d - 2(d\\cdot n)n$.")]);
        assert!(found[0].contains("no page shows the exercise"), "{found:?}");
    }
}
