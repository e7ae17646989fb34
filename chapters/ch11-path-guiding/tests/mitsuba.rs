//! Agreement with Mitsuba 3, rendered afresh. Needs a Python with the `mitsuba` package
//! (`pip install mitsuba`), so it is ignored by default. Run it with
//!
//! ```text
//! MITSUBA_PYTHON=/path/to/python cargo test --release -p ch11-path-guiding --test mitsuba -- --ignored --nocapture
//! ```
//!
//! With `UPDATE_MITSUBA_RENDERS=1` as well, it replaces the stored renders in
//! `scenes/mitsuba/` that the test `agreement` compares against; `AGREEMENT_ONLY=name1,name2`
//! keeps to those scenes.

use ch11_path_guiding::lab::agreement::AGREEMENT;
use workbench::agreement::refresh_agreement_from_env;

#[test]
#[ignore = "needs Mitsuba 3 (set MITSUBA_PYTHON)"]
fn the_guided_path_tracer_agrees_with_mitsuba() {
    match refresh_agreement_from_env(&AGREEMENT) {
        Ok(lines) => eprintln!("{}", lines.join("\n")),
        Err(message) => panic!("{message}"),
    }
}
