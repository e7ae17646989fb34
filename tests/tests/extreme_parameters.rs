//! Extreme parameters, swept by property tests: cameras with fields of view from 1e-3 to
//! 179.9 degrees placed far out, scenes from 1e-4 to 1e5 in size, lights near and far, glass of
//! any index, deep recursion, every pixel sampler and filter at any radius, lenses from a
//! pinhole to 1e4 wide focused from 1e-6 to 1e9 away, and shutters from an instant to 1e30
//! long. Every pixel must be finite and no sample may be non-finite: a NaN or an infinity is a
//! bug at its source, which the render loop counts in `nonfinite_samples` and keeps out of the
//! image.
//!
//! Case counts are modest so that the suite stays fast; `PROPTEST_CASES=10000` sweeps harder,
//! and `PROPTEST_RNG_SEED=N` sweeps other cases (the seed is fixed, so a run is repeatable).
//!
//! The recursion limit is swept up to 64 here, not to the command line's 1000: Whitted's
//! tracer follows both branches at every glass surface, and in the test scene (a mirror and a
//! glass sphere side by side) the number of rays grows exponentially beyond a depth of about
//! 200 (chapter 01's `spheres` scene at 32x24 pixels: 0.07 s at depth 200, 17 s at 500, hours
//! at 1000). [`a_recursion_limit_of_1000_finishes`] records that; it is ignored until the
//! tracer bounds the tree.

use ch01_whitted::PixelPattern;
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::aperture::{Aperture, LensWarp};
use ch04_depth_of_field::lens::Lens;
use common::render::{RenderOutput, RenderSettings};
use glam::Vec3;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use workbook_tests::{WhittedSceneParams, whitted_scene};

/// Cases per property: `PROPTEST_CASES` if set, else few enough for CI.
fn config() -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|n| n.parse().ok());
    let seed = std::env::var("PROPTEST_RNG_SEED")
        .ok()
        .and_then(|n| n.parse().ok());
    ProptestConfig {
        cases: cases.unwrap_or(40),
        rng_seed: RngSeed::Fixed(seed.unwrap_or(20_261_122)),
        // Shrunk failures are printed; nothing is written into the source tree.
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// A number between `lo` and `hi` (both positive), spread evenly over its orders of magnitude.
fn log_uniform(lo: f32, hi: f32) -> impl Strategy<Value = f32> {
    (lo.log10()..=hi.log10()).prop_map(|e| 10f32.powf(e))
}

/// A coordinate from -1000 to 1000 scene sizes away, often zero.
///
/// Not further: `f32` has 24 bits, so a scene moved 1e5 of its sizes away has features of only a
/// few dozen float steps (see `scale_invariance.rs`), and one moved 1e6 away is smaller than
/// one step. There its surfaces collapse into each other, and Whitted's tree of glass and
/// mirror rays bouncing between them grows exponentially (5 pixels at a depth of 44 took 15
/// million rays). Absolute distances still reach 1e8, at scale 1e5.
fn far_coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![Just(0.0f32), -1e3f32..1e3f32]
}

/// Every chapter 01 knob of the test scene.
fn whitted_params() -> impl Strategy<Value = WhittedSceneParams> {
    (
        log_uniform(1e-4, 1e5),
        (far_coordinate(), far_coordinate(), far_coordinate()),
        (1u32..=6, 1u32..=5),
        prop_oneof![log_uniform(1e-3, 179.9), Just(179.9f32), Just(1e-3f32)],
        log_uniform(1e-3, 1e6),
        log_uniform(1e-2, 1e6),
        prop_oneof![1.0f32..=4.0, Just(1.0f32), Just(4.0f32)],
        prop_oneof![1u32..=64, Just(1u32), Just(64u32)],
    )
        .prop_map(
            |(scale, (x, y, z), (width, height), fov, camera, light, ior, depth)| {
                WhittedSceneParams {
                    scale,
                    offset: Vec3::new(x, y, z) * scale,
                    width,
                    height,
                    fov_degrees: fov,
                    camera_distance: camera,
                    light_distance: light,
                    glass_ior: ior,
                    max_depth: depth,
                }
            },
        )
}

/// Why `out` is not acceptable, if it is not.
fn check_finite(out: &RenderOutput) -> Result<(), TestCaseError> {
    prop_assert_eq!(out.stats.nonfinite_samples, 0, "non-finite samples");
    prop_assert!(
        out.image.pixels.iter().all(|p| p.is_finite()),
        "a non-finite pixel"
    );
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn whitted_pixels_are_finite(params in whitted_params(), grid in any::<bool>()) {
        let scene = whitted_scene(&params);
        prop_assume!(scene.is_some(), "the camera is at its target");
        let scene = scene.unwrap();
        let (pattern, spp) = if grid { (PixelPattern::Grid, 4) } else { (PixelPattern::Centre, 1) };
        let settings = RenderSettings::new(params.width, params.height, spp);
        let out = ch01_whitted::render(&scene, &settings, pattern, 1).unwrap();
        check_finite(&out)?;
    }

    #[test]
    fn every_sampler_and_filter_gives_finite_pixels(
        params in whitted_params(),
        sampler in prop::sample::select(PixelSamplerKind::ALL.to_vec()),
        filter in prop::sample::select(FilterKind::ALL.to_vec()),
        radius in prop_oneof![log_uniform(1e-6, 16.0), Just(16.0f32)],
        spp in prop_oneof![1u64..=64, Just(64u64)],
        seed in any::<u64>(),
    ) {
        let scene = whitted_scene(&params);
        prop_assume!(scene.is_some(), "the camera is at its target");
        let scene = scene.unwrap();
        let sampler = PixelSampler::new(sampler, spp, seed).unwrap();
        let filter = ReconstructionFilter::new(filter, Some(radius)).unwrap();
        let settings = RenderSettings::new(params.width, params.height, spp);
        let out = ch03_anti_aliasing::render_with(&scene, &settings, &sampler, &filter);
        check_finite(&out)?;
        prop_assert_eq!(out.stats.spp, spp);
    }

    #[test]
    fn every_shutter_gives_finite_pixels(
        builtin in prop::sample::select(ch05_motion_blur::scenes::Builtin::ALL.to_vec()),
        open in prop_oneof![Just(0.0f32), -1e6f32..1e6, Just(-1e30f32)],
        length in prop_oneof![Just(0.0f32), log_uniform(1e-6, 1e6), Just(1e30f32)],
        stratified in any::<bool>(),
        radius in prop_oneof![Just(0.0f32), log_uniform(1e-6, 1e3)],
        focus in log_uniform(1e-6, 1e9),
        spp in 1u64..=8,
        (width, height) in (1u32..=6, 1u32..=5),
        seed in any::<u64>(),
    ) {
        use ch05_motion_blur::{Shutter, StratifiedTime, render_with};
        let shutter = Shutter::new(open, open + length).unwrap();
        let scene = builtin.build(12, shutter);
        let lens = Lens::new(radius, focus).unwrap();
        let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
        let settings = RenderSettings::new(width, height, spp);
        let pixels = PixelSampler::new(PixelSamplerKind::Random, spp, seed).unwrap();
        let out = if stratified {
            render_with(&scene, &lens, &settings, &StratifiedTime::new(pixels, spp, seed), &filter)
        } else {
            render_with(&scene, &lens, &settings, &pixels, &filter)
        };
        check_finite(&out)?;
    }

    #[test]
    fn every_roughness_index_and_choice_at_glass_gives_finite_pixels(
        builtin in prop::sample::select(ch06_fuzzy_reflections::scenes::Builtin::ALL.to_vec()),
        exponent in prop_oneof![Just(0.0f32), log_uniform(1e-3, 1e7), Just(1e7f32)],
        ior in prop_oneof![Just(1.0f32), 1.0f32..4.0, log_uniform(1e-2, 1e2)],
        glass in prop::sample::select(ch06_fuzzy_reflections::GlassStrategy::ALL.to_vec()),
        fuzz in prop::sample::select(ch06_fuzzy_reflections::FuzzMethod::ALL.to_vec()),
        below in prop::sample::select(ch06_fuzzy_reflections::BelowSurface::ALL.to_vec()),
        max_depth in 1u32..=16,
        spp in 1u64..=4,
        (width, height) in (1u32..=6, 1u32..=5),
        seed in any::<u64>(),
    ) {
        use ch06_fuzzy_reflections::{PointLights, TraceOptions, render_with};
        use common::scene::Material;
        let mut scene = builtin.build(max_depth, exponent);
        for surface in &mut scene.scene.surfaces {
            if let Material::RoughGlass(glass) = &mut surface.material {
                glass.int_ior = ior;
            }
        }
        let options = TraceOptions { glass, fuzz, below };
        let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
        let settings = RenderSettings::new(width, height, spp);
        let pixels = PixelSampler::new(PixelSamplerKind::Random, spp, seed).unwrap();
        let out = render_with(
            &scene, &PointLights, options, &Lens::PINHOLE, &settings, &pixels, &filter,
        );
        check_finite(&out)?;
    }

    #[test]
    fn every_light_size_and_sampling_gives_finite_pixels(
        builtin in prop::sample::select(ch07_soft_shadows::scenes::Builtin::ALL.to_vec()),
        light_scale in prop_oneof![Just(1e-4f32), log_uniform(1e-4, 1e4), Just(1e4f32)],
        samples in 1u32..=9,
        strata in prop::sample::select(ch07_soft_shadows::shadow_rays::LightStrata::ALL.to_vec()),
        strategy in prop::sample::select(ch07_soft_shadows::strategy::Strategy::ALL.to_vec()),
        disc_warp in prop::sample::select(ch07_soft_shadows::disc_warp::DiscWarp::ALL.to_vec()),
        max_depth in 1u32..=16,
        spp in 1u64..=4,
        (width, height) in (1u32..=6, 1u32..=5),
        seed in any::<u64>(),
    ) {
        use ch07_soft_shadows::shadow_rays::LightOptions;
        use ch07_soft_shadows::strategy::LightSampling;
        let scene = builtin.build(max_depth, light_scale);
        let lights = LightOptions { samples, strata, sampling: LightSampling { strategy, disc_warp } };
        let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
        let settings = RenderSettings::new(width, height, spp);
        let pixels = PixelSampler::new(PixelSamplerKind::Random, spp, seed).unwrap();
        let out = ch07_soft_shadows::render_with(
            &scene,
            lights,
            ch06_fuzzy_reflections::TraceOptions::default(),
            &Lens::PINHOLE,
            &settings,
            &pixels,
            &filter,
        );
        check_finite(&out)?;
    }

    #[test]
    fn every_path_estimator_and_depth_gives_finite_pixels(
        builtin in prop::sample::select(ch07_soft_shadows::scenes::Builtin::ALL.to_vec()),
        light_scale in prop_oneof![Just(1e-4f32), log_uniform(1e-4, 1e4), Just(1e4f32)],
        nee in any::<bool>(),
        mis in prop::sample::select(ch08_path_tracing::MisHeuristic::ALL.to_vec()),
        rr_depth in prop_oneof![Just(None), (1u32..=8).prop_map(Some)],
        max_depth in prop_oneof![1u32..=16, Just(1000u32)],
        spp in 1u64..=4,
        (width, height) in (1u32..=6, 1u32..=5),
        seed in any::<u64>(),
        direct in prop_oneof![
            Just(None),
            (0u32..=3, 0u32..=3)
                .prop_filter("one sample at least", |(e, b)| e + b > 0)
                .prop_map(|(emitter, bsdf)| Some(common::scene::DirectSamples { emitter, bsdf })),
        ],
    ) {
        use ch08_path_tracing::{Method, PathOptions, render_with};
        let scene = builtin.build(12, light_scale);
        let method = Method::new(PathOptions { nee, mis, rr_depth, max_depth, hide_emitters: false, direct });
        let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
        let settings = RenderSettings::new(width, height, spp);
        let pixels = PixelSampler::new(PixelSamplerKind::Random, spp, seed).unwrap();
        let out = render_with(&scene, method, &Lens::PINHOLE, &settings, &pixels, &filter);
        check_finite(&out)?;
    }

    /// Chapter 08 on the Whitted scene of any size, place, camera, light and index, its mirror
    /// and glass made glossy and frosted with any exponent (or left smooth), its sky the
    /// environment light, seen through any lens, with every estimator.
    #[test]
    fn path_traced_whitted_scenes_give_finite_pixels(
        params in whitted_params(),
        exponent in prop_oneof![Just(None), Just(Some(0.0f32)), log_uniform(1e-3, 1e7).prop_map(Some)],
        nee in any::<bool>(),
        mis in prop::sample::select(ch08_path_tracing::MisHeuristic::ALL.to_vec()),
        rr_depth in prop_oneof![Just(None), (1u32..=8).prop_map(Some)],
        radius in prop_oneof![Just(0.0f32), log_uniform(1e-6, 1e4)],
        focus in log_uniform(1e-6, 1e9),
        spp in 1u64..=4,
        seed in any::<u64>(),
    ) {
        use ch05_motion_blur::MotionScene;
        use common::scene::Material;
        use ch08_path_tracing::{Method, PathOptions, render_with};
        let scene = whitted_scene(&params);
        prop_assume!(scene.is_some(), "the camera is at its target");
        let mut scene = scene.unwrap();
        if let Some(exponent) = exponent {
            for surface in &mut scene.surfaces {
                surface.material = match surface.material.clone() {
                    Material::Mirror { reflectance } => Material::glossy(reflectance, exponent),
                    Material::Dielectric { int_ior, .. } => Material::rough_glass(int_ior, exponent),
                    other => other,
                };
            }
        }
        let scene = MotionScene::still(scene);
        let method = Method::new(PathOptions { nee, mis, rr_depth, max_depth: params.max_depth, hide_emitters: false, direct: None });
        let lens = Lens::new(radius, focus).unwrap();
        let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
        let settings = RenderSettings::new(params.width, params.height, spp);
        let pixels = PixelSampler::new(PixelSamplerKind::Random, spp, seed).unwrap();
        let out = render_with(&scene, method, &lens, &settings, &pixels, &filter);
        check_finite(&out)?;
    }

    #[test]
    fn every_lens_gives_finite_pixels(
        params in whitted_params(),
        radius in prop_oneof![Just(0.0f32), log_uniform(1e-6, 1e4), Just(1e4f32)],
        focus in prop_oneof![log_uniform(1e-6, 1e9), Just(1e-6f32), Just(1e9f32)],
        blades in prop_oneof![Just(0u32), 3u32..=64],
        rotation in -10.0f32..10.0,
        warp in prop::sample::select(LensWarp::ALL.to_vec()),
        spp in 1u64..=8,
        seed in any::<u64>(),
    ) {
        let scene = whitted_scene(&params);
        prop_assume!(scene.is_some(), "the camera is at its target");
        let scene = scene.unwrap();
        let mut lens = Lens::new(radius, focus).unwrap();
        lens = if blades == 0 {
            lens.with_warp(warp)
        } else {
            lens.with_aperture(Aperture::polygon(blades, rotation).unwrap())
        };
        let sampler = PixelSampler::new(PixelSamplerKind::Random, spp, seed).unwrap();
        let filter = ReconstructionFilter::new(FilterKind::Gaussian, None).unwrap();
        let settings = RenderSettings::new(params.width, params.height, spp);
        let out = ch04_depth_of_field::render_with(&scene, &lens, &settings, &sampler, &filter);
        check_finite(&out)?;
    }
}

/// The command line accepts `--max-depth 1000`; the render must then finish, in time linear in
/// the depth at worst. Today it does not (see the top of this file): the tracer needs to stop
/// following a branch whose contribution has become negligible.
#[test]
#[ignore = "Whitted's ray tree grows exponentially with the recursion limit beyond ~200"]
fn a_recursion_limit_of_1000_finishes() {
    let scene = ch01_whitted::scenes::Builtin::Spheres.build(1000);
    let start = std::time::Instant::now();
    let settings = RenderSettings::new(32, 24, 1);
    let out = ch01_whitted::render(&scene, &settings, PixelPattern::Centre, 0).unwrap();
    assert_eq!(out.stats.nonfinite_samples, 0);
    let seconds = start.elapsed().as_secs_f64();
    assert!(seconds < 5.0, "{seconds} s");
}

/// Chapter 08's binary at the ends of its options' ranges, on the suite's tiny scene: each
/// render succeeds, and its `--stats` say that no sample was non-finite.
#[test]
fn the_path_tracer_binary_counts_no_non_finite_samples_at_extreme_settings() {
    use workbook_tests::binaries::{TINY_SCENE, run_chapter};
    let settings: &[&[&str]] = &[
        &["--max-depth", "1"],
        &["--max-depth", "1000", "--rr-depth", "off"],
        &["--max-depth", "1000", "--rr-depth", "1"],
        &["--no-nee"],
        &["--mis", "none"],
        &["--mis", "balance"],
        &["--exponent", "0"],
        &["--exponent", "1e7"],
        &["--aperture-radius", "1e4", "--focus-distance", "1e-6"],
        &["--aperture-radius", "1e-6", "--focus-distance", "1e9"],
        &[
            "--f-number",
            "1e-3",
            "--focal-length",
            "1e3",
            "--blades",
            "3",
        ],
        &["--filter", "mitchell", "--filter-radius", "16"],
        &["--filter", "gaussian", "--filter-radius", "1e-6"],
        &["--sampler", "halton", "--seed", "18446744073709551615"],
        &["--light-sampling", "area", "--disc-warp", "naive"],
        &["--width", "1", "--height", "1"],
        &["--width", "2000", "--height", "1", "--spp", "1"],
    ];
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.pfm");
    let stats = dir.path().join("stats.json");
    for extra in settings {
        let mut args = vec!["render", "--scene", TINY_SCENE, "--threads", "2"];
        args.extend([
            "--out",
            out.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ]);
        // A small image with two samples per pixel, unless the row sizes it itself.
        if !extra.contains(&"--width") {
            args.extend(["--width", "6", "--height", "4", "--spp", "2"]);
        }
        args.extend_from_slice(extra);
        let done = run_chapter("ch08-path-tracing", &args);
        let stderr = String::from_utf8_lossy(&done.stderr);
        assert!(done.status.success(), "{extra:?}: {stderr}");
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
        assert_eq!(json["nonfinite_samples"], 0, "{extra:?}: {json}");
        let image = workbench::output::read_image(&out).unwrap();
        assert!(image.pixels.iter().all(|p| p.is_finite()), "{extra:?}");
    }
}
