//! Determinism: the same seed gives a bit-identical image with 1, 2 or 7 threads, and from one
//! run of a binary to the next.
//!
//! The render loop merges tiles in a fixed order, and every sample's random numbers depend only
//! on (seed, pixel, sample index); anything that broke either (a shared RNG, a merge in
//! completion order, a hash map iterated in random order) shows up here.

use ch01_whitted::PixelPattern;
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::aperture::Aperture;
use ch04_depth_of_field::lens::Lens;
use common::image::Image;
use common::render::RenderSettings;
use workbook_tests::binaries::{RENDERING_CHAPTERS, run_chapter, scene_args};

/// 40x20 pixels: six tiles, fewer than the largest thread count, so some threads idle.
const WIDTH: u32 = 40;
const HEIGHT: u32 = 20;
const THREADS: [usize; 3] = [1, 2, 7];

fn settings(threads: usize, spp: u64) -> RenderSettings {
    RenderSettings {
        threads: Some(threads),
        ..RenderSettings::new(WIDTH, HEIGHT, spp)
    }
}

/// Renders with each thread count and checks the images are the same, bit for bit.
fn assert_thread_independent(what: &str, render: impl Fn(usize) -> Image) {
    let images: Vec<Image> = THREADS.iter().map(|&t| render(t)).collect();
    for (image, threads) in images.iter().zip(THREADS).skip(1) {
        let same = image
            .pixels
            .iter()
            .zip(&images[0].pixels)
            .all(|(a, b)| a.to_array().map(f32::to_bits) == b.to_array().map(f32::to_bits));
        assert!(same, "{what}: {threads} threads differ from 1");
    }
}

#[test]
fn chapter_01_is_thread_independent() {
    for builtin in ch01_whitted::scenes::Builtin::ALL {
        let scene = builtin.build(12);
        for (pattern, spp) in [(PixelPattern::Centre, 1), (PixelPattern::Grid, 4)] {
            assert_thread_independent(&format!("ch01 {} {pattern:?}", builtin.name()), |t| {
                ch01_whitted::render(&scene, &settings(t, spp), pattern, 11)
                    .unwrap()
                    .image
            });
        }
    }
}

#[test]
fn chapter_03_is_thread_independent_with_every_sampler_and_wide_filters() {
    let scene = ch03_anti_aliasing::scenes::Builtin::Edges.build(4);
    // Filters reaching over several tile borders, one with negative lobes.
    let filters = [
        ReconstructionFilter::new(FilterKind::Gaussian, Some(3.0)).unwrap(),
        ReconstructionFilter::new(FilterKind::Mitchell, Some(2.5)).unwrap(),
    ];
    for kind in PixelSamplerKind::ALL {
        for filter in &filters {
            let sampler = PixelSampler::new(kind, 4, 11).unwrap();
            assert_thread_independent(
                &format!("ch03 {} {}", kind.name(), filter.kind().name()),
                |t| {
                    ch03_anti_aliasing::render_with(&scene, &settings(t, 4), &sampler, filter).image
                },
            );
        }
    }
}

#[test]
fn chapter_04_is_thread_independent_with_a_lens() {
    use ch04_depth_of_field::scenes::Builtin;
    let scene = Builtin::Bokeh.build(12);
    let disc = Builtin::Bokeh.default_lens();
    let hexagon = disc.with_aperture(Aperture::polygon(6, 0.3).unwrap());
    let filter = ReconstructionFilter::new(FilterKind::Gaussian, None).unwrap();
    for (name, lens) in [("disc", disc), ("hexagon", hexagon)] {
        let sampler = PixelSampler::new(PixelSamplerKind::Halton, 4, 11).unwrap();
        assert_thread_independent(&format!("ch04 {name}"), |t| {
            ch04_depth_of_field::render_with(&scene, &lens, &settings(t, 4), &sampler, &filter)
                .image
        });
    }
}

#[test]
fn two_runs_of_each_binary_write_the_same_bytes() {
    let dir = tempfile::tempdir().unwrap();
    for chapter in RENDERING_CHAPTERS {
        let run = |name: &str| {
            let path = dir.path().join(format!("{chapter}-{name}.pfm"));
            let mut args = vec!["render"];
            args.extend(scene_args(chapter));
            args.extend([
                "--width",
                "24",
                "--height",
                "16",
                "--spp",
                "4",
                "--seed",
                "3",
                "--threads",
                "7",
                "--out",
                path.to_str().unwrap(),
            ]);
            let out = run_chapter(chapter, &args);
            assert!(
                out.status.success(),
                "{}",
                String::from_utf8_lossy(&out.stderr)
            );
            std::fs::read(path).unwrap()
        };
        assert!(run("first") == run("second"), "{chapter}: two runs differ");
    }
}

#[test]
fn chapter_05_is_thread_independent_with_motion_and_a_lens() {
    use ch05_motion_blur::scenes::{Builtin, DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER};
    use ch05_motion_blur::{StratifiedTime, render_with};
    let lens = Lens::new(0.05, 5.0).unwrap();
    let filter = ReconstructionFilter::new(FilterKind::Gaussian, None).unwrap();
    for builtin in Builtin::ALL {
        let scene = builtin.build(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
        let pixels = PixelSampler::new(PixelSamplerKind::Stratified, 4, 11).unwrap();
        let sampler = StratifiedTime::new(pixels, 4, 11);
        assert_thread_independent(&format!("ch05 {}", builtin.name()), |t| {
            render_with(&scene, &lens, &settings(t, 4), &sampler, &filter).image
        });
    }
}

#[test]
fn chapter_06_is_thread_independent_with_every_choice_at_glass_and_stray_ray_policy() {
    use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_MAX_DEPTH};
    use ch06_fuzzy_reflections::{BelowSurface, FuzzMethod, GlassStrategy, PointLights};
    use ch06_fuzzy_reflections::{TraceOptions, render_with};
    let lens = Lens::new(0.05, 5.0).unwrap();
    let filter = ReconstructionFilter::new(FilterKind::Gaussian, None).unwrap();
    for builtin in Builtin::ALL {
        let scene = builtin.build(DEFAULT_MAX_DEPTH, 10.0);
        for (glass, fuzz, below) in [
            (GlassStrategy::Fresnel, FuzzMethod::Lobe, BelowSurface::Drop),
            (
                GlassStrategy::Half,
                FuzzMethod::Disc,
                BelowSurface::Resample,
            ),
            (GlassStrategy::Both, FuzzMethod::Lobe, BelowSurface::Reflect),
        ] {
            let options = TraceOptions { glass, fuzz, below };
            let sampler = PixelSampler::new(PixelSamplerKind::Stratified, 4, 11).unwrap();
            assert_thread_independent(&format!("ch06 {} {options:?}", builtin.name()), |t| {
                render_with(
                    &scene,
                    &PointLights,
                    options,
                    &lens,
                    &settings(t, 4),
                    &sampler,
                    &filter,
                )
                .image
            });
        }
    }
}

#[test]
fn chapter_07_is_thread_independent_with_every_light_option() {
    use ch07_soft_shadows::disc_warp::DiscWarp;
    use ch07_soft_shadows::render_with;
    use ch07_soft_shadows::scenes::{Builtin, DEFAULT_MAX_DEPTH};
    use ch07_soft_shadows::shadow_rays::{LightOptions, LightStrata};
    use ch07_soft_shadows::strategy::{LightSampling, Strategy};
    let filter = ReconstructionFilter::new(FilterKind::Gaussian, None).unwrap();
    for builtin in Builtin::ALL {
        let scene = builtin.build(DEFAULT_MAX_DEPTH, 1.0);
        for (samples, strata, strategy, disc_warp) in [
            (
                1,
                LightStrata::Stratified,
                Strategy::SolidAngle,
                DiscWarp::Concentric,
            ),
            (4, LightStrata::Stratified, Strategy::Area, DiscWarp::Naive),
            (
                3,
                LightStrata::Independent,
                Strategy::SolidAngle,
                DiscWarp::Polar,
            ),
        ] {
            let lights = LightOptions {
                samples,
                strata,
                sampling: LightSampling {
                    strategy,
                    disc_warp,
                },
            };
            let sampler = PixelSampler::new(PixelSamplerKind::Stratified, 4, 11).unwrap();
            assert_thread_independent(&format!("ch07 {} {lights:?}", builtin.name()), |t| {
                render_with(
                    &scene,
                    lights,
                    ch06_fuzzy_reflections::TraceOptions::default(),
                    &Lens::PINHOLE,
                    &settings(t, 4),
                    &sampler,
                    &filter,
                )
                .image
            });
        }
    }
}

#[test]
fn chapter_08_path_tracing_is_thread_independent_with_every_estimator() {
    use ch07_soft_shadows::scenes::{Builtin, DEFAULT_MAX_DEPTH};
    use ch08_path_tracing::{Method, MisHeuristic, PathOptions, render_with};
    let filter = ReconstructionFilter::new(FilterKind::Gaussian, None).unwrap();
    for builtin in Builtin::ALL {
        let scene = builtin.build(DEFAULT_MAX_DEPTH, 1.0);
        let counts = Some(common::scene::DirectSamples {
            emitter: 3,
            bsdf: 2,
        });
        for (nee, mis, rr_depth, direct) in [
            (true, MisHeuristic::Power, Some(2), None),
            (true, MisHeuristic::None, None, None),
            (false, MisHeuristic::Balance, Some(1), None),
            (true, MisHeuristic::Power, None, counts),
        ] {
            let method = Method::new(PathOptions {
                nee,
                mis,
                rr_depth,
                max_depth: 8,
                hide_emitters: false,
                direct,
            });
            let sampler = PixelSampler::new(PixelSamplerKind::Stratified, 4, 11).unwrap();
            assert_thread_independent(&format!("ch08 {} {method:?}", builtin.name()), |t| {
                render_with(
                    &scene,
                    method,
                    &Lens::PINHOLE,
                    &settings(t, 4),
                    &sampler,
                    &filter,
                )
                .image
            });
        }
    }
}
