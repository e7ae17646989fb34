//! The chapter's `render` options, which chapter 07 flattens into its own `render`: the lobe
//! exponent, the choices at glass and at the surface, and the depth limit.

use crate::{BelowSurface, FuzzMethod, GlassStrategy, TraceOptions};
use common::cli::parse_number;
use common::scene::{Scene, check_exponent};

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
    /// Longest path in segments, counting the camera ray (Mitsuba's max_depth)
    /// [default: the scene file's, or 12].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub max_depth: Option<u32>,
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

    /// `scene` with `--exponent` and `--max-depth` applied where given.
    pub fn apply(&self, scene: Scene) -> anyhow::Result<Scene> {
        let mut scene = match self.exponent()? {
            Some(exponent) => scene.with_exponent(exponent),
            None => scene,
        };
        if let Some(max_depth) = self.max_depth {
            scene.max_depth = max_depth;
        }
        Ok(scene)
    }

    /// The options as the render's statistics record them, to add to its other entries.
    pub fn stats(&self) -> serde_json::Map<String, serde_json::Value> {
        let mut stats = serde_json::Map::new();
        stats.insert("glass".into(), self.glass.name().into());
        stats.insert("fuzz".into(), self.fuzz.name().into());
        stats.insert("below_surface".into(), self.below_surface.name().into());
        stats.insert("exponent".into(), self.exponent.into());
        stats
    }
}
