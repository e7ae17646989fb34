//! No input, however broken, makes the loader panic.

use std::path::Path;

use proptest::prelude::*;

use super::super::parse_scene;

const CORNELL: &str = include_str!("../../../tests/scenes/cornell.xml");

/// One edit of a text: delete, duplicate or replace the character at a position.
#[derive(Clone, Debug)]
enum Edit {
    Delete(usize),
    Duplicate(usize),
    Replace(usize, char),
}

fn apply(text: &str, edits: &[Edit]) -> String {
    let mut chars: Vec<char> = text.chars().collect();
    for edit in edits {
        if chars.is_empty() {
            break;
        }
        match *edit {
            Edit::Delete(i) => {
                chars.remove(i % chars.len());
            }
            Edit::Duplicate(i) => {
                let i = i % chars.len();
                chars.insert(i, chars[i]);
            }
            Edit::Replace(i, c) => {
                let i = i % chars.len();
                chars[i] = c;
            }
        }
    }
    chars.into_iter().collect()
}

fn edit() -> impl Strategy<Value = Edit> {
    let interesting = prop::sample::select(vec!['<', '>', '/', '"', '$', '0', '-', ' ', 'x', '=']);
    prop_oneof![
        any::<usize>().prop_map(Edit::Delete),
        any::<usize>().prop_map(Edit::Duplicate),
        (any::<usize>(), interesting).prop_map(|(i, c)| Edit::Replace(i, c)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..512)) {
        let text = String::from_utf8_lossy(&bytes);
        let _ = parse_scene(&text, Path::new("random.xml"), &[]);
    }

    #[test]
    fn mutated_cornell_never_panics(edits in prop::collection::vec(edit(), 1..8)) {
        let text = apply(CORNELL, &edits);
        let _ = parse_scene(&text, Path::new("cornell.xml"), &[]);
    }
}
