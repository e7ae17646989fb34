//! What one measurement of error against cost holds: plain data, written by the chapters'
//! lectures (chapter 02's estimator at growing sample counts) as much as by the workbench's
//! renders at growing budgets.

use serde::{Deserialize, Serialize};

/// One render of one technique at one budget: how long it took and how wrong it was.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ConvergenceRecord {
    /// Which technique rendered it.
    pub technique: String,
    /// Samples per pixel asked for.
    pub spp: u64,
    /// Wall-clock seconds the render took.
    pub seconds: f64,
    /// Root-mean-square error against the reference.
    pub rmse: f64,
    /// Relative mean squared error against the reference.
    pub relmse: f64,
}
