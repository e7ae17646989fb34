use super::*;
use crate::filters::{FilterKind, ReconstructionFilter};
use crate::pixel_samplers::{PixelSampler, PixelSamplerKind};
use common::image::Image;
use common::render::{self, RenderSettings};
use glam::DVec3;
use std::sync::{Arc, Mutex};

const EXERCISE: &str = "ch03-filtered-pixel";

/// A small picture with edges in every direction and colour everywhere, so that every slip in
/// the weights shows: a bright disc, a dark band, a ramp. The radiance also uses the sample's
/// next number, as a lens or a time would, so the numbers must be drawn in the render's order.
fn radiance<S: Sampler>(p: Vec2, sampler: &mut S) -> Vec3 {
    let disc = if p.distance(Vec2::new(5.3, 4.1)) < 2.6 {
        2.0
    } else {
        0.0
    };
    let band = if (p.x + 0.6 * p.y - 9.0).abs() < 0.7 {
        0.1
    } else {
        1.0
    };
    let ramp = Vec3::new(0.2 + p.x / 12.0, 0.3 + p.y / 9.0, 0.5);
    (ramp + Vec3::splat(disc)) * band * (0.75 + 0.5 * sampler.get_1d())
}

/// What `filtered_pixel` asked of its sampler, in order.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Call {
    Start(UVec2, u64),
    Position,
    Number,
}

/// A sampler that writes down every call before answering it as `inner` does, so that the
/// check can say when the samples are not drawn as the render draws them.
#[derive(Clone, Debug)]
struct Watched<S> {
    inner: S,
    calls: Arc<Mutex<Vec<Call>>>,
}

impl<S: Sampler> Sampler for Watched<S> {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.calls
            .lock()
            .unwrap()
            .push(Call::Start(pixel, sample_index));
        self.inner.start_pixel_sample(pixel, sample_index);
    }

    fn get_pixel_2d(&mut self) -> Vec2 {
        self.calls.lock().unwrap().push(Call::Position);
        self.inner.get_pixel_2d()
    }

    fn get_1d(&mut self) -> f32 {
        self.calls.lock().unwrap().push(Call::Number);
        self.inner.get_1d()
    }
}

/// What is wrong with the way `calls` drew the samples of an image of `size` pixels with `spp`
/// samples each, in words; `None` if each sample was started, then placed, then given its
/// further numbers, as the render does.
fn drawing_mistake(calls: &[Call], size: UVec2, spp: u64) -> Option<String> {
    let (mut started, mut placed) = (false, false);
    for &call in calls {
        match call {
            Call::Start(pixel, index) => {
                if pixel.x >= size.x || pixel.y >= size.y {
                    return Some(format!(
                        "it drew sample {index} of pixel {pixel}, outside the {} x {} image: \
                         pixels outside the image take no samples, so only the pixels of the \
                         image can reach this one",
                        size.x, size.y
                    ));
                }
                if index >= spp {
                    return Some(format!(
                        "it drew sample {index} of pixel {pixel}: every pixel takes {spp} \
                         samples, numbered 0..{spp}"
                    ));
                }
                (started, placed) = (true, false);
            }
            Call::Position | Call::Number if !started => {
                return Some(
                    "it drew numbers from the sampler before starting a sample: each sample \
                     begins with sampler.start_pixel_sample(q, k), which says which sample of \
                     which pixel it is, and so where it lies"
                        .to_string(),
                );
            }
            Call::Position if placed => {
                return Some(
                    "it drew two pixel positions after one start_pixel_sample: each sample is \
                     started anew, and its position is its first number"
                        .to_string(),
                );
            }
            Call::Position => placed = true,
            Call::Number if !placed => {
                return Some(
                    "the radiance drew its numbers from a sample whose pixel position was not \
                     drawn first (or that was started again after it): as in the render, a \
                     sample's position is its first number and the radiance's numbers follow \
                     it"
                    .to_string(),
                );
            }
            Call::Number => {}
        }
    }
    None
}

/// The usual slips, each a way of computing a pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Slip {
    NotDivided,
    DividedByCount,
    FilterAtPosition,
    CentreAtCorner,
    OwnSamplesOnly,
    PositionWithoutPixel,
}

impl Slip {
    const ALL: [Slip; 6] = [
        Slip::NotDivided,
        Slip::DividedByCount,
        Slip::FilterAtPosition,
        Slip::CentreAtCorner,
        Slip::OwnSamplesOnly,
        Slip::PositionWithoutPixel,
    ];

    fn says(self) -> &'static str {
        match self {
            Slip::NotDivided => {
                "the weighted sum is not divided by the sum of the weights: without it the \
                 weights do not sum to one, and the image is as bright as the weights are large"
            }
            Slip::DividedByCount => {
                "the weighted sum is divided by the number of samples, not by the sum of their \
                 weights: with any filter but the box the weights do not sum to one then"
            }
            Slip::FilterAtPosition => {
                "the filter is evaluated at the sample's position in the film, not at its offset \
                 from the pixel's centre"
            }
            Slip::CentreAtCorner => {
                "the offsets are measured from the pixel's corner: its centre is half a pixel \
                 further in, at (i + 0.5, j + 0.5)"
            }
            Slip::OwnSamplesOnly => {
                "only the pixel's own samples are counted: a filter wider than half a pixel also \
                 reaches samples that neighbouring pixels drew"
            }
            Slip::PositionWithoutPixel => {
                "the sample's film position is its position inside its pixel only: the pixel's \
                 corner has to be added"
            }
        }
    }
}

/// The pixel as the slip `slip` computes it (a plain gather, not the student's).
fn with_slip<S: Sampler>(
    slip: Slip,
    pixel: UVec2,
    size: UVec2,
    spp: u64,
    sampler: &mut S,
    filter: &dyn Filter,
) -> Vec3 {
    let centre = pixel.as_vec2() + 0.5;
    let reach = if slip == Slip::OwnSamplesOnly {
        0
    } else {
        filter.radius().max_element().ceil() as i64 + 1
    };
    let (mut sum, mut weights, mut count) = (DVec3::ZERO, 0.0f64, 0u32);
    for dy in -reach..=reach {
        for dx in -reach..=reach {
            let (x, y) = (i64::from(pixel.x) + dx, i64::from(pixel.y) + dy);
            if x < 0 || y < 0 || x >= i64::from(size.x) || y >= i64::from(size.y) {
                continue;
            }
            let q = UVec2::new(x as u32, y as u32);
            for index in 0..spp {
                sampler.start_pixel_sample(q, index);
                let inside = sampler.get_pixel_2d();
                let p = if slip == Slip::PositionWithoutPixel {
                    inside
                } else {
                    q.as_vec2() + inside
                };
                let offset = match slip {
                    Slip::FilterAtPosition => p,
                    Slip::CentreAtCorner => p - pixel.as_vec2(),
                    _ => p - centre,
                };
                let w = f64::from(filter.evaluate(offset));
                if w == 0.0 {
                    continue;
                }
                sum += w * radiance(p, sampler).as_dvec3();
                weights += w;
                count += 1;
            }
        }
    }
    let value = match slip {
        Slip::NotDivided => sum,
        Slip::DividedByCount if count > 0 => sum / f64::from(count),
        _ if weights != 0.0 => sum / weights,
        _ => DVec3::ZERO,
    };
    value.as_vec3()
}

fn close(a: Vec3, b: Vec3) -> bool {
    a.is_finite() && (a - b).abs().max_element() <= 1e-4 * (1.0 + b.abs().max_element())
}

/// Renders the picture with the film (common's render loop, which scatters every sample), and
/// gathers every pixel with `filtered_pixel`; says what is wrong if they differ.
fn check(kind: PixelSamplerKind, spp: u64, filter: ReconstructionFilter) {
    let size = UVec2::new(12, 9);
    let sampler = PixelSampler::new(kind, spp, 7).unwrap();
    let settings = RenderSettings::new(size.x, size.y, spp);
    let expected = render::render(&settings, &sampler, &filter, radiance).image;
    let mut mine = Image::new(size.x, size.y);
    let mut first_wrong = None;
    let calls = Arc::new(Mutex::new(Vec::new()));
    let mut drawing = None;
    for y in 0..size.y {
        for x in 0..size.x {
            let pixel = UVec2::new(x, y);
            let mut watched = Watched {
                inner: sampler.clone(),
                calls: Arc::clone(&calls),
            };
            let got = workbench::test_support::catch_panic(|| {
                filtered_pixel(pixel, size, spp, &mut watched, &filter, radiance)
            })
            .unwrap_or_else(|message| {
                panic!(
                    "filtered_pixel panicked at pixel {pixel} of a {} x {} image ({message}){}",
                    size.x,
                    size.y,
                    if message.contains("subtract with overflow") {
                        ": pixel coordinates are unsigned, and near the top or left edge of the \
                         image a neighbour's coordinate below 0 does not exist; keep the range \
                         of neighbours inside the image before you subtract (or work in signed \
                         or float coordinates)"
                    } else {
                        ""
                    }
                )
            });
            let calls = std::mem::take(&mut *calls.lock().unwrap());
            drawing = drawing.or_else(|| drawing_mistake(&calls, size, spp));
            mine.set(x, y, got);
            if first_wrong.is_none() && !close(got, expected.get(x, y)) {
                first_wrong = Some(pixel);
            }
        }
    }
    let Some(pixel) = first_wrong else {
        return;
    };
    if let Some(drawing) = drawing {
        panic!(
            "filtered_pixel: {drawing}.\n  {kind:?} samples, {spp} per pixel, {filter:?}: pixel \
             {pixel} gave {}, the film gives {}; {}",
            mine.get(pixel.x, pixel.y),
            expected.get(pixel.x, pixel.y),
            workbench::test_support::image_comparison(EXERCISE, &mine, &expected)
        );
    }
    // Which slip gives the student's image? Judged on the pixels that are wrong (a slip may
    // reach a few pixels differently, depending on which neighbours are visited).
    let wrong: Vec<UVec2> = (0..size.y)
        .flat_map(|y| (0..size.x).map(move |x| UVec2::new(x, y)))
        .filter(|p| !close(mine.get(p.x, p.y), expected.get(p.x, p.y)))
        .collect();
    let slip = Slip::ALL
        .into_iter()
        .map(|slip| {
            let matching = wrong
                .iter()
                .filter(|p| {
                    let theirs = with_slip(slip, **p, size, spp, &mut sampler.clone(), &filter);
                    close(mine.get(p.x, p.y), theirs)
                })
                .count();
            (slip, matching)
        })
        .max_by_key(|&(_, matching)| matching)
        .filter(|&(_, matching)| matching * 10 >= wrong.len() * 9)
        .map(|(slip, _)| slip);
    let mistake = match slip {
        Some(slip) => slip.says().to_string(),
        None if !mine.get(pixel.x, pixel.y).is_finite() => "the value is not a number".to_string(),
        None => "the pixel should be the weighted average of the radiance of every sample the \
                 filter reaches, each weighted by the filter at its offset from the pixel's \
                 centre, with the samples drawn as the render draws them (pixel position first, \
                 then the radiance's own numbers)"
            .to_string(),
    };
    panic!(
        "filtered_pixel: {mistake}.\n  {kind:?} samples, {spp} per pixel, {filter:?}: pixel \
         {pixel} gave {}, the film gives {}; {}",
        mine.get(pixel.x, pixel.y),
        expected.get(pixel.x, pixel.y),
        workbench::test_support::image_comparison(EXERCISE, &mine, &expected)
    );
}

fn filter(kind: FilterKind, radius: Option<f32>) -> ReconstructionFilter {
    ReconstructionFilter::new(kind, radius).unwrap()
}

#[test]
fn exercise_filtered_pixel_box_is_the_plain_average() {
    check(
        PixelSamplerKind::Stratified,
        9,
        filter(FilterKind::Box, None),
    );
    check(PixelSamplerKind::Random, 4, filter(FilterKind::Box, None));
}

#[test]
fn exercise_filtered_pixel_wide_filters_reach_the_neighbours() {
    check(PixelSamplerKind::Random, 4, filter(FilterKind::Tent, None));
    check(
        PixelSamplerKind::Halton,
        8,
        filter(FilterKind::Tent, Some(1.5)),
    );
    check(
        PixelSamplerKind::Stratified,
        4,
        filter(FilterKind::Gaussian, None),
    );
    check(
        PixelSamplerKind::Halton,
        6,
        filter(FilterKind::Mitchell, None),
    );
}

#[test]
fn exercise_filtered_pixel_unreached_pixels_are_black() {
    // A box far narrower than a pixel: many pixels get no sample with any weight.
    check(
        PixelSamplerKind::Random,
        2,
        filter(FilterKind::Box, Some(0.1)),
    );
    // Mitchell squeezed to one pixel: weights of both signs, some pixels' sums cancel.
    check(
        PixelSamplerKind::Stratified,
        4,
        filter(FilterKind::Mitchell, Some(1.0)),
    );
}

/// The chapter's render draws every pixel with `filtered_pixel`: a tiny render of the test's
/// picture through the chapter's render loop ([`super::render`], which `crate::render_with`
/// calls with chapter 01's tracer), for three samplers and filters, against the same render
/// through the film, which scatters every sample. Writes both images and their difference when
/// they differ.
#[test]
fn exercise_filtered_pixel_draws_the_chapter_images() {
    let size = UVec2::new(24, 16);
    for (kind, spp, filter) in [
        (
            PixelSamplerKind::Stratified,
            4,
            filter(FilterKind::Box, None),
        ),
        (PixelSamplerKind::Random, 3, filter(FilterKind::Tent, None)),
        (
            PixelSamplerKind::Halton,
            4,
            filter(FilterKind::Mitchell, None),
        ),
    ] {
        let settings = RenderSettings::new(size.x, size.y, spp);
        let sampler = PixelSampler::new(kind, spp, 5).unwrap();
        let expected = render::render(&settings, &sampler, &filter, radiance).image;
        let mine = workbench::test_support::catch_panic(|| {
            super::render(&settings, &sampler, &filter, radiance).image
        })
        .unwrap_or_else(|message| {
            panic!(
                "the chapter's render panicked in filtered_pixel ({message}); it draws every \
                 pixel of a {} x {} image with it",
                size.x, size.y
            )
        });
        let wrong: Vec<UVec2> = (0..size.y)
            .flat_map(|y| (0..size.x).map(move |x| UVec2::new(x, y)))
            .filter(|p| !close(mine.get(p.x, p.y), expected.get(p.x, p.y)))
            .collect();
        if let Some(&pixel) = wrong.first() {
            panic!(
                "filtered_pixel draws the chapter's images, and a render of the test's \
                 picture ({kind:?} samples, {spp} per pixel, {filter:?}) came out wrong at {} \
                 of its {} pixels: pixel {pixel} is {}, the film gives {}. The checks above name the likely \
                 slip; {}",
                wrong.len(),
                size.x * size.y,
                mine.get(pixel.x, pixel.y),
                expected.get(pixel.x, pixel.y),
                workbench::test_support::image_comparison(EXERCISE, &mine, &expected)
            );
        }
    }
}

/// The gathered render is the film's render bit for bit, image and ray count, for every sampler
/// and filter, on any number of threads.
#[test]
fn the_gathered_render_is_the_films_bit_for_bit() {
    for kind in PixelSamplerKind::ALL {
        for filter_kind in FilterKind::ALL {
            for radius in [None, Some(2.5)] {
                let filter = filter(filter_kind, radius);
                let spp = 5;
                let sampler = PixelSampler::new(kind, spp, 11).unwrap();
                let film = render::render(
                    &RenderSettings::new(37, 21, spp),
                    &sampler,
                    &filter,
                    radiance,
                );
                for threads in [1, 3] {
                    let settings = RenderSettings {
                        threads: Some(threads),
                        ..RenderSettings::new(37, 21, spp)
                    };
                    let gathered = super::render(&settings, &sampler, &filter, radiance);
                    assert_eq!(gathered.image, film.image, "{kind:?} {filter:?} {threads}");
                    assert_eq!(gathered.stats.samples, film.stats.samples);
                }
            }
        }
    }
}

/// A time budget renders at least once, and its image is the film's at the samples per pixel
/// it reached; a stop before the first render leaves no samples.
#[test]
fn a_time_budget_and_a_stop() {
    let sampler = PixelSampler::new(PixelSamplerKind::Random, 1, 3).unwrap();
    let filter = filter(FilterKind::Tent, None);
    let timed = RenderSettings {
        budget: render::Budget::Seconds(1e-9),
        ..RenderSettings::new(9, 7, 1)
    };
    let out = super::render(&timed, &sampler, &filter, radiance);
    assert!(out.stats.spp >= 1 && !out.stats.interrupted);
    assert_eq!(out.stats.requested_spp, None);
    let film = render::render(
        &RenderSettings::new(9, 7, out.stats.spp),
        &sampler,
        &filter,
        radiance,
    );
    assert_eq!(out.image, film.image);
    let stopped = RenderSettings::new(9, 7, 4);
    stopped.stop.request();
    let out = super::render(&stopped, &sampler, &filter, radiance);
    assert!(out.stats.interrupted);
    assert_eq!((out.stats.spp, out.stats.samples), (0, 0));
}
