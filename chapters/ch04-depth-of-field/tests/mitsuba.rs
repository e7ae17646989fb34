//! Agreement with Mitsuba 3, rendered afresh. Needs a Python with the `mitsuba` package
//! (`pip install mitsuba`), so it is ignored by default. Run it with
//!
//! ```text
//! MITSUBA_PYTHON=/path/to/python cargo test --release -p ch04-depth-of-field --test mitsuba -- --ignored --nocapture
//! ```
//!
//! With `UPDATE_MITSUBA_RENDERS=1` as well, it replaces the stored renders in
//! `scenes/mitsuba/` that the test `agreement` and the book compare against.

use ch04_depth_of_field::agreement::{AGREEMENT_SCENES, render_scene_file, scenes_dir};
use common::metrics::{mitsuba_python, refresh_agreement};

#[test]
#[ignore = "needs Mitsuba 3 (set MITSUBA_PYTHON)"]
fn chapter_04_agrees_with_mitsuba() {
    let python = mitsuba_python().expect("set MITSUBA_PYTHON to a Python with mitsuba");
    let update = std::env::var("UPDATE_MITSUBA_RENDERS").is_ok_and(|v| v == "1");
    let report = refresh_agreement(
        &python,
        &scenes_dir(),
        AGREEMENT_SCENES,
        &render_scene_file,
        update,
    );
    match report {
        Ok(lines) => eprintln!("{}", lines.join("\n")),
        Err(message) => panic!("{message}"),
    }
}
