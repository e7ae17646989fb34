//! A progress bar for renders, shown only on a terminal, and only with the `progress` feature
//! (the workbench turns it on; without it, as in a browser, the render loop counts nothing).

#[cfg(feature = "progress")]
use super::Budget;
use super::RenderSettings;
#[cfg(feature = "progress")]
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
#[cfg(feature = "progress")]
use std::io::IsTerminal;

/// Without the `progress` feature: a bar that is never drawn.
#[cfg(not(feature = "progress"))]
pub(super) struct Progress;

#[cfg(not(feature = "progress"))]
impl Progress {
    pub(super) fn new(_settings: &RenderSettings, _tiles: usize, _planned_spp: u64) -> Self {
        Self
    }

    pub(super) fn tile_done(&self, _spp: u64) {}

    pub(super) fn pass_done(&self, _spp: u64) {}

    pub(super) fn finish(&self) {}
}

/// The bar of a render: with a sample budget, the samples traced against those planned (a tile
/// of `n` samples per pixel advances it by `n`); with a time budget, the time spent against the
/// budget. Its message is the samples per pixel done. It draws nothing when disabled or when
/// stderr is not a terminal (tests, CI logs, pipes).
#[cfg(feature = "progress")]
pub(super) struct Progress {
    bar: Option<ProgressBar>,
    timed: bool,
}

#[cfg(feature = "progress")]
impl Progress {
    /// `planned_spp` is the samples per pixel the whole render traces with a sample budget,
    /// counting every pass (and every whole render, for a render that starts over).
    pub(super) fn new(settings: &RenderSettings, tiles: usize, planned_spp: u64) -> Self {
        let bar = (settings.progress && std::io::stderr().is_terminal()).then(|| {
            let (len, unit) = match settings.budget {
                Budget::Samples(_) => (planned_spp.saturating_mul(tiles as u64), "spp"),
                Budget::Seconds(seconds) => ((seconds.max(0.0) * 1000.0) as u64, "spp so far"),
            };
            let bar = ProgressBar::with_draw_target(Some(len), ProgressDrawTarget::stderr());
            let template = format!(
                "{{spinner}} [{{elapsed_precise}}] {{wide_bar}} {{msg}} {unit} (eta {{eta}})"
            );
            bar.set_style(
                ProgressStyle::with_template(&template)
                    .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            bar
        });
        Self {
            bar,
            timed: matches!(settings.budget, Budget::Seconds(_)),
        }
    }

    /// A tile is done with `spp` samples per pixel.
    pub(super) fn tile_done(&self, spp: u64) {
        if let Some(bar) = &self.bar {
            if self.timed {
                let spent = bar.elapsed().as_millis().min(u128::from(u64::MAX)) as u64;
                bar.set_position(spent.min(bar.length().unwrap_or(u64::MAX)));
            } else {
                bar.inc(spp);
            }
        }
    }

    /// A pass (or a whole render) has finished; `spp` samples per pixel are now done.
    pub(super) fn pass_done(&self, spp: u64) {
        if let Some(bar) = &self.bar {
            bar.set_message(spp.to_string());
        }
    }

    pub(super) fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
