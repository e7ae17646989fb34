//! Typeset mathematics that needs no network.
//!
//! mdbook-katex typesets every formula while the site is built (it runs KaTeX in an embedded
//! JavaScript engine), so pages carry finished HTML and no script. That HTML still needs KaTeX's
//! stylesheet and fonts. By default mdbook-katex links them from a CDN, which breaks offline,
//! so the builder turns the link off and the book ships KaTeX's own files in `theme/katex/`,
//! taken from the `katex` npm package at the version the typesetter embeds.

use std::path::Path;

use anyhow::{Context, Result};
use mdbook_driver::config::Config;
use mdbook_katex::cfg::KatexConfig;

/// KaTeX's files, relative to the book's root; `book.toml` lists the stylesheet as
/// `additional-css`.
pub const KATEX_DIR: &str = "theme/katex";

/// Sets mdbook-katex's options.
///
/// They are set here rather than in `book.toml`, because a `[preprocessor.katex]` table there
/// would make mdBook look for an external `mdbook-katex` program as well.
pub fn configure(config: &mut Config) -> Result<()> {
    let options = KatexConfig {
        no_css: true,
        ..KatexConfig::default()
    };
    config
        .set("preprocessor.katex", options)
        .context("cannot set the KaTeX options")
}

/// Copies KaTeX's fonts and licence into the built site, beside the stylesheet (which looks for
/// its fonts in `fonts/` next to itself): mdBook copies an `additional-css` file but nothing it
/// refers to.
pub fn copy_fonts_and_licence(book_dir: &Path, site_dir: &Path) -> Result<()> {
    let from = book_dir.join(KATEX_DIR);
    let to = site_dir.join(KATEX_DIR);
    copy_file(&from.join("LICENSE"), &to.join("LICENSE"))?;
    let fonts = from.join("fonts");
    let listing =
        std::fs::read_dir(&fonts).with_context(|| format!("cannot list {}", fonts.display()))?;
    for entry in listing {
        let font = entry?.path();
        if let Some(name) = font.file_name() {
            copy_file(&font, &to.join("fonts").join(name))?;
        }
    }
    Ok(())
}

fn copy_file(from: &Path, to: &Path) -> Result<()> {
    if let Some(dir) = to.parent() {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    std::fs::copy(from, to).with_context(|| format!("cannot copy {}", from.display()))?;
    Ok(())
}
