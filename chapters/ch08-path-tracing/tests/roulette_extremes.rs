//! Russian roulette at its extremes: a throughput near 0, where a survivor's factor is
//! enormous, and near 1, where the chance of surviving is capped at 0.95 so that even a white
//! furnace ends. The factor must stay finite, the game fair, and renders finite and unbiased.
//! `beta` is what the roulette is given: the throughput's largest channel, its radiance
//! scaling removed.

mod support;

use ch03_anti_aliasing::{FilterKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch08_path_tracing::furnace::spheres;
use ch08_path_tracing::roulette::{MAX_SURVIVAL, russian_roulette};
use ch08_path_tracing::{Method, PathOptions, render_with};
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use common::scene::Material as Smooth;
use glam::{Vec2, Vec3};

/// The step between the uniform numbers a sampler hands out (`common::sampler::unit_f32`).
const U_STEP: f32 = 1.0 / (1u32 << 24) as f32;

/// The chance that a path of throughput `beta` survives, found without knowing the rule: the
/// smallest `u` that ends it, by bisection over the positive floats in order (their bit
/// patterns are ordered as they are), given that small `u` survive and large `u` end.
fn survival_chance(beta: f32) -> f32 {
    let (mut survives, mut ends) = (0u32, 1.0f32.to_bits());
    assert!(russian_roulette(beta, 0.0).is_some() && russian_roulette(beta, 1.0).is_none());
    while ends - survives > 1 {
        let middle = survives + (ends - survives) / 2;
        if russian_roulette(beta, f32::from_bits(middle)).is_some() {
            survives = middle;
        } else {
            ends = middle;
        }
    }
    f32::from_bits(ends)
}

#[test]
fn near_zero_the_factor_is_finite_and_the_game_fair_on_the_samplers_numbers() {
    // From the smallest normal float up (below it, a survivor's factor would overflow f32).
    for beta in [f32::MIN_POSITIVE, 1e-30, 1e-12, 1e-7, 1e-4, 1e-3] {
        // The smallest u survives, with a finite factor that makes up exactly for the chance
        // of surviving (found by bisection), which is the throughput itself down here.
        let factor = russian_roulette(beta, 0.0).expect("u = 0 survives any chance above 0");
        let chance = survival_chance(beta);
        assert_eq!(chance, beta, "{beta}: the chance of surviving");
        assert!(factor.is_finite(), "{beta}: {factor}");
        assert!(
            (f64::from(chance) * f64::from(factor) - 1.0).abs() <= f64::from(f32::EPSILON),
            "{beta}: the chance {chance} times the factor {factor}"
        );
        assert_eq!(
            russian_roulette(beta, beta),
            None,
            "{beta}: u at the chance of surviving ends the path"
        );
        assert_eq!(russian_roulette(beta, 0.5), None, "{beta}");
        // Fair on the numbers a sampler can give, k · 2^-24: the survivors are the
        // ceil(β 2^24) values below β, so the mean factor is 1 to within 1 / (β 2^24).
        let survivors = (0u32..)
            .take_while(|&k| russian_roulette(beta, k as f32 * U_STEP).is_some())
            .count() as f64;
        let grid = f64::from(beta) / f64::from(U_STEP);
        if grid >= 1.0 {
            let mean = survivors * f64::from(U_STEP) * f64::from(factor);
            assert!(
                (mean - 1.0).abs() <= 1.0 / grid,
                "{beta}: mean factor {mean}"
            );
        } else {
            assert_eq!(survivors, 1.0, "{beta}: only u = 0 is below the chance");
        }
    }
}

#[test]
fn near_one_the_survival_is_capped_so_every_path_ends() {
    let below = MAX_SURVIVAL - f32::EPSILON;
    for beta in [
        below,
        MAX_SURVIVAL,
        1.0 - U_STEP,
        1.0,
        1.0 + f32::EPSILON,
        1e30,
        f32::MAX,
    ] {
        // Below the cap the chance is the throughput; at and above it, the cap.
        let chance = survival_chance(beta);
        let capped = if beta < MAX_SURVIVAL {
            beta
        } else {
            MAX_SURVIVAL
        };
        assert_eq!(chance, capped, "{beta}: the chance of surviving");
        let factor = russian_roulette(beta, chance - U_STEP).expect("survives below the chance");
        assert!(
            (f64::from(chance) * f64::from(factor) - 1.0).abs() <= f64::from(f32::EPSILON),
            "{beta}: the chance {chance} times the factor {factor}"
        );
        // A path of throughput 1 or more still ends one time in twenty.
        assert_eq!(russian_roulette(beta, chance), None, "{beta}");
        assert_eq!(russian_roulette(beta, 1.0 - U_STEP), None, "{beta}");
        // The mean factor over u (midpoints of 10⁵ cells) is 1.
        let n = 100_000;
        let mean = (0..n)
            .map(|i| f64::from(russian_roulette(beta, (i as f32 + 0.5) / n as f32).unwrap_or(0.0)))
            .sum::<f64>()
            / f64::from(n);
        assert!((mean - 1.0).abs() < 1e-4, "{beta}: {mean}");
    }
}

/// The furnace camera's centre (64 x 48) and two points beside it, all on the spheres.
const PIXELS: [Vec2; 3] = [
    Vec2::new(32.5, 24.5),
    Vec2::new(29.5, 29.5),
    Vec2::new(36.5, 22.5),
];

/// Roulette from the first bounce on, as deep as a path likes.
fn roulette_from_the_start() -> PathOptions {
    PathOptions {
        rr_depth: Some(1),
        ..PathOptions::with_depth(1000)
    }
}

#[test]
fn roulette_at_throughput_one_keeps_the_white_furnace_at_one() {
    // White spheres and glass keep the throughput (radiance scaling removed) at 1: every
    // bounce plays at the cap, surviving 19 times in 20, and its survivors make up for the
    // paths that ended.
    let white = Smooth::diffuse(Vec3::ONE);
    let glass = Smooth::glass(1.5);
    for materials in [
        [white.clone(), white.clone(), white.clone()],
        [glass.clone(), white, glass],
    ] {
        let scene = spheres(&materials, 1000);
        let method = Method::new(roulette_from_the_start());
        let (mean, se) = support::estimate(&scene, method, &PIXELS, 5000, 11);
        eprintln!("furnace, roulette from 1: {mean:.5} ± {se:.5}");
        assert!(
            (mean - 1.0).abs() <= 5.0 * se + 1e-4,
            "{materials:?}: {mean} ± {se}"
        );
    }
}

#[test]
fn roulette_at_throughput_near_zero_is_unbiased_and_finite() {
    // A dark convex sphere in the furnace sends back exactly its albedo; after the first
    // bounce the path survives one time in fifty, and its survivors make up for the rest.
    let albedo = 0.02;
    let dark = spheres(&[Smooth::diffuse(Vec3::splat(albedo))], 1000);
    let method = Method::new(roulette_from_the_start());
    let (mean, se) = support::estimate(&dark, method, &PIXELS, 10_000, 12);
    eprintln!("albedo {albedo}, roulette from 1: {mean:.5} ± {se:.5}");
    assert!(
        (mean - f64::from(albedo)).abs() <= 5.0 * se + 1e-6,
        "{mean} ± {se}"
    );
    // Far darker, touching spheres: throughputs of 1e-6, 1e-12 ... 1e-40 and their survivors.
    for albedo in [1e-6, 1e-20] {
        let materials = vec![Smooth::diffuse(Vec3::splat(albedo)); 3];
        let out = render_with(
            &spheres(&materials, 1000),
            method,
            &Lens::PINHOLE,
            &RenderSettings::new(16, 16, 16),
            &IndependentSampler::new(13),
            &ReconstructionFilter::new(FilterKind::Box, None).unwrap(),
        );
        assert_eq!(out.stats.nonfinite_samples, 0, "albedo {albedo}");
        assert!(out.image.pixels.iter().all(|p| p.is_finite()));
    }
}
