//! The white furnace: white surfaces in a world of radiance 1 must send back exactly 1.
//!
//! A convex white matte sphere sends every reflected path straight to the sky, so every depth
//! limit of 2 or more gives 1 there; depth 1 sees only what glows (the sky, not the sphere).
//! Glass and several spheres need more bounces, which Russian roulette or a depth of 1000
//! allows. Tolerance: 5 standard errors of the mean (plus float rounding), from the samples.

mod support;

use ch08_path_tracing::furnace::spheres;
use ch08_path_tracing::{Method, MisHeuristic, PathOptions};
use common::scene::Material as Smooth;
use common::scene::Material;
use glam::{Vec2, Vec3};

/// The image centre of the furnace camera (64 x 48), which sees the spheres.
const CENTRE: Vec2 = Vec2::new(32.5, 24.5);

fn variants(max_depth: u32) -> Vec<PathOptions> {
    let base = PathOptions::with_depth(max_depth);
    vec![
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
        PathOptions {
            rr_depth: None,
            ..base
        },
    ]
}

fn assert_one(materials: &[Material], max_depth: u32, n: u64) {
    let scene = spheres(materials, max_depth);
    for options in variants(max_depth) {
        let pixels = [
            CENTRE,
            CENTRE + Vec2::new(-3.0, 5.0),
            CENTRE + Vec2::new(4.0, -2.0),
        ];
        let (mean, se) = support::estimate(&scene, Method::new(options), &pixels, n, 7);
        eprintln!(
            "furnace depth {max_depth} nee {} {:?} rr {:?}: {mean:.5} ± {se:.5}",
            options.nee, options.mis, options.rr_depth
        );
        assert!(
            (mean - 1.0).abs() <= 5.0 * se + 1e-4,
            "{materials:?} depth {max_depth} {options:?}: {mean} ± {se}"
        );
    }
}

#[test]
fn a_white_matte_sphere_gives_one_at_every_depth_from_two() {
    let white = Smooth::diffuse(Vec3::ONE);
    for depth in [2, 3, 8, 1000] {
        assert_one(std::slice::from_ref(&white), depth, 400);
    }
}

#[test]
fn depth_one_sees_only_the_sky() {
    let scene = spheres(&[Smooth::diffuse(Vec3::ONE)], 1);
    let method = Method::new(PathOptions::with_depth(1));
    let (sphere, _) = support::estimate(&scene, method, &[CENTRE], 50, 1);
    assert_eq!(sphere, 0.0);
    let (sky, _) = support::estimate(&scene, method, &[Vec2::new(0.5, 0.5)], 50, 1);
    assert_eq!(sky, 1.0);
}

#[test]
fn touching_spheres_glass_and_glossy_give_one_with_enough_bounces() {
    let white = Smooth::diffuse(Vec3::ONE);
    let glass = Smooth::glass(1.5);
    let glossy = Material::glossy(Vec3::ONE, 20.0);
    assert_one(&[white.clone(), white.clone(), white.clone()], 1000, 300);
    assert_one(&[glass.clone(), glossy, white], 1000, 300);
    assert_one(&[glass.clone(), glass.clone(), glass], 1000, 300);
}
