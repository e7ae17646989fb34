//! A map of the sphere of directions onto a rectangle on which a sampler's lobes, however
//! narrow, fill chapter 02's chi-square grid, with one more row for "no direction".
//!
//! Chapter 02 bins directions on an even grid over `(φ, cos θ)`. A lobe a hundredth of a
//! radian wide would fall into one bin of it. So each lobe gets a strip of its own, in
//! coordinates around its own axis: the azimuth `φ` in `[0, 2π)` and a `v` in `[0, 1)` that
//! grows with the angle `θ` from the axis, chosen by the lobe ([`StripLobe`]) so that the lobe
//! covers its strip almost evenly while the whole sphere still maps into the strip. A density
//! per unit solid angle becomes one per unit area of the strip by the Jacobian `dω / (dφ dv)`.
//! The map only decides where the bins are: the density compared is the sampler's, whatever
//! the map.
//!
//! Lobe `k`'s strip is `y = k + v` in `[k, k + 1)`, `x = φ`. Each lobe lives on one side of
//! the surface (reflection on `wo`'s side, transmission on the other), and a direction is
//! counted in the strip of its side only, so no direction is counted twice.
//!
//! After the strips, one row of bins stands for the sampler's other outcome: no direction at
//! all (a lobe direction below the surface is dropped, which is how a BSDF loses energy). Its
//! share must be `1 - ∫ pdf dω`, so one chi-square test checks both where the directions go
//! and how often there is none.
//!
//! `bsdf_sampling` charts `cos^m` lobes by an exponential map, `microfacet_sampling` the power
//! tails of microfacet lobes by the half-angle tangent; both bin through this one chart.

use crate::quadrature::{around, simpson};
use ch02_monte_carlo::warps::Domain;
use glam::{DVec2, DVec3, Vec2, Vec3};
use std::f64::consts::TAU;

/// Bins across the azimuth.
pub const COLUMNS: usize = 16;
/// Bins along each lobe's strip; the "no direction" row is one such row high.
pub const ROWS: usize = 32;

/// A lobe the chart can bin: where it is, and how the angle from its axis maps to its strip.
pub trait StripLobe {
    /// The unit direction the lobe is centred on.
    fn axis(&self) -> Vec3;
    /// A normal pointing to the lobe's side of the surface.
    fn side(&self) -> Vec3;
    /// `v` in `[0, 1]` of the unit direction `d`, `axis` being [`axis`](Self::axis) in double
    /// precision.
    fn v(&self, d: DVec3, axis: DVec3) -> f64;
    /// `(sin θ, cos θ)` of the angle from the axis at `v`; `None` beyond the sphere.
    fn angle(&self, v: f64) -> Option<(f64, f64)>;
    /// `dω / (dφ dv)` at `v`.
    fn jacobian(&self, v: f64) -> f64;
    /// How far, relatively, the sampler's `f32` density may be off on this lobe (0: no more
    /// than any `f32`).
    fn rounding(&self) -> f64 {
        0.0
    }
}

/// The lobes of one sampler, in the order of their strips.
#[derive(Clone, Debug)]
pub struct Chart<L> {
    /// The lobes, on different sides of the surface.
    pub lobes: Vec<L>,
}

/// The frame around a lobe's axis in which `φ` is measured.
struct Frame {
    a: DVec3,
    b: DVec3,
    axis: DVec3,
}

impl Frame {
    fn of(lobe: &impl StripLobe) -> Self {
        let axis = lobe.axis().as_dvec3().normalize();
        let (a, b) = axis.any_orthonormal_pair();
        Self { a, b, axis }
    }

    /// `(φ, v)` of the unit direction `d`.
    fn coordinates(&self, lobe: &impl StripLobe, d: DVec3) -> DVec2 {
        let v = lobe.v(d, self.axis);
        let phi = d.dot(self.b).atan2(d.dot(self.a)).rem_euclid(TAU);
        // A direction in the farthest tail would round onto the next strip.
        DVec2::new(phi, v.min(1.0 - 1.0 / f64::from(1u32 << 20)))
    }

    /// The direction at `(φ, v)`, `None` beyond the sphere.
    fn direction(&self, lobe: &impl StripLobe, phi: f64, v: f64) -> Option<Vec3> {
        let (sin, cos) = lobe.angle(v)?;
        let d = sin * (phi.cos() * self.a + phi.sin() * self.b) + cos * self.axis;
        Some(d.as_vec3())
    }
}

impl<L: StripLobe> Chart<L> {
    /// The chart of `lobes`.
    pub fn new(lobes: Vec<L>) -> Self {
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
            .position(|l| d.dot(l.side().as_dvec3()) > 0.0)
        else {
            return Vec2::NAN;
        };
        let lobe = &self.lobes[k];
        let c = Frame::of(lobe).coordinates(lobe, d);
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
        match Frame::of(lobe).direction(lobe, phi, v) {
            Some(d) if d.dot(lobe.side()) > 0.0 => f64::from(pdf(d)) * lobe.jacobian(v),
            _ => 0.0,
        }
    }

    /// How far, relatively, the sampler's `f32` density may be off on lobe `k`.
    pub fn rounding(&self, k: usize) -> f64 {
        self.lobes[k].rounding()
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
