//! What a render cost, as written by `render --stats FILE.json`.

use super::{Budget, RenderSettings};
use serde::Serialize;

/// What a render counts as it goes: sums gathered per tile and added up in tile order.
#[derive(Clone, Copy, Debug, Default)]
pub struct Totals {
    /// Rays cast: camera, secondary and shadow rays.
    pub rays: u64,
    /// Pixel samples taken.
    pub samples: u64,
    /// Samples whose radiance was NaN or infinite, left out of the image.
    pub nonfinite_samples: u64,
}

impl Totals {
    /// Adds `other`'s counts to these.
    pub fn add(&mut self, other: &Totals) {
        self.rays += other.rays;
        self.samples += other.samples;
        self.nonfinite_samples += other.nonfinite_samples;
    }
}

/// The cost of a render, serialised as the `--stats` JSON file.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RenderStats {
    /// Wall-clock seconds of the whole render.
    pub seconds: f64,
    /// Samples per pixel in the image (of completed passes only, if interrupted).
    pub spp: u64,
    /// Samples per pixel the budget asked for; `None` for a time budget.
    pub requested_spp: Option<u64>,
    /// Whether the render was stopped before its budget was spent.
    pub interrupted: bool,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
    /// Rays cast: camera, secondary and shadow rays.
    pub rays: u64,
    /// Pixel samples taken, `width * height * spp`.
    pub samples: u64,
    /// Pixel samples per second of wall-clock time.
    pub samples_per_second: f64,
    /// Rays per second of wall-clock time.
    pub rays_per_second: f64,
    /// Samples whose radiance was NaN or infinite and was left out of the image; any
    /// value but 0 is a bug.
    pub nonfinite_samples: u64,
    /// Worker threads used.
    pub threads: usize,
}

impl RenderStats {
    /// The stats of a render of `settings` that made an image of `spp` samples per pixel in
    /// `seconds`, having counted `totals`; the rates per second are worked out here. Renders
    /// outside the render loops (one that learns before it renders, say) make theirs with it
    /// too, so that every `--stats` file means the same.
    pub fn new(
        settings: &RenderSettings,
        spp: u64,
        interrupted: bool,
        seconds: f64,
        totals: &Totals,
    ) -> Self {
        let per_second = |n: u64| {
            if seconds > 0.0 {
                n as f64 / seconds
            } else {
                0.0
            }
        };
        Self {
            seconds,
            spp,
            requested_spp: match settings.budget {
                Budget::Samples(spp) => Some(spp),
                Budget::Seconds(_) => None,
            },
            interrupted,
            width: settings.width,
            height: settings.height,
            rays: totals.rays,
            samples: totals.samples,
            samples_per_second: per_second(totals.samples),
            rays_per_second: per_second(totals.rays),
            nonfinite_samples: totals.nonfinite_samples,
            threads: settings.threads.unwrap_or_else(rayon::current_num_threads),
        }
    }
}
