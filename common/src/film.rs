//! The film: where samples are averaged into pixels.
//!
//! Each pixel keeps the running sums `Σ f(x_i) L_i` and `Σ f(x_i)` in `f64`, so that the
//! weighted average of the lecture's anti-aliasing slide,
//! `L = Σ f L / Σ f`, can be taken at any time. In `f64` a sum of 1e8 samples of value 1 is
//! still exact to the last digit; in `f32` it would stop growing at 2^24 ≈ 1.7e7.
//!
//! Rendering happens in tiles ([`FilmTile`]) that are merged back in a fixed order, so the
//! image does not depend on which thread finished first.

use crate::image::Image;
use glam::{DVec3, UVec2, Vec2, Vec3};

// ANCHOR: filter_trait
/// A reconstruction filter: how much a sample at `offset` from a pixel centre (in pixels)
/// counts towards that pixel. Chapter 03 adds tent, Gaussian and Mitchell–Netravali filters.
pub trait Filter: Send + Sync {
    /// Half-width of the filter's support along x and y, in pixels.
    fn radius(&self) -> Vec2;

    /// The filter's weight at `offset` from the pixel centre; zero outside the radius.
    fn evaluate(&self, offset: Vec2) -> f32;
}
// ANCHOR_END: filter_trait

/// The box filter of radius half a pixel: every sample counts fully for the one pixel it
/// falls into, and the pixel value is the plain average of its samples.
#[derive(Clone, Copy, Debug, Default)]
pub struct PixelBoxFilter;

impl Filter for PixelBoxFilter {
    fn radius(&self) -> Vec2 {
        Vec2::splat(0.5)
    }

    fn evaluate(&self, offset: Vec2) -> f32 {
        if offset.x.abs() <= 0.5 && offset.y.abs() <= 0.5 {
            1.0
        } else {
            0.0
        }
    }
}

/// The running sums of one pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelSum {
    /// `Σ f(x_i) L_i`.
    pub weighted_radiance: DVec3,
    /// `Σ f(x_i)`.
    pub weight: f64,
}

impl PixelSum {
    /// The weighted average, or black where no sample has any weight.
    pub fn value(&self) -> DVec3 {
        if self.weight.abs() > 0.0 {
            self.weighted_radiance / self.weight
        } else {
            DVec3::ZERO
        }
    }
}

/// A rectangle of pixels, `min` inclusive and `max` exclusive.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelRect {
    /// The first pixel inside.
    pub min: UVec2,
    /// One past the last pixel inside.
    pub max: UVec2,
}

impl PixelRect {
    /// Number of pixels across.
    pub fn width(&self) -> u32 {
        self.max.x.saturating_sub(self.min.x)
    }

    /// Number of pixels down.
    pub fn height(&self) -> u32 {
        self.max.y.saturating_sub(self.min.y)
    }

    /// Every pixel of the rectangle, row by row.
    pub fn pixels(&self) -> impl Iterator<Item = UVec2> + '_ {
        (self.min.y..self.max.y)
            .flat_map(move |y| (self.min.x..self.max.x).map(move |x| UVec2::new(x, y)))
    }
}

/// The whole image's pixel sums.
#[derive(Clone, Debug)]
pub struct Film {
    width: u32,
    height: u32,
    sums: Vec<PixelSum>,
}

impl Film {
    /// An empty film.
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            sums: vec![PixelSum::default(); width as usize * height as usize],
        }
    }

    /// Pixels across.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Pixels down.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The sums of pixel `(x, y)`.
    pub fn pixel(&self, x: u32, y: u32) -> PixelSum {
        self.sums[y as usize * self.width as usize + x as usize]
    }

    /// A tile that collects the samples taken in `samples_from`. With a filter wider than
    /// half a pixel a sample also reaches pixels outside that rectangle, so the tile covers
    /// those too, up to the film's edges; [`Film::merge`] adds them back.
    pub fn tile(&self, samples_from: PixelRect, filter: &dyn Filter) -> FilmTile {
        let r = filter.radius();
        // Saturating: a filter's radius may be huge or infinite (and reaches the whole film).
        let reach = |v: f32| v.max(0.0).ceil() as u32;
        let bounds = PixelRect {
            min: UVec2::new(
                samples_from.min.x.saturating_sub(reach(r.x - 0.5)),
                samples_from.min.y.saturating_sub(reach(r.y - 0.5)),
            ),
            max: UVec2::new(
                (samples_from.max.x.saturating_add(reach(r.x - 0.5))).min(self.width),
                (samples_from.max.y.saturating_add(reach(r.y - 0.5))).min(self.height),
            ),
        };
        FilmTile {
            bounds,
            sums: vec![PixelSum::default(); bounds.width() as usize * bounds.height() as usize],
        }
    }

    /// Adds a finished tile's sums. Merging tiles in a fixed order keeps the floating-point
    /// sums, and so the image, independent of the thread schedule.
    pub fn merge(&mut self, tile: &FilmTile) {
        for (i, p) in tile.bounds.pixels().enumerate() {
            let dst = &mut self.sums[p.y as usize * self.width as usize + p.x as usize];
            dst.weighted_radiance += tile.sums[i].weighted_radiance;
            dst.weight += tile.sums[i].weight;
        }
    }

    /// The current image: each pixel's weighted average, in `f32`.
    ///
    /// An average beyond the largest `f32` (weights of opposite signs that nearly cancel
    /// under a huge radiance) is clamped to it rather than made infinite.
    pub fn image(&self) -> Image {
        let largest = f64::from(f32::MAX);
        // Comparisons rather than `clamp`, which glam's `max` would make turn a NaN into a
        // number: a NaN that got into the sums must show.
        let within_f32 = |v: f64| {
            if v > largest {
                largest
            } else if v < -largest {
                -largest
            } else {
                v
            }
        };
        Image {
            width: self.width,
            height: self.height,
            pixels: self
                .sums
                .iter()
                .map(|s| s.value().map(within_f32).as_vec3())
                .collect(),
        }
    }
}

/// The part of the film one worker writes to.
#[derive(Clone, Debug)]
pub struct FilmTile {
    bounds: PixelRect,
    sums: Vec<PixelSum>,
}

impl FilmTile {
    /// The pixels this tile holds sums for.
    pub fn bounds(&self) -> PixelRect {
        self.bounds
    }

    /// Adds radiance `radiance` seen by a sample at continuous film position `p_film`
    /// (in pixels; pixel `(i, j)` covers `[i, i+1) x [j, j+1)`) to every pixel whose filter
    /// reaches it.
    ///
    /// A radiance or a filter weight that is NaN or infinite is left out (the render loop
    /// counts such radiance first, [`RenderStats`](crate::render::RenderStats)): only a bug
    /// gives one, and averaged in it would turn its pixels into NaN. A position that is NaN
    /// reaches no pixel.
    pub fn add_sample(&mut self, p_film: Vec2, radiance: Vec3, filter: &dyn Filter) {
        if !radiance.is_finite() {
            return;
        }
        let r = filter.radius();
        // Pixel j (centre j + 0.5) is reached when -r < p - (j + 0.5) <= r. For the box of
        // radius 1/2 that is exactly the one pixel the sample falls into. Saturating: the
        // position may be huge or infinite, and then reaches no pixel of the tile.
        let first = |p: f32, r: f32| floor_to_i64(p - 0.5 - r).saturating_add(1);
        let last = |p: f32, r: f32| floor_to_i64(p - 0.5 + r);
        let x0 = first(p_film.x, r.x).max(i64::from(self.bounds.min.x));
        let x1 = last(p_film.x, r.x).min(i64::from(self.bounds.max.x) - 1);
        let y0 = first(p_film.y, r.y).max(i64::from(self.bounds.min.y));
        let y1 = last(p_film.y, r.y).min(i64::from(self.bounds.max.y) - 1);
        let radiance = radiance.as_dvec3();
        for y in y0..=y1 {
            for x in x0..=x1 {
                let centre = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
                let weight = f64::from(filter.evaluate(p_film - centre));
                if weight == 0.0 || !weight.is_finite() {
                    continue;
                }
                let local = (y - i64::from(self.bounds.min.y)) as usize
                    * self.bounds.width() as usize
                    + (x - i64::from(self.bounds.min.x)) as usize;
                self.sums[local].weighted_radiance += weight * radiance;
                self.sums[local].weight += weight;
            }
        }
    }
}

/// `x.floor() as i64`, for every `x` (NaN gives 0, infinities saturate), in a few
/// instructions: on the baseline x86-64 instruction set `floor` is a library call, and this
/// runs four times for every sample of every render.
#[inline]
fn floor_to_i64(x: f32) -> i64 {
    // Rounds towards zero (and saturates); a float this large is a whole number already, so
    // only a negative fraction needs the step down.
    let truncated = x as i64;
    if truncated as f32 > x {
        truncated.saturating_sub(1)
    } else {
        truncated
    }
}

#[cfg(test)]
mod awkward_samples;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floor_to_i64_is_floor_then_the_cast() {
        let special = [
            0.0f32,
            -0.0,
            0.5,
            -0.5,
            -1.0,
            1.0,
            -1e-30,
            2.5e9,
            -2.5e9,
            f32::MAX,
            f32::MIN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
        ];
        // Every 65 521st bit pattern (a prime stride) covers all exponents, signs and NaNs.
        let spread = (0..=u32::MAX).step_by(65_521).map(f32::from_bits);
        for x in special.into_iter().chain(spread) {
            assert_eq!(floor_to_i64(x), x.floor() as i64, "{x:e}");
        }
    }

    fn whole(film: &Film) -> PixelRect {
        PixelRect {
            min: UVec2::ZERO,
            max: UVec2::new(film.width(), film.height()),
        }
    }

    #[test]
    fn box_filter_gives_the_plain_average_of_the_pixel_it_falls_in() {
        let mut film = Film::new(3, 2);
        let mut tile = film.tile(whole(&film), &PixelBoxFilter);
        // Both samples fall into pixel (1, 0), one of them on its lower-left corner.
        tile.add_sample(Vec2::new(1.0, 0.0), Vec3::splat(1.0), &PixelBoxFilter);
        tile.add_sample(Vec2::new(1.75, 0.5), Vec3::splat(3.0), &PixelBoxFilter);
        film.merge(&tile);
        let image = film.image();
        assert_eq!(image.get(1, 0), Vec3::splat(2.0));
        for (x, y) in [(0, 0), (2, 0), (0, 1), (1, 1), (2, 1)] {
            assert_eq!(film.pixel(x, y).weight, 0.0, "pixel ({x}, {y})");
        }
    }

    #[test]
    fn a_hundred_million_samples_sum_exactly() {
        // 1e8 unit samples: an f32 sum would stall at 2^24. Adding them in batches of a
        // million per tile mirrors how the renderer accumulates passes.
        let mut film = Film::new(1, 1);
        for _ in 0..100 {
            let mut tile = film.tile(whole(&film), &PixelBoxFilter);
            for _ in 0..1_000_000 {
                tile.add_sample(Vec2::splat(0.5), Vec3::new(1.0, 0.1, 1e-3), &PixelBoxFilter);
            }
            film.merge(&tile);
        }
        let sum = film.pixel(0, 0);
        assert_eq!(sum.weight, 1e8);
        assert_eq!(sum.value().x, 1.0);
        assert!((sum.value().y - f64::from(0.1f32)).abs() < 1e-12);
    }

    /// A filter wider than a pixel, to check that samples spill into neighbours.
    struct Wide;
    impl Filter for Wide {
        fn radius(&self) -> Vec2 {
            Vec2::splat(1.5)
        }
        fn evaluate(&self, offset: Vec2) -> f32 {
            if offset.abs().max_element() <= 1.5 {
                1.0
            } else {
                0.0
            }
        }
    }

    #[test]
    fn wide_filters_reach_neighbouring_tiles() {
        let mut film = Film::new(4, 1);
        let left = PixelRect {
            min: UVec2::ZERO,
            max: UVec2::new(2, 1),
        };
        let mut tile = film.tile(left, &Wide);
        assert_eq!(tile.bounds().max.x, 3, "the tile reaches one pixel further");
        tile.add_sample(Vec2::new(1.5, 0.5), Vec3::ONE, &Wide);
        film.merge(&tile);
        let weights: Vec<f64> = (0..4).map(|x| film.pixel(x, 0).weight).collect();
        assert_eq!(weights, vec![1.0, 1.0, 1.0, 0.0]);
    }
}
