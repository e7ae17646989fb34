//! Renders at the limits: filters from a thousandth of a pixel to 16 pixels, 1 and 4096
//! samples per pixel, every sampler and filter. No pixel may be NaN or infinite, and no sample
//! may be either.

use ch03_anti_aliasing::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch03_anti_aliasing::{
    FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter, render_with,
};
use common::render::{RenderOutput, RenderSettings};
use glam::Vec3;

fn render(
    builtin: Builtin,
    (width, height, spp): (u32, u32, u64),
    sampler: PixelSamplerKind,
    filter: ReconstructionFilter,
) -> RenderOutput {
    let scene = builtin.build(DEFAULT_MAX_DEPTH);
    let settings = RenderSettings::new(width, height, spp);
    let sampler = PixelSampler::new(sampler, spp, 7).unwrap();
    render_with(&scene, &settings, &sampler, &filter)
}

fn assert_finite(out: &RenderOutput, what: &str) {
    assert_eq!(out.stats.nonfinite_samples, 0, "{what}");
    assert!(
        out.image.pixels.iter().all(|p| p.is_finite()),
        "{what}: a pixel is not finite"
    );
}

#[test]
fn every_sampler_and_filter_at_every_radius_gives_finite_pixels() {
    for builtin in Builtin::ALL {
        for sampler in PixelSamplerKind::ALL {
            for kind in FilterKind::ALL {
                for radius in [Some(1e-3), None, Some(16.0)] {
                    let filter = ReconstructionFilter::new(kind, radius).unwrap();
                    let out = render(builtin, (12, 8, 4), sampler, filter);
                    assert_finite(&out, &format!("{builtin:?} {sampler:?} {filter:?}"));
                }
            }
        }
    }
}

#[test]
fn a_tiny_filter_leaves_pixels_without_nearby_samples_black() {
    // Random positions almost never come within 1/1000 of a pixel centre: nearly every pixel
    // gets no weight at all and is black, not NaN.
    let filter = ReconstructionFilter::new(FilterKind::Tent, Some(1e-3)).unwrap();
    let out = render(
        Builtin::Checkerboard,
        (16, 12, 4),
        PixelSamplerKind::Random,
        filter,
    );
    assert_finite(&out, "tiny tent");
    let black = out
        .image
        .pixels
        .iter()
        .filter(|&&p| p == Vec3::ZERO)
        .count();
    assert!(black >= 16 * 12 - 4, "{black} black pixels");
    // At the centre every sample lands exactly on the pixel centre: full weight everywhere.
    let centred = render(
        Builtin::Checkerboard,
        (16, 12, 1),
        PixelSamplerKind::Centre,
        filter,
    );
    let box_centred = render(
        Builtin::Checkerboard,
        (16, 12, 1),
        PixelSamplerKind::Centre,
        ReconstructionFilter::new(FilterKind::Box, None).unwrap(),
    );
    assert_eq!(centred.image, box_centred.image);
}

#[test]
fn a_wide_filter_blurs_the_whole_tiny_image_towards_its_mean() {
    let wide = ReconstructionFilter::new(FilterKind::Box, Some(16.0)).unwrap();
    let out = render(
        Builtin::Edges,
        (10, 8, 4),
        PixelSamplerKind::Stratified,
        wide,
    );
    assert_finite(&out, "radius 16");
    // Each pixel averages every sample of the 10 x 8 image: all pixels are equal.
    let first = out.image.pixels[0];
    for p in &out.image.pixels {
        assert!((*p - first).abs().max_element() < 1e-5, "{p} vs {first}");
    }
}

#[test]
fn one_and_4096_samples_per_pixel() {
    for sampler in PixelSamplerKind::ALL {
        for kind in [FilterKind::Box, FilterKind::Mitchell] {
            let filter = ReconstructionFilter::new(kind, None).unwrap();
            let one = render(Builtin::Edges, (4, 3, 1), sampler, filter);
            assert_finite(&one, "1 spp");
            assert_eq!(one.stats.spp, 1);
            let many = render(Builtin::Edges, (4, 3, 4096), sampler, filter);
            assert_finite(&many, "4096 spp");
            assert_eq!(many.stats.spp, 4096);
        }
    }
}

#[test]
fn wide_filters_and_every_sampler_give_the_same_image_on_any_thread_count() {
    // Samples cross tile borders with a filter wider than a pixel; tiles merge in a fixed
    // order, so the sums, and the image, do not depend on the schedule.
    let scene = Builtin::Checkerboard.build(DEFAULT_MAX_DEPTH);
    let filter = ReconstructionFilter::new(FilterKind::Mitchell, None).unwrap();
    for kind in PixelSamplerKind::ALL {
        let sampler = PixelSampler::new(kind, 3, 1).unwrap();
        let render_on = |threads| {
            let settings = RenderSettings {
                threads: Some(threads),
                ..RenderSettings::new(40, 20, 3)
            };
            render_with(&scene, &settings, &sampler, &filter).image
        };
        let one = render_on(1);
        assert_eq!(one, render_on(3), "{kind:?}");
    }
}
