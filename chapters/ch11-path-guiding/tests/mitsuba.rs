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
use workbench::agreement::{
    AGREEMENT_ONLY, UPDATE_MITSUBA_RENDERS, make_reference_renders, mitsuba_python,
    refresh_agreement_from_env,
};

#[test]
#[ignore = "needs Mitsuba 3 (set MITSUBA_PYTHON)"]
fn the_guided_path_tracer_agrees_with_mitsuba() {
    match refresh_agreement_from_env(&AGREEMENT) {
        Ok(lines) => eprintln!("{}", lines.join("\n")),
        Err(message) => panic!("{message}"),
    }
}

/// The scenes of [`HEAVY_TAILED`], as `refresh_agreement_from_env` does the others but with
/// Mitsuba's second render at [`HEAVY_TAILED_SPP`] samples, the count ours has there, and its
/// reference at [`HEAVY_TAILED_REFERENCE_SPP`].
#[test]
#[ignore = "needs Mitsuba 3 (set MITSUBA_PYTHON)"]
fn the_guided_path_tracer_agrees_with_mitsuba_on_heavy_tailed_scenes() {
    let python = mitsuba_python().expect("set MITSUBA_PYTHON to a Python with mitsuba");
    let update = std::env::var(UPDATE_MITSUBA_RENDERS).is_ok_and(|v| v == "1");
    let only = std::env::var(AGREEMENT_ONLY).ok().filter(|v| !v.is_empty());
    let mut failures = Vec::new();
    for scene in HEAVY_TAILED.scenes {
        if only
            .as_deref()
            .is_some_and(|names| !names.split(',').any(|n| n == scene.name))
        {
            continue;
        }
        let file = HEAVY_TAILED.file(scene);
        let renders = make_reference_renders(
            &python,
            scene.variant,
            &file,
            HEAVY_TAILED_SPP,
            HEAVY_TAILED_REFERENCE_SPP,
            &[],
        )
        .unwrap();
        let agreement = renders.agreement(&(HEAVY_TAILED.render)(&file).unwrap());
        eprintln!(
            "{} at {HEAVY_TAILED_SPP} spp: RMSE ours {:.2e} / Mitsuba {:.2e}, bias_blocks ours {:.4} / Mitsuba {:.4}",
            scene.name,
            agreement.ours.rmse,
            agreement.other.rmse,
            agreement.ours.bias_blocks,
            agreement.other.bias_blocks
        );
        if !agreement.holds() {
            failures.push(scene.name);
        }
        if update {
            renders
                .save(&HEAVY_TAILED.stored_renders_dir(), scene.name)
                .unwrap();
        }
    }
    assert!(failures.is_empty(), "disagreement on {failures:?}");
}
