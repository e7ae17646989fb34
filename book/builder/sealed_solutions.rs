//! Sealed solutions: the reference solutions travelling inside a student edition, for
//! `checkpoint` alone to read.
//!
//! A teacher hands out the student edition in one of two ways. *With sealed solutions*
//! (`student --out DIR --sealed-solutions`), the edition carries [`SEALED_PATH`]: every
//! exercise's reference lines, compressed, so that a student stuck without the workbook can
//! still `checkpoint` their way on; the site never shows them (the book is built from the
//! edition's sources, where every solution is a stub) and no text search through the edition
//! finds them by accident. *Without* (the default), the edition holds no solution at all, and
//! `checkpoint` needs the workbook (`--from PATH`), which the teacher gives out when they choose.
//!
//! The seal keeps honest students honest: it is compression, not encryption, and the file's
//! first line says what it holds. A student who wants to read it can, as a student who wants to
//! can read the workbook's solutions on the web.

use std::collections::BTreeMap;
use std::io::{Read, Write};
use std::path::Path;

use anyhow::{Context, Result, bail};
use flate2::Compression;
use flate2::read::DeflateDecoder;
use flate2::write::DeflateEncoder;
use serde::{Deserialize, Serialize};

use crate::exercise_list::Exercise;
use crate::solution_markers::{self, Marker};

/// Where a student edition keeps its sealed solutions, relative to its root.
pub const SEALED_PATH: &str = "book/solutions.sealed";

/// The file's first line: what it is, for anyone who opens it.
const HEADER: &[u8] = b"Sealed reference solutions of this student edition, read by \
`cargo run -p book -- checkpoint`; opening them yourself spoils the exercises.\n";

/// The reference lines of each exercise (its anchor's body, markers left out), by name.
pub type References = BTreeMap<String, Vec<String>>;

#[derive(Serialize, Deserialize)]
struct Sealed {
    solution: Vec<Solution>,
}

#[derive(Serialize, Deserialize)]
struct Solution {
    name: String,
    lines: Vec<String>,
}

/// The reference lines of every exercise of `exercises`, read from the workbook at `root`.
pub fn collect(root: &Path, exercises: &[Exercise]) -> Result<References> {
    let mut references = References::new();
    for exercise in exercises {
        let path = root.join(&exercise.file);
        let source = std::fs::read_to_string(&path)
            .with_context(|| format!("cannot read {}", path.display()))?;
        references.insert(
            exercise.name.clone(),
            reference_lines(&source, &exercise.anchor)
                .with_context(|| format!("{}: exercise `{}`", path.display(), exercise.name))?,
        );
    }
    Ok(references)
}

/// The lines inside `anchor` of `source`, without the solution markers: what `checkpoint`
/// writes in place of the student's lines. Fails where the anchor holds no solution region.
pub fn reference_lines(source: &str, anchor: &str) -> Result<Vec<String>> {
    let lines: Vec<&str> = source.lines().collect();
    solution_markers::locate(&lines, anchor)?;
    let body = solution_markers::anchor_body(&lines, anchor)?;
    Ok(lines[body]
        .iter()
        .filter(|line| Marker::of_line(line).is_none())
        .map(|line| (*line).to_owned())
        .collect())
}

/// `references` sealed: the header, then the compressed list.
pub fn seal(references: &References) -> Result<Vec<u8>> {
    let sealed = Sealed {
        solution: references
            .iter()
            .map(|(name, lines)| Solution {
                name: name.clone(),
                lines: lines.clone(),
            })
            .collect(),
    };
    let text = toml::to_string(&sealed).context("cannot write the solutions as TOML")?;
    let mut bytes = HEADER.to_vec();
    let mut encoder = DeflateEncoder::new(&mut bytes, Compression::best());
    encoder.write_all(text.as_bytes())?;
    encoder.finish()?;
    Ok(bytes)
}

/// The references `bytes` (a file written by [`seal`]) holds.
pub fn open(bytes: &[u8]) -> Result<References> {
    let Some(compressed) = bytes.strip_prefix(HEADER) else {
        bail!("not a file of sealed solutions (its first line is not the one `student` writes)");
    };
    let mut text = String::new();
    DeflateDecoder::new(compressed)
        .read_to_string(&mut text)
        .context("the sealed solutions are damaged (they do not inflate to text)")?;
    let sealed: Sealed = toml::from_str(&text).context("the sealed solutions are damaged")?;
    Ok(sealed
        .solution
        .into_iter()
        .map(|solution| (solution.name, solution.lines))
        .collect())
}

/// The sealed solutions of the edition at `root`, or `None` if it was handed out without them.
pub fn read(root: &Path) -> Result<Option<References>> {
    let path = root.join(SEALED_PATH);
    match std::fs::read(&path) {
        Ok(bytes) => open(&bytes)
            .with_context(|| format!("{}", path.display()))
            .map(Some),
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => Ok(None),
        Err(error) => Err(error).with_context(|| format!("cannot read {}", path.display())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOURCE: &str = "// ANCHOR: reflect\npub fn reflect(x: f32) -> f32 {\n    // BEGIN \
                          SOLUTION\n    -x\n    // END SOLUTION\n}\n// ANCHOR_END: reflect\n";

    #[test]
    fn the_reference_is_the_anchor_without_markers() {
        assert_eq!(
            reference_lines(SOURCE, "reflect").unwrap(),
            ["pub fn reflect(x: f32) -> f32 {", "    -x", "}"]
        );
        let stub = SOURCE.replace(
            "    // BEGIN SOLUTION\n    -x\n    // END SOLUTION\n",
            "    todo!()\n",
        );
        assert!(reference_lines(&stub, "reflect").is_err());
    }

    #[test]
    fn sealed_solutions_open_to_what_was_sealed_and_hide_it_from_a_search() {
        let mut references = References::new();
        references.insert(
            "ch01-reflect".into(),
            vec![
                "    u - 3.0 * u.dot(v) * w".into(),
                "    \"quoted\" \\ ok".into(),
            ],
        );
        references.insert("ch02-other".into(), vec![]);
        let bytes = seal(&references).unwrap();
        assert!(bytes.starts_with(HEADER));
        let shown = String::from_utf8_lossy(&bytes);
        assert!(!shown.contains("u.dot(v)"), "readable in the sealed file");
        assert_eq!(open(&bytes).unwrap(), references);
    }

    #[test]
    fn a_damaged_or_foreign_file_is_named_as_such() {
        let bytes = seal(&References::new()).unwrap();
        let damaged = [&bytes[..HEADER.len()], b"\x00\x01garbage".as_slice()].concat();
        assert!(format!("{:#}", open(&damaged).unwrap_err()).contains("damaged"));
        assert!(format!("{:#}", open(b"hello").unwrap_err()).contains("not a file of sealed"));
    }
}
