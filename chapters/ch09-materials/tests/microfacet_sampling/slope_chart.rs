//! The strip map of microfacet lobes for the [`strip_chart`](crate::strip_chart), for
//! power-law tails.
//!
//! `bsdf_sampling` charts a lobe by `v = 1 - exp(-(m + 1)(1 - cos θ))`, even for a `cos^m`
//! lobe. GGX's tail falls only like a power of `tan θ`; on that chart a narrow GGX lobe puts
//! a few per cent of its mass within `10⁻¹⁶` of the strip's far edge, where nothing resolves
//! it. Here a lobe of width `c` is charted by the half-angle tangent `q = tan(θ / 2)`:
//!
//! `v = q / (c + q)` in `[0, 1)`,
//!
//! which covers the whole sphere (`θ` up to `π`), puts half of the strip within `θ ≈ 2c` and
//! gives a tail of `tan θ`'s power law a density that stays bounded to the far edge. With
//! `dω = sin θ dθ dφ` and `θ = 2 atan q`, a density per unit solid angle becomes one per unit
//! area of the strip by `dω / (dφ dv) = 4 c q / ((1 + q²)² (1 - v)²)`.

use crate::strip_chart::{Chart, StripLobe};
use glam::{DVec3, Vec3};

/// The chart of a microfacet sampler's lobes.
pub type SlopeChart = Chart<Lobe>;

/// One lobe: directions spread about `width` (radians, roughly) around `axis`, on the side
/// of the surface `side` points to.
#[derive(Clone, Copy, Debug)]
pub struct Lobe {
    /// The unit direction the lobe is centred on.
    pub axis: Vec3,
    /// A normal pointing to the lobe's side of the surface.
    pub side: Vec3,
    /// Half of the strip lies within about twice this angle of the axis.
    pub width: f32,
}

impl Lobe {
    /// `c`, the half-angle tangent at the middle of the strip.
    fn c(&self) -> f64 {
        (f64::from(self.width) / 2.0).tan()
    }

    /// `q` at `v`.
    fn q(&self, v: f64) -> f64 {
        self.c() * v / (1.0 - v)
    }
}

impl StripLobe for Lobe {
    fn axis(&self) -> Vec3 {
        self.axis
    }

    fn side(&self) -> Vec3 {
        self.side
    }

    /// `tan(θ/2) = |d - axis| / |d + axis|`, which keeps its digits near the axis.
    fn v(&self, d: DVec3, axis: DVec3) -> f64 {
        let q = (d - axis).length() / (d + axis).length();
        if q.is_finite() {
            q / (self.c() + q)
        } else {
            1.0
        }
    }

    fn angle(&self, v: f64) -> Option<(f64, f64)> {
        let q = self.q(v);
        Some((2.0 * q / (1.0 + q * q), (1.0 - q * q) / (1.0 + q * q)))
    }

    fn jacobian(&self, v: f64) -> f64 {
        let q = self.q(v);
        4.0 * self.c() * q / ((1.0 + q * q).powi(2) * (1.0 - v).powi(2))
    }
}
