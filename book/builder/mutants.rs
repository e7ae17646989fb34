//! `check-exercises --mutants N`: mistakes nobody recorded, tried on every check.
//!
//! The recorded wrong answers prove that a check names the mistakes its author thought of. A
//! student makes others, and a check must meet those too without crashing: a wrong answer may
//! make a check fail, in words of its own or in a panic of the student's own code, but never in
//! a panic of the workbook's code (an index out of bounds, an overflow, an `unwrap` of nothing,
//! another exercise's stub, anything inside `common`), never by hanging, never by aborting.
//!
//! For each exercise this derives up to N mutants of its solution, each one slip a student
//! could make (an answer that gives up and returns the type's default, an operator swapped, a
//! square root or a normalisation left out, a `max` for a `min`, a constant that became zero,
//! a sign dropped), puts them into a copy of the workspace in rounds in which no check runs the code of another mutant of its round,
//! compiles the round once, and runs each mutant's check alone, with a time limit. A mutant
//! that does not compile is set aside; one that passes its check "survived" (listed, since a
//! slip can be harmless, but not an error). The sweep fails on every crash and hang, printing
//! where the panic was and what it said. It is slow (about a minute a round): an author's tool,
//! not part of CI.

use std::collections::{BTreeSet, HashMap};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};

use crate::check_exercises::{Compiled, Trial};
use crate::exercise_calls::MarkedRun;
use crate::exercise_list::Exercise;
use crate::solution_markers;

/// How long one check may run before it counts as hanging.
const TIME_LIMIT: Duration = Duration::from_secs(300);

/// One slip put into a solution.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Mutant {
    /// What was changed, for the report: "line 3: ` + ` -> ` - `".
    pub what: String,
    /// The solution with the slip, indented as the wrong answers are (from the region's left).
    pub code: String,
}

/// The slips tried, in the order they are taken: each a text and what replaces it.
const SLIPS: &[(&str, &str)] = &[
    (" + ", " - "),
    (" * ", " / "),
    (".sqrt()", ""),
    (" - ", " + "),
    (" / ", " * "),
    (".normalize()", ""),
    (" < ", " > "),
    (" > ", " < "),
    (".max(", ".min("),
    (".min(", ".max("),
    ("(-", "("),
    (".abs()", ""),
    (" && ", " || "),
    (" || ", " && "),
    (" <= ", " >= "),
    (" >= ", " <= "),
];

/// One place where a slip can go: the line, the byte it starts at, what is there, and what
/// replaces it.
type Place = (usize, usize, String, String);

/// Up to `most` mutants of `solution` (its lines as they stand between the markers, `indent`
/// being the region's indentation), one slip each: the slips in [`SLIPS`]' order, each at its
/// places in the text in turn, then every decimal constant made zero.
pub fn mutants(solution: &[String], indent: &str, most: usize) -> Vec<Mutant> {
    let lines: Vec<&str> = solution
        .iter()
        .map(|line| line.strip_prefix(indent).unwrap_or(line.trim_start()))
        .collect();
    // Every place of every slip, by slip.
    let mut places: Vec<Vec<Place>> = Vec::new();
    for &(from, to) in SLIPS {
        let mut found = Vec::new();
        for (number, line) in lines.iter().enumerate() {
            for (at, _) in code_part(line).match_indices(from) {
                found.push((number, at, from.to_owned(), to.to_owned()));
            }
        }
        places.push(found);
    }
    let mut zeros = Vec::new();
    for (number, line) in lines.iter().enumerate() {
        for (at, literal) in decimal_literals(&code_part(line)) {
            if literal.trim_start_matches(['0', '.', '_']).is_empty() {
                continue; // already zero
            }
            zeros.push((number, at, literal, "0.0".to_owned()));
        }
    }
    places.push(zeros);
    // Round robin over the kinds of slip, so that a few mutants are of different kinds.
    let mut chosen: Vec<&Place> = Vec::new();
    let mut depth = 0;
    while chosen.len() < most && places.iter().any(|found| found.len() > depth) {
        for found in &places {
            if let Some(place) = found.get(depth)
                && chosen.len() < most
            {
                chosen.push(place);
            }
        }
        depth += 1;
    }
    let slips = chosen.into_iter().map(|(number, at, from, to)| {
        let mut changed: Vec<String> = lines.iter().map(|line| (*line).to_owned()).collect();
        changed[*number].replace_range(*at..*at + from.len(), to);
        Mutant {
            what: format!("line {}: `{}` -> `{}`", number + 1, from.trim(), to.trim()),
            code: changed.join("\n"),
        }
    });
    // First, the answer that gives up: nothing computed, the type's default (zero, no hit, an
    // empty list), as a student who returns early would.
    let gives_up = Mutant {
        what: "the whole answer: `Default::default()`".to_owned(),
        code: "Default::default()".to_owned(),
    };
    std::iter::once(gives_up).chain(slips).take(most).collect()
}

/// `line` up to a `//` comment, with string and character literals blanked out (so that no
/// slip lands in a comment or a message), every byte kept in its place.
fn code_part(line: &str) -> String {
    let bytes = line.as_bytes();
    let mut out = vec![b' '; bytes.len()];
    let mut in_string = false;
    let mut escaped = false;
    for (index, &byte) in bytes.iter().enumerate() {
        if in_string {
            if escaped {
                escaped = false;
            } else if byte == b'\\' {
                escaped = true;
            } else if byte == b'"' {
                in_string = false;
            }
            continue;
        }
        match byte {
            b'/' if bytes.get(index + 1) == Some(&b'/') => break,
            b'"' => in_string = true,
            _ if byte.is_ascii() => out[index] = byte,
            _ => {}
        }
    }
    String::from_utf8(out).expect("ASCII")
}

/// The decimal constants (`2.0`, `0.25`, `1.5f32`) in `code`, with where each starts; digits
/// that belong to a name (`p2`), a field (`.0`) or an exponent form are left alone.
fn decimal_literals(code: &str) -> Vec<(usize, String)> {
    let bytes = code.as_bytes();
    let word = |byte: u8| byte.is_ascii_alphanumeric() || byte == b'_';
    let mut found = Vec::new();
    let mut index = 0;
    while index < bytes.len() {
        let starts = bytes[index].is_ascii_digit()
            && (index == 0 || !(word(bytes[index - 1]) || bytes[index - 1] == b'.'));
        if !starts {
            index += 1;
            continue;
        }
        let mut end = index;
        while end < bytes.len() && (bytes[end].is_ascii_digit() || bytes[end] == b'_') {
            end += 1;
        }
        if end + 1 < bytes.len() && bytes[end] == b'.' && bytes[end + 1].is_ascii_digit() {
            end += 1;
            while end < bytes.len() && (bytes[end].is_ascii_digit() || bytes[end] == b'_') {
                end += 1;
            }
            let suffix = &code[end..];
            let plain = !suffix.starts_with(['e', 'E']);
            if plain {
                let typed = ["f32", "f64"].iter().find(|t| suffix.starts_with(*t));
                found.push((index, code[index..end].to_owned()));
                end += typed.map_or(0, |t| t.len());
            }
        }
        index = end.max(index + 1);
    }
    found
}

/// What a mutant's check did.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The check failed without a crash: what it is meant to do.
    Refused,
    /// The check passed: the slip made no difference it tests.
    Survived,
    /// The mutant does not compile: no student would run it.
    DoesNotCompile,
    /// The check crashed in the workbook's code, or the process died: where and what.
    Crash(String),
    /// The check ran past [`TIME_LIMIT`].
    Hang,
}

/// How the workbook's own panics begin that a wrong answer must never cause, whatever their
/// place: the standard library's messages for indexing, arithmetic, unwrapping and bare
/// assertions, and a stub's. A check that caught such a panic and explains it quotes it after
/// words of its own, so only a message that *begins* so is a crash.
const CRASH_STARTS: &[&str] = &[
    "index out of bounds",
    "attempt to ",
    "called `Option::unwrap()` on a `None` value",
    "called `Result::unwrap()` on an `Err` value",
    "not yet implemented",
    "this check needs ",
    "this program needs ",
    "slice index starts at",
    "range end index",
    "range start index",
    "byte index",
    "capacity overflow",
    "already borrowed",
    "already mutably borrowed",
    "assertion failed",
];

/// Whether `message` is a bare `assert_eq!` or `assert_ne!`: one with words of its own reads
/// "assertion `left == right` failed: <words>".
fn bare_comparison(message: &str) -> bool {
    message.starts_with("assertion `") && !message.contains("failed: ")
}

/// One panic a run printed: where (`file:line:column` as the compiler wrote it) and what.
#[derive(Debug, PartialEq, Eq)]
struct Panic {
    file: String,
    line: usize,
    message: String,
}

/// Every `thread '...' panicked at FILE:LINE:COL:` in `output`, with the line after it.
fn panics(output: &str) -> Vec<Panic> {
    let lines: Vec<&str> = output.lines().collect();
    let mut found = Vec::new();
    for (index, line) in lines.iter().enumerate() {
        let Some(place) = line
            .split_once("' panicked at ")
            .or_else(|| line.split_once(") panicked at "))
            .map(|(_, place)| place.trim_end_matches(':'))
        else {
            continue;
        };
        let mut parts = place.rsplitn(3, ':');
        let (_column, line_number, file) = (parts.next(), parts.next(), parts.next());
        let (Some(line_number), Some(file)) = (line_number.and_then(|n| n.parse().ok()), file)
        else {
            continue;
        };
        found.push(Panic {
            file: file.to_owned(),
            line: line_number,
            message: lines.get(index + 1).copied().unwrap_or_default().to_owned(),
        });
    }
    found
}

/// The verdict on a check that ran to its end (`passed`, what it printed), for a mutant of the
/// exercise whose anchor spans `own` (file relative to the workspace, lines numbered from 1) in
/// the copy.
fn verdict(passed: bool, output: &str, own: &(PathBuf, std::ops::Range<usize>)) -> Verdict {
    if passed {
        return Verdict::Survived;
    }
    if output.contains("has overflowed its stack") || output.contains("(signal: ") {
        return Verdict::Crash(format!(
            "the process died: {}",
            output
                .lines()
                .find(|line| line.contains("overflowed") || line.contains("signal"))
                .unwrap_or_default()
        ));
    }
    for panic in panics(output) {
        let in_own_code = Path::new(&panic.file) == own.0 && own.1.contains(&panic.line);
        if in_own_code {
            continue; // the student's own code panicked: theirs to read
        }
        let in_common = (panic.file.starts_with("common/src/")
            || panic.file.starts_with("workbench/src/"))
            && !panic.file.contains("test_support");
        let message = panic.message.trim_start();
        let crash_words =
            CRASH_STARTS.iter().any(|start| message.starts_with(start)) || bare_comparison(message);
        if in_common || crash_words {
            return Verdict::Crash(format!(
                "panicked at {}:{}: {}",
                panic.file, panic.line, panic.message
            ));
        }
    }
    Verdict::Refused
}

/// Runs the sweep over the `selected` exercises (of `all`) in a fresh copy of the workspace at
/// `root`, up to `most` mutants each; fails on any crash or hang.
pub fn run(
    root: &Path,
    all: &[Exercise],
    selected: &dyn Fn(&Exercise) -> bool,
    most: usize,
) -> Result<()> {
    let chosen: Vec<Exercise> = all.iter().filter(|e| selected(e)).cloned().collect();
    let mut trial = Trial::in_workspace(root)?;
    sweep(&mut trial, all, &chosen, most)
}

/// The sweep over the `chosen` exercises (of `all`) in `trial`.
fn sweep(trial: &mut Trial<'_>, all: &[Exercise], chosen: &[Exercise], most: usize) -> Result<()> {
    let started = Instant::now();
    let runs = trial.run_marked(chosen, all)?;
    let mut pending: Vec<(&Exercise, Mutant)> = Vec::new();
    for exercise in chosen {
        let source = std::fs::read_to_string(trial.root().join(&exercise.file))
            .with_context(|| format!("cannot read {}", exercise.file.display()))?;
        let solution = solution_markers::solution_lines(&source, &exercise.anchor)
            .with_context(|| format!("{}: {}", exercise.name, exercise.file.display()))?;
        let indent = region_indent(&source, &exercise.anchor)?;
        for mutant in mutants(&solution, &indent, most) {
            pending.push((exercise, mutant));
        }
    }
    println!(
        "\n{} mutant(s) of {} exercise(s), tried in rounds in which no check runs another \
         mutant's code",
        pending.len(),
        chosen.len()
    );
    println!("{:<30} {:<36} verdict", "exercise", "mutant");
    let mut verdicts: Vec<(&Exercise, Mutant, Verdict)> = Vec::new();
    let mut round_number = 0;
    while !pending.is_empty() {
        round_number += 1;
        let round = take_round(&mut pending, &runs);
        let mut members = round;
        loop {
            let splices: Vec<(&Exercise, String)> =
                members.iter().map(|(e, m)| (*e, m.code.clone())).collect();
            trial.put_in(&splices)?;
            let packages: BTreeSet<&str> = members
                .iter()
                .filter_map(|(e, _)| crate::progress::standard_check(&e.check).map(|(p, _)| p))
                .collect();
            let packages: Vec<&str> = packages.into_iter().collect();
            match trial.compile_library_tests(&packages)? {
                Compiled::Binaries(binaries) => {
                    for (exercise, mutant) in members.drain(..) {
                        let own = own_span(trial.copy_dir(), exercise)?;
                        let verdict = run_check(exercise, &binaries, &own)?;
                        print_verdict(exercise, &mutant, &verdict);
                        verdicts.push((exercise, mutant, verdict));
                    }
                    break;
                }
                Compiled::Errors { places, text, .. } => {
                    // Set aside the mutants the errors point into; try the rest again.
                    let mut broken = Vec::new();
                    for (index, (exercise, _)) in members.iter().enumerate() {
                        let (file, span) = own_span(trial.copy_dir(), exercise)?;
                        if places
                            .iter()
                            .any(|(f, line)| *f == file && span.contains(line))
                        {
                            broken.push(index);
                        }
                    }
                    if broken.is_empty() {
                        if members.len() == 1 {
                            bail!(
                                "round {round_number}: the copy does not compile, and not where \
                                 the mutant is:\n{text}"
                            );
                        }
                        // Not placed: each member again alone, later.
                        for member in members.drain(..) {
                            pending.push(member);
                        }
                        break;
                    }
                    for index in broken.into_iter().rev() {
                        let (exercise, mutant) = members.remove(index);
                        print_verdict(exercise, &mutant, &Verdict::DoesNotCompile);
                        verdicts.push((exercise, mutant, Verdict::DoesNotCompile));
                    }
                    if members.is_empty() {
                        break;
                    }
                }
            }
        }
        println!(
            "  (round {round_number} done, {:.0} s so far)",
            started.elapsed().as_secs_f64()
        );
    }
    trial.put_in(&[])?;
    report(&verdicts, started)
}

/// The next round: from the front of `pending`, each mutant whose exercise has none in the
/// round yet, whose check runs none of the round's exercises' code, and whose code no check of
/// the round runs.
fn take_round<'e>(
    pending: &mut Vec<(&'e Exercise, Mutant)>,
    runs: &HashMap<String, MarkedRun>,
) -> Vec<(&'e Exercise, Mutant)> {
    let runs_code_of = |check: &Exercise, other: &Exercise| {
        runs.get(&check.name)
            .is_some_and(|run| run.ran.contains(&other.name))
    };
    let mut round: Vec<(&Exercise, Mutant)> = Vec::new();
    let mut rest = Vec::new();
    for (exercise, mutant) in pending.drain(..) {
        let apart = round.iter().all(|(other, _)| {
            other.name != exercise.name
                && !runs_code_of(exercise, other)
                && !runs_code_of(other, exercise)
        });
        if apart {
            round.push((exercise, mutant));
        } else {
            rest.push((exercise, mutant));
        }
    }
    *pending = rest;
    round
}

/// The indentation of the `BEGIN` marker of `anchor`'s solution region in `source`.
fn region_indent(source: &str, anchor: &str) -> Result<String> {
    let lines: Vec<&str> = source.lines().collect();
    let span = solution_markers::locate(&lines, anchor)?;
    let begin = lines[span.solution.start];
    Ok(begin[..begin.len() - begin.trim_start().len()].to_owned())
}

/// The exercise's file and the lines of its anchor (numbered from 1) in the copy as it is now.
fn own_span(copy: &Path, exercise: &Exercise) -> Result<(PathBuf, std::ops::Range<usize>)> {
    let source = std::fs::read_to_string(copy.join(&exercise.file))
        .with_context(|| format!("cannot read {}", exercise.file.display()))?;
    let lines: Vec<&str> = source.lines().collect();
    let body = solution_markers::anchor_body(&lines, &exercise.anchor)?;
    Ok((exercise.file.clone(), body.start + 1..body.end + 1))
}

/// Runs `exercise`'s check (of the usual form) alone with its package's test binary, within
/// [`TIME_LIMIT`], and judges what it did.
fn run_check(
    exercise: &Exercise,
    binaries: &HashMap<String, (PathBuf, PathBuf)>,
    own: &(PathBuf, std::ops::Range<usize>),
) -> Result<Verdict> {
    let Some((package, filter)) = crate::progress::standard_check(&exercise.check) else {
        bail!(
            "{}: the sweep runs checks of the usual form only",
            exercise.name
        );
    };
    let Some((binary, dir)) = binaries.get(package) else {
        bail!("{}: no test binary for {package}", exercise.name);
    };
    let log = tempfile::NamedTempFile::new().context("cannot make a log file")?;
    let mut child = Command::new(binary)
        .arg(filter)
        .current_dir(dir)
        .env("CARGO_MANIFEST_DIR", dir)
        .env("RUST_BACKTRACE", "0")
        .stdin(Stdio::null())
        .stdout(log.reopen()?)
        .stderr(log.reopen()?)
        .spawn()
        .with_context(|| format!("cannot run {}", binary.display()))?;
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait()? {
            break Some(status);
        }
        if started.elapsed() > TIME_LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let output = std::fs::read_to_string(log.path()).unwrap_or_default();
    Ok(match status {
        None => Verdict::Hang,
        Some(status) if status.code().is_none() => Verdict::Crash(format!(
            "the process was killed by a signal ({status}): {}",
            output
                .lines()
                .rev()
                .find(|l| !l.trim().is_empty())
                .unwrap_or_default()
        )),
        Some(status) => verdict(status.success(), &output, own),
    })
}

fn print_verdict(exercise: &Exercise, mutant: &Mutant, verdict: &Verdict) {
    let word = match verdict {
        Verdict::Refused => "refused".to_owned(),
        Verdict::Survived => "survived (the check passed)".to_owned(),
        Verdict::DoesNotCompile => "does not compile".to_owned(),
        Verdict::Crash(what) => format!("CRASH: {what}"),
        Verdict::Hang => format!("HANG (over {} s)", TIME_LIMIT.as_secs()),
    };
    println!("{:<30} {:<36} {word}", exercise.name, mutant.what);
}

fn report(verdicts: &[(&Exercise, Mutant, Verdict)], started: Instant) -> Result<()> {
    let count =
        |wanted: fn(&Verdict) -> bool| verdicts.iter().filter(|(_, _, v)| wanted(v)).count();
    let refused = count(|v| *v == Verdict::Refused);
    let survived = count(|v| *v == Verdict::Survived);
    let broken = count(|v| *v == Verdict::DoesNotCompile);
    let bad: Vec<&(&Exercise, Mutant, Verdict)> = verdicts
        .iter()
        .filter(|(_, _, v)| matches!(v, Verdict::Crash(_) | Verdict::Hang))
        .collect();
    println!(
        "\n{} mutant(s) in {:.0} s: {refused} refused, {survived} survived, {broken} did not \
         compile, {} crashed or hung.",
        verdicts.len(),
        started.elapsed().as_secs_f64(),
        bad.len()
    );
    if bad.is_empty() {
        return Ok(());
    }
    for (exercise, mutant, verdict) in &bad {
        println!(
            "\n--- {} with {}: {verdict:?}\n{}",
            exercise.name, mutant.what, mutant.code
        );
    }
    bail!(
        "{} mutant(s) crashed or hung a check: a wrong answer must make its check fail in words, \
         never in a panic of the workbook's code",
        bad.len()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lines(text: &str) -> Vec<String> {
        text.lines().map(str::to_owned).collect()
    }

    #[test]
    fn mutants_take_one_slip_each_outside_comments_and_strings() {
        let solution = lines(
            "    let r = u.sqrt() * 2.0; // not this * one\n    let s = \"a + b\";\n    Vec2::new(r + 1.5, -v.y)",
        );
        let all = mutants(&solution, "    ", 100);
        let whats: Vec<&str> = all.iter().map(|m| m.what.as_str()).collect();
        assert_eq!(
            whats,
            [
                "the whole answer: `Default::default()`",
                "line 3: `+` -> `-`",
                "line 1: `*` -> `/`",
                "line 1: `.sqrt()` -> ``",
                "line 1: `2.0` -> `0.0`",
                "line 3: `1.5` -> `0.0`",
            ]
        );
        assert_eq!(all[0].code, "Default::default()");
        assert_eq!(
            all[1].code,
            "let r = u.sqrt() * 2.0; // not this * one\nlet s = \"a + b\";\nVec2::new(r - 1.5, -v.y)"
        );
        assert_eq!(mutants(&solution, "    ", 2).len(), 2);
    }

    #[test]
    fn decimals_are_told_from_names_fields_and_exponents() {
        let found = decimal_literals("p2.x + t.0 + 1e-4 + 0.5f32 * 12.25 + 3");
        let texts: Vec<&str> = found.iter().map(|(_, t)| t.as_str()).collect();
        assert_eq!(texts, ["0.5", "12.25"]);
    }

    #[test]
    fn crashes_are_told_from_a_check_that_refuses() {
        let own = (PathBuf::from("chapters/c/src/a.rs"), 10..20);
        let refused = "thread 'a::exercise_x' (7) panicked at chapters/c/src/a/tests.rs:40:9:\n\
                       reflect: the sign of the normal part is wrong\n";
        assert_eq!(verdict(false, refused, &own), Verdict::Refused);
        let theirs = "thread 'x' (7) panicked at chapters/c/src/a.rs:12:5:\nindex out of bounds: the len is 3 but the index is 3\n";
        assert_eq!(verdict(false, theirs, &own), Verdict::Refused);
        let ours = "thread '<unnamed>' (9) panicked at chapters/c/src/b.rs:12:5:\nindex out of bounds: the len is 1 but the index is 4294967295\n";
        assert!(
            matches!(verdict(false, ours, &own), Verdict::Crash(what) if what.contains("b.rs:12"))
        );
        let common = "thread 'x' panicked at common/src/film.rs:3:1:\nweights must be finite\n";
        assert!(matches!(verdict(false, common, &own), Verdict::Crash(_)));
        let stub = "thread 'x' (1) panicked at chapters/c/src/z.rs:4:5:\nthis check needs ch01-z (not written yet)\n";
        assert!(matches!(verdict(false, stub, &own), Verdict::Crash(_)));
        let explained = "thread 'x' (1) panicked at chapters/c/src/a/tests.rs:158:5:\n\
                         strata_grid(2) panicked (attempt to subtract with overflow): 0 strata\n";
        assert_eq!(verdict(false, explained, &own), Verdict::Refused);
        let bare =
            "thread 'x' (1) panicked at chapters/c/src/b.rs:9:5:\nassertion failed: w > 0.0\n";
        assert!(matches!(verdict(false, bare, &own), Verdict::Crash(_)));
        let bare_eq = "thread 'x' (1) panicked at chapters/c/src/b.rs:9:5:\nassertion `left == right` failed\n  left: 1\n";
        assert!(matches!(verdict(false, bare_eq, &own), Verdict::Crash(_)));
        let worded = "thread 'x' (1) panicked at chapters/c/src/b.rs:9:5:\nassertion `left == right` failed: the fold moved it\n";
        assert_eq!(verdict(false, worded, &own), Verdict::Refused);
        assert_eq!(verdict(true, "", &own), Verdict::Survived);
        let died = "thread 'x' has overflowed its stack\nfatal runtime error: stack overflow\n";
        assert!(matches!(verdict(false, died, &own), Verdict::Crash(_)));
    }
}
