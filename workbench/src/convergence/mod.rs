//! Error against time: how a chapter backs the claim "technique B beats technique A".
//!
//! Render both against a converged reference at several budgets ([`run_convergence`]), measure
//! how far each render is from the reference (`common::metrics`), save the table
//! ([`write_convergence_csv`]) and plot error against time ([`plot_error_vs_time`]).

mod csv;
mod plots;
mod runner;

/// The record each measurement writes (plain data, in `common`, since lectures write it too).
pub use common::metrics::ConvergenceRecord;
pub use csv::{CONVERGENCE_CSV_HEADER, write_convergence_csv};
pub use plots::{plot_error_vs_spp, plot_error_vs_time, series_by_technique};
pub use runner::{Technique, convergence_markdown, run_convergence};
