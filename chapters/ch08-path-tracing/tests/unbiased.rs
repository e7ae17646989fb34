//! NEE, MIS and Russian roulette change the noise, never the mean: every variant must agree
//! with Mitsuba's default (NEE, power heuristic, roulette from 5) through the same film
//! positions, the difference of the means within 5 standard errors of the difference.
//!
//! The scene is the chapter's Cornell box (area light only: without NEE a point light could
//! not be found at all, so NEE off is *meant* to lose it), smaller and shallower to run fast.

mod support;

use ch08_path_tracing::{Method, MisHeuristic, PathOptions};

#[test]
fn nee_mis_and_roulette_variants_agree() {
    let scene = support::scene_file("cornell-box.xml");
    let world = &scene.world.scene;
    let pixels = workbench::test_support::pixel_centre_grid(world.film.width, world.film.height, 6);
    let base = PathOptions {
        max_depth: 5,
        ..scene.options
    };
    let n = 1500;
    let (reference, se_ref) = support::estimate(&scene.world, Method::new(base), &pixels, n, 1);
    for options in [
        PathOptions { nee: false, ..base },
        PathOptions {
            mis: MisHeuristic::None,
            ..base
        },
        PathOptions {
            mis: MisHeuristic::Balance,
            ..base
        },
        PathOptions {
            rr_depth: None,
            ..base
        },
        PathOptions {
            rr_depth: Some(1),
            ..base
        },
    ] {
        let (mean, se) = support::estimate(&scene.world, Method::new(options), &pixels, n, 2);
        let tolerance = 5.0 * (se * se + se_ref * se_ref).sqrt();
        assert!(
            (mean - reference).abs() <= tolerance,
            "{options:?}: {mean} vs {reference} (tolerance {tolerance})"
        );
    }
}
