//! Agreement with Mitsuba 3: the same scene file rendered by a chapter and by Mitsuba, and the
//! test that the two differ by no more than their noise.
//!
//! [`comparison`](AgreementSet) holds the scenes, the measured differences and the figure;
//! the `mitsuba` part runs Mitsuba 3 (from Python) to make the reference renders.

mod comparison;
mod mitsuba;

pub use comparison::{
    AGREEMENT_SPP, Agreement, AgreementScene, AgreementSet, BIAS_SLACK, Comparison,
    NOISE_TOLERANCE, REFERENCE_SPP, ReferenceRenders, RenderProvenance, RenderSceneFile,
    agreement_table, write_agreement_figure,
};
pub use mitsuba::{
    AGREEMENT_ONLY, MITSUBA_JIT_VARIANT, MITSUBA_PYTHON, MITSUBA_VARIANT, UPDATE_MITSUBA_RENDERS,
    make_reference_renders, mitsuba_python, refresh_agreement, refresh_agreement_at,
    refresh_agreement_from_env, refresh_agreement_from_env_at, render_with_mitsuba,
};
