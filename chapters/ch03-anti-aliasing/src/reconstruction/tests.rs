use super::*;
use crate::filters::{FilterKind, ReconstructionFilter};
use crate::pixel_samplers::{PixelSampler, PixelSamplerKind};
use common::image::Image;
use common::render::{self, RenderSettings};
use glam::DVec3;

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
    let expected = render::render(&settings, &sampler, &filter, |p, s, _| radiance(p, s)).image;
    let mut mine = Image::new(size.x, size.y);
    let mut first_wrong = None;
    for y in 0..size.y {
        for x in 0..size.x {
            let pixel = UVec2::new(x, y);
            let got = filtered_pixel(pixel, size, spp, &mut sampler.clone(), &filter, radiance);
            mine.set(x, y, got);
            if first_wrong.is_none() && !close(got, expected.get(x, y)) {
                first_wrong = Some(pixel);
            }
        }
    }
    let Some(pixel) = first_wrong else {
        return;
    };
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
        common::test_support::image_comparison(EXERCISE, &mine, &expected)
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
