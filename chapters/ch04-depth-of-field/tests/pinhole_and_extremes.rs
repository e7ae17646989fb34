//! A zero aperture is exactly the pinhole, and no lens, however extreme, puts a NaN or an
//! infinity into a pixel.

use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch04_depth_of_field::{Aperture, Lens, LensWarp, render_with};
use common::render::{RenderOutput, RenderSettings};
use common::sampler::Sampler;
use glam::{UVec2, Vec2};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

fn box_filter() -> ReconstructionFilter {
    ReconstructionFilter::new(FilterKind::Box, None).unwrap()
}

#[test]
fn a_zero_aperture_renders_chapter_03s_pinhole_image_bit_for_bit() {
    let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
    let settings = RenderSettings::new(40, 27, 4);
    for kind in [PixelSamplerKind::Random, PixelSamplerKind::Stratified] {
        let sampler = PixelSampler::new(kind, 4, 3).unwrap();
        let filter = ReconstructionFilter::new(FilterKind::Gaussian, None).unwrap();
        let pinhole = ch03_anti_aliasing::render_with(&scene, &settings, &sampler, &filter);
        // Any focus distance, shape or warp: without an aperture none of them matters.
        let lens = Lens::new(0.0, 123.0)
            .unwrap()
            .with_aperture(Aperture::polygon(5, 0.2).unwrap())
            .with_warp(LensWarp::Naive);
        let ours = render_with(&scene, &lens, &settings, &sampler, &filter);
        assert_eq!(ours.image, pinhole.image, "{kind:?}");
        assert_eq!(ours.stats.rays, pinhole.stats.rays);
    }
}

/// Counts the dimensions handed out after the pixel position, over every clone.
#[derive(Clone)]
struct Counting {
    inner: PixelSampler,
    dimensions: Arc<AtomicU64>,
}

impl Sampler for Counting {
    fn start_pixel_sample(&mut self, pixel: UVec2, sample_index: u64) {
        self.inner.start_pixel_sample(pixel, sample_index);
    }
    fn get_pixel_2d(&mut self) -> Vec2 {
        self.inner.get_pixel_2d()
    }
    fn get_1d(&mut self) -> f32 {
        self.dimensions.fetch_add(1, Ordering::Relaxed);
        self.inner.get_1d()
    }
    fn get_2d(&mut self) -> Vec2 {
        self.dimensions.fetch_add(2, Ordering::Relaxed);
        self.inner.get_2d()
    }
}

fn dimensions_drawn(lens: Lens) -> u64 {
    let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
    let sampler = Counting {
        inner: PixelSampler::new(PixelSamplerKind::Random, 3, 0).unwrap(),
        dimensions: Arc::default(),
    };
    render_with(
        &scene,
        &lens,
        &RenderSettings::new(20, 10, 3),
        &sampler,
        &box_filter(),
    );
    sampler.dimensions.load(Ordering::Relaxed)
}

#[test]
fn a_zero_aperture_draws_no_lens_dimensions_and_a_lens_draws_two_per_sample() {
    assert_eq!(dimensions_drawn(Lens::PINHOLE), 0);
    assert_eq!(
        dimensions_drawn(Lens::new(0.1, 5.0).unwrap()),
        20 * 10 * 3 * 2
    );
}

fn all_finite(out: &RenderOutput) -> bool {
    out.stats.nonfinite_samples == 0 && out.image.pixels.iter().all(|p| p.is_finite())
}

#[test]
fn extreme_lenses_and_budgets_give_finite_pixels() {
    let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
    let radii = [0.0, 1e-6, 0.1, 1e3];
    let focus_distances = [1e-4, 1.0, 7.0, 1e8];
    let shapes = [Aperture::Disc, Aperture::polygon(3, 1.0).unwrap()];
    for spp in [1, 4096] {
        let (width, height) = if spp == 1 { (8, 6) } else { (3, 2) };
        let settings = RenderSettings::new(width, height, spp);
        let sampler = PixelSampler::new(PixelSamplerKind::Random, spp, 1).unwrap();
        for radius in radii {
            for focus in focus_distances {
                for shape in shapes {
                    // Every warp once; at 4096 spp the concentric one stands for them all.
                    let warps: &[LensWarp] = if spp == 1 {
                        &LensWarp::ALL
                    } else {
                        &[LensWarp::Concentric]
                    };
                    for &warp in warps {
                        let lens = Lens::new(radius, focus)
                            .unwrap()
                            .with_aperture(shape)
                            .with_warp(warp);
                        let out = render_with(&scene, &lens, &settings, &sampler, &box_filter());
                        assert!(all_finite(&out), "{lens:?} at {spp} spp");
                        assert_eq!(out.stats.spp, spp);
                    }
                }
            }
        }
    }
}

#[test]
fn a_huge_aperture_blurs_everything_into_nearly_the_same_colour() {
    // Focused at 1e-4 with a lens of radius 1e3, each pixel averages over almost the whole
    // scene: neighbouring pixels differ far less than in the pinhole image.
    let scene = Builtin::Bokeh.build(DEFAULT_MAX_DEPTH);
    let settings = RenderSettings::new(8, 6, 256);
    let sampler = PixelSampler::new(PixelSamplerKind::Random, 256, 1).unwrap();
    let spread = |lens: Lens| {
        let image = render_with(&scene, &lens, &settings, &sampler, &box_filter()).image;
        let lum: Vec<f32> = image.pixels.iter().map(|p| p.element_sum()).collect();
        let max = lum.iter().copied().fold(f32::MIN, f32::max);
        let min = lum.iter().copied().fold(f32::MAX, f32::min);
        max - min
    };
    let sharp = spread(Lens::PINHOLE);
    let blurred = spread(Lens::new(1e3, 1e-4).unwrap());
    assert!(
        blurred < 0.5 * sharp,
        "pinhole spread {sharp}, blurred {blurred}"
    );
}
