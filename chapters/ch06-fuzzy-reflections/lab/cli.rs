//! The chapter's `render` options, which chapter 07 flattens into its own `render`: the lobe
//! exponent, the choices at glass and at the surface, and the depth limit.

use crate::{BelowSurface, FuzzMethod, GlassStrategy, TraceOptions};
use common::scene::{Scene, check_exponent};
use workbench::cli::parse_number;

/// How fuzzy surfaces and glass are traced.
#[derive(clap::Args, Clone, Debug)]
pub struct FuzzyArgs {
    /// The exponent n of every cos^n lobe: 0 is a hemisphere, 1e6 almost a mirror
    /// [default: the scene's].
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = parse_number)]
    pub exponent: Option<f32>,
    /// Which ray to trace at glass: both, one with probability 1/2, or one by the Fresnel term.
    #[arg(long, value_enum, default_value_t = GlassStrategy::Fresnel)]
    pub glass: GlassStrategy,
    /// How fuzzy surfaces spread their rays: the cos^n lobe, or the empirical disc.
    #[arg(long, value_enum, default_value_t = FuzzMethod::Lobe)]
    pub fuzz: FuzzMethod,
    /// What to do with a spread ray that points below the surface.
    #[arg(long, value_enum, default_value_t = BelowSurface::Drop)]
    pub below_surface: BelowSurface,
}

impl FuzzyArgs {
    /// The tracer's choices.
    pub fn options(&self) -> TraceOptions {
        TraceOptions {
            glass: self.glass,
            fuzz: self.fuzz,
            below: self.below_surface,
        }
    }

    /// `--exponent`, checked.
    pub fn exponent(&self) -> anyhow::Result<Option<f32>> {
        self.exponent
            .map(check_exponent)
            .transpose()
            .map_err(|e| anyhow::anyhow!("--exponent: {e}"))
    }

    /// `scene` with `--exponent` applied where given.
    pub fn apply(&self, scene: Scene) -> anyhow::Result<Scene> {
        Ok(match self.exponent()? {
            Some(exponent) => scene.with_exponent(exponent),
            None => scene,
        })
    }

    /// Adds the options to a render's statistics (a JSON object).
    pub fn record_stats(&self, stats: &mut serde_json::Value) {
        stats["glass"] = self.glass.name().into();
        stats["fuzz"] = self.fuzz.name().into();
        stats["below_surface"] = self.below_surface.name().into();
        stats["exponent"] = self.exponent.into();
    }
}
