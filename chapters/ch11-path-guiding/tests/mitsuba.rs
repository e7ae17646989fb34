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

use ch11_path_guiding::lab::agreement::{
    AGREEMENT, HEAVY_TAILED, HEAVY_TAILED_REFERENCE_SPP, HEAVY_TAILED_SPP,
};
use workbench::agreement::{refresh_agreement_from_env, refresh_agreement_from_env_at};

#[test]
#[ignore = "needs Mitsuba 3 (set MITSUBA_PYTHON)"]
fn the_guided_path_tracer_agrees_with_mitsuba() {
    match refresh_agreement_from_env(&AGREEMENT) {
        Ok(lines) => eprintln!("{}", lines.join("\n")),
        Err(message) => panic!("{message}"),
    }
}

/// The scenes of [`HEAVY_TAILED`], with Mitsuba's second render at [`HEAVY_TAILED_SPP`]
/// samples, the count ours has there, and its reference at [`HEAVY_TAILED_REFERENCE_SPP`].
/// `AGREEMENT_ONLY` must name scenes of this set: pick the test by name
/// (`-- --ignored heavy_tailed`) to refresh one of them alone.
#[test]
#[ignore = "needs Mitsuba 3 (set MITSUBA_PYTHON)"]
fn the_guided_path_tracer_agrees_with_mitsuba_on_heavy_tailed_scenes() {
    match refresh_agreement_from_env_at(&HEAVY_TAILED, HEAVY_TAILED_SPP, HEAVY_TAILED_REFERENCE_SPP)
    {
        Ok(lines) => eprintln!("{}", lines.join("\n")),
        Err(message) => panic!("{message}"),
    }
}
