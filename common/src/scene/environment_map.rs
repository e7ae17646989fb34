//! Light from an image around the scene: Mitsuba 3's `envmap` emitter.
//!
//! The image is a latitude–longitude map: its columns go once around the vertical axis and
//! its rows from straight up (the top row) to straight down (the bottom row). The conventions
//! are Mitsuba 3's, so that a scene file lights its objects as Mitsuba does:
//!
//! - in the map's own frame `+y` is up; a direction `d` has `u = atan2(d.x, -d.z) / 2π`
//!   (so `u = 0` looks along `-z` and `u` grows towards `+x`) and `v = acos(d.y) / π`;
//! - `to_world` turns the map's frame into the world's; a ray's direction is taken back into
//!   the map's frame before the lookup;
//! - columns are read **between pixel centres** around the circle (pixel `i` at
//!   `u = (i + 1/2) / w`, the last column blending into the first), rows **from edge to edge**
//!   (row `j` at `v = j / (h - 1)`: the top row is the north pole itself);
//! - between those points the colour is interpolated bilinearly, and multiplied by `scale`.
//!
//! How to sample the map is [`EnvironmentSampling`](super::EnvironmentSampling)'s business.

use super::environment_sampling::EnvironmentSampling;
use super::lat_long::direction_to_uv;
use glam::{Mat3, Vec2, Vec3};
use std::sync::Arc;

/// An image of radiance around the scene, infinitely far away.
#[derive(Clone, Debug, PartialEq)]
pub struct EnvironmentMap {
    width: u32,
    height: u32,
    /// Radiance, `scale` included: row by row from the top, each row from the left.
    pixels: Arc<[Vec3]>,
    /// The map's frame to the world's (a rotation, possibly with a reflection).
    to_world: Mat3,
    /// The world's frame to the map's: `to_world`'s inverse.
    to_local: Mat3,
    /// Where to send light samples, built once from the pixels.
    sampling: EnvironmentSampling,
}

/// Why an image cannot be an environment map.
#[derive(Clone, Debug, PartialEq)]
pub enum EnvironmentMapError {
    /// The pixel count does not match the size, or there is no pixel.
    Size,
    /// A pixel, after scaling, is NaN or infinite.
    NotFinite {
        /// Its column.
        x: u32,
        /// Its row.
        y: u32,
    },
    /// `to_world` is not a rotation (or a reflection): the map would be stretched.
    NotRotation,
}

impl std::fmt::Display for EnvironmentMapError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Size => write!(f, "the image has no pixel, or not as many as its size says"),
            Self::NotFinite { x, y } => write!(
                f,
                "pixel ({x}, {y}) times the scale is not a finite number (NaN or infinite)"
            ),
            Self::NotRotation => write!(
                f,
                "to_world must be a rotation (a scale or shear would stretch the sky)"
            ),
        }
    }
}

impl EnvironmentMap {
    /// The map of a `width` x `height` image of linear RGB `pixels` (row by row from the
    /// top), each multiplied by `scale`, turned into the world by `to_world`.
    pub fn new(
        width: u32,
        height: u32,
        pixels: &[Vec3],
        scale: f32,
        to_world: Mat3,
    ) -> Result<Self, EnvironmentMapError> {
        let count = (width as usize).checked_mul(height as usize);
        if count.is_none_or(|count| count == 0 || count != pixels.len()) {
            return Err(EnvironmentMapError::Size);
        }
        let pixels: Arc<[Vec3]> = pixels.iter().map(|&p| p * scale).collect();
        if let Some(i) = pixels.iter().position(|p| !p.is_finite()) {
            return Err(EnvironmentMapError::NotFinite {
                x: (i % width as usize) as u32,
                y: (i / width as usize) as u32,
            });
        }
        // Orthogonal columns of unit length: the inverse is the transpose.
        let orthogonal = (to_world.transpose() * to_world).abs_diff_eq(Mat3::IDENTITY, 1e-4);
        if !orthogonal {
            return Err(EnvironmentMapError::NotRotation);
        }
        let sampling = EnvironmentSampling::new(width, height, &pixels);
        Ok(Self {
            width,
            height,
            pixels,
            to_world,
            to_local: to_world.transpose(),
            sampling,
        })
    }

    /// Width and height in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// How light samples are drawn from the map.
    pub fn sampling(&self) -> &EnvironmentSampling {
        &self.sampling
    }

    /// The radiance arriving from world direction `direction` (towards the sky; any length).
    pub fn radiance(&self, direction: Vec3) -> Vec3 {
        self.lookup(direction_to_uv(self.to_local * direction))
    }

    /// The map's direction `local` (in its own frame) in the world.
    pub fn to_world(&self, local: Vec3) -> Vec3 {
        self.to_world * local
    }

    /// The world direction `world` in the map's own frame.
    pub fn to_local(&self, world: Vec3) -> Vec3 {
        self.to_local * world
    }

    /// The colour at map coordinates `uv`: bilinear between pixel centres, around the circle
    /// in `u`, from pole to pole in `v`.
    pub fn lookup(&self, uv: Vec2) -> Vec3 {
        if !uv.is_finite() {
            return Vec3::ZERO;
        }
        let (w, h) = (self.width as f32, self.height as f32);
        // Column position: pixel centres at whole numbers, the last blending into the first.
        let x = (uv.x - uv.x.floor()) * w - 0.5;
        // Row position: the first row at the north pole, the last at the south pole.
        let y = uv.y.clamp(0.0, 1.0) * (h - 1.0);
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let column = |x: f32| (x.rem_euclid(w) as usize).min(self.width as usize - 1);
        let row = |y: f32| (y.max(0.0) as usize).min(self.height as usize - 1);
        let (c0, c1) = (column(x0), column(x0 + 1.0));
        let (r0, r1) = (row(y0), row(y0 + 1.0));
        let pixel = |r: usize, c: usize| self.pixels[r * self.width as usize + c];
        let top = pixel(r0, c0) * (1.0 - fx) + pixel(r0, c1) * fx;
        let bottom = pixel(r1, c0) * (1.0 - fx) + pixel(r1, c1) * fx;
        top * (1.0 - fy) + bottom * fy
    }
}

#[cfg(test)]
mod tests;
