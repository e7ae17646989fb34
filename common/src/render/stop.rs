//! Stopping a render early, keeping the passes already done.
//!
//! A render of an hour that is stopped after forty minutes should leave forty minutes of
//! image, not nothing. Whoever wants the render to stop (a Ctrl-C handler installed by a
//! binary, a test) sets a [`StopFlag`]; the render loop looks at it before each tile and
//! each pixel, so it reacts within a pixel's worth of work, throws away the pass it was in
//! the middle of (so that every pixel holds the same number of samples) and returns the
//! image of the passes it completed.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// A shared "please stop" signal. Clones share the same flag.
///
/// The render loop never installs a signal handler itself: a library must not take over a
/// process's Ctrl-C behind the back of its caller (a test runner, say). The binaries do, with
/// `workbench::cli::ctrl_c_stop_flag`.
#[derive(Clone, Debug, Default)]
pub struct StopFlag(Arc<AtomicBool>);

impl StopFlag {
    /// A flag that nobody has set yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Asks every render holding this flag to stop at its next check.
    pub fn request(&self) {
        self.0.store(true, Ordering::Relaxed);
    }

    /// Whether a stop has been asked for.
    pub fn is_requested(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
}
