//! Which warp of chapter 02 puts the points on a disc light.
//!
//! Three ways to turn `u` into a point of the unit disc, from chapter 02: Shirley and Chiu's
//! concentric map and the polar map whose radius chapter 02's exercise derives are uniform by
//! area; the lecture's first try, `r = ξ2`, is not: it crowds the centre, with density
//! `1 / (2π r)`. A disc light sampled
//! with it still *claims* the uniform density `1 / area`, which is exactly the lecture's
//! mistake, and the estimate then weights the middle of the light too much: the penumbra of a
//! shadow edge comes out wrong and the irradiance below the light too bright.

use ch02_monte_carlo::warps::{
    sample_disc_naive, sample_uniform_disc_concentric, sample_uniform_disc_polar,
};
use glam::Vec2;

/// How a point of a disc light is made from two uniform numbers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum DiscWarp {
    /// Shirley and Chiu's concentric map: uniform, little distortion (Mitsuba's and pbrt's
    /// choice, and the default).
    #[default]
    Concentric,
    /// Polar coordinates with the radius that makes them uniform (chapter 02's exercise).
    Polar,
    /// Polar coordinates with `r = ξ2`: **not** uniform, yet sampled as if it were. Kept to
    /// show the mistake.
    Naive,
}

impl DiscWarp {
    /// Every warp, in the order of the enum.
    pub const ALL: [DiscWarp; 3] = [DiscWarp::Concentric, DiscWarp::Polar, DiscWarp::Naive];

    /// The name used in tests and figures.
    pub fn name(self) -> &'static str {
        match self {
            DiscWarp::Concentric => "concentric",
            DiscWarp::Polar => "polar",
            DiscWarp::Naive => "naive",
        }
    }

    /// The point of the unit disc this warp makes of `u`.
    pub fn sample(self, u: Vec2) -> Vec2 {
        match self {
            DiscWarp::Concentric => sample_uniform_disc_concentric(u),
            DiscWarp::Polar => sample_uniform_disc_polar(u),
            DiscWarp::Naive => sample_disc_naive(u),
        }
    }
}
