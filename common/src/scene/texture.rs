//! Colours that vary over a surface: Mitsuba 3's `checkerboard` and `bitmap` textures.
//!
//! A [`Texture`] is plain `Copy` data like the rest of a material: a checkerboard carries its
//! two colours, a bitmap only the number of its image in [`Scene::bitmaps`](super::Scene),
//! which holds each image once however many materials use it. [`Scene::albedo`](super::Scene)
//! reads a texture at a hit's surface parameters `uv`; every chapter goes through it.

use glam::{Affine2, Vec2, Vec3};
use std::sync::Arc;

/// A colour over the surface parameters `uv`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Texture {
    /// Two colours in squares.
    Checkerboard(Checkerboard),
    /// An image, by its number in [`Scene::bitmaps`](super::Scene).
    Bitmap(BitmapId),
}

/// The number of an image in [`Scene::bitmaps`](super::Scene).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BitmapId(pub u32);

/// Mitsuba 3's `checkerboard` texture: two colours alternating over the surface parameters.
///
/// With `uv' = to_uv(uv)`, a point is in colour 0 where the fractional parts of `u'` and `v'`
/// are on the same side of 1/2, else in colour 1: one period of `uv'` holds 2 x 2 squares.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Checkerboard {
    /// Mitsuba's `color0`.
    pub colour0: Vec3,
    /// Mitsuba's `color1`.
    pub colour1: Vec3,
    /// Mitsuba's `to_uv`: the affine map applied to `uv` before the squares are found.
    pub to_uv: Affine2,
}

impl Checkerboard {
    /// A checkerboard with `scale` periods per unit of `u` and `v`.
    pub fn scaled(colour0: Vec3, colour1: Vec3, scale: Vec2) -> Self {
        Self {
            colour0,
            colour1,
            to_uv: Affine2::from_scale(scale),
        }
    }

    /// The colour at surface parameters `uv`.
    pub fn eval(&self, uv: Vec2) -> Vec3 {
        let mapped = self.to_uv.transform_point2(uv);
        let upper_half = |t: f32| t - t.floor() > 0.5;
        if upper_half(mapped.x) == upper_half(mapped.y) {
            self.colour0
        } else {
            self.colour1
        }
    }
}

/// How a bitmap is read between its pixels' centres (Mitsuba's `filter_type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BitmapFilter {
    /// The pixel the point falls in.
    Nearest,
    /// A mix of the four pixels whose centres surround the point (Mitsuba's default).
    Bilinear,
}

/// What a bitmap shows outside `[0, 1]²` (Mitsuba's `wrap_mode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WrapMode {
    /// The image again, tiled (Mitsuba's default).
    Repeat,
    /// The image again, every other copy flipped, so the edges meet.
    Mirror,
    /// The edge pixels, drawn out.
    Clamp,
}

/// An image to read colours from, in linear RGB, with how to read it.
///
/// Mitsuba 3's conventions: `uv = (0, 0)` is the image's top-left corner and `v` grows
/// downwards with the rows; pixel `(i, j)` has its centre at `((i + 1/2) / w, (j + 1/2) / h)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Bitmap {
    width: u32,
    height: u32,
    /// Row by row from the top, each row from the left; shared by the textures that read the
    /// same file.
    pixels: Arc<[Vec3]>,
    /// How to read between pixels.
    pub filter: BitmapFilter,
    /// What to show outside the image.
    pub wrap: WrapMode,
    /// Mitsuba's `to_uv`: the affine map applied to `uv` before the lookup.
    pub to_uv: Affine2,
}

impl Bitmap {
    /// An image of `width` x `height` linear RGB `pixels` (row by row from the top), read
    /// bilinearly and repeated; `None` when the sizes do not match or the image is empty.
    pub fn new(width: u32, height: u32, pixels: Arc<[Vec3]>) -> Option<Self> {
        let expected = (width as usize).checked_mul(height as usize)?;
        if expected == 0 || pixels.len() != expected {
            return None;
        }
        Some(Self {
            width,
            height,
            pixels,
            filter: BitmapFilter::Bilinear,
            wrap: WrapMode::Repeat,
            to_uv: Affine2::IDENTITY,
        })
    }

    /// Width and height in pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// The colour at surface parameters `uv`; black where `uv` (after `to_uv`, in pixels) is
    /// not a finite number, which is nowhere on the image, tiled or not.
    pub fn eval(&self, uv: Vec2) -> Vec3 {
        let uv = self.to_uv.transform_point2(uv);
        let size = Vec2::new(self.width as f32, self.height as f32);
        let texel = uv * size;
        // Also a huge `uv` whose pixel position overflows: its fraction would be `∞ - ∞`.
        if !texel.is_finite() {
            return Vec3::ZERO;
        }
        match self.filter {
            BitmapFilter::Nearest => self.pixel(texel.x.floor(), texel.y.floor()),
            BitmapFilter::Bilinear => {
                // Pixel centres sit at half-integers: shift them to the integers.
                let p = texel - Vec2::splat(0.5);
                let (x0, y0) = (p.x.floor(), p.y.floor());
                let (fx, fy) = (p.x - x0, p.y - y0);
                let top = self.pixel(x0, y0) * (1.0 - fx) + self.pixel(x0 + 1.0, y0) * fx;
                let bottom =
                    self.pixel(x0, y0 + 1.0) * (1.0 - fx) + self.pixel(x0 + 1.0, y0 + 1.0) * fx;
                top * (1.0 - fy) + bottom * fy
            }
        }
    }

    /// The pixel at column `x` and row `y` (whole numbers, any size), wrapped into the image.
    fn pixel(&self, x: f32, y: f32) -> Vec3 {
        let column = wrap(x, self.width, self.wrap);
        let row = wrap(y, self.height, self.wrap);
        self.pixels[row * self.width as usize + column]
    }
}

/// Index `i` (a whole number, possibly negative or huge) brought into `0..n` by `mode`.
fn wrap(i: f32, n: u32, mode: WrapMode) -> usize {
    let n_f = n as f32;
    let index = match mode {
        WrapMode::Repeat => i.rem_euclid(n_f),
        WrapMode::Clamp => i.clamp(0.0, n_f - 1.0),
        WrapMode::Mirror => {
            let folded = i.rem_euclid(2.0 * n_f);
            if folded < n_f {
                folded
            } else {
                2.0 * n_f - 1.0 - folded
            }
        }
    };
    // `rem_euclid` may round up to `n` for a tiny negative `i`; the cast saturates.
    (index as usize).min(n as usize - 1)
}

#[cfg(test)]
mod tests;
