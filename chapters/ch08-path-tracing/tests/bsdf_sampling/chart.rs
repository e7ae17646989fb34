//! A map of the sphere of directions onto a rectangle on which a BSDF's lobes, however
//! narrow, fill chapter 02's chi-square grid, with one more row for "no direction".
//!
//! Chapter 02 bins directions on an even grid over `(φ, cos θ)`. A lobe of exponent `10⁴` is
//! a hundredth of a radian wide and would fall into one bin of it. So each lobe gets a strip
//! of its own, in coordinates around its own axis: the azimuth `φ` in `[0, 2π)` and
//!
//! `v = 1 - exp(-(m + 1)(1 - cos θ))` in `[0, 1)`,
//!
//! `θ` the angle from the axis and `m` the lobe's exponent. For large `m`,
//! `cos^m θ ≈ exp(-m (1 - cos θ))`, so a `cos^m` lobe covers its strip almost evenly, and still
//! the whole sphere maps into the strip. As `dω = dφ d(cos θ)`, a density per unit solid angle
//! becomes one per unit area of the strip by the factor `d(cos θ) / dv = 1 / ((m + 1)(1 - v))`.
//! The map only decides where the bins are: the density compared is the BSDF's, whatever `m`.
//!
//! Lobe `k`'s strip is `y = k + v` in `[k, k + 1)`, `x = φ`. Each lobe lives on one side of the surface
//! (reflection on `wo`'s side, transmission on the other), and a direction is counted in the
//! strip of its side only, so no direction is counted twice.
//!
//! After the strips, one row of bins stands for the sampler's other outcome: no direction at
//! all (a lobe direction below the surface is dropped, which is how a BSDF loses energy). Its
//! share must be `1 - ∫ pdf dω`, so one chi-square test checks both where the directions go and
//! how often there is none.

use crate::quadrature::{around, simpson};
use ch02_monte_carlo::warps::Domain;
use glam::{DVec2, DVec3, Vec2, Vec3};
use std::f64::consts::TAU;

/// Bins across the azimuth.
pub const COLUMNS: usize = 16;
/// Bins along each lobe's strip; the "no direction" row is one such row high.
pub const ROWS: usize = 32;

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

/// The lobes of one BSDF, in the order of their strips.
#[derive(Clone, Debug)]
pub struct Chart {
    /// The lobes, on different sides of the surface.
    pub lobes: Vec<Lobe>,
}

/// The `(φ, v)` coordinates of a direction around a lobe's axis, and back.
struct Frame {
    a: DVec3,
    b: DVec3,
    axis: DVec3,
    /// `m + 1`.
    spread: f64,
}

impl Frame {
    fn of(lobe: &Lobe) -> Self {
        let axis = lobe.axis.as_dvec3().normalize();
        let (a, b) = axis.any_orthonormal_pair();
        Self {
            a,
            b,
            axis,
            spread: f64::from(lobe.exponent) + 1.0,
        }
    }

    /// `(φ, v)` of the unit direction `d`. `1 - cos θ` is computed as `|d - axis|² / 2`, which
    /// keeps its digits even when `θ` is a thousandth of a radian.
    fn coordinates(&self, d: DVec3) -> DVec2 {
        let one_minus_cos = (d - self.axis).length_squared() / 2.0;
        let v = -(-self.spread * one_minus_cos).exp_m1();
        let phi = d.dot(self.b).atan2(d.dot(self.a)).rem_euclid(TAU);
        // A direction in the farthest tail would round onto the next strip.
        DVec2::new(phi, v.min(1.0 - 1.0 / f64::from(1u32 << 20)))
    }

    /// The direction at `(φ, v)`, `None` beyond the sphere (`1 - cos θ > 2`).
    fn direction(&self, phi: f64, v: f64) -> Option<Vec3> {
        let one_minus_cos = -(-v).ln_1p() / self.spread;
        if !(0.0..=2.0).contains(&one_minus_cos) {
            return None;
        }
        let sin = (one_minus_cos * (2.0 - one_minus_cos)).sqrt();
        let d = sin * (phi.cos() * self.a + phi.sin() * self.b) + (1.0 - one_minus_cos) * self.axis;
        Some(d.as_vec3())
    }

    /// `dω / (dφ dv)` at `v`.
    fn jacobian(&self, v: f64) -> f64 {
        1.0 / (self.spread * (1.0 - v))
    }
}

impl Chart {
    /// The chart of `lobes`.
    pub fn new(lobes: Vec<Lobe>) -> Self {
        Self { lobes }
    }

    fn strips(&self) -> f32 {
        self.lobes.len() as f32
    }

    /// The rectangle: `φ` across, the strips and the "no direction" row up.
    pub fn domain(&self) -> Domain {
        Domain::Plane {
            min: Vec2::ZERO,
            max: Vec2::new(TAU as f32, self.strips() + 1.0 / ROWS as f32),
        }
    }

    /// `(columns, rows)` of the chi-square grid: [`ROWS`] per strip and one for "no direction".
    pub fn resolution(&self) -> (usize, usize) {
        (COLUMNS, self.lobes.len() * ROWS + 1)
    }

    /// Where a sample lands: the direction `wi` in the strip of its side (NaN, an impossible
    /// point, if it is on no lobe's side or not a unit vector), or no direction at the point
    /// of the last row that `u` picks (uniformly: the row has one density).
    pub fn point(&self, wi: Option<Vec3>, u: Vec2) -> Vec2 {
        let Some(wi) = wi else {
            return Vec2::new(TAU as f32 * u.x, self.strips() + u.y / ROWS as f32);
        };
        let d = wi.as_dvec3();
        if !d.is_finite() || (d.length() - 1.0).abs() > 1e-3 {
            return Vec2::NAN;
        }
        let d = d.normalize();
        let Some(k) = self
            .lobes
            .iter()
            .position(|l| d.dot(l.side.as_dvec3()) > 0.0)
        else {
            return Vec2::NAN;
        };
        let c = Frame::of(&self.lobes[k]).coordinates(d);
        Vec2::new(c.x as f32, (k as f64 + c.y) as f32)
    }

    /// The density per unit area of the rectangle at `q`: `pdf` (per unit solid angle) times
    /// the strip's Jacobian on the lobes' sides, and `no_direction` (the probability of no
    /// direction) spread evenly over the last row.
    pub fn density(&self, q: Vec2, pdf: &impl Fn(Vec3) -> f32, no_direction: f64) -> f64 {
        let k = q.y.floor() as usize;
        if k >= self.lobes.len() {
            return no_direction * ROWS as f64 / TAU;
        }
        self.strip_density(k, f64::from(q.x), f64::from(q.y) - k as f64, pdf)
    }

    /// The density on lobe `k`'s strip at `(φ, v)`: 0 off the lobe's side of the surface.
    fn strip_density(&self, k: usize, phi: f64, v: f64, pdf: &impl Fn(Vec3) -> f32) -> f64 {
        let lobe = &self.lobes[k];
        let frame = Frame::of(lobe);
        match frame.direction(phi, v) {
            Some(d) if d.dot(lobe.side) > 0.0 => f64::from(pdf(d)) * frame.jacobian(v),
            _ => 0.0,
        }
    }

    /// How far, relatively, the BSDF's `f32` density may be off on lobe `k`: `cos θ` is rounded
    /// to a few parts in `2^24`, and `cos^m θ` multiplies that by `m`. (At `m = 16 000`, a
    /// refracted direction `3·10⁻⁸` short of unit length already makes the density `4·10⁻⁴`
    /// too small.)
    pub fn rounding(&self, k: usize) -> f64 {
        (f64::from(self.lobes[k].exponent) + 1.0) * f64::from(f32::EPSILON)
    }

    /// `∫ pdf dω` over the sphere, strip by strip, and an estimate of the quadrature's error.
    ///
    /// Adaptive Simpson must not be asked for more than the `f32` density holds: below its
    /// rounding, it would halve every panel to the last in pursuit of noise.
    pub fn integral(&self, pdf: &impl Fn(Vec3) -> f32) -> (f64, f64) {
        let (mut sum, mut error) = (0.0, 0.0);
        for k in 0..self.lobes.len() {
            let along = 1e-7 + self.rounding(k) / 10.0;
            let (value, around_error) = around(
                &|phi| simpson(&|v| self.strip_density(k, phi, v, pdf), 0.0, 1.0, along),
                256,
            );
            sum += value;
            error += around_error + TAU * along;
        }
        (sum, error)
    }
}
