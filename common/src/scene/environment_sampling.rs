//! Where to send an environment map's light samples: more often where the sky is bright.
//!
//! The sphere is cut into the cells the map's lookup interpolates over
//! ([`EnvironmentMap`](super::EnvironmentMap)): between neighbouring pixel centres around the
//! circle, and between neighbouring rows from pole to pole. A cell is chosen with a chance
//! proportional to its **power**, the mean luminance of its four corner pixels times its
//! **solid angle** `Δφ (cos θ₀ - cos θ₁)`; inside it, a point `(x, y)` of the unit square is
//! drawn with a density proportional to the corners' luminance interpolated bilinearly, and
//! becomes the direction of azimuth `φ₀ + x Δφ` and height `cos θ₀ + y (cos θ₁ - cos θ₀)`.
//! The square is uniform by solid angle (uniform in `φ` and in `cos θ`), so the density per
//! unit solid angle is the interpolated luminance over the whole map's: close to
//! proportional to the light the lookup gives (which interpolates in `θ`, not `cos θ`),
//! finite at the poles, and never zero where the lookup gives light. A single bright pixel,
//! a sun, is thus sampled nearly as its light falls off, as Mitsuba 3's bilinear warp does;
//! a density constant over each cell would put four times too many samples at its edges.
//!
//! The solid angle is the `sin θ` of pbrt's and Mitsuba's constructions, integrated over the
//! cell: without it the thin cells near the poles would be chosen as often as the wide ones
//! at the horizon, and the estimate would be noisier there (still unbiased: the density below
//! is the one samples are drawn with).

use super::lat_long::{direction_of, direction_to_uv};
use glam::{Vec2, Vec3};

/// Luminance of linear sRGB (Rec. 709 primaries, D65), the weights Mitsuba's `luminance` uses.
pub fn luminance(rgb: Vec3) -> f32 {
    0.212671 * rgb.x + 0.715160 * rgb.y + 0.072169 * rgb.z
}

/// A piecewise-constant density over the cells of an environment map.
#[derive(Clone, Debug, PartialEq)]
pub struct EnvironmentSampling {
    /// Cells around the circle (the map's width).
    columns: usize,
    /// Cells from pole to pole (the map's height minus one, at least one).
    rows: usize,
    /// Each pixel's luminance (of its channels' sizes), row by row from the top.
    pixel_luminance: Vec<f32>,
    /// The map's height in pixels.
    height: usize,
    /// `cos θ` at the rows' edges, from 1 (north) down to -1 (south): `rows + 1` values.
    cos_edges: Vec<f64>,
    /// The chance of each row and those before it: `rows + 1` values from 0 to 1.
    row_cdf: Vec<f64>,
    /// In each row, the chance of each cell and those before it: `columns + 1` values per
    /// row from 0 to 1.
    column_cdf: Vec<f64>,
    /// The map's luminance integrated over the sphere (per cell: mean luminance times solid
    /// angle); 0 for a black map, which offers no sample.
    integral: f64,
}

impl EnvironmentSampling {
    /// The density of a `width` x `height` map of radiance `pixels` (row by row from the top).
    /// Negative channels count by their size, so a cell whose light is not zero can be chosen.
    ///
    /// # Panics
    /// If `pixels` holds fewer than `width * height` values (the map checks this first).
    pub fn new(width: u32, height: u32, pixels: &[Vec3]) -> Self {
        let (width, height) = (width as usize, height as usize);
        let columns = width;
        let rows = height.saturating_sub(1).max(1);
        let cos_edges: Vec<f64> = (0..=rows)
            .map(|j| (std::f64::consts::PI * j as f64 / rows as f64).cos())
            .collect();
        let pixel_luminance: Vec<f32> = pixels[..width * height]
            .iter()
            .map(|p| luminance(p.abs()))
            .collect();
        let mut column_cdf = Vec::with_capacity(rows * (columns + 1));
        let mut row_power = Vec::with_capacity(rows);
        let cell_angle = std::f64::consts::TAU / columns as f64;
        for j in 0..rows {
            let solid_angle = cell_angle * (cos_edges[j] - cos_edges[j + 1]).max(0.0);
            let mut running = vec![0.0];
            for i in 0..columns {
                let corners = corners_of(&pixel_luminance, width, height, j, i);
                let mean = corners.iter().map(|&c| f64::from(c)).sum::<f64>() / 4.0;
                running.push(running[i] + mean * solid_angle);
            }
            row_power.push(running[columns]);
            column_cdf.extend(normalised(running));
        }
        let mut row_cdf = vec![0.0];
        for (j, power) in row_power.iter().enumerate() {
            row_cdf.push(row_cdf[j] + power);
        }
        let integral = row_cdf[rows];
        let integral = if integral.is_finite() { integral } else { 0.0 };
        Self {
            columns,
            rows,
            pixel_luminance,
            height,
            cos_edges,
            row_cdf: normalised(row_cdf),
            column_cdf,
            integral,
        }
    }

    /// The map's luminance integrated over the sphere, as the cells see it: what the
    /// luminance of a constant sky of the same power times `4π` would be.
    pub fn integral(&self) -> f64 {
        self.integral
    }

    /// A direction in the map's frame drawn with the numbers `u` in `[0, 1)²`, and its
    /// density per unit solid angle; `None` for a black map. Numbers outside `[0, 1)`, NaN
    /// too, draw as the nearest number inside does (NaN as 0).
    pub fn sample(&self, u: Vec2) -> Option<(Vec3, f32)> {
        if self.integral <= 0.0 {
            return None;
        }
        let (row, fy) = pick(&self.row_cdf, f64::from(u.y))?;
        let cdf = &self.column_cdf[row * (self.columns + 1)..(row + 1) * (self.columns + 1)];
        let (column, fx) = pick(cdf, f64::from(u.x))?;
        // Where in the cell, by its corners' light; the cell starts at pixel centre `column`
        // in φ and at the row's upper edge in cos θ.
        let corners = self.corners(row, column);
        let (x, y) = sample_bilinear(fx, fy, corners);
        let u_map = (column as f64 + 0.5 + x) / self.columns as f64;
        let (top, bottom) = (self.cos_edges[row], self.cos_edges[row + 1]);
        let cos_theta = top + y * (bottom - top);
        let direction = direction_of(u_map as f32, cos_theta as f32);
        let pdf = self.density(corners, x, y);
        (pdf > 0.0 && pdf.is_finite()).then_some((direction, pdf))
    }

    /// The density per unit solid angle with which [`sample`](Self::sample) draws direction
    /// `d` (in the map's frame, any length).
    pub fn pdf(&self, d: Vec3) -> f32 {
        if self.integral <= 0.0 {
            return 0.0;
        }
        let uv = direction_to_uv(d);
        let cos_theta = f64::from(d.y / d.length());
        if !uv.is_finite() || !cos_theta.is_finite() {
            return 0.0;
        }
        let x = f64::from((uv.x - uv.x.floor()) * self.columns as f32) - 0.5;
        let column = (x.floor().rem_euclid(self.columns as f64) as usize).min(self.columns - 1);
        let x = (x - x.floor()).clamp(0.0, 1.0);
        // The row whose edges hold cos θ, found as the sample placed it: by cos θ.
        let row = self.cos_edges[1..self.rows].partition_point(|&edge| edge > cos_theta);
        let (top, bottom) = (self.cos_edges[row], self.cos_edges[row + 1]);
        let y = if top > bottom {
            ((top - cos_theta) / (top - bottom)).clamp(0.0, 1.0)
        } else {
            0.5
        };
        self.density(self.corners(row, column), x, y)
    }

    /// The luminance at the corners of cell (`row`, `column`): upper left, upper right,
    /// lower left, lower right.
    fn corners(&self, row: usize, column: usize) -> [f32; 4] {
        corners_of(
            &self.pixel_luminance,
            self.columns,
            self.height,
            row,
            column,
        )
    }

    /// The density per unit solid angle at `(x, y)` of the cell with luminance `corners`.
    fn density(&self, corners: [f32; 4], x: f64, y: f64) -> f32 {
        (bilinear(corners, x, y) / self.integral) as f32
    }
}

/// The luminance at the corners of cell (`row`, `column`) of a `width` x `height` map:
/// pixels `column` and the next one around the circle, in rows `row` and the next one (the
/// same row again in a map of one row).
fn corners_of(
    luminance: &[f32],
    width: usize,
    height: usize,
    row: usize,
    column: usize,
) -> [f32; 4] {
    let at = |r: usize, c: usize| luminance[r.min(height - 1) * width + c % width];
    [
        at(row, column),
        at(row, column + 1),
        at(row + 1, column),
        at(row + 1, column + 1),
    ]
}

/// `corners` (upper left, upper right, lower left, lower right) interpolated at `(x, y)`.
fn bilinear(corners: [f32; 4], x: f64, y: f64) -> f64 {
    let [a, b, c, d] = corners.map(f64::from);
    (1.0 - y) * ((1.0 - x) * a + x * b) + y * ((1.0 - x) * c + x * d)
}

/// A point of `[0, 1]` drawn with `u` with a density proportional to the line from `a` at 0
/// to `b` at 1 (both not negative), by inverting its distribution in the form that does not
/// cancel when `a` and `b` are close.
fn sample_linear(u: f64, a: f64, b: f64) -> f64 {
    if a + b <= 0.0 {
        return u;
    }
    let x = u * (a + b) / (a + ((1.0 - u) * a * a + u * b * b).sqrt());
    x.clamp(0.0, 1.0)
}

/// A point of the unit square drawn with `(u, v)` with a density proportional to `corners`
/// interpolated bilinearly: `y` by its marginal (a line), then `x` given `y` (a line).
fn sample_bilinear(u: f64, v: f64, corners: [f32; 4]) -> (f64, f64) {
    let [a, b, c, d] = corners.map(f64::from);
    let y = sample_linear(v, a + b, c + d);
    let x = sample_linear(u, (1.0 - y) * a + y * c, (1.0 - y) * b + y * d);
    (x, y)
}

/// `running` sums divided by the last, so they end at exactly 1 (all 0 if the last is 0).
fn normalised(mut running: Vec<f64>) -> Vec<f64> {
    let total = *running.last().unwrap_or(&0.0);
    if total > 0.0 && total.is_finite() {
        for value in &mut running {
            *value /= total;
        }
        if let Some(last) = running.last_mut() {
            *last = 1.0;
        }
    } else {
        running.iter_mut().for_each(|value| *value = 0.0);
    }
    running
}

/// The bin of `cdf` (running chances from 0 to 1) that `u` in `[0, 1)` falls in, and where in
/// it, from 0 to 1; never a bin of chance 0. `None` when every chance is 0. A number outside
/// `[0, 1)` picks as the nearest number inside does, and NaN as 0.
fn pick(cdf: &[f64], u: f64) -> Option<(usize, f64)> {
    let bins = cdf.len().checked_sub(1)?;
    if bins == 0 || cdf[bins] <= 0.0 {
        return None;
    }
    // Not `clamp`, which keeps a NaN: no edge would then be at or below it.
    let u = if u > 0.0 {
        u.min(1.0 - f64::EPSILON)
    } else {
        0.0
    };
    // The last edge at or below `u`: the bin after it has a chance above 0.
    let bin = (cdf.partition_point(|&edge| edge <= u) - 1).min(bins - 1);
    let width = cdf[bin + 1] - cdf[bin];
    let within = if width > 0.0 {
        ((u - cdf[bin]) / width).clamp(0.0, 1.0 - f64::EPSILON)
    } else {
        0.5
    };
    Some((bin, within))
}

#[cfg(test)]
mod tests;
