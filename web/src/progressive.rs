//! A render refined a slice at a time: the page asks for a few thousand samples per animation
//! frame and shows the film between slices.
//!
//! Passes add one sample to every pixel, row by row; a slice ends anywhere in a pass. Sample
//! `index` of a pixel is the same sample the command-line render takes (the chapter's sampler
//! fixes every number by seed, pixel and index), so a finished demo at `N` samples per pixel is
//! the chapter's render at `N`, and the same values always give the same image.

use common::film::{Film, PixelRect};
use common::image::Image;
use common::srgb::to_srgb8;
use glam::UVec2;

use crate::demo::{Demo, Picture, Values};

/// One view of a demo, being refined.
pub struct Session {
    picture: Box<dyn Picture>,
    film: Film,
    /// The pass under way: every pixel before `next_pixel` has `pass + 1` samples, the rest
    /// `pass`.
    pass: u64,
    next_pixel: u32,
    /// Where refining stops.
    target_spp: u64,
    /// Samples traced so far, over all pixels.
    samples: u64,
}

impl Session {
    /// A session of `picture` on an empty `width x height` film, to refine to `target_spp`.
    pub fn new(picture: Box<dyn Picture>, width: u32, height: u32, target_spp: u64) -> Self {
        Self {
            picture,
            film: Film::new(width.max(1), height.max(1)),
            pass: 0,
            next_pixel: 0,
            target_spp: target_spp.max(1),
            samples: 0,
        }
    }

    /// Traces up to `budget` more samples, whole rows at a time (at least one row); stops at
    /// the target. Gives the samples traced.
    pub fn advance(&mut self, budget: u64) -> u64 {
        let width = self.film.width();
        let height = self.film.height();
        let mut traced = 0;
        while !self.is_done() && (traced == 0 || traced + u64::from(width) <= budget) {
            let pixel_count = width * height;
            let rows = (budget.saturating_sub(traced) / u64::from(width)).max(1) as u32;
            let first_row = self.next_pixel / width;
            let last_row = (first_row + rows).min(height);
            let rect = PixelRect {
                min: UVec2::new(0, first_row),
                max: UVec2::new(width, last_row),
            };
            let pixels: Vec<UVec2> = rect.pixels().collect();
            let filter = self.picture.filter();
            let mut tile = self.film.tile(rect, filter);
            self.picture
                .trace(&pixels, self.pass, &mut |p_film, radiance| {
                    tile.add_sample(p_film, radiance, filter);
                });
            self.film.merge(&tile);
            traced += pixels.len() as u64;
            self.next_pixel = last_row * width;
            if self.next_pixel >= pixel_count {
                self.next_pixel = 0;
                self.pass += 1;
            }
        }
        self.samples += traced;
        traced
    }

    /// Whether every pixel has its target's samples.
    pub fn is_done(&self) -> bool {
        self.pass >= self.target_spp
    }

    /// Complete passes: the samples every pixel has.
    pub fn spp(&self) -> u64 {
        self.pass
    }

    /// Samples traced so far.
    pub fn samples(&self) -> u64 {
        self.samples
    }

    /// The film's current image, linear.
    pub fn image(&self) -> Image {
        self.film.image()
    }

    /// The image as the page draws it: sRGB, 8 bits, red, green, blue and opaque alpha per
    /// pixel, row by row from the top. A pixel no sample reached yet shows black.
    pub fn rgba(&self) -> Vec<u8> {
        let image = self.film.image();
        let mut bytes = Vec::with_capacity(image.pixels.len() * 4);
        for pixel in &image.pixels {
            bytes.extend([to_srgb8(pixel.x), to_srgb8(pixel.y), to_srgb8(pixel.z), 255]);
        }
        bytes
    }
}

/// View 0 of `demo` with `values`, rendered whole at `size` and `spp` samples per pixel (for
/// claims), or why the demo cannot make that picture.
pub fn render_demo(
    demo: &dyn Demo,
    values: &Values,
    size: UVec2,
    spp: u64,
) -> Result<Image, String> {
    let picture = demo.picture(values, 0, size.x, size.y)?;
    Ok(render_still(picture, size.x, size.y, spp))
}

/// Renders `picture` whole at `spp` samples per pixel (for claims and tests).
pub fn render_still(picture: Box<dyn Picture>, width: u32, height: u32, spp: u64) -> Image {
    let mut session = Session::new(picture, width, height, spp);
    while !session.is_done() {
        session.advance(u64::MAX);
    }
    session.image()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::demo::trace_each;
    use common::sampler::{IndependentSampler, Sampler};
    use glam::{Vec2, Vec3};

    /// A picture whose radiance is the sample's random number: its image is the mean of
    /// uniform numbers.
    struct Noise;

    impl Picture for Noise {
        fn trace(&self, pixels: &[UVec2], index: u64, add: &mut dyn FnMut(Vec2, Vec3)) {
            trace_each(&IndependentSampler::new(3), pixels, index, add, |_, s| {
                Vec3::splat(s.get_1d())
            });
        }
    }

    #[test]
    fn slices_of_any_size_give_the_same_image() {
        let whole = render_still(Box::new(Noise), 9, 7, 5);
        let mut sliced = Session::new(Box::new(Noise), 9, 7, 5);
        let mut slices = 0;
        while !sliced.is_done() {
            let traced = sliced.advance(13);
            assert!(
                traced <= 18,
                "a slice of 13 traced {traced}, more than two rows"
            );
            slices += 1;
        }
        assert_eq!(sliced.image().pixels, whole.pixels);
        assert_eq!(sliced.samples(), 9 * 7 * 5);
        assert_eq!(sliced.spp(), 5);
        assert!(slices > 5);
    }

    #[test]
    fn a_slice_smaller_than_a_row_still_traces_a_row() {
        let mut session = Session::new(Box::new(Noise), 9, 7, 1);
        assert_eq!(session.advance(1), 9);
        assert_eq!(session.spp(), 0);
        assert_eq!(session.rgba().len(), 9 * 7 * 4);
    }
}
