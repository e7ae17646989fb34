//! Light from an environment map (Mitsuba's `envmap`) in the path tracer.
//!
//! - A map of constant value is the constant environment: a white sphere in the furnace gives 1 with the
//!   map, with the constant, and with the two together, with and without light sampling.
//! - Under a map with a sun, the three estimators (BSDF rays only, light samples only, MIS)
//!   agree: the density a light sample is drawn with is the one MIS weighs a BSDF ray by.
//! - A map with one pixel of 10²⁰, or black, never puts NaN or infinity in a pixel.
//!
//! Tolerance: 5 standard errors of the mean, from the samples.

mod support;

use ch05_motion_blur::MotionScene;
use ch08_path_tracing::furnace::spheres;
use ch08_path_tracing::{Method, MisHeuristic, PathOptions};
use common::scene::{EnvironmentMap, Material};
use glam::{Mat3, Vec2, Vec3};

/// The image centre of the furnace camera (64 x 48), which sees the spheres.
const CENTRE: Vec2 = Vec2::new(32.5, 24.5);

/// A `width` x `height` map of `colour(x, y)`, turned by `to_world`.
fn map_of(
    width: u32,
    height: u32,
    to_world: Mat3,
    colour: impl Fn(u32, u32) -> Vec3,
) -> EnvironmentMap {
    let mut pixels = Vec::new();
    for y in 0..height {
        for x in 0..width {
            pixels.push(colour(x, y));
        }
    }
    EnvironmentMap::new(width, height, &pixels, 1.0, to_world).unwrap()
}

/// The furnace's white spheres with `constant` and `map` for environment.
fn furnace(
    materials: &[Material],
    max_depth: u32,
    constant: Vec3,
    map: EnvironmentMap,
) -> MotionScene {
    let mut world = spheres(materials, max_depth);
    world.scene.environment = constant;
    world.scene.environment_map = Some(map);
    world
}

fn estimators(max_depth: u32) -> [PathOptions; 4] {
    let base = PathOptions::with_depth(max_depth);
    [
        PathOptions { nee: false, ..base },
        PathOptions {
            mis: MisHeuristic::None,
            ..base
        },
        PathOptions {
            mis: MisHeuristic::Balance,
            ..base
        },
        base,
    ]
}

fn pixels() -> [Vec2; 3] {
    [
        CENTRE,
        CENTRE + Vec2::new(-3.0, 5.0),
        CENTRE + Vec2::new(4.0, -2.0),
    ]
}

#[test]
fn a_constant_map_is_the_constant_environment_in_the_furnace() {
    let white = Material::diffuse(Vec3::ONE);
    let turned = Mat3::from_rotation_x(0.7) * Mat3::from_rotation_y(2.0);
    let cases = [
        (
            "a map of 1",
            Vec3::ZERO,
            map_of(8, 5, Mat3::IDENTITY, |_, _| Vec3::ONE),
        ),
        (
            "a turned map of 1",
            Vec3::ZERO,
            map_of(7, 4, turned, |_, _| Vec3::ONE),
        ),
        (
            "0.25 and a map of 0.75",
            Vec3::splat(0.25),
            map_of(6, 3, turned, |_, _| Vec3::splat(0.75)),
        ),
    ];
    for (what, constant, map) in cases {
        for depth in [2, 5] {
            let scene = furnace(std::slice::from_ref(&white), depth, constant, map.clone());
            for options in estimators(depth) {
                let (mean, se) = support::estimate(&scene, Method::new(options), &pixels(), 300, 3);
                eprintln!("{what}, depth {depth}, {options:?}: {mean:.5} ± {se:.5}");
                assert!(
                    (mean - 1.0).abs() <= 5.0 * se + 1e-4,
                    "{what}, depth {depth}, {options:?}: {mean} ± {se}, expected 1"
                );
            }
        }
    }
}

/// A blue sky brightening towards the top with a sun of `sun` in one pixel, 24 x 12.
fn sunny(sun: f32, to_world: Mat3) -> EnvironmentMap {
    map_of(24, 12, to_world, |x, y| {
        if (x, y) == (7, 3) {
            Vec3::new(1.0, 0.9, 0.8) * sun
        } else {
            Vec3::new(0.2, 0.3, 0.6) * (1.0 + 0.2 * (12 - y) as f32)
        }
    })
}

#[test]
fn light_samples_bsdf_rays_and_mis_agree_under_a_sky_with_a_sun() {
    let turned = Mat3::from_rotation_z(0.4) * Mat3::from_rotation_y(-1.1);
    let scene = furnace(
        &[
            Material::diffuse(Vec3::splat(0.7)),
            Material::diffuse(Vec3::splat(0.5)),
        ],
        3,
        Vec3::splat(0.05),
        sunny(40.0, turned),
    );
    let mut estimates = Vec::new();
    for options in estimators(3) {
        let (mean, se) = support::estimate(&scene, Method::new(options), &pixels(), 30_000, 11);
        eprintln!("{options:?}: {mean:.5} ± {se:.5}");
        estimates.push((options, mean, se));
    }
    // BSDF rays alone do not use the map's density at all: the others must agree with them.
    let (_, reference, reference_se) = estimates[0];
    for (options, mean, se) in estimates {
        let tolerance = 5.0 * (se * se + reference_se * reference_se).sqrt();
        assert!(
            (mean - reference).abs() <= tolerance,
            "{options:?} gives {mean} ± {se}, BSDF rays alone {reference} ± {reference_se}"
        );
    }
}

#[test]
fn extreme_maps_never_give_nan_or_infinity() {
    let hot = map_of(32, 16, Mat3::IDENTITY, |x, y| {
        if (x, y) == (3, 2) {
            Vec3::splat(1e20)
        } else {
            Vec3::ZERO
        }
    });
    let black = map_of(4, 2, Mat3::IDENTITY, |_, _| Vec3::ZERO);
    let polar = map_of(3, 2, Mat3::IDENTITY, |_, y| {
        if y == 0 { Vec3::ONE } else { Vec3::ZERO }
    });
    let metal = Material::mirror();
    for (what, map) in [
        ("a hot pixel", hot),
        ("black", black),
        ("light at the pole only", polar),
    ] {
        let scene = furnace(
            &[Material::diffuse(Vec3::ONE), metal.clone()],
            6,
            Vec3::ZERO,
            map,
        );
        let out = support::render_pinhole(&scene, PathOptions::with_depth(6), (32, 24, 16), 5);
        assert_eq!(out.stats.nonfinite_samples, 0, "{what}");
        assert!(out.image.pixels.iter().all(|p| p.is_finite()), "{what}");
    }
}
