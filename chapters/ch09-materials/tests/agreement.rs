//! Agreement with Mitsuba 3's stored renders of the crate's scenes (see
//! `ch09_materials::lab::agreement`): our render at the same sample count must be as unbiased as
//! Mitsuba's own second render against Mitsuba's reference, and no noisier.
//!
//! The quick figures are checked here too, in the same process, because they show the same
//! renders (made once per process): they must write every generated Markdown file that the
//! crate's page and the appendix include, so the book never quotes a number that no
//! run wrote.

use std::path::Path;

use ch09_materials::lab::agreement::AGREEMENT;

#[test]
fn renders_agree_with_the_stored_mitsuba_renders() {
    AGREEMENT.check_stored().unwrap();
}

/// The diagrams, `figures/ch09/diagrams/NAME.svg`, that `page` shows.
fn shown_diagrams(page: &str) -> Vec<String> {
    page.match_indices("](figures/ch09/diagrams/")
        .filter_map(|(at, prefix)| {
            let rest = &page[at + prefix.len()..];
            Some(format!("diagrams/{}", &rest[..rest.find(')')?]))
        })
        .collect()
}

/// The `figures/ch09/NAME.md` files that `page` includes.
fn included_markdown(page: &str) -> Vec<String> {
    page.match_indices("{{#include figures/ch09/")
        .filter_map(|(at, prefix)| {
            let rest = &page[at + prefix.len()..];
            let name = &rest[..rest.find("}}")?];
            name.ends_with(".md").then(|| name.to_string())
        })
        .collect()
}

#[test]
fn the_quick_figures_write_every_markdown_file_the_pages_include() {
    let book = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../book/src");
    let out = tempfile::tempdir().unwrap();
    ch09_materials::lab::figures::write_all(out.path(), true).unwrap();
    let mut checked = 0;
    for page in ["ch09-materials.md", "appendix-mitsuba.md"] {
        let text = std::fs::read_to_string(book.join(page)).unwrap();
        for name in included_markdown(&text) {
            let written = std::fs::read_to_string(out.path().join(&name))
                .unwrap_or_else(|e| panic!("{page} includes figures/ch09/{name}: {e}"));
            assert!(
                !written.trim().is_empty(),
                "{page} includes figures/ch09/{name}, which the figures wrote empty"
            );
            checked += 1;
        }
    }
    let page = std::fs::read_to_string(book.join("ch09-materials.md")).unwrap();
    let diagrams = shown_diagrams(&page);
    assert!(diagrams.len() >= 3, "the page shows {diagrams:?}");
    for name in diagrams {
        let svg = std::fs::read_to_string(out.path().join(&name))
            .unwrap_or_else(|e| panic!("ch09-materials.md shows figures/ch09/{name}: {e}"));
        assert!(svg.contains("<title>"), "{name} has no title");
    }
    assert!(checked >= 4, "only {checked} generated files are included");
}
