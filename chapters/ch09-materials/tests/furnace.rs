//! The white furnace with Mitsuba's materials: white surfaces in a world of radiance 1 must
//! send back exactly 1, however much of them a mask cuts out. Tolerance: 5 standard errors of
//! the mean (plus float rounding), from the samples.

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

/// `nested` behind a mask of uniform `opacity`.
fn masked(opacity: f32, nested: Material) -> Material {
    Material::Mask(common::scene::Mask {
        opacity: common::scene::Opacity::Uniform(opacity),
        nested: Box::new(nested),
    })
}

#[test]
fn a_white_sphere_with_a_cut_out_gives_one_and_a_transparent_black_one_is_not_seen() {
    // Light passes through where the surface is not: inside, the two-sided white sphere's
    // back face scatters the rest, so the furnace stays white at every opacity.
    for opacity in [0.3, 1.0] {
        assert_one(
            &[masked(opacity, Smooth::two_sided_diffuse(Vec3::ONE))],
            1000,
            300,
        );
    }
    // Opacity 0: a black sphere that is not there; paths pass on and find the sky.
    assert_one(&[masked(0.0, Smooth::diffuse(Vec3::ZERO))], 8, 50);
}
