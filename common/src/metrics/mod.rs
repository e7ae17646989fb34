//! Error metrics, and the runner that measures error against time.
//!
//! A chapter claims "technique B beats technique A". This module is how it backs the claim:
//! render both against a converged reference at several budgets ([`run_convergence`]), measure
//! how far each render is from the reference ([`rmse`], [`relmse`]), tell noise from bias ([`bias_blocks`]), save the table
//! ([`write_convergence_csv`]) and plot error against time ([`plot_error_vs_time`]).

mod agreement;
mod bias_blocks;
mod convergence;
mod csv;
mod error_metrics;
mod mitsuba;
mod plots;

pub use agreement::{
    AGREEMENT_SPP, Agreement, AgreementScene, AgreementSet, BIAS_SLACK, Comparison,
    NOISE_TOLERANCE, REFERENCE_SPP, ReferenceRenders, RenderProvenance, RenderSceneFile,
    agreement_table, write_agreement_figure,
};
pub use bias_blocks::{BIAS_BLOCK_SIZE, BIAS_THRESHOLD, bias_blocks};
pub use convergence::{ConvergenceRecord, Technique, convergence_markdown, run_convergence};
pub use csv::{CONVERGENCE_CSV_HEADER, write_convergence_csv};
pub use error_metrics::{RELMSE_EPSILON, mean, relmse, rmse};
pub use mitsuba::{
    AGREEMENT_ONLY, MITSUBA_JIT_VARIANT, MITSUBA_PYTHON, MITSUBA_VARIANT, UPDATE_MITSUBA_RENDERS,
    make_reference_renders, mitsuba_python, refresh_agreement, refresh_agreement_from_env,
    render_with_mitsuba,
};
pub use plots::{plot_error_vs_spp, plot_error_vs_time, series_by_technique};
