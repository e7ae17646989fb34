//! A pass that learns as it renders: every sample's radiance averaged into its pixel (a box
//! filter), and what the sample recorded handed back in a fixed order.
//!
//! Chapter 11 trains its guiding structure on the paths of one pass and samples from it in
//! the next. Its records cannot be added to the structure from the threads as they come (the
//! floating-point sums would then depend on the schedule, and the image on the thread count),
//! and a whole pass of them may not fit in memory. So the image is rendered a slice of tiles
//! at a time, the tiles of a slice in parallel, and the caller adds each slice's records, tile
//! by tile, pixel by pixel, sample by sample, before the next slice starts.

use glam::{Vec2, Vec3};
use std::ops::Range;

use super::progress::Progress;
use super::{Budget, RenderSettings, counting_rays, tiles};
use crate::film::PixelRect;
use crate::image::Image;
use crate::sampler::Sampler;

/// Tiles rendered in parallel before their records are handed back: enough to keep the
/// cores busy, few enough that a slice's records stay small (a slice of 16 tiles at 64
/// samples per pixel and four records a path holds about a million).
const TILES_PER_SLICE: usize = 16;

/// What a recorded pass cost.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PassCost {
    /// Rays cast.
    pub rays: u64,
    /// Pixel samples taken.
    pub samples: u64,
    /// Samples whose radiance was not finite, left out of their pixel's mean (a bug upstream).
    pub nonfinite_samples: u64,
}

/// Renders samples `samples` of every pixel: `radiance(p_film, sampler, records)` gives a
/// sample's radiance and may push records; the image holds each pixel's mean (its finite
/// samples only). After each slice of tiles, `add_records` receives the slice's records in
/// tile, pixel and sample order. Returns the image and the cost, or `None` when a stop is
/// requested (the records of the slices done so far have been handed back).
pub fn render_recorded<S, R, F, A>(
    settings: &RenderSettings,
    sampler: &S,
    samples: Range<u64>,
    radiance: F,
    mut add_records: A,
) -> Option<(Image, PassCost)>
where
    S: Sampler,
    R: Send,
    F: Fn(Vec2, &mut S, &mut Vec<R>) -> Vec3 + Sync,
    A: FnMut(Vec<R>),
{
    let tiles = tiles(settings.width, settings.height);
    let mut image = Image::new(settings.width, settings.height);
    // A bar for this pass alone, however the whole render is budgeted.
    let spp = samples.end.saturating_sub(samples.start);
    let pass = RenderSettings {
        budget: Budget::Samples(spp),
        ..settings.clone()
    };
    let progress = Progress::new(&pass, tiles.len(), spp);
    let mut cost = PassCost::default();
    // The slices' tiles run on the pool the settings ask for; the records are added here,
    // on the caller's thread, between slices.
    let pool = settings.threads.map(|n| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .expect("a thread pool of the requested size")
    });
    for slice in tiles.chunks(TILES_PER_SLICE) {
        let render = || render_slice(settings, sampler, slice, &samples, &radiance, &progress);
        let done = match &pool {
            Some(pool) => pool.install(render),
            None => render(),
        }?;
        for (rect, (pixels, records, tile_cost)) in slice.iter().zip(done) {
            for (p, value) in rect.pixels().zip(pixels) {
                image.set(p.x, p.y, value);
            }
            cost.rays += tile_cost.rays;
            cost.samples += tile_cost.samples;
            cost.nonfinite_samples += tile_cost.nonfinite_samples;
            add_records(records);
        }
    }
    progress.pass_done(spp);
    progress.finish();
    Some((image, cost))
}

/// The tiles of `slice` in parallel: each pixel's mean, the records in order, the cost.
type SliceDone<R> = Vec<(Vec<Vec3>, Vec<R>, PassCost)>;

fn render_slice<S, R, F>(
    settings: &RenderSettings,
    sampler: &S,
    slice: &[PixelRect],
    samples: &Range<u64>,
    radiance: &F,
    progress: &Progress,
) -> Option<SliceDone<R>>
where
    S: Sampler,
    R: Send,
    F: Fn(Vec2, &mut S, &mut Vec<R>) -> Vec3 + Sync,
{
    use rayon::prelude::*;
    slice
        .par_iter()
        .map(|rect| {
            let mut own = sampler.clone();
            let mut records = Vec::new();
            let mut cost = PassCost::default();
            let mut pixels = Vec::with_capacity(rect.width() as usize * rect.height() as usize);
            for pixel in rect.pixels() {
                if settings.stop.is_requested() {
                    return None;
                }
                let (mut sum, mut finite) = (Vec3::ZERO, 0u64);
                for index in samples.clone() {
                    let (l, rays) = counting_rays(|| {
                        own.start_pixel_sample(pixel, index);
                        let p_film = pixel.as_vec2() + own.get_pixel_2d();
                        radiance(p_film, &mut own, &mut records)
                    });
                    cost.rays += rays;
                    cost.samples += 1;
                    if l.is_finite() {
                        sum += l;
                        finite += 1;
                    } else {
                        cost.nonfinite_samples += 1;
                    }
                }
                pixels.push(if finite > 0 {
                    sum / finite as f32
                } else {
                    Vec3::ZERO
                });
            }
            progress.tile_done(samples.end.saturating_sub(samples.start));
            Some((pixels, records, cost))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::IndependentSampler;
    use glam::UVec2;

    /// A pass whose samples record their pixel and index: the records come back in tile,
    /// pixel and sample order whatever the threads, and the image holds each pixel's mean.
    #[test]
    fn records_come_back_in_a_fixed_order_and_pixels_hold_their_mean() {
        let run = |threads| {
            let mut settings = RenderSettings::new(37, 21, 3);
            settings.threads = Some(threads);
            let mut seen = Vec::new();
            let (image, cost) = render_recorded(
                &settings,
                &IndependentSampler::new(3),
                5..8,
                |p_film: Vec2, sampler: &mut IndependentSampler, records: &mut Vec<(u32, u32)>| {
                    let pixel = p_film.floor().as_uvec2();
                    records.push((pixel.x, pixel.y));
                    Vec3::splat(sampler.get_1d())
                },
                |records| seen.extend(records),
            )
            .expect("not stopped");
            (image, cost, seen)
        };
        let (one, cost, seen) = run(1);
        let (two, _, seen_two) = run(2);
        assert_eq!(seen, seen_two, "the records' order depends on the threads");
        assert_eq!(one.pixels, two.pixels, "the image depends on the threads");
        assert_eq!(cost.samples, 37 * 21 * 3);
        assert_eq!(seen.len(), 37 * 21 * 3);
        // The first tile's first pixel, three times, then its second pixel.
        assert_eq!(&seen[..4], &[(0, 0), (0, 0), (0, 0), (1, 0)]);
        // A pixel's value is the mean of its three samples' first numbers.
        let mut sampler = IndependentSampler::new(3);
        let mean: f32 = (5..8)
            .map(|i| {
                sampler.start_pixel_sample(UVec2::new(20, 17), i);
                sampler.get_pixel_2d();
                sampler.get_1d()
            })
            .sum::<f32>()
            / 3.0;
        assert!((one.get(20, 17).x - mean).abs() < 1e-6);
    }
}
