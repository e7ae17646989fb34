//! A map of the sphere of directions onto a rectangle on which a microfacet lobe, however
//! narrow and however long its tail, fills chapter 02's chi-square grid, with one more row for
//! "no direction". The same idea as `bsdf_sampling`'s chart, for power-law tails.
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
//!
//! Lobe `k`'s strip is `y = k + v`, `x = φ`; a direction is counted in the strip of its side of
//! the surface; the last row stands for no direction.

use crate::quadrature::{around, simpson};
use ch02_monte_carlo::warps::Domain;
use glam::{DVec2, DVec3, Vec2, Vec3};
use std::f64::consts::TAU;

/// Bins across the azimuth.
pub const COLUMNS: usize = 16;
/// Bins along each lobe's strip; the "no direction" row is one such row high.
pub const ROWS: usize = 32;

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

/// The lobes of one sampler, in the order of their strips.
pub struct SlopeChart {
    lobes: Vec<Lobe>,
}

/// The `(φ, v)` coordinates around a lobe's axis.
struct Frame {
    a: DVec3,
    b: DVec3,
    axis: DVec3,
    /// `c`, the half-angle tangent at the middle of the strip.
    c: f64,
}

impl Frame {
    fn of(lobe: &Lobe) -> Self {
        let axis = lobe.axis.as_dvec3().normalize();
        let (a, b) = axis.any_orthonormal_pair();
        Self {
            a,
            b,
            axis,
            c: (f64::from(lobe.width) / 2.0).tan(),
        }
    }

    /// `(φ, v)` of the unit direction `d`, with `tan(θ/2) = |d - axis| / |d + axis|`, which
    /// keeps its digits near the axis.
    fn coordinates(&self, d: DVec3) -> DVec2 {
        let q = (d - self.axis).length() / (d + self.axis).length();
        let v = if q.is_finite() { q / (self.c + q) } else { 1.0 };
        let phi = d.dot(self.b).atan2(d.dot(self.a)).rem_euclid(TAU);
        DVec2::new(phi, v.min(1.0 - 1.0 / f64::from(1u32 << 20)))
    }

    /// The direction at `(φ, v)`.
    fn direction(&self, phi: f64, v: f64) -> Vec3 {
        let q = self.c * v / (1.0 - v);
        let (sin, cos) = (2.0 * q / (1.0 + q * q), (1.0 - q * q) / (1.0 + q * q));
        (sin * (phi.cos() * self.a + phi.sin() * self.b) + cos * self.axis).as_vec3()
    }

    /// `dω / (dφ dv)` at `v`.
    fn jacobian(&self, v: f64) -> f64 {
        let q = self.c * v / (1.0 - v);
        4.0 * self.c * q / ((1.0 + q * q).powi(2) * (1.0 - v).powi(2))
    }
}

impl SlopeChart {
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

    /// `(columns, rows)` of the chi-square grid.
    pub fn resolution(&self) -> (usize, usize) {
        (COLUMNS, self.lobes.len() * ROWS + 1)
    }

    /// Where a sample lands: `wi` in the strip of its side (NaN, impossible, if on no lobe's
    /// side or not a unit vector), or no direction at the point of the last row `u` picks.
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

    /// The density per unit area of the rectangle at `q`.
    pub fn density(&self, q: Vec2, pdf: &impl Fn(Vec3) -> f32, no_direction: f64) -> f64 {
        let k = q.y.floor() as usize;
        if k >= self.lobes.len() {
            return no_direction * ROWS as f64 / TAU;
        }
        self.strip_density(k, f64::from(q.x), f64::from(q.y) - k as f64, pdf)
    }

    fn strip_density(&self, k: usize, phi: f64, v: f64, pdf: &impl Fn(Vec3) -> f32) -> f64 {
        let lobe = &self.lobes[k];
        let frame = Frame::of(lobe);
        let d = frame.direction(phi, v);
        if d.dot(lobe.side) > 0.0 {
            f64::from(pdf(d)) * frame.jacobian(v)
        } else {
            0.0
        }
    }

    /// `∫ pdf dω` over the sphere, strip by strip, and an estimate of the quadrature's error.
    pub fn integral(&self, pdf: &impl Fn(Vec3) -> f32) -> (f64, f64) {
        let (mut sum, mut error) = (0.0, 0.0);
        let along = 1e-7;
        for k in 0..self.lobes.len() {
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
