//! Rendering by gathering: each pixel computed from the samples around it, as a formula for
//! one pixel reads, instead of each sample scattered into the pixels it reaches as
//! [`render`](super::render) does.
//!
//! Chapter 03 draws its images this way, so that its lecture's one-pixel weighted average (the
//! student's capstone) is what makes them. The machinery is here, apart from the lecture: the
//! image is cut into tiles done in parallel; each tile traces the samples of its pixels, and of
//! the border of neighbours the filter reaches, once each, and hands the pixel's gathering a
//! sampler that replays them ([`Replay`]), so that a sample is not traced again for every
//! pixel it reaches. A gathering that draws a sample differently from the render (only a wrong
//! one does) gets it traced again through the real sampler, so its image is what its code
//! really gives.

use glam::{UVec2, Vec2, Vec3};
use std::time::Instant;

use super::progress::Progress;
use super::stats::Totals;
use super::{Budget, RenderOutput, RenderSettings, RenderStats, StopFlag, counting_rays};
use crate::film::{Filter, PixelRect};
use crate::image::Image;
use crate::sampler::Sampler;

/// One pixel's value from the samples around it: what [`render_gathered`] asks of a chapter.
pub trait GatherPixel: Sync {
    /// The value of `pixel` in an image of `image_size` pixels, each taking `spp` samples
    /// numbered `0..spp`, drawn from `sampler` as the render draws them (started with
    /// `start_pixel_sample`, the pixel position first), `filter` reconstructing, and
    /// `radiance(p_film, sampler)` the radiance through a film position.
    fn pixel<S: Sampler>(
        &self,
        pixel: UVec2,
        image_size: UVec2,
        spp: u64,
        sampler: &mut S,
        filter: &dyn Filter,
        radiance: &mut dyn FnMut(Vec2, &mut S) -> Vec3,
    ) -> Vec3;
}

/// Pixels per side of the tiles gathered at a time, one tile per task. Each tile first traces
/// the samples of its pixels and of the border of neighbours its filter reaches, once each, so
/// that the pixel's gathering reads them instead of tracing a sample again for every pixel it
/// reaches; a larger tile traces its border less often.
const TILE_SIZE: u32 = 32;

/// Renders an image in which every pixel is `gather`'s value of it ([`GatherPixel::pixel`]),
/// from the samples `radiance` gives. Takes and returns what [`render`](super::render) does,
/// which scatters each sample into the film instead; with a gathering that computes the
/// film's weighted average, both give the same image.
///
/// The image is rendered whole at growing sample counts, each render from scratch, and the last
/// one completed is kept: with a sample budget at 1, 4, 16, ... samples per pixel up to the
/// budget (the earlier renders cost at most a third of the last), with a time budget at 1, 2,
/// 4, ... until the time is up. A stop keeps the last completed render, and ends the one under
/// way within a pixel's samples. Samples whose radiance is not finite
/// are counted in the statistics but, unlike the film, not left out: a pixel they reach shows
/// the bug.
pub fn render_gathered<S, F, G>(
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
    radiance: F,
    gather: &G,
) -> RenderOutput
where
    S: Sampler,
    F: Fn(Vec2, &mut S) -> Vec3 + Sync,
    G: GatherPixel,
{
    let size = UVec2::new(settings.width, settings.height);
    let tiles = tiles_of(size);
    in_growing_renders(settings, tiles.len(), |spp, progress| {
        gather_image(
            settings, &tiles, spp, sampler, filter, &radiance, gather, progress,
        )
    })
}

/// Renders an image in which every pixel is `pixel_value(pixel, spp, sampler)`: a function
/// that takes the pixel's `spp` samples itself (starting each with
/// [`Sampler::start_pixel_sample`], the position in the pixel drawn first) and returns the
/// pixel's value, each pixel from its own samples alone, as with a box filter. For an
/// estimator that is not an average of its samples' values (chapter 10's optimal
/// combination of techniques solves a small system per pixel). The budget is spent as
/// [`render_gathered`] spends it, in whole renders of growing sample counts; rays and samples
/// are counted as the other loops count them, and a pixel whose value is not finite counts
/// as one sample that is not.
pub fn render_per_pixel<S, F>(
    settings: &RenderSettings,
    sampler: &S,
    pixel_value: F,
) -> RenderOutput
where
    S: Sampler,
    F: Fn(UVec2, u64, &mut S) -> Vec3 + Sync,
{
    use rayon::prelude::*;
    let size = UVec2::new(settings.width, settings.height);
    let tiles = tiles_of(size);
    in_growing_renders(settings, tiles.len(), |spp, progress| {
        let done: Vec<(Vec<Vec3>, Totals)> = tiles
            .par_iter()
            .map(|&rect| {
                let mut own = sampler.clone();
                let mut totals = Totals::default();
                let mut pixels = Vec::with_capacity(rect.width() as usize * rect.height() as usize);
                for pixel in rect.pixels() {
                    if settings.stop.is_requested() {
                        return None;
                    }
                    let (value, rays) = counting_rays(|| pixel_value(pixel, spp, &mut own));
                    totals.rays += rays;
                    totals.samples += spp;
                    totals.nonfinite_samples += u64::from(!value.is_finite());
                    pixels.push(value);
                }
                progress.tile_done(spp);
                Some((pixels, totals))
            })
            .collect::<Option<_>>()?;
        let mut image = Image::new(size.x, size.y);
        let mut totals = Totals::default();
        for (rect, (pixels, tile_totals)) in tiles.iter().zip(&done) {
            for (p, &value) in rect.pixels().zip(pixels) {
                image.set(p.x, p.y, value);
            }
            totals.add(tile_totals);
        }
        Some((image, totals))
    })
}

/// The budget loop of [`render_gathered`] and [`render_per_pixel`]: whole renders of the
/// image (`render(spp, progress)`, `None` when stopped) at growing sample counts, each from
/// scratch, the last one completed kept, so that a stop loses no more than the render under
/// way: with a sample budget at 1, 4, 16, ... samples per pixel up to the budget (the earlier
/// renders cost at most a third of the last), with a time budget at 1, 2, 4, ... until the
/// time is up.
fn in_growing_renders<R>(settings: &RenderSettings, tiles: usize, render: R) -> RenderOutput
where
    R: Fn(u64, &Progress) -> Option<(Image, Totals)> + Sync,
{
    let start = Instant::now();
    let planned_spp = match settings.budget {
        Budget::Samples(target) => std::iter::successors(Some(1), |&spp| {
            (spp < target).then(|| next_spp(spp, target))
        })
        .sum(),
        Budget::Seconds(_) => 0,
    };
    let progress = Progress::new(settings, tiles, planned_spp);
    let gather = |spp| {
        let done = render(spp, &progress);
        progress.pass_done(spp);
        done
    };
    // Whole renders of growing sample counts, each from scratch; the last one completed is
    // kept, so a stop loses no more than the render under way.
    let run = || {
        let mut kept = None;
        let mut kept_spp = 0;
        let mut spp = 1u64;
        loop {
            let Some(done) = gather(spp) else {
                break (kept, kept_spp, true);
            };
            kept = Some(done);
            kept_spp = spp;
            match settings.budget {
                Budget::Samples(target) => {
                    if spp >= target {
                        break (kept, kept_spp, false);
                    }
                    spp = next_spp(spp, target);
                }
                // Twice the samples each time, until the time is up.
                Budget::Seconds(seconds) => {
                    let elapsed = start.elapsed().as_secs_f64();
                    if elapsed.is_nan() || elapsed >= seconds {
                        break (kept, kept_spp, false);
                    }
                    spp = spp.saturating_mul(2);
                }
            }
        }
    };
    let (done, spp, interrupted) = match settings.threads {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .expect("a thread pool of the requested size")
            .install(run),
        None => run(),
    };
    progress.finish();
    let (image, totals) = done.unwrap_or_else(|| {
        (
            Image::new(settings.width, settings.height),
            Totals::default(),
        )
    });
    let seconds = start.elapsed().as_secs_f64();
    let stats = RenderStats::new(settings, spp, interrupted, seconds, &totals);
    RenderOutput { image, stats }
}

/// The samples per pixel of the render after one of `spp`, under a budget of `target`: four
/// times as many, so that the renders before the last cost a third of it at most.
fn next_spp(spp: u64, target: u64) -> u64 {
    spp.saturating_mul(4).min(target)
}

/// The tiles of an image of `size`, row by row.
fn tiles_of(size: UVec2) -> Vec<PixelRect> {
    (0..size.y)
        .step_by(TILE_SIZE as usize)
        .flat_map(|y| {
            (0..size.x)
                .step_by(TILE_SIZE as usize)
                .map(move |x| PixelRect {
                    min: UVec2::new(x, y),
                    max: (UVec2::new(x, y) + TILE_SIZE).min(size),
                })
        })
        .collect()
}

/// Every pixel of the image gathered with `spp` samples per pixel, tiles in parallel; `None`
/// when a stop is requested before it is done.
#[allow(clippy::too_many_arguments)]
fn gather_image<S, F, G>(
    settings: &RenderSettings,
    tiles: &[PixelRect],
    spp: u64,
    sampler: &S,
    filter: &dyn Filter,
    radiance: &F,
    gather: &G,
    progress: &Progress,
) -> Option<(Image, Totals)>
where
    S: Sampler,
    F: Fn(Vec2, &mut S) -> Vec3 + Sync,
    G: GatherPixel,
{
    use rayon::prelude::*;
    let size = UVec2::new(settings.width, settings.height);
    let gathered: Vec<(Vec<Vec3>, Totals)> = tiles
        .par_iter()
        .map(|&rect| {
            let done = gather_tile(
                rect,
                size,
                spp,
                sampler,
                filter,
                radiance,
                gather,
                &settings.stop,
            );
            progress.tile_done(spp);
            done
        })
        .collect::<Option<_>>()?;
    let mut image = Image::new(size.x, size.y);
    let mut totals = Totals::default();
    for (rect, (pixels, tile_totals)) in tiles.iter().zip(&gathered) {
        for (p, &value) in rect.pixels().zip(pixels) {
            image.set(p.x, p.y, value);
        }
        totals.add(tile_totals);
    }
    Some((image, totals))
}

/// The pixels of `rect`, row by row, each `gather`'s. The samples of `rect` and of the border
/// its filter reaches are traced first, once each, and the gathering is handed a sampler that
/// replays them ([`Replay`]). Only the samples of `rect` itself are counted, so
/// that every sample of the image is counted once.
#[allow(clippy::too_many_arguments)]
fn gather_tile<S, F, G>(
    rect: PixelRect,
    size: UVec2,
    spp: u64,
    sampler: &S,
    filter: &dyn Filter,
    radiance: &F,
    gather: &G,
    stop: &StopFlag,
) -> Option<(Vec<Vec3>, Totals)>
where
    S: Sampler,
    F: Fn(Vec2, &mut S) -> Vec3 + Sync,
    G: GatherPixel,
{
    if stop.is_requested() {
        return None;
    }
    // A sample of pixel q lies in [q, q + 1), so it can reach the centre of a pixel of `rect`
    // only from ceil(radius - 1/2) pixels away or nearer, as the film's tiles reckon it.
    let radius = filter.radius();
    let reach = |r: f32| (r - 0.5).max(0.0).ceil().min(u32::MAX as f32) as u32;
    let reach = UVec2::new(reach(radius.x), reach(radius.y));
    let border = PixelRect {
        min: rect.min.saturating_sub(reach),
        max: rect.max.saturating_add(reach).min(size),
    };
    let mut tracer = sampler.clone();
    let mut totals = Totals::default();
    let mut traced = Vec::with_capacity(border.width() as usize * border.height() as usize);
    for q in border.pixels() {
        if stop.is_requested() {
            return None;
        }
        let own = q.cmpge(rect.min).all() && q.cmplt(rect.max).all();
        for index in 0..spp {
            tracer.start_pixel_sample(q, index);
            let offset = tracer.get_pixel_2d();
            let p_film = q.as_vec2() + offset;
            let (l, rays) = counting_rays(|| radiance(p_film, &mut tracer));
            if own {
                totals.rays += rays;
                totals.samples += 1;
                totals.nonfinite_samples += u64::from(!l.is_finite());
            }
            traced.push((offset, l));
        }
    }
    let mut replay = Replay {
        traced: &traced,
        border,
        spp,
        inner: sampler.clone(),
        current: None,
        positions_drawn: 0,
        inner_started: false,
    };
    let pixels = rect
        .pixels()
        .map(|pixel| {
            if stop.is_requested() {
                return None;
            }
            let mut traced = |p_film: Vec2, replay: &mut Replay<S>| {
                match replay.traced_radiance(p_film) {
                    Some(l) => l,
                    // Any other sample (one beyond the border, of a pixel outside the image, or
                    // looked at from elsewhere than where it lies) is traced now, from the
                    // numbers the render would give it.
                    None => radiance(p_film, replay.inner()),
                }
            };
            Some(gather.pixel(pixel, size, spp, &mut replay, filter, &mut traced))
        })
        .collect::<Option<_>>()?;
    Some((pixels, totals))
}

/// The sampler the gathering is handed by the render: the samples of `border` were traced
/// already, so it answers a sample's first pixel position from `traced` and leaves the real
/// sampler `inner` alone. Anything else (a second position, a further number, a sample beyond
/// the border) starts `inner` on the sample and replays the numbers drawn so far, so that
/// every answer is the one the real sampler would give.
#[derive(Clone, Debug)]
struct Replay<'a, S> {
    /// Position in its pixel and radiance of sample `k` of pixel `q` of `border`, row by row,
    /// `spp` samples per pixel.
    traced: &'a [(Vec2, Vec3)],
    border: PixelRect,
    spp: u64,
    inner: S,
    /// The sample started last.
    current: Option<(UVec2, u64)>,
    /// Pixel positions drawn since that start.
    positions_drawn: u32,
    /// Whether `inner` has been started on `current` and has drawn what was drawn since.
    inner_started: bool,
}

impl<S: Sampler> Replay<'_, S> {
    /// The traced position in its pixel and radiance of the current sample, if it was traced.
    fn traced(&self) -> Option<(Vec2, Vec3)> {
        let (q, index) = self.current?;
        let inside = q.cmpge(self.border.min).all() && q.cmplt(self.border.max).all();
        if !inside || index >= self.spp {
            return None;
        }
        let q = q - self.border.min;
        let slot = (q.y as usize * self.border.width() as usize + q.x as usize) * self.spp as usize
            + index as usize;
        Some(self.traced[slot])
    }

    /// The traced radiance of the current sample, if its position was drawn once and is
    /// `p_film`, and nothing else was drawn.
    fn traced_radiance(&self, p_film: Vec2) -> Option<Vec3> {
        if self.inner_started || self.positions_drawn != 1 {
            return None;
        }
        let (q, _) = self.current?;
        let (offset, l) = self.traced()?;
        (q.as_vec2() + offset == p_film).then_some(l)
    }

    /// The real sampler, brought to where the calls so far have left the current sample.
    fn inner(&mut self) -> &mut S {
        if !self.inner_started {
            if let Some((q, index)) = self.current {
                self.inner.start_pixel_sample(q, index);
                for _ in 0..self.positions_drawn {
                    self.inner.get_pixel_2d();
                }
            }
            self.inner_started = true;
        }
        &mut self.inner
    }
}

impl<S: Sampler> Sampler for Replay<'_, S> {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.current = Some((pixel, sample_index));
        self.positions_drawn = 0;
        self.inner_started = false;
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        if !self.inner_started
            && self.positions_drawn == 0
            && let Some((offset, _)) = self.traced()
        {
            self.positions_drawn = 1;
            return offset;
        }
        self.positions_drawn += 1;
        self.inner().get_pixel_2d()
    }

    fn get_1d(&mut self) -> f32 {
        self.inner().get_1d()
    }

    fn get_2d(&mut self) -> Vec2 {
        self.inner().get_2d()
    }
}
