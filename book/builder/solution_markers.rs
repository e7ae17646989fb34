//! The one transformation behind every exercise: cut a solution out of its source file.
//!
//! Chapter sources carry their exercises' solutions, so the solutions are compiled and tested
//! like any other code. An exercise is an mdBook anchor (the `ANCHOR: name` and
//! `ANCHOR_END: name` comments that `{{#include file:name}}` understands) holding exactly one
//! *solution region*: the lines between a line that reads `// BEGIN SOLUTION` and a line that
//! reads `// END SOLUTION`, nothing else on either line but indentation.
//!
//! Cutting the solution out replaces the region, both marker lines included, by one line at
//! the indentation of the `BEGIN` marker: `todo!()` on the page, and in the student edition a
//! call of `common::exercise::todo` that names the exercise and its first hint (and says, when a
//! check runs into it, that the check needs that exercise). The book's exercise stubs and the
//! student edition both go through [`splice_todos`], so a reader sees on the page the lines a
//! student finds in their copy of the code, but for that one line.

use std::fmt;
use std::ops::Range;

/// The line that opens a solution region (compared after trimming whitespace).
pub const BEGIN_SOLUTION: &str = "// BEGIN SOLUTION";
/// The line that closes a solution region (compared after trimming whitespace).
pub const END_SOLUTION: &str = "// END SOLUTION";

/// One of the two marker lines around a solution region.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Marker {
    /// `// BEGIN SOLUTION`
    Begin,
    /// `// END SOLUTION`
    End,
}

impl Marker {
    /// Which marker `line` is, if it is one.
    pub fn of_line(line: &str) -> Option<Marker> {
        match line.trim() {
            BEGIN_SOLUTION => Some(Marker::Begin),
            END_SOLUTION => Some(Marker::End),
            _ => None,
        }
    }
}

impl fmt::Display for Marker {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Marker::Begin => BEGIN_SOLUTION,
            Marker::End => END_SOLUTION,
        })
    }
}

/// Why an exercise's markers could not be understood. Line numbers count from 1.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MarkerError {
    /// No line names the anchor.
    #[error("there is no `ANCHOR: {anchor}` line")]
    AnchorNotFound {
        /// The anchor looked for.
        anchor: String,
    },
    /// The anchor opens but never closes.
    #[error("`ANCHOR: {anchor}` on line {line} has no `ANCHOR_END: {anchor}` after it")]
    AnchorNotClosed {
        /// The anchor looked for.
        anchor: String,
        /// Where it opens.
        line: usize,
    },
    /// The anchor holds no solution region at all.
    #[error("anchor `{anchor}` holds no `{BEGIN_SOLUTION}` line")]
    NoSolution {
        /// The anchor looked in.
        anchor: String,
    },
    /// A second region: an exercise has exactly one.
    #[error(
        "anchor `{anchor}` holds a second solution region (line {line}); an exercise has exactly one"
    )]
    SecondSolution {
        /// The anchor looked in.
        anchor: String,
        /// Where the second region begins.
        line: usize,
    },
    /// A `BEGIN` inside an open region: regions do not nest.
    #[error("`{BEGIN_SOLUTION}` on line {line} is inside the region opened on line {opened}")]
    NestedSolution {
        /// The inner `BEGIN`.
        line: usize,
        /// The `BEGIN` of the region it sits in.
        opened: usize,
    },
    /// A `BEGIN` whose `END` is missing before the anchor ends.
    #[error("`{BEGIN_SOLUTION}` on line {line} has no `{END_SOLUTION}` before the anchor ends")]
    UnclosedSolution {
        /// The lonely `BEGIN`.
        line: usize,
    },
    /// An `END` with no `BEGIN` before it.
    #[error("`{END_SOLUTION}` on line {line} has no `{BEGIN_SOLUTION}` before it")]
    UnopenedSolution {
        /// The lonely `END`.
        line: usize,
    },
    /// Two listed exercises claim the same solution region.
    #[error(
        "the solution region on line {line} belongs to two listed exercises, `{first}` and `{second}`"
    )]
    SharedSolution {
        /// Where the region begins.
        line: usize,
        /// The anchor of one exercise.
        first: String,
        /// The anchor of the other.
        second: String,
    },
    /// A marker outside every exercise anchor named for this file.
    #[error("`{marker}` on line {line} is not inside the anchor of any listed exercise")]
    StrayMarker {
        /// Which marker.
        marker: Marker,
        /// Where it is.
        line: usize,
    },
}

/// Where one exercise sits in a source file, as 0-based line indices.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExerciseSpan {
    /// The lines strictly between `ANCHOR: name` and `ANCHOR_END: name`.
    pub body: Range<usize>,
    /// The solution region, both marker lines included.
    pub solution: Range<usize>,
}

/// The name after `marker` on `line`, read the way mdBook reads anchor names.
fn anchor_name<'a>(line: &'a str, marker: &str) -> Option<&'a str> {
    let after = &line[line.find(marker)? + marker.len()..];
    let name = after.trim_start();
    let end = name
        .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == '-'))
        .unwrap_or(name.len());
    (end > 0).then(|| &name[..end])
}

/// Whether `line` opens or closes an anchor, whatever its name (mdBook hides such lines in
/// includes).
fn is_anchor_line(line: &str) -> bool {
    anchor_name(line, "ANCHOR:").is_some() || anchor_name(line, "ANCHOR_END:").is_some()
}

/// Finds the exercise `anchor` in `lines` and checks it holds exactly one solution region.
pub fn locate(lines: &[&str], anchor: &str) -> Result<ExerciseSpan, MarkerError> {
    let opens = |line: &&str| anchor_name(line, "ANCHOR:") == Some(anchor);
    let closes = |line: &&str| anchor_name(line, "ANCHOR_END:") == Some(anchor);

    let start = lines
        .iter()
        .position(opens)
        .ok_or_else(|| MarkerError::AnchorNotFound {
            anchor: anchor.to_owned(),
        })?;
    let end = start
        + 1
        + lines[start + 1..].iter().position(closes).ok_or_else(|| {
            MarkerError::AnchorNotClosed {
                anchor: anchor.to_owned(),
                line: start + 1,
            }
        })?;

    let body = start + 1..end;
    let mut open: Option<usize> = None;
    let mut solution: Option<Range<usize>> = None;
    for index in body.clone() {
        match (Marker::of_line(lines[index]), open) {
            (Some(Marker::Begin), Some(opened)) => {
                return Err(MarkerError::NestedSolution {
                    line: index + 1,
                    opened: opened + 1,
                });
            }
            (Some(Marker::Begin), None) if solution.is_some() => {
                return Err(MarkerError::SecondSolution {
                    anchor: anchor.to_owned(),
                    line: index + 1,
                });
            }
            (Some(Marker::Begin), None) => open = Some(index),
            (Some(Marker::End), Some(opened)) => {
                solution = Some(opened..index + 1);
                open = None;
            }
            (Some(Marker::End), None) => {
                return Err(MarkerError::UnopenedSolution { line: index + 1 });
            }
            (None, _) => {}
        }
    }
    if let Some(opened) = open {
        return Err(MarkerError::UnclosedSolution { line: opened + 1 });
    }
    let solution = solution.ok_or_else(|| MarkerError::NoSolution {
        anchor: anchor.to_owned(),
    })?;
    Ok(ExerciseSpan { body, solution })
}

/// The call that stands in for a solution: on a page, `todo!()`; in the student edition,
/// [`STUDENT_STUB`] with the exercise's name and first hint (`"ch01-reflect: Which part ...?"`),
/// which says, when a check runs into it, that the check needs that exercise and it is not
/// written yet. The message is one valid string literal.
pub fn todo_call(message: Option<&str>) -> String {
    match message {
        None => "todo!()".to_owned(),
        Some(message) => format!("{STUDENT_STUB}({message:?})"),
    }
}

/// The function a student's stub calls: `common::exercise::todo`, named from the root so that
/// no module of the chapter called `common` can hide it.
pub const STUDENT_STUB: &str = "::common::exercise::todo";

/// `lines` with each solution region replaced by its `todo!` line, indented like the region's
/// `BEGIN` marker. The regions must not overlap; they may come in any order.
pub fn splice_todos(lines: &[&str], regions: &[(Range<usize>, String)]) -> Vec<String> {
    let mut regions: Vec<&(Range<usize>, String)> = regions.iter().collect();
    regions.sort_by_key(|(range, _)| range.start);

    let mut out = Vec::with_capacity(lines.len());
    let mut next = 0;
    for (range, todo) in regions {
        out.extend(lines[next..range.start].iter().map(|l| (*l).to_owned()));
        let begin = lines[range.start];
        let indent = &begin[..begin.len() - begin.trim_start().len()];
        out.push(format!("{indent}{todo}"));
        next = range.end;
    }
    out.extend(lines[next..].iter().map(|l| (*l).to_owned()));
    out
}

/// What the book shows for an exercise: the anchor's lines (without any anchor comments,
/// as mdBook's `{{#include}}` would show them) with the solution replaced by `todo!()`.
pub fn book_stub(source: &str, anchor: &str) -> Result<String, MarkerError> {
    let lines: Vec<&str> = source.lines().collect();
    let span = locate(&lines, anchor)?;
    let body = &lines[span.body.clone()];
    let offset = span.body.start;
    let solution = span.solution.start - offset..span.solution.end - offset;
    let stub = splice_todos(body, &[(solution, todo_call(None))]);
    let shown: Vec<&str> = stub
        .iter()
        .map(String::as_str)
        .filter(|line| !is_anchor_line(line))
        .collect();
    Ok(shown.join("\n"))
}

/// The solution of an exercise as the book's collapsed "Solution" block shows it: the
/// anchor's lines with the solution in place, without the anchor and marker lines.
pub fn book_solution(source: &str, anchor: &str) -> Result<String, MarkerError> {
    let lines: Vec<&str> = source.lines().collect();
    let span = locate(&lines, anchor)?;
    let shown: Vec<&str> = lines[span.body]
        .iter()
        .copied()
        .filter(|line| !is_anchor_line(line) && Marker::of_line(line).is_none())
        .collect();
    Ok(shown.join("\n"))
}

/// The lines strictly between `// ANCHOR: anchor` and its `// ANCHOR_END`, whatever they hold
/// (in a student edition: the stub, or the student's own code).
pub fn anchor_body(lines: &[&str], anchor: &str) -> Result<Range<usize>, MarkerError> {
    let start = lines
        .iter()
        .position(|line| anchor_name(line, "ANCHOR:") == Some(anchor))
        .ok_or_else(|| MarkerError::AnchorNotFound {
            anchor: anchor.to_owned(),
        })?;
    let end = start
        + 1
        + lines[start + 1..]
            .iter()
            .position(|line| anchor_name(line, "ANCHOR_END:") == Some(anchor))
            .ok_or_else(|| MarkerError::AnchorNotClosed {
                anchor: anchor.to_owned(),
                line: start + 1,
            })?;
    Ok(start + 1..end)
}

/// What the book shows for an exercise in a student edition, where it holds no solution: the
/// anchor's lines as they stand (the stub, or the student's own answer).
pub fn book_as_written(source: &str, anchor: &str) -> Result<String, MarkerError> {
    let lines: Vec<&str> = source.lines().collect();
    let body = anchor_body(&lines, anchor)?;
    let shown: Vec<&str> = lines[body]
        .iter()
        .copied()
        .filter(|line| !is_anchor_line(line))
        .collect();
    Ok(shown.join("\n"))
}

/// The lines of an exercise's solution region (markers left out), for finding a solution
/// written out somewhere it should not be.
pub fn solution_lines(source: &str, anchor: &str) -> Result<Vec<String>, MarkerError> {
    let lines: Vec<&str> = source.lines().collect();
    let span = locate(&lines, anchor)?;
    let inner = span.solution.start + 1..span.solution.end - 1;
    Ok(lines[inner].iter().map(|line| (*line).to_owned()).collect())
}

/// `source` with the solution region of exercise `anchor` replaced by `code` (a wrong answer
/// to try), each of its lines indented as the region's `BEGIN` marker is.
pub fn splice_code(source: &str, anchor: &str, code: &str) -> Result<String, MarkerError> {
    let lines: Vec<&str> = source.lines().collect();
    let span = locate(&lines, anchor)?;
    let begin = lines[span.solution.start];
    let indent = &begin[..begin.len() - begin.trim_start().len()];
    let mut out: Vec<String> = lines[..span.solution.start]
        .iter()
        .map(|line| (*line).to_owned())
        .collect();
    for line in code.trim_end().lines() {
        out.push(if line.trim().is_empty() {
            String::new()
        } else {
            format!("{indent}{line}")
        });
    }
    out.extend(
        lines[span.solution.end..]
            .iter()
            .map(|line| (*line).to_owned()),
    );
    Ok(joined_like(&out, source))
}

/// `lines` joined into a file's text, ending with a line break if `source` does.
fn joined_like(lines: &[String], source: &str) -> String {
    let mut text = lines.join("\n");
    if source.ends_with('\n') {
        text.push('\n');
    }
    text
}

/// The parameters of the function whose body holds the exercise's solution that nothing
/// outside the solution uses: what the stub would leave unused. Read from the signature, the
/// last `fn` line in the anchor before the solution, up to its opening brace.
fn unused_inputs(lines: &[&str], span: &ExerciseSpan) -> Vec<String> {
    let before = &lines[span.body.start..span.solution.start];
    let Some(fn_line) = before.iter().rposition(|line| {
        let code = line.trim_start();
        !code.starts_with("//") && (code.starts_with("fn ") || code.contains(" fn "))
    }) else {
        return Vec::new();
    };
    let signature: String = before[fn_line..].join(" ");
    let Some(open) = signature.find('(') else {
        return Vec::new();
    };
    // The parameter list: up to the parenthesis that closes the first one.
    // A `>` after `-` is an arrow (`Fn(u32) -> f32`), not a closing bracket.
    let closes = |text: &str, index: usize, c: char| {
        matches!(c, ')' | ']') || (c == '>' && !text[..index].ends_with('-'))
    };
    let mut depth = 0;
    let mut close = None;
    for (index, c) in signature[open..].char_indices() {
        match c {
            '(' | '<' | '[' => depth += 1,
            c if closes(&signature[open..], index, c) => {
                depth -= 1;
                if depth == 0 {
                    close = Some(open + index);
                    break;
                }
            }
            _ => {}
        }
    }
    let Some(close) = close else {
        return Vec::new();
    };
    let mut names = Vec::new();
    let (mut level, mut start) = (0, open + 1);
    let list = &signature[..close];
    for (index, c) in list.char_indices().skip(open + 1) {
        match c {
            '(' | '<' | '[' => level += 1,
            c if closes(list, index, c) => level -= 1,
            ',' if level == 0 => {
                names.push(list[start..index].to_string());
                start = index + 1;
            }
            _ => {}
        }
    }
    names.push(list[start..].to_string());
    // The body starts after the line that opens it.
    let Some(opens) = before[fn_line..]
        .iter()
        .position(|line| line.trim_end().ends_with('{'))
    else {
        return Vec::new();
    };
    let body_outside: Vec<&str> = lines[span.body.start + fn_line + opens + 1..span.solution.start]
        .iter()
        .chain(&lines[span.solution.end..span.body.end])
        .copied()
        .collect();
    names
        .iter()
        .filter_map(|parameter| {
            let name = parameter.split(':').next()?.trim();
            let name = name.strip_prefix("mut ").unwrap_or(name).trim();
            let is_identifier = !name.is_empty()
                && name != "self"
                && !name.starts_with('_')
                && name.chars().all(|c| c.is_alphanumeric() || c == '_');
            let used = body_outside.iter().any(|line| uses_word(line, name));
            (is_identifier && parameter.contains(':') && !used).then(|| name.to_string())
        })
        .collect()
}

/// Whether `line` holds `word` as a whole identifier.
fn uses_word(line: &str, word: &str) -> bool {
    line.match_indices(word).any(|(at, _)| {
        let before = line[..at].chars().next_back();
        let after = line[at + word.len()..].chars().next();
        let part = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
        !part(before) && !part(after)
    })
}

/// What stands in a solution's place in the student edition: its `todo!` call, after a line
/// that names the inputs the stub would leave unused. Lines after the first are indented by
/// `indent`; the first is placed where the region's `BEGIN` marker was.
fn stub_text(lines: &[&str], span: &ExerciseSpan, message: &str, indent: &str) -> String {
    let todo = todo_call(Some(message));
    match unused_inputs(lines, span).as_slice() {
        [] => todo,
        inputs => {
            // The stub leaves the function's inputs unused; naming them keeps the build
            // free of warnings until the student's code uses them.
            // Borrowed, not moved: the student's code may still use them all after it.
            let borrowed: Vec<String> = inputs.iter().map(|name| format!("&{name}")).collect();
            let inputs = match borrowed.as_slice() {
                [one] => one.clone(),
                many => format!("({})", many.join(", ")),
            };
            format!("let _ = {inputs}; // the inputs, until your code uses them\n{indent}{todo}")
        }
    }
}

/// `source` with `line` put first in the solution region of exercise `anchor` (just after its
/// `BEGIN` marker, indented as the marker is), the solution left as it is. Every solution
/// region is the tail of a block, so one statement may always stand first in it.
pub fn mark_solution(source: &str, anchor: &str, line: &str) -> Result<String, MarkerError> {
    let lines: Vec<&str> = source.lines().collect();
    let span = locate(&lines, anchor)?;
    let begin = lines[span.solution.start];
    let indent = &begin[..begin.len() - begin.trim_start().len()];
    let mut out: Vec<String> = lines.iter().map(|line| (*line).to_owned()).collect();
    out.insert(span.solution.start + 1, format!("{indent}{line}"));
    Ok(joined_like(&out, source))
}

/// `source` with the solution region of exercise `anchor` made a switch among its recorded
/// wrong answers: `match CHOICE { 1 => { wrong 1 } ... _ => { MARK solution } }`, the markers
/// kept around it. Every solution region is the tail of a function's body, so the `match` is
/// the function's value whichever arm runs; one build then serves every wrong answer, chosen
/// when the check runs (`choice` is the expression that reads which). `mark` stands first in
/// the solution's arm, as [`mark_solution`] puts it.
pub fn switch_solution(
    source: &str,
    anchor: &str,
    mark: &str,
    choice: &str,
    wrong: &[&str],
) -> Result<String, MarkerError> {
    let lines: Vec<&str> = source.lines().collect();
    let span = locate(&lines, anchor)?;
    let begin = lines[span.solution.start];
    let indent = &begin[..begin.len() - begin.trim_start().len()];
    let arm = |out: &mut Vec<String>, pattern: &str, code: &mut dyn Iterator<Item = String>| {
        out.push(format!("{indent}    {pattern} => {{"));
        for line in code {
            out.push(if line.trim().is_empty() {
                String::new()
            } else {
                format!("{indent}        {line}")
            });
        }
        out.push(format!("{indent}    }}"));
    };
    let mut out: Vec<String> = lines[..=span.solution.start]
        .iter()
        .map(|line| (*line).to_owned())
        .collect();
    out.push(format!("{indent}match {choice} {{"));
    for (index, code) in wrong.iter().enumerate() {
        let mut code = code.trim_end().lines().map(str::to_owned);
        arm(&mut out, &(index + 1).to_string(), &mut code);
    }
    let solution = &lines[span.solution.start + 1..span.solution.end - 1];
    let mut code = std::iter::once(mark.to_owned()).chain(
        solution
            .iter()
            .map(|line| line.strip_prefix(indent).unwrap_or(line).to_owned()),
    );
    arm(&mut out, "_", &mut code);
    out.push(format!("{indent}}}"));
    out.extend(
        lines[span.solution.end - 1..]
            .iter()
            .map(|line| (*line).to_owned()),
    );
    Ok(joined_like(&out, source))
}

/// One exercise to cut out of a file: its anchor and the message of its `todo!`.
#[derive(Debug, Clone)]
pub struct Cut<'a> {
    /// The exercise's anchor name.
    pub anchor: &'a str,
    /// The message its `todo!` carries.
    pub message: String,
}

/// The student edition of a whole source file: every listed exercise's solution replaced by its
/// `todo!` line, everything else untouched. A marker outside those exercises is an error, so
/// that no solution leaks into the student edition unnoticed.
pub fn student_source(source: &str, cuts: &[Cut<'_>]) -> Result<String, Vec<MarkerError>> {
    let lines: Vec<&str> = source.lines().collect();
    let mut errors = Vec::new();
    let mut regions: Vec<(Range<usize>, String)> = Vec::new();
    let mut owners: Vec<&str> = Vec::new();
    for cut in cuts {
        let span = match locate(&lines, cut.anchor) {
            Ok(span) => span,
            Err(error) => {
                errors.push(error);
                continue;
            }
        };
        let claimed = regions
            .iter()
            .position(|(range, _)| overlap(range, &span.solution));
        if let Some(other) = claimed {
            errors.push(MarkerError::SharedSolution {
                line: span.solution.start + 1,
                first: owners[other].to_owned(),
                second: cut.anchor.to_owned(),
            });
            continue;
        }
        let begin = lines[span.solution.start];
        let indent = &begin[..begin.len() - begin.trim_start().len()];
        let stub = stub_text(&lines, &span, &cut.message, indent);
        regions.push((span.solution, stub));
        owners.push(cut.anchor);
    }
    for (index, marker) in marker_lines(source) {
        let expected = regions
            .iter()
            .any(|(range, _)| index == range.start || index + 1 == range.end);
        if !expected {
            errors.push(MarkerError::StrayMarker {
                marker,
                line: index + 1,
            });
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }

    let mut out = splice_todos(&lines, &regions).join("\n");
    if source.ends_with('\n') {
        out.push('\n');
    }
    Ok(out)
}

fn overlap(a: &Range<usize>, b: &Range<usize>) -> bool {
    a.start < b.end && b.start < a.end
}

/// Every marker line in `source`, with its 0-based line index.
pub fn marker_lines(source: &str) -> impl Iterator<Item = (usize, Marker)> + '_ {
    source
        .lines()
        .enumerate()
        .filter_map(|(index, line)| Marker::of_line(line).map(|marker| (index, marker)))
}

#[cfg(test)]
mod tests {
    use super::*;

    // Test sources are built from escaped one-line strings on purpose: a marker on a line of
    // its own here would be a stray marker in the workspace's own sources.
    const REFLECT: &str = "use glam::Vec3;\n\n// ANCHOR: reflect\n/// A made-up formula in the place of the mirror direction.\npub fn reflect(u: Vec3, v: Vec3, w: Vec3) -> Vec3 {\n    // BEGIN SOLUTION\n    u - 3.0 * u.dot(v) * w\n    // END SOLUTION\n}\n// ANCHOR_END: reflect\n";

    #[test]
    fn a_mark_goes_first_in_the_solution_which_stays() {
        let marked = mark_solution(REFLECT, "reflect", "mark();").unwrap();
        assert_eq!(
            marked,
            "use glam::Vec3;\n\n// ANCHOR: reflect\n/// A made-up formula in the place of the mirror direction.\npub fn reflect(u: Vec3, v: Vec3, w: Vec3) -> Vec3 {\n    // BEGIN SOLUTION\n    mark();\n    u - 3.0 * u.dot(v) * w\n    // END SOLUTION\n}\n// ANCHOR_END: reflect\n"
        );
        assert!(mark_solution(REFLECT, "refract", "mark();").is_err());
    }

    #[test]
    fn a_switch_holds_every_wrong_answer_and_the_marked_solution_last() {
        let switched = switch_solution(
            REFLECT,
            "reflect",
            "mark();",
            "which()",
            &["u", "let k = 2.0;\nu - k * w"],
        )
        .unwrap();
        assert_eq!(
            switched,
            "use glam::Vec3;\n\n// ANCHOR: reflect\n/// A made-up formula in the place of the mirror direction.\npub fn reflect(u: Vec3, v: Vec3, w: Vec3) -> Vec3 {\n    // BEGIN SOLUTION\n    match which() {\n        1 => {\n            u\n        }\n        2 => {\n            let k = 2.0;\n            u - k * w\n        }\n        _ => {\n            mark();\n            u - 3.0 * u.dot(v) * w\n        }\n    }\n    // END SOLUTION\n}\n// ANCHOR_END: reflect\n"
        );
        // Still one exercise: the markers stand where they stood, around the switch.
        assert_eq!(
            locate(&lines(&switched), "reflect").unwrap().solution,
            5..20
        );
        assert!(switch_solution(REFLECT, "refract", "", "0", &[]).is_err());
    }

    fn lines(source: &str) -> Vec<&str> {
        source.lines().collect()
    }

    #[test]
    fn locates_anchor_body_and_solution() {
        let span = locate(&lines(REFLECT), "reflect").unwrap();
        assert_eq!(span.body, 3..9);
        assert_eq!(span.solution, 5..8);
    }

    #[test]
    fn book_stub_shows_anchor_with_todo() {
        let stub = book_stub(REFLECT, "reflect").unwrap();
        assert_eq!(
            stub,
            "/// A made-up formula in the place of the mirror direction.\npub fn reflect(u: Vec3, v: Vec3, w: Vec3) -> Vec3 {\n    todo!()\n}"
        );
    }

    #[test]
    fn book_stub_hides_other_anchor_lines() {
        let source = "// ANCHOR: outer\nfn f() {\n    // ANCHOR: inner\n    // BEGIN SOLUTION\n    1\n    // END SOLUTION\n    // ANCHOR_END: inner\n}\n// ANCHOR_END: outer\n";
        assert_eq!(
            book_stub(source, "outer").unwrap(),
            "fn f() {\n    todo!()\n}"
        );
    }

    #[test]
    fn todo_keeps_nested_indentation() {
        let source = "// ANCHOR: shade\nfn shade(hit: bool) -> f32 {\n    if hit {\n        let k = 0.5;\n        // BEGIN SOLUTION\n        k * 2.0\n        // END SOLUTION\n    } else {\n        0.0\n    }\n}\n// ANCHOR_END: shade\n";
        let stub = book_stub(source, "shade").unwrap();
        assert!(stub.contains("\n        let k = 0.5;\n        todo!()\n    } else {"));
    }

    #[test]
    fn student_source_replaces_only_the_region_and_keeps_the_rest() {
        let cut = Cut {
            anchor: "reflect",
            message: "ch01-reflect: lever `u` about `v`".to_owned(),
        };
        let student = student_source(REFLECT, &[cut]).unwrap();
        assert_eq!(
            student,
            "use glam::Vec3;\n\n// ANCHOR: reflect\n/// A made-up formula in the place of the mirror direction.\npub fn reflect(u: Vec3, v: Vec3, w: Vec3) -> Vec3 {\n    let _ = (&u, &v, &w); // the inputs, until your code uses them\n    ::common::exercise::todo(\"ch01-reflect: lever `u` about `v`\")\n}\n// ANCHOR_END: reflect\n"
        );
    }

    #[test]
    fn student_source_handles_two_exercises_in_one_file() {
        let source = "// ANCHOR: a\nfn a() -> u8 {\n    // BEGIN SOLUTION\n    1\n    // END SOLUTION\n}\n// ANCHOR_END: a\n// ANCHOR: b\nfn b() -> u8 {\n  // BEGIN SOLUTION\n  2\n  // END SOLUTION\n}\n// ANCHOR_END: b";
        let cuts = [
            Cut {
                anchor: "b",
                message: "b".to_owned(),
            },
            Cut {
                anchor: "a",
                message: "a".to_owned(),
            },
        ];
        let student = student_source(source, &cuts).unwrap();
        assert!(student.contains("fn a() -> u8 {\n    ::common::exercise::todo(\"a\")\n}"));
        assert!(student.contains("fn b() -> u8 {\n  ::common::exercise::todo(\"b\")\n}"));
        assert!(!student.ends_with('\n'));
    }

    #[test]
    fn student_source_reports_markers_outside_listed_exercises() {
        let source = format!("{REFLECT}fn other() {{\n    // BEGIN SOLUTION\n}}\n");
        let cut = Cut {
            anchor: "reflect",
            message: String::new(),
        };
        let errors = student_source(&source, &[cut]).unwrap_err();
        assert_eq!(
            errors,
            vec![MarkerError::StrayMarker {
                marker: Marker::Begin,
                line: 12
            }]
        );
    }

    #[test]
    fn unlisted_file_with_markers_is_all_strays() {
        let errors = student_source(REFLECT, &[]).unwrap_err();
        assert_eq!(errors.len(), 2);
    }

    #[test]
    fn two_exercises_cannot_share_a_solution() {
        let source = "// ANCHOR: outer\n// ANCHOR: inner\n// BEGIN SOLUTION\n// END SOLUTION\n// ANCHOR_END: inner\n// ANCHOR_END: outer\n";
        let cut = |anchor| Cut {
            anchor,
            message: String::new(),
        };
        let errors = student_source(source, &[cut("outer"), cut("inner")]).unwrap_err();
        assert_eq!(
            errors,
            vec![MarkerError::SharedSolution {
                line: 3,
                first: "outer".to_owned(),
                second: "inner".to_owned()
            }]
        );
    }

    #[test]
    fn the_students_stub_is_one_valid_literal() {
        assert_eq!(todo_call(None), "todo!()");
        assert_eq!(
            todo_call(Some("say \"hi\" to {x}")),
            r#"::common::exercise::todo("say \"hi\" to {x}")"#
        );
    }

    #[test]
    fn missing_anchor_is_an_error() {
        assert_eq!(
            book_stub(REFLECT, "refract"),
            Err(MarkerError::AnchorNotFound {
                anchor: "refract".to_owned()
            })
        );
    }

    #[test]
    fn anchor_name_must_match_exactly() {
        let source = "// ANCHOR: reflect_all\n// BEGIN SOLUTION\n// END SOLUTION\n// ANCHOR_END: reflect_all\n";
        assert!(matches!(
            book_stub(source, "reflect"),
            Err(MarkerError::AnchorNotFound { .. })
        ));
    }

    #[test]
    fn unclosed_anchor_is_an_error() {
        let source = "// ANCHOR: a\n// BEGIN SOLUTION\n// END SOLUTION\n";
        assert_eq!(
            book_stub(source, "a"),
            Err(MarkerError::AnchorNotClosed {
                anchor: "a".to_owned(),
                line: 1
            })
        );
    }

    #[test]
    fn anchor_without_solution_is_an_error() {
        let source = "// ANCHOR: a\nfn a() {}\n// ANCHOR_END: a\n";
        assert!(matches!(
            book_stub(source, "a"),
            Err(MarkerError::NoSolution { .. })
        ));
    }

    #[test]
    fn unmatched_begin_is_an_error() {
        let source = "// ANCHOR: a\n  // BEGIN SOLUTION\n  1\n// ANCHOR_END: a\n// END SOLUTION\n";
        assert_eq!(
            book_stub(source, "a"),
            Err(MarkerError::UnclosedSolution { line: 2 })
        );
    }

    #[test]
    fn unmatched_end_is_an_error() {
        let source = "// ANCHOR: a\n  1\n  // END SOLUTION\n// ANCHOR_END: a\n";
        assert_eq!(
            book_stub(source, "a"),
            Err(MarkerError::UnopenedSolution { line: 3 })
        );
    }

    #[test]
    fn nested_regions_are_an_error() {
        let source = "// ANCHOR: a\n// BEGIN SOLUTION\n// BEGIN SOLUTION\n// END SOLUTION\n// END SOLUTION\n// ANCHOR_END: a\n";
        assert_eq!(
            book_stub(source, "a"),
            Err(MarkerError::NestedSolution { line: 3, opened: 2 })
        );
    }

    #[test]
    fn second_region_is_an_error() {
        let source = "// ANCHOR: a\n// BEGIN SOLUTION\n// END SOLUTION\n// BEGIN SOLUTION\n// END SOLUTION\n// ANCHOR_END: a\n";
        assert_eq!(
            book_stub(source, "a"),
            Err(MarkerError::SecondSolution {
                anchor: "a".to_owned(),
                line: 4
            })
        );
    }

    #[test]
    fn markers_must_stand_alone_on_their_line() {
        assert_eq!(
            Marker::of_line("    // BEGIN SOLUTION  "),
            Some(Marker::Begin)
        );
        assert_eq!(Marker::of_line("x; // BEGIN SOLUTION"), None);
        assert_eq!(Marker::of_line("/// // END SOLUTION"), None);
    }

    #[test]
    fn a_wrong_answer_takes_the_solutions_place() {
        let spliced = splice_code(REFLECT, "reflect", "u - u.dot(v) * w\n").unwrap();
        assert_eq!(
            spliced,
            "use glam::Vec3;\n\n// ANCHOR: reflect\n/// A made-up formula in the place of the mirror direction.\npub fn reflect(u: Vec3, v: Vec3, w: Vec3) -> Vec3 {\n    u - u.dot(v) * w\n}\n// ANCHOR_END: reflect\n"
        );
        assert!(splice_code(REFLECT, "refract", "x").is_err());
    }

    #[test]
    fn the_stub_names_the_inputs_it_leaves_unused() {
        let source = "// ANCHOR: step\npub fn step<S: Sampler>(\n    &self,\n    ray: &Ray,\n    depth: u32,\n    f: impl Fn(u32, f32) -> f32,\n) -> f32 {\n    let scale = 2.0 * depth as f32;\n    // BEGIN SOLUTION\n    scale * f(depth, ray.t_max)\n    // END SOLUTION\n}\n// ANCHOR_END: step\n";
        let lines: Vec<&str> = source.lines().collect();
        let span = locate(&lines, "step").unwrap();
        // `depth` is used before the solution; `self` is no input to name.
        assert_eq!(unused_inputs(&lines, &span), ["ray", "f"]);
        let cut = Cut {
            anchor: "step",
            message: "go".into(),
        };
        let student = student_source(source, &[cut]).unwrap();
        assert!(
            student.contains(
                "    let _ = (&ray, &f); // the inputs, until your code uses them\n    ::common::exercise::todo(\"go\")"
            ),
            "{student}"
        );
    }
}
