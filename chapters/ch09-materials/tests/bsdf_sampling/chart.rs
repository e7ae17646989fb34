//! The strip map of `cos^m` lobes for the [`strip_chart`](crate::strip_chart): around a lobe
//! of exponent `m`,
//!
//! `v = 1 - exp(-(m + 1)(1 - cos θ))` in `[0, 1)`,
//!
//! `θ` the angle from the axis. For large `m`, `cos^m θ ≈ exp(-m (1 - cos θ))`, so a `cos^m`
//! lobe covers its strip almost evenly, and still the whole sphere maps into the strip. As
//! `dω = dφ d(cos θ)`, a density per unit solid angle becomes one per unit area of the strip
//! by the factor `d(cos θ) / dv = 1 / ((m + 1)(1 - v))`.

use crate::strip_chart::{self, StripLobe};
use glam::{DVec3, Vec3};

/// The chart of a BSDF's lobes.
pub type Chart = strip_chart::Chart<Lobe>;

/// One lobe: directions spread around `axis`, on the side of the surface `side` points to,
/// charted as a `cos^exponent` lobe would be.
#[derive(Clone, Copy, Debug)]
pub struct Lobe {
    /// The unit direction the lobe is centred on.
    pub axis: Vec3,
    /// A normal pointing to the lobe's side of the surface.
    pub side: Vec3,
    /// How narrow the lobe is: its strip is even for a `cos^exponent` lobe.
    pub exponent: f32,
}

impl Lobe {
    /// `m + 1`.
    fn spread(&self) -> f64 {
        f64::from(self.exponent) + 1.0
    }
}

impl StripLobe for Lobe {
    fn axis(&self) -> Vec3 {
        self.axis
    }

    fn side(&self) -> Vec3 {
        self.side
    }

    /// `1 - cos θ` is computed as `|d - axis|² / 2`, which keeps its digits even when `θ` is a
    /// thousandth of a radian.
    fn v(&self, d: DVec3, axis: DVec3) -> f64 {
        let one_minus_cos = (d - axis).length_squared() / 2.0;
        -(-self.spread() * one_minus_cos).exp_m1()
    }

    fn angle(&self, v: f64) -> Option<(f64, f64)> {
        let one_minus_cos = -(-v).ln_1p() / self.spread();
        if !(0.0..=2.0).contains(&one_minus_cos) {
            return None;
        }
        let sin = (one_minus_cos * (2.0 - one_minus_cos)).sqrt();
        Some((sin, 1.0 - one_minus_cos))
    }

    fn jacobian(&self, v: f64) -> f64 {
        1.0 / (self.spread() * (1.0 - v))
    }

    /// `cos θ` is rounded to a few parts in `2^24`, and `cos^m θ` multiplies that by `m`. (At
    /// `m = 16 000`, a refracted direction `3·10⁻⁸` short of unit length already makes the
    /// density `4·10⁻⁴` too small.)
    fn rounding(&self) -> f64 {
        self.spread() * f64::from(f32::EPSILON)
    }
}
