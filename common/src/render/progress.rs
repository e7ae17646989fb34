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
    pub(super) fn new(_settings: &RenderSettings, _tiles_per_pass: usize) -> Self {
        Self
    }

    pub(super) fn tile_done(&self) {}

    pub(super) fn pass_done(&self, _spp: u64) {}

    pub(super) fn finish(&self) {}
}

/// Counts finished tiles; draws nothing when disabled or when stderr is not a terminal
/// (tests, CI logs, pipes).
#[cfg(feature = "progress")]
pub(super) struct Progress {
    bar: Option<ProgressBar>,
    tiles_per_pass: u64,
}

#[cfg(feature = "progress")]
impl Progress {
    pub(super) fn new(settings: &RenderSettings, tiles_per_pass: usize) -> Self {
        let tiles_per_pass = tiles_per_pass as u64;
        let bar = (settings.progress && std::io::stderr().is_terminal()).then(|| {
            let (len, unit) = match settings.budget {
                Budget::Samples(spp) => (spp, "spp"),
                Budget::Seconds(_) => (0, "spp so far"),
            };
            let bar = ProgressBar::with_draw_target(
                Some(len * tiles_per_pass),
                ProgressDrawTarget::stderr(),
            );
            let template = format!(
                "{{spinner}} [{{elapsed_precise}}] {{wide_bar}} {{msg}} {unit} (eta {{eta}})"
            );
            bar.set_style(
                ProgressStyle::with_template(&template)
                    .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            if len == 0 {
                bar.set_length(tiles_per_pass);
            }
            bar
        });
        Self {
            bar,
            tiles_per_pass,
        }
    }

    pub(super) fn tile_done(&self) {
        if let Some(bar) = &self.bar {
            bar.inc(1);
        }
    }

    /// A pass has finished; `spp` samples per pixel are now done. A samples budget advances
    /// the bar per tile of each pass; a time budget grows the bar as passes are added.
    pub(super) fn pass_done(&self, spp: u64) {
        if let Some(bar) = &self.bar {
            bar.set_message(spp.to_string());
            if bar.length().is_some_and(|len| bar.position() >= len) {
                bar.inc_length(self.tiles_per_pass);
            }
        }
    }

    pub(super) fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
