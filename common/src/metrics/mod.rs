//! How far an image is from a reference: the error metrics, the test that tells noise from
//! bias, and the record of one measurement of error against cost.
//!
//! Plain arithmetic over images, below every chapter: a chapter's own measurements (the share
//! of each depth in chapter 08's ray tree, say) use it as much as the workbench's runner that
//! plots error against time (`workbench::convergence`) and its agreement with Mitsuba 3
//! (`workbench::agreement`).

mod bias_blocks;
mod error_metrics;
mod record;

pub use bias_blocks::{BIAS_BLOCK_SIZE, BIAS_THRESHOLD, bias_blocks};
pub use error_metrics::{RELMSE_EPSILON, mean, relmse, rmse};
pub use record::ConvergenceRecord;
