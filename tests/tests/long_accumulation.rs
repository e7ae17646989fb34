//! Long accumulation: sums over very many samples stay exact enough, and the error-against-time
//! runner stays right far beyond the budgets the chapters' figures use.
//!
//! (The film's own tests add 1e8 identical samples in one thread; here the samples mix
//! magnitudes six orders apart and the tiles come from several threads, as in a render.)
//!
//! Chapter 08's path tracer is run through the same runner in a furnace, where the answer is
//! known, up to 65536 samples per pixel: its error keeps falling as 1/sqrt(spp).

use common::film::{Film, PixelBoxFilter, PixelRect};
use common::image::Image;
use common::render::{RenderSettings, render};
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2, Vec3};
use workbench::convergence::{
    Technique, plot_error_vs_time, run_convergence, write_convergence_csv,
};

const SAMPLES: u64 = 100_000_000;
const PER_TILE: u64 = 1_000_000;
/// Every thousandth sample is a firefly.
const FIREFLY: f32 = 1e4;
const DIM: f32 = 0.01;

/// The value of sample `k`.
fn sample_value(k: u64) -> f32 {
    if k.is_multiple_of(1000) { FIREFLY } else { DIM }
}

#[test]
fn a_hundred_million_samples_of_mixed_magnitude_average_to_their_mean() {
    let mut film = Film::new(1, 1);
    let whole = PixelRect {
        min: UVec2::ZERO,
        max: UVec2::ONE,
    };
    let tiles = SAMPLES / PER_TILE;
    // Two threads fill the tiles, which are then merged in order, as the render loop does.
    let filled: Vec<_> = std::thread::scope(|scope| {
        let halves: Vec<_> = [0..tiles / 2, tiles / 2..tiles]
            .into_iter()
            .map(|range| {
                let film = &film;
                scope.spawn(move || {
                    range
                        .map(|t| {
                            let mut tile = film.tile(whole, &PixelBoxFilter);
                            for k in t * PER_TILE..(t + 1) * PER_TILE {
                                let l = sample_value(k);
                                tile.add_sample(
                                    Vec2::splat(0.5),
                                    Vec3::new(l, DIM, FIREFLY),
                                    &PixelBoxFilter,
                                );
                            }
                            tile
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        halves
            .into_iter()
            .flat_map(|h| h.join().expect("a filling thread"))
            .collect()
    });
    for tile in &filled {
        film.merge(tile);
    }
    let sum = film.pixel(0, 0);
    assert_eq!(sum.weight, SAMPLES as f64, "the sample count is exact");
    // The exact mean of the f32 values, in f64: one firefly per thousand samples.
    let mean = (f64::from(FIREFLY) + 999.0 * f64::from(DIM)) / 1000.0;
    let value = sum.value();
    let relative = |got: f64, want: f64| ((got - want) / want).abs();
    assert!(
        relative(value.x, mean) < 1e-12,
        "mixed: {} vs {mean}",
        value.x
    );
    assert!(
        relative(value.y, f64::from(DIM)) < 1e-12,
        "dim: {}",
        value.y
    );
    assert!(
        relative(value.z, f64::from(FIREFLY)) < 1e-12,
        "bright: {}",
        value.z
    );
    assert_eq!(film.image().get(0, 0).x, mean as f32);
}

/// Standard deviation of the synthetic radiance: uniform on [0, 1) around 0.5.
const SIGMA: f64 = 0.288_675_134_594_812_9; // 1 / sqrt(12)

/// A 2x2 image of constant radiance 0.5 plus uniform noise, through the real render loop.
fn noisy_constant(spp: u64) -> Image {
    render(
        &RenderSettings {
            threads: Some(2),
            ..RenderSettings::new(2, 2, spp)
        },
        &IndependentSampler::new(spp),
        &PixelBoxFilter,
        |_p: Vec2, s: &mut IndependentSampler| Vec3::new(s.get_1d(), s.get_1d(), s.get_1d()),
    )
    .image
}

#[test]
fn the_convergence_runner_is_right_at_its_largest_budgets() {
    // Up to 4^10 ≈ 1e6 samples per pixel, 4000 times the chapters' largest (256).
    let budgets: Vec<u64> = (0..=10).map(|k| 4u64.pow(k)).collect();
    let reference = Image::filled(2, 2, Vec3::splat(0.5));
    let techniques = [Technique::new("independent", noisy_constant)];
    let records = run_convergence(&techniques, &budgets, &reference);
    assert_eq!(records.len(), budgets.len());
    for (record, &spp) in records.iter().zip(&budgets) {
        assert_eq!(record.spp, spp);
        assert!(
            record.seconds.is_finite() && record.seconds > 0.0,
            "{record:?}"
        );
        // RMSE² over the 12 pixel channels is σ²/spp times a χ² with 12 degrees of freedom
        // over 12, which lies in [0.16, 2.9] with probability 1 - 1e-4 (two-sided; fixed
        // seeds make the outcome the same on every run). A bias or a loss of precision at
        // large budgets would leave a floor the 1/sqrt(spp) law runs into.
        let normalised = record.rmse * (spp as f64).sqrt() / SIGMA;
        assert!(
            (0.4..1.7).contains(&normalised),
            "{spp} spp: RMSE {} is {normalised} times sigma/sqrt(spp)",
            record.rmse
        );
        // RELMSE is the same squared error over 0.5² + 0.01.
        let expected = record.rmse * record.rmse / 0.26;
        assert!(
            (record.relmse - expected).abs() <= 1e-9 * expected,
            "{record:?}"
        );
    }
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("convergence.csv");
    write_convergence_csv(&csv, &records).unwrap();
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.contains("independent,1048576,"), "{text}");
    plot_error_vs_time(&dir.path().join("error.png"), "long runs", &records).unwrap();
}

/// Side of chapter 08's furnace image: 16 pixels, each an independent estimate of 1.
const FURNACE_SIDE: u32 = 4;

/// Chapter 08's path tracer on its own white furnace (a white matte and a glass ball under a
/// sky of radiance 1, depth 1000, Mitsuba's roulette): every pixel's expected value is 1.
fn path_traced_furnace(spp: u64) -> Image {
    use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};

    use ch08_path_tracing::{Method, PathOptions, furnace, render_with};
    use common::scene::Material as Smooth;
    let white = Smooth::diffuse(Vec3::ONE);
    let glass = Smooth::glass(1.5);
    let scene = furnace::spheres(&[white, glass], 1000);
    let sampler = PixelSampler::new(PixelSamplerKind::Random, spp, spp).unwrap();
    let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
    let settings = RenderSettings {
        threads: Some(2),
        ..RenderSettings::new(FURNACE_SIDE, FURNACE_SIDE, spp)
    };
    let method = Method::new(PathOptions::with_depth(1000));
    let out = render_with(
        &scene,
        method,
        &ch04_depth_of_field::Lens::PINHOLE,
        &settings,
        &sampler,
        &filter,
    );
    assert_eq!(out.stats.nonfinite_samples, 0);
    out.image
}

#[test]
fn the_path_tracer_converges_without_a_floor_to_65536_samples_per_pixel() {
    let budgets: Vec<u64> = (0..=8).map(|k| 4u64.pow(k)).collect();
    let reference = Image::filled(FURNACE_SIDE, FURNACE_SIDE, Vec3::ONE);
    let techniques = [Technique::new("path", path_traced_furnace)];
    let records = run_convergence(&techniques, &budgets, &reference);
    // RMSE * sqrt(spp) estimates the noise of one sample, the same at every budget: the 16
    // pixels (the channels agree: everything is grey) make its square sigma^2 times a chi^2
    // with 16 degrees of freedom over 16, so it lies within [0.43, 1.61] sigma with probability
    // 1 - 1e-4. Sigma is not known for a path tracer: the geometric mean over the budgets up
    // to 256 spp, where no small bias can show, stands in for it (to within some 10%, hence
    // the wider band). A bias b leaves a floor under the RMSE: at 65536 spp it leaves the band
    // once b > sqrt(3) sigma / 256, here 0.08%.
    let normalised: Vec<f64> = records
        .iter()
        .map(|r| r.rmse * (r.spp as f64).sqrt())
        .collect();
    let small = &normalised[..5];
    let sigma = (small.iter().map(|x| x.ln()).sum::<f64>() / small.len() as f64).exp();
    for (record, n) in records.iter().zip(&normalised) {
        assert!(
            record.seconds.is_finite() && record.seconds > 0.0,
            "{record:?}"
        );
        assert!(
            (0.35..2.0).contains(&(n / sigma)),
            "{} spp: RMSE {} is {} times the typical sigma/sqrt(spp) ({sigma})",
            record.spp,
            record.rmse,
            n / sigma
        );
    }
}
