//! Agreement with Mitsuba 3, rendered afresh. Needs a Python with the `mitsuba` package
//! (`pip install mitsuba`), so it is ignored by default. Run it with
//!
//! ```text
//! MITSUBA_PYTHON=/path/to/python cargo test --release -p ch01-whitted --test mitsuba -- --ignored --nocapture
//! ```
//!
//! With `UPDATE_MITSUBA_RENDERS=1` as well, it replaces the stored renders in
//! `scenes/mitsuba/` that the test `agreement` and the book compare against.

use ch01_whitted::agreement::{
    AGREEMENT_SCENES, AGREEMENT_SPP, REFERENCE_SPP, mitsuba_dir, render_agreement_scene, scenes_dir,
};
use common::metrics::{make_reference_renders, mitsuba_python};

#[test]
#[ignore = "needs Mitsuba 3 (set MITSUBA_PYTHON)"]
fn chapter_01_agrees_with_mitsuba() {
    let python = mitsuba_python().expect("set MITSUBA_PYTHON to a Python with mitsuba");
    let update = std::env::var("UPDATE_MITSUBA_RENDERS").is_ok_and(|v| v == "1");
    let mut failures = Vec::new();
    for (name, checks) in AGREEMENT_SCENES {
        let scene = scenes_dir().join(format!("{name}.xml"));
        let renders =
            make_reference_renders(&python, &scene, AGREEMENT_SPP, REFERENCE_SPP, &[]).unwrap();
        let ours = render_agreement_scene(name).unwrap();
        let agreement = renders.agreement(&ours);
        eprintln!(
            "{name} ({checks}): RMSE ours {:.2e} / Mitsuba {:.2e}, bias_blocks ours {:.4} / Mitsuba {:.4}",
            agreement.ours.rmse,
            agreement.other.rmse,
            agreement.ours.bias_blocks,
            agreement.other.bias_blocks
        );
        if !(agreement.unbiased(0.005) && agreement.noise_no_worse(1.05)) {
            failures.push(name);
        }
        if update {
            renders.save(&mitsuba_dir(), name).unwrap();
        }
    }
    assert!(failures.is_empty(), "disagreement on {failures:?}");
}
