//! The render loop: tiles in parallel, passes until the budget is spent.
//!
//! A chapter supplies one function, "the radiance arriving through this film position", and
//! the loop does the rest: it splits the image into tiles, renders them on a rayon pool, starts
//! each sample's [`Sampler`] stream, adds the result to the [`Film`] and counts rays.
//!
//! Rays are counted where they are cast: a world calls [`count_ray`] once for every query it
//! answers (a nearest hit or a shadow test), on the thread that casts it, and the loop reads
//! that count around each sample ([`counting_rays`]). pbrt-v4 counts its rays the same way,
//! with a statistics counter outside the integrator's arguments, so the tracers pass none.
//!
//! The work is done in passes of growing sample counts. Each pass is merged into the film
//! tile by tile in a fixed order, so the image depends only on the seed and the pass schedule,
//! never on the number of threads. A `--time` budget simply keeps adding passes until the time
//! is up. A [`StopFlag`] set during a render (Ctrl-C in the binaries) ends it early with the
//! image of the passes completed so far.

mod budget;
mod gather;
mod progress;
mod recorded;
mod stats;
mod stop;

pub use budget::Budget;
pub use gather::{GatherPixel, render_gathered, render_per_pixel};
pub use recorded::{PassCost, render_recorded};
pub use stats::{RenderStats, Totals};
pub use stop::StopFlag;

use crate::film::{Film, FilmTile, Filter, PixelRect};
use crate::image::Image;
use crate::sampler::Sampler;
use glam::{UVec2, Vec2, Vec3};
use std::cell::Cell;
use std::time::Instant;

/// What a render needs besides the scene.
#[derive(Clone, Debug)]
pub struct RenderSettings {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// How many samples per pixel, or how long.
    pub budget: Budget,
    /// Worker threads; `None` lets rayon choose (one per core).
    pub threads: Option<usize>,
    /// Show a progress bar on a terminal.
    pub progress: bool,
    /// Set it to stop the render early; the image then holds the passes completed.
    pub stop: StopFlag,
}

impl RenderSettings {
    /// `width x height` pixels at `spp` samples per pixel, quietly, on every core.
    pub fn new(width: u32, height: u32, spp: u64) -> Self {
        Self {
            width,
            height,
            budget: Budget::Samples(spp),
            threads: None,
            progress: false,
            stop: StopFlag::new(),
        }
    }
}

thread_local! {
    /// Rays cast on this thread so far: camera rays, secondary rays and shadow rays.
    static RAYS_CAST: Cell<u64> = const { Cell::new(0) };
}

/// Counts one ray cast on this thread. A world calls it once per query it answers, so that
/// every ray of a render is counted once, however the tracer reached it.
#[inline]
pub fn count_ray() {
    RAYS_CAST.set(RAYS_CAST.get() + 1);
}

/// What `cast` returns, and the rays it cast on this thread ([`count_ray`]). A count inside
/// `cast` keeps its rays to itself: a thread that waits for the pool in the middle of a sample
/// may render another tile meanwhile, and that tile's rays are its own.
pub fn counting_rays<T>(cast: impl FnOnce() -> T) -> (T, u64) {
    let outer = RAYS_CAST.replace(0);
    let out = cast();
    let rays = RAYS_CAST.replace(outer);
    (out, rays)
}

/// A finished render, or the completed passes of an interrupted one
/// ([`RenderStats::interrupted`]).
#[derive(Clone, Debug)]
pub struct RenderOutput {
    /// The averaged image: every pixel holds [`RenderStats::spp`] samples.
    pub image: Image,
    /// What it cost.
    pub stats: RenderStats,
}

/// Pixels per tile side: large enough to amortise the bookkeeping, small enough that two
/// cores share even a thumbnail fairly.
const TILE_SIZE: u32 = 16;

/// Renders an image.
///
/// `radiance(p_film, sampler)` returns the radiance arriving through the continuous
/// film position `p_film` (in pixels, `y` down). The sampler has already handed out the
/// pixel dimension used for `p_film`; the function draws its own dimensions after it, in the
/// fixed order time, lens, then per bounce.
// ANCHOR: render_loop
pub fn render<S, F>(
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
    radiance: F,
) -> RenderOutput
where
    S: Sampler,
    F: Fn(Vec2, &mut S) -> Vec3 + Sync,
{
    let start = Instant::now();
    let mut film = Film::new(settings.width, settings.height);
    let tiles = tiles(settings.width, settings.height);
    let planned_spp = match settings.budget {
        Budget::Samples(spp) => spp,
        Budget::Seconds(_) => 0,
    };
    let progress = progress::Progress::new(settings, tiles.len(), planned_spp);
    let mut totals = stats::Totals::default();

    let stop = &settings.stop;

    let mut run = || {
        let mut done_spp = 0u64;
        let mut interrupted = false;
        while let Some(pass) = settings.budget.next_pass(done_spp, start.elapsed()) {
            let samples = done_spp..done_spp + pass;
            // `None` as soon as one tile saw the stop flag: the pass is then incomplete, and
            // it is dropped whole so that every pixel keeps the same number of samples.
            let rendered: Option<Vec<(FilmTile, stats::Totals)>> = {
                use rayon::prelude::*;
                tiles
                    .par_iter()
                    .map(|&rect| {
                        let out = render_tile(
                            &film,
                            rect,
                            samples.clone(),
                            sampler,
                            filter,
                            &radiance,
                            stop,
                        );
                        progress.tile_done(pass);
                        out
                    })
                    .collect()
            };
            let Some(rendered) = rendered else {
                interrupted = true;
                break;
            };
            // Merge in tile order: floating-point sums then come out the same on any schedule.
            for (tile, tile_totals) in &rendered {
                film.merge(tile);
                totals.add(tile_totals);
            }
            done_spp += pass;
            progress.pass_done(done_spp);
        }
        (done_spp, interrupted)
    };
    let (spp, interrupted) = match settings.threads {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .expect("a thread pool of the requested size")
            .install(run),
        None => run(),
    };
    progress.finish();
    let seconds = start.elapsed().as_secs_f64();
    RenderOutput {
        image: film.image(),
        stats: RenderStats::new(settings, spp, interrupted, seconds, &totals),
    }
}
// ANCHOR_END: render_loop

/// Renders samples `samples` of every pixel of `rect` into a fresh tile, or `None` when
/// `stop` is requested before it is done (checked per pixel, so a stop is prompt even in a
/// pass of many samples).
fn render_tile<S, F>(
    film: &Film,
    rect: PixelRect,
    samples: std::ops::Range<u64>,
    sampler: &S,
    filter: &dyn Filter,
    radiance: &F,
    stop: &StopFlag,
) -> Option<(FilmTile, stats::Totals)>
where
    S: Sampler,
    F: Fn(Vec2, &mut S) -> Vec3 + Sync,
{
    let mut tile = film.tile(rect, filter);
    let mut sampler = sampler.clone();
    let mut totals = stats::Totals::default();
    for pixel in rect.pixels() {
        if stop.is_requested() {
            return None;
        }
        for index in samples.clone() {
            let ((p_film, l), rays) =
                counting_rays(|| trace_pixel_sample(&mut sampler, pixel, index, radiance));
            totals.rays += rays;
            totals.samples += 1;
            if l.is_finite() {
                tile.add_sample(p_film, l, filter);
            } else {
                // A NaN or infinity is a bug upstream. It is counted and reported, never
                // averaged into the image where it would blacken or whiten a whole pixel.
                totals.nonfinite_samples += 1;
            }
        }
    }
    Some((tile, totals))
}

/// Sample `index` of `pixel`: the sampler starts the sample, its first dimension places it in
/// the pixel, and `radiance` draws the rest. Gives the film position and the radiance. The
/// render loop takes every sample this way, and so do the book's live demos, a slice at a time.
pub fn trace_pixel_sample<S, F>(
    sampler: &mut S,
    pixel: UVec2,
    index: u64,
    radiance: &F,
) -> (Vec2, Vec3)
where
    S: Sampler,
    F: Fn(Vec2, &mut S) -> Vec3,
{
    sampler.start_pixel_sample(pixel, index);
    let p_film = pixel.as_vec2() + sampler.get_pixel_2d();
    (p_film, radiance(p_film, sampler))
}

/// The image cut into tiles, row by row.
fn tiles(width: u32, height: u32) -> Vec<PixelRect> {
    let mut out = Vec::new();
    for y in (0..height).step_by(TILE_SIZE as usize) {
        for x in (0..width).step_by(TILE_SIZE as usize) {
            out.push(PixelRect {
                min: UVec2::new(x, y),
                max: UVec2::new((x + TILE_SIZE).min(width), (y + TILE_SIZE).min(height)),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::film::PixelBoxFilter;
    use crate::sampler::IndependentSampler;

    /// A "scene" whose radiance is a noisy function of the film position.
    fn noisy(p: Vec2, s: &mut IndependentSampler) -> Vec3 {
        count_ray();
        Vec3::new(p.x.sin(), s.get_1d(), (p.y * 0.1).cos() * s.get_1d())
    }

    #[test]
    fn images_are_identical_with_any_thread_count() {
        let render_with = |threads| {
            let settings = RenderSettings {
                threads: Some(threads),
                ..RenderSettings::new(37, 21, 5)
            };
            render(
                &settings,
                &IndependentSampler::new(3),
                &PixelBoxFilter,
                noisy,
            )
        };
        let one = render_with(1);
        for threads in [2, 3, 8] {
            let many = render_with(threads);
            assert_eq!(one.image, many.image, "{threads} threads");
        }
        assert_eq!(one.stats.rays, 37 * 21 * 5);
        assert_eq!(one.stats.spp, 5);
    }

    #[test]
    fn non_finite_samples_are_counted_and_kept_out_of_the_image() {
        let settings = RenderSettings::new(4, 4, 2);
        let out = render(
            &settings,
            &IndependentSampler::new(1),
            &PixelBoxFilter,
            |p, _: &mut IndependentSampler| {
                if p.x < 1.0 { Vec3::NAN } else { Vec3::ONE }
            },
        );
        assert_eq!(out.stats.nonfinite_samples, 4 * 2);
        assert!(out.image.pixels.iter().all(|p| p.is_finite()));
        assert_eq!(out.image.get(2, 2), Vec3::ONE);
    }

    #[test]
    fn a_time_budget_renders_at_least_one_pass() {
        let settings = RenderSettings {
            budget: Budget::Seconds(1e-9),
            ..RenderSettings::new(3, 3, 1)
        };
        let out = render(
            &settings,
            &IndependentSampler::new(1),
            &PixelBoxFilter,
            noisy,
        );
        assert!(out.stats.spp >= 1);
    }

    /// A stop requested in the middle of the fourth pass (passes of 1, 1, 2, 4, ... samples)
    /// leaves exactly the image of the first three: 4 samples per pixel, bit for bit the same
    /// as a render asked for 4.
    #[test]
    fn a_stop_mid_render_keeps_exactly_the_completed_passes() {
        use std::sync::atomic::{AtomicU64, Ordering};
        let (width, height) = (40, 24);
        let pixels = u64::from(width * height);
        let stop = StopFlag::new();
        let calls = AtomicU64::new(0);
        let settings = RenderSettings {
            stop: stop.clone(),
            threads: Some(2),
            ..RenderSettings::new(width, height, 1000)
        };
        let out = render(
            &settings,
            &IndependentSampler::new(7),
            &PixelBoxFilter,
            |p, s: &mut IndependentSampler| {
                if calls.fetch_add(1, Ordering::Relaxed) == 4 * pixels + pixels / 2 {
                    stop.request();
                }
                noisy(p, s)
            },
        );
        assert!(out.stats.interrupted);
        assert_eq!(out.stats.spp, 4);
        assert_eq!(out.stats.requested_spp, Some(1000));
        assert_eq!(
            out.stats.samples,
            4 * pixels,
            "the broken pass is not counted"
        );
        assert!(
            calls.load(Ordering::Relaxed) < 8 * pixels,
            "the fourth pass was not cut short"
        );
        let four = render(
            &RenderSettings::new(width, height, 4),
            &IndependentSampler::new(7),
            &PixelBoxFilter,
            noisy,
        );
        assert!(!four.stats.interrupted);
        assert_eq!(out.image, four.image);
    }

    #[test]
    fn a_stop_before_the_first_pass_leaves_no_samples() {
        let settings = RenderSettings::new(8, 8, 16);
        settings.stop.request();
        let out = render(
            &settings,
            &IndependentSampler::new(1),
            &PixelBoxFilter,
            noisy,
        );
        assert!(out.stats.interrupted);
        assert_eq!((out.stats.spp, out.stats.samples), (0, 0));
    }

    #[test]
    fn tiles_cover_the_image_once() {
        let tiles = tiles(40, 17);
        let mut covered = vec![0u32; 40 * 17];
        for t in &tiles {
            for p in t.pixels() {
                covered[(p.y * 40 + p.x) as usize] += 1;
            }
        }
        assert!(covered.iter().all(|&c| c == 1));
    }
}
