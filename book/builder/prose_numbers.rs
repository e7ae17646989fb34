//! No measured number in the prose: a page's own words hold no number a run produced.
//!
//! Figures are regenerated on every build, so a timing, an error or a count typed into a page
//! drifts from the figure beside it the next time the code changes. Such numbers are written by
//! the chapter's figures run into small files under `book/src/figures/` that the page includes
//! (`{{#include figures/ch08/path-cost.md}}`); this check keeps them there. It reads each
//! hand-written page of `book/src/` (everything but the generated `figures/`) without its code
//! blocks, inline code, directives, comments, HTML tags and link targets, and finds decimal
//! numbers (`0.184`, `.5`), numbers with an exponent (`2e-4`) and percentages (`40 %`). Each
//! must be listed for its page in `book/prose-numbers.toml`, with why it is a constant the text
//! names (an index of refraction, a formula's coefficient) rather than a measurement. A listed
//! number that the page no longer holds is an error too, so that the list stays the truth.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

/// The list of allowed numbers, relative to the workspace root.
pub const ALLOWED_PATH: &str = "book/prose-numbers.toml";

/// A number found in a page's prose.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ProseNumber {
    /// As written, with a percentage sign glued on (`"40%"` for `40 %`).
    pub text: String,
    /// The line of the page it is on, from 1.
    pub line: usize,
}

/// Checks every page of `book_src` against the allowed list; fails naming every page, line and
/// number that breaks the rule.
pub fn check(root: &Path, book_src: &Path) -> Result<()> {
    let allowed_path = root.join(ALLOWED_PATH);
    // Without a list (a book made for a test), no number is allowed: the strictest reading.
    let allowed_text = match std::fs::read_to_string(&allowed_path) {
        Err(error) if error.kind() == std::io::ErrorKind::NotFound => String::new(),
        read => read.with_context(|| format!("cannot read {}", allowed_path.display()))?,
    };
    let allowed = parse_allowed(&allowed_text)
        .with_context(|| format!("{} is not a valid list", allowed_path.display()))?;

    let mut problems = Vec::new();
    let pages = pages_under(book_src)?;
    for page in &pages {
        let name = page_name(book_src, page);
        let text = std::fs::read_to_string(page)
            .with_context(|| format!("cannot read {}", page.display()))?;
        let page_allowed = allowed.get(&name);
        let found = numbers_in_prose(&text);
        for number in &found {
            if !page_allowed.is_some_and(|list| list.contains_key(&number.text)) {
                problems.push(format!(
                    "book/src/{name}:{}: `{}` in the prose",
                    number.line, number.text
                ));
            }
        }
        for listed in page_allowed.into_iter().flat_map(|list| list.keys()) {
            if !found.iter().any(|number| &number.text == listed) {
                problems.push(format!(
                    "{ALLOWED_PATH}: `{listed}` is allowed for {name}, which no longer holds it; \
                     remove it from the list"
                ));
            }
        }
    }
    for name in allowed.keys() {
        if !pages.iter().any(|page| &page_name(book_src, page) == name) {
            problems.push(format!(
                "{ALLOWED_PATH}: there is no page book/src/{name}; remove its table"
            ));
        }
    }
    if !problems.is_empty() {
        bail!(
            "numbers in the pages' prose that no generated file vouches for:\n  {}\n\
             A number measured by a run (an error, a time, a ratio, a count) belongs in a small \
             file the chapter's figures write under book/src/figures/, which the page includes; \
             then it is true on every build. A constant the text itself names (an index of \
             refraction, a formula's coefficient) goes into {ALLOWED_PATH} under its page, with \
             why.",
            problems.join("\n  ")
        );
    }
    Ok(())
}

/// The allowed list: page name -> (number -> why).
fn parse_allowed(text: &str) -> Result<BTreeMap<String, BTreeMap<String, String>>> {
    let table: toml::Table = toml::from_str(text)?;
    let mut allowed = BTreeMap::new();
    for (page, numbers) in table {
        let Some(numbers) = numbers.as_table() else {
            bail!("`{page}` must be a table of number = \"why\"");
        };
        let mut list = BTreeMap::new();
        for (number, why) in numbers {
            match why.as_str() {
                Some(why) if !why.trim().is_empty() => {
                    list.insert(number.clone(), why.to_owned());
                }
                _ => bail!("`{number}` under `{page}` needs a sentence saying why it is allowed"),
            }
        }
        allowed.insert(page, list);
    }
    Ok(allowed)
}

/// The page's path below `book_src`, with `/` between folders: `ch01-whitted.md`.
fn page_name(book_src: &Path, page: &Path) -> String {
    let relative = page.strip_prefix(book_src).unwrap_or(page);
    relative
        .components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}

/// Every Markdown file under `book_src` but the generated `figures/` and `SUMMARY.md`, sorted.
fn pages_under(book_src: &Path) -> Result<Vec<PathBuf>> {
    let figures = book_src.join("figures");
    let mut pages: Vec<PathBuf> = crate::workspace::files_under(book_src)?
        .into_iter()
        .filter(|path| !path.starts_with(&figures))
        .filter(|path| path.extension().is_some_and(|ext| ext == "md"))
        .filter(|path| *path != book_src.join("SUMMARY.md"))
        .collect();
    pages.sort();
    Ok(pages)
}

/// The numbers in a page's prose, in order.
pub fn numbers_in_prose(page: &str) -> Vec<ProseNumber> {
    let mut found = Vec::new();
    for (index, line) in prose_lines(page) {
        for text in numbers_in_line(&line) {
            found.push(ProseNumber {
                text,
                line: index + 1,
            });
        }
    }
    found
}

/// The page's lines without fenced code blocks, HTML comments and `{{#...}}` directives, each
/// with inline code, HTML tags and link targets blanked out. Line numbers are kept.
fn prose_lines(page: &str) -> Vec<(usize, String)> {
    let mut lines = Vec::new();
    let mut fence: Option<&str> = None;
    let mut in_comment = false;
    for (index, line) in page.lines().enumerate() {
        let trimmed = line.trim_start();
        if let Some(marker) = fence {
            if trimmed.starts_with(marker) {
                fence = None;
            }
            continue;
        }
        if let Some(marker) = ["```", "~~~"].into_iter().find(|m| trimmed.starts_with(m)) {
            fence = Some(marker);
            continue;
        }
        let mut kept = String::new();
        let mut rest = line;
        loop {
            if in_comment {
                match rest.find("-->") {
                    Some(end) => {
                        rest = &rest[end + 3..];
                        in_comment = false;
                    }
                    None => break,
                }
            } else {
                match rest.find("<!--") {
                    Some(start) => {
                        kept.push_str(&rest[..start]);
                        rest = &rest[start + 4..];
                        in_comment = true;
                    }
                    None => {
                        kept.push_str(rest);
                        break;
                    }
                }
            }
        }
        lines.push((index, blank_non_prose(&kept)));
    }
    lines
}

/// Replaces inline code, `{{#...}}` directives, HTML tags and the targets of links and images
/// by spaces.
fn blank_non_prose(line: &str) -> String {
    let mut out = String::with_capacity(line.len());
    let mut chars = line.char_indices().peekable();
    while let Some((at, c)) = chars.next() {
        let rest = &line[at..];
        let skip_to = if c == '`' {
            let ticks = rest.chars().take_while(|&t| t == '`').count();
            let opener = &rest[..ticks];
            rest[ticks..]
                .find(opener)
                .map(|end| at + ticks + end + ticks)
        } else if rest.starts_with("{{#") {
            rest.find("}}").map(|end| at + end + 2)
        } else if rest.starts_with("](") {
            rest.find(')').map(|end| at + end + 1)
        } else if c == '<' && rest[1..].starts_with(|n: char| n.is_ascii_alphabetic() || n == '/') {
            rest.find('>').map(|end| at + end + 1)
        } else {
            None
        };
        match skip_to {
            Some(end) => {
                out.push(' ');
                while chars.peek().is_some_and(|&(next, _)| next < end) {
                    chars.next();
                }
            }
            None => out.push(c),
        }
    }
    out
}

/// Decimal numbers, numbers with an exponent and percentages in one line of prose.
fn numbers_in_line(line: &str) -> Vec<String> {
    let bytes = line.as_bytes();
    let mut found = Vec::new();
    let mut at = 0;
    while at < bytes.len() {
        let starts_number = bytes[at].is_ascii_digit()
            || (bytes[at] == b'.' && bytes.get(at + 1).is_some_and(u8::is_ascii_digit));
        // A digit glued to a word (`ch01`, `x2`, `f32`) is part of a name, not a number.
        let glued = at > 0 && (bytes[at - 1].is_ascii_alphabetic() || bytes[at - 1] == b'_');
        if !starts_number || glued {
            at += 1;
            continue;
        }
        let start = at;
        while at < bytes.len() && bytes[at].is_ascii_digit() {
            at += 1;
        }
        let mut notable = false;
        if at + 1 < bytes.len() && bytes[at] == b'.' && bytes[at + 1].is_ascii_digit() {
            at += 1;
            while at < bytes.len() && bytes[at].is_ascii_digit() {
                at += 1;
            }
            notable = true;
        }
        if at < bytes.len() && (bytes[at] == b'e' || bytes[at] == b'E') {
            let mut exponent = at + 1;
            if exponent < bytes.len() && (bytes[exponent] == b'-' || bytes[exponent] == b'+') {
                exponent += 1;
            }
            let digits = bytes[exponent..]
                .iter()
                .take_while(|b| b.is_ascii_digit())
                .count();
            let word_follows = bytes
                .get(exponent + digits)
                .is_some_and(|b| b.is_ascii_alphabetic());
            if digits > 0 && !word_follows {
                at = exponent + digits;
                notable = true;
            }
        }
        let mut text = line[start..at].to_owned();
        let after = line[at..].trim_start_matches([' ', '\u{a0}', '\u{202f}']);
        if after.starts_with('%') || after.starts_with("\\%") {
            text.push('%');
            notable = true;
        }
        // Part of a longer name or version (`1.2.3`, `x86_64`): skip the whole run.
        let continues = !text.ends_with('%')
            && bytes.get(at).is_some_and(|&b| {
                b.is_ascii_alphabetic()
                    || b == b'_'
                    || (b == b'.' && bytes.get(at + 1).is_some_and(u8::is_ascii_digit))
            });
        if notable && !continues {
            found.push(text);
        }
        while at < bytes.len() && (bytes[at].is_ascii_alphanumeric() || bytes[at] == b'.') {
            if bytes[at] == b'.' && !bytes.get(at + 1).is_some_and(u8::is_ascii_digit) {
                break;
            }
            at += 1;
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(page: &str) -> Vec<String> {
        numbers_in_prose(page).into_iter().map(|n| n.text).collect()
    }

    #[test]
    fn finds_decimals_exponents_and_percentages_in_prose_and_math() {
        let page = "The RMSE fell to 0.184 in .5 s; the bias was 2.6e-4, or 3e-5.\n\
                    About 40 % of rays (and 7\u{a0}% more), with $\\eta = 1.5$.\n";
        assert_eq!(
            texts(page),
            ["0.184", ".5", "2.6e-4", "3e-5", "40%", "7%", "1.5"]
        );
        assert_eq!(numbers_in_prose(page)[4].line, 2);
    }

    #[test]
    fn integers_names_and_sentence_ends_are_not_measurements() {
        let page = "Chapter 3. Use ch01 and f32 on 16 x 16 pixels, 2^10 samples, 1e5 scale.\n\
                    See ch03-anti-aliasing.md, version 1.2.3, x86_64, and section 2.";
        assert_eq!(texts(page), ["1e5"]);
    }

    #[test]
    fn code_links_tags_comments_and_directives_are_not_prose() {
        let page = "Run `--spp 0.5` or ``a `0.25` b``.\n\
                    ```sh\nrender --gamma 2.2\n```\n\
                    ![The image](figures/ch03/tent-0.75.png) <img src=\"a-1.5.png\" width=\"50%\">\n\
                    <!-- 0.184\n still 0.2 -->\n\
                    {{#include figures/ch08/table-0.1.md}}\nbut 0.3 here";
        assert_eq!(texts(page), ["0.3"]);
        assert_eq!(numbers_in_prose(page).last().unwrap().line, 9);
    }

    #[test]
    fn every_unlisted_number_and_every_stale_entry_fails_the_check() {
        let root = tempfile::tempdir().unwrap();
        let src = root.path().join("book/src");
        std::fs::create_dir_all(src.join("figures/ch01")).unwrap();
        std::fs::write(
            src.join("ch01.md"),
            "Glass of index 1.5 took 0.04 s.\n{{#include figures/ch01/t.md}}\n",
        )
        .unwrap();
        // Generated files are the place for measured numbers; they are not read.
        std::fs::write(src.join("figures/ch01/t.md"), "RMSE 0.184\n").unwrap();
        std::fs::write(
            root.path().join(ALLOWED_PATH),
            "[\"ch01.md\"]\n\"1.5\" = \"the index of refraction of glass\"\n\"2.2\" = \"gone\"\n",
        )
        .unwrap();
        let message = format!("{:#}", check(root.path(), &src).unwrap_err());
        assert!(
            message.contains("book/src/ch01.md:1: `0.04` in the prose"),
            "{message}"
        );
        assert!(
            message.contains("`2.2` is allowed for ch01.md"),
            "{message}"
        );
        assert!(!message.contains("`1.5`"), "{message}");
        assert!(!message.contains("0.184"), "{message}");

        std::fs::write(
            root.path().join(ALLOWED_PATH),
            "[\"ch01.md\"]\n\"1.5\" = \"the index of refraction of glass\"\n\
             \"0.04\" = \"a constant of the scene\"\n",
        )
        .unwrap();
        check(root.path(), &src).unwrap();
    }

    #[test]
    fn an_entry_without_a_reason_is_refused() {
        assert!(parse_allowed("[\"ch01.md\"]\n\"1.5\" = \"\"\n").is_err());
        assert!(parse_allowed("\"1.5\" = \"a page missing\"\n").is_err());
    }
}
