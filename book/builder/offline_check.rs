//! A last look at the built site: nothing it loads may come from the network.
//!
//! Students open the book from disk, often offline, so every stylesheet, script and font must
//! be part of the site. One forgotten CDN link (a new preprocessor's default, a theme tweak)
//! would silently break pages; this check makes it a build error instead.

use std::path::Path;

use anyhow::{Context, Result, bail};

/// Fails, naming the files and addresses, if a page or stylesheet of `site_dir` loads anything
/// from the network.
pub fn ensure_offline(site_dir: &Path) -> Result<()> {
    let mut found = Vec::new();
    for file in crate::workspace::files_under(site_dir)? {
        let is_page = file.extension().is_some_and(|ext| ext == "html");
        let is_style = file.extension().is_some_and(|ext| ext == "css");
        if !(is_page || is_style) {
            continue;
        }
        let text = std::fs::read_to_string(&file)
            .with_context(|| format!("cannot read {}", file.display()))?;
        let remote = if is_page {
            remote_resources_in_html(&text)
        } else {
            remote_urls_in_css(&text)
        };
        found.extend(
            remote
                .into_iter()
                .map(|url| format!("{}: {url}", file.display())),
        );
    }
    if !found.is_empty() {
        bail!(
            "the site loads resources from the network, which breaks it offline:\n  {}",
            found.join("\n  ")
        );
    }
    Ok(())
}

fn is_remote(url: &str) -> bool {
    ["http://", "https://", "//"]
        .iter()
        .any(|scheme| url.starts_with(scheme))
}

/// Remote `href`s of `<link>` tags and `src`s of `<script>` tags. Ordinary `<a href>` links to
/// other websites are fine: following them is the reader's choice.
fn remote_resources_in_html(html: &str) -> Vec<String> {
    let mut remote = Vec::new();
    for (tag, attribute) in [("<link", "href="), ("<script", "src=")] {
        for (start, _) in html.match_indices(tag) {
            let rest = &html[start..];
            let element = &rest[..rest.find('>').unwrap_or(rest.len())];
            if let Some(url) = attribute_value(element, attribute)
                && is_remote(url)
            {
                remote.push(url.to_owned());
            }
        }
    }
    remote
}

fn attribute_value<'a>(element: &'a str, attribute: &str) -> Option<&'a str> {
    let after = &element[element.find(attribute)? + attribute.len()..];
    let quote = after.chars().next().filter(|c| *c == '"' || *c == '\'')?;
    let value = &after[1..];
    Some(&value[..value.find(quote)?])
}

/// Remote `url(...)`s and `@import`s in a stylesheet.
fn remote_urls_in_css(css: &str) -> Vec<String> {
    let mut remote = Vec::new();
    for marker in ["url(", "@import"] {
        for (start, _) in css.match_indices(marker) {
            let value = css[start + marker.len()..]
                .trim_start()
                .trim_start_matches(['"', '\'']);
            if is_remote(value) {
                let end = value.find(['"', '\'', ')', ';']).unwrap_or(value.len());
                remote.push(value[..end].to_owned());
            }
        }
    }
    remote
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_remote_stylesheets_and_scripts_only() {
        let html = r#"<link rel="stylesheet" href="https://cdn.example/katex.css">
<link rel="stylesheet" href="theme/katex/katex.min.css">
<script src='//cdn.example/x.js'></script><script src="book.js"></script>
<a href="https://example.org">a reference</a>"#;
        assert_eq!(
            remote_resources_in_html(html),
            ["https://cdn.example/katex.css", "//cdn.example/x.js"]
        );
    }

    #[test]
    fn finds_remote_fonts_in_css() {
        let css = r#"@font-face{src:url(fonts/KaTeX_Main-Regular.woff2) format("woff2"),url("https://fonts.example/a.woff")}
@import "https://fonts.example/b.css";"#;
        assert_eq!(
            remote_urls_in_css(css),
            [
                "https://fonts.example/a.woff",
                "https://fonts.example/b.css"
            ]
        );
    }
}
