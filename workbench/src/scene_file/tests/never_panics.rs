//! No input, however broken, makes the loader panic.
//!
//! Each property runs 256 cases in the test suite. For a longer fuzzing run, set
//! `SCENE_FUZZ_CASES`, e.g.
//! `SCENE_FUZZ_CASES=200000 cargo test --release -p common never_panics`.

use std::path::Path;

use proptest::prelude::*;

use super::super::{parse_description, parse_obj, parse_scene, world_shapes};

const CORNELL: &str = include_str!("../../../tests/scenes/cornell.xml");

/// A small OBJ mesh with normals, negative indices and a parallelogram.
const OBJ: &str =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\nf -4 -3 -2\n";

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
    let interesting = prop::sample::select(vec![
        '<', '>', '/', '"', '$', '0', '-', ' ', 'x', '=', '\n', '9', 'e', 'f', 'v',
    ]);
    prop_oneof![
        any::<usize>().prop_map(Edit::Delete),
        any::<usize>().prop_map(Edit::Duplicate),
        (any::<usize>(), interesting).prop_map(|(i, c)| Edit::Replace(i, c)),
    ]
}

proptest! {
    #![proptest_config(super::property_config())]

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..512)) {
        let text = String::from_utf8_lossy(&bytes);
        let _ = parse_scene(&text, Path::new("random.xml"), &[]);
    }

    #[test]
    fn mutated_cornell_never_panics(edits in prop::collection::vec(edit(), 1..8)) {
        let text = apply(CORNELL, &edits);
        // A file that still parses must also place its shapes without panicking: a mutated
        // number can make a transform degenerate or a radius zero.
        if let Ok(loaded) = parse_description(&text, Path::new("cornell.xml"), &[]) {
            for shape in &loaded.scene.shapes {
                let _ = world_shapes(shape);
            }
        }
        let _ = parse_scene(&text, Path::new("cornell.xml"), &[]);
    }

    #[test]
    fn mutated_obj_never_panics(edits in prop::collection::vec(edit(), 1..8)) {
        let _ = parse_obj(&apply(OBJ, &edits));
    }
}
