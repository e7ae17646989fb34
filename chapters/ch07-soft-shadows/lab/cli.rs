//! The light options of `render`, for this chapter's binary and the chapters after it.

use crate::disc_warp::DiscWarp;
use crate::shadow_rays::{LightOptions, LightStrata, MAX_LIGHT_SAMPLES};
use crate::strategy::{LightSampling, Strategy};

/// How area lights are sampled: `--light-samples`, `--light-strata`, `--light-sampling`,
/// `--disc-warp`.
#[derive(clap::Args, Clone, Debug)]
pub struct LightArgs {
    /// Shadow rays to each area light at every matte hit (1 to 4096); a pixel then averages
    /// spp x N points of every light.
    #[arg(long, value_name = "N", default_value_t = 1, allow_negative_numbers = true,
          value_parser = clap::value_parser!(u32).range(1..=i64::from(MAX_LIGHT_SAMPLES)))]
    pub light_samples: u32,
    /// How one hit's N points on a light are spread: a jittered k x k grid (N = k²) or a
    /// Latin hypercube (other N), or independent points.
    #[arg(long, value_enum, default_value_t = LightStrata::Stratified)]
    pub light_strata: LightStrata,
    /// How sphere lights are sampled: uniformly over their area, or over the cone of
    /// directions they cover (planar lights are always sampled by area).
    #[arg(long, value_enum, default_value_t = Strategy::SolidAngle)]
    pub light_sampling: Strategy,
    /// How points are put on disc lights; `naive` (r = ξ) is the lecture's wrong one, kept
    /// to show its wrong penumbra.
    #[arg(long, value_enum, default_value_t = DiscWarp::Concentric)]
    pub disc_warp: DiscWarp,
}

impl Default for LightArgs {
    fn default() -> Self {
        Self {
            light_samples: 1,
            light_strata: LightStrata::Stratified,
            light_sampling: Strategy::SolidAngle,
            disc_warp: DiscWarp::Concentric,
        }
    }
}

impl LightArgs {
    /// The options these arguments ask for.
    pub fn options(&self) -> LightOptions {
        LightOptions {
            samples: self.light_samples,
            strata: self.light_strata,
            sampling: LightSampling {
                strategy: self.light_sampling,
                disc_warp: self.disc_warp,
            },
        }
    }
}
