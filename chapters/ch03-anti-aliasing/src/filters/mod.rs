//! Reconstruction filters: how the samples near a pixel are combined into its value.
//!
//! The lecture's weighted average: a pixel's value is `Σ f(x_i - c) L_i / Σ f(x_i - c)` over
//! the samples `x_i` near its centre `c`. The box of radius 1/2 is the plain average of the
//! pixel's own samples. Wider filters let a sample count for several pixels: the tent and the
//! Gaussian blur slightly and suppress the patterns a box lets through; Mitchell–Netravali's
//! cubic has negative lobes that keep edges sharp, at the price of a little ringing.
//! `common::film` does the sums; this module supplies `f`.

mod kernels;

pub use kernels::{box_1d, gaussian_1d, mitchell_1d, tent_1d};

use common::film::Filter;
use glam::Vec2;

/// The largest radius accepted, in pixels: a filter 33 pixels wide already touches about a
/// thousand pixels per sample.
pub const MAX_RADIUS: f32 = 16.0;

/// Filter weights are rounded to multiples of this (2^-20, a millionth of the peak).
///
/// With a filter that has negative lobes, `Σ f` of a pixel can cancel to almost nothing and
/// `Σ f L / Σ f` explode, up to infinity in `f32`. Weights on a grid of `2^-20` add up
/// *exactly* in `f64` (up to 2^33 of them): a sum that cancels is exactly 0, which the film
/// shows as black (no information), and any other sum is at least `2^-20`, so the quotient stays
/// finite. The rounding changes no weight by more than a millionth of the peak.
pub const WEIGHT_QUANTUM: f32 = 1.0 / (1u32 << 20) as f32;

/// The command-line names of the filters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum FilterKind {
    /// The plain average (radius 1/2: only the pixel's own samples).
    Box,
    /// The triangle, radius 1.
    Tent,
    /// A truncated Gaussian, standard deviation 1/2, radius 2.
    Gaussian,
    /// Mitchell–Netravali's cubic with `B = C = 1/3`, radius 2.
    Mitchell,
}

impl FilterKind {
    /// Every filter, in the order of the enum.
    pub const ALL: [FilterKind; 4] = [
        FilterKind::Box,
        FilterKind::Tent,
        FilterKind::Gaussian,
        FilterKind::Mitchell,
    ];

    /// The name used on the command line and in figures.
    pub fn name(self) -> &'static str {
        match self {
            FilterKind::Box => "box",
            FilterKind::Tent => "tent",
            FilterKind::Gaussian => "gaussian",
            FilterKind::Mitchell => "mitchell",
        }
    }
}

/// A reconstruction filter with its parameters, implementing [`Filter`].
///
/// Each is separable, `f(x, y) = f(x) f(y)`. Weights need not sum to one: the film divides
/// by `Σ f`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ReconstructionFilter {
    /// 1 inside the square of half-width `radius`.
    Box {
        /// Half-width in pixels.
        radius: f32,
    },
    /// The tent of half-width `radius` along `x` times the same along `y`.
    Tent {
        /// Half-width in pixels.
        radius: f32,
    },
    /// A Gaussian lowered to reach zero at `radius`.
    Gaussian {
        /// Standard deviation in pixels.
        stddev: f32,
        /// Half-width in pixels.
        radius: f32,
    },
    /// Mitchell–Netravali's cubic stretched from its natural support `[-2, 2]` to `radius`.
    Mitchell {
        /// Half-width in pixels.
        radius: f32,
        /// Blur parameter.
        b: f32,
        /// Ringing parameter.
        c: f32,
    },
}

impl ReconstructionFilter {
    /// The filter `kind` with Mitsuba 3's defaults (box 1/2, tent 1, Gaussian of standard
    /// deviation 1/2 cut at four deviations, Mitchell radius 2 with `B = C = 1/3`), or with the
    /// half-width `radius` (for the Gaussian the standard deviation is a quarter of it).
    ///
    /// Errors: a radius that is not a finite number in `(0, 16]`.
    pub fn new(kind: FilterKind, radius: Option<f32>) -> Result<Self, String> {
        if let Some(r) = radius {
            check_radius(r)?;
        }
        Ok(match kind {
            FilterKind::Box => ReconstructionFilter::Box {
                radius: radius.unwrap_or(0.5),
            },
            FilterKind::Tent => ReconstructionFilter::Tent {
                radius: radius.unwrap_or(1.0),
            },
            FilterKind::Gaussian => {
                let stddev = radius.map_or(0.5, |r| r / 4.0);
                ReconstructionFilter::Gaussian {
                    stddev,
                    radius: 4.0 * stddev,
                }
            }
            FilterKind::Mitchell => ReconstructionFilter::Mitchell {
                radius: radius.unwrap_or(2.0),
                b: 1.0 / 3.0,
                c: 1.0 / 3.0,
            },
        })
    }

    /// Which kind of filter this is.
    pub fn kind(&self) -> FilterKind {
        match self {
            ReconstructionFilter::Box { .. } => FilterKind::Box,
            ReconstructionFilter::Tent { .. } => FilterKind::Tent,
            ReconstructionFilter::Gaussian { .. } => FilterKind::Gaussian,
            ReconstructionFilter::Mitchell { .. } => FilterKind::Mitchell,
        }
    }

    /// The half-width of the support, in pixels.
    pub fn half_width(&self) -> f32 {
        match *self {
            ReconstructionFilter::Box { radius }
            | ReconstructionFilter::Tent { radius }
            | ReconstructionFilter::Gaussian { radius, .. }
            | ReconstructionFilter::Mitchell { radius, .. } => radius,
        }
    }

    // ANCHOR: filter_profile
    /// The 1-D profile `f(x)` (before rounding), of which the 2-D filter is the product: this
    /// filter's kernel with its own parameters, reaching exactly as far as its half-width.
    ///
    /// The kernels (`box_1d`, `tent_1d`, `gaussian_1d`, `mitchell_1d`) take their parameters
    /// as they are stored here, but one: which kernel has a support of its own, and how must `x`
    /// be changed for that support to end at this filter's radius?
    pub fn evaluate_1d(&self, x: f32) -> f32 {
        // BEGIN SOLUTION
        match *self {
            ReconstructionFilter::Box { radius } => box_1d(x, radius),
            ReconstructionFilter::Tent { radius } => tent_1d(x, radius),
            ReconstructionFilter::Gaussian { stddev, radius } => gaussian_1d(x, stddev, radius),
            ReconstructionFilter::Mitchell { radius, b, c } => {
                if x.abs() > radius {
                    0.0
                } else {
                    mitchell_1d(2.0 * x / radius, b, c)
                }
            }
        }
        // END SOLUTION
    }
    // ANCHOR_END: filter_profile
}

/// Accepts a filter radius in `(0, MAX_RADIUS]`, or says what is wrong with it.
pub fn check_radius(radius: f32) -> Result<(), String> {
    if radius.is_finite() && radius > 0.0 && radius <= MAX_RADIUS {
        Ok(())
    } else {
        Err(format!(
            "a filter radius must be a number of pixels in (0, {MAX_RADIUS}], got {radius}"
        ))
    }
}

// ANCHOR: filter_impl
/// Rounds a weight to the nearest multiple of [`WEIGHT_QUANTUM`].
pub fn quantise_weight(weight: f32) -> f32 {
    (weight / WEIGHT_QUANTUM).round() * WEIGHT_QUANTUM
}

impl Filter for ReconstructionFilter {
    fn radius(&self) -> Vec2 {
        Vec2::splat(self.half_width())
    }

    fn evaluate(&self, offset: Vec2) -> f32 {
        let r = self.half_width();
        if offset.x.abs() > r || offset.y.abs() > r {
            return 0.0;
        }
        quantise_weight(self.evaluate_1d(offset.x) * self.evaluate_1d(offset.y))
    }
}
// ANCHOR_END: filter_impl

#[cfg(test)]
mod tests;
