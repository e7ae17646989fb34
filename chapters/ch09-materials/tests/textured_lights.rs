//! A light whose radiance is a texture sends from each point its texture's colour there. A
//! path finds that light in two ways: by hitting it, where the texture is read at the hit's
//! `uv`, and by a light sample, where it is read at the `uv` of the point the sample picked.
//! Both must give the same direct light: the means of the two estimators (next-event
//! estimation alone, and BSDF rays alone) agree within 5 standard errors of their difference.
//!
//! The scene is the agreement scene `textured-more.xml`, lit mainly by a panel of four
//! squares of different colours, direct light only (two segments) and no MIS, so that every
//! light sample at a matte or rough surface counts in full.

mod support;

use ch08_path_tracing::{Method, MisHeuristic, PathOptions};

#[test]
fn light_samples_read_a_textured_light_where_they_land() {
    let scene = support::scene_file("textured-more.xml");
    let world = &scene.world.scene;
    // The floor's half of the image, which the panel lights (the upper half shows the
    // glowing wall, found alike by both estimators, which would only add to the mean).
    let (width, height) = (world.film.width, world.film.height);
    let pixels: Vec<_> = workbench::test_support::pixel_centre_grid(width, height / 2, 6)
        .into_iter()
        .map(|p| p + glam::Vec2::new(0.0, (height / 2) as f32))
        .collect();
    let direct = PathOptions {
        max_depth: 2,
        ..scene.options
    };
    let n = 8000;
    let by_light_samples = PathOptions {
        mis: MisHeuristic::None,
        ..direct
    };
    let by_hits = PathOptions {
        nee: false,
        ..direct
    };
    let (sampled, se_sampled) =
        support::estimate(&scene.world, Method::new(by_light_samples), &pixels, n, 1);
    let (hit, se_hit) = support::estimate(&scene.world, Method::new(by_hits), &pixels, n, 2);
    let tolerance = 5.0 * (se_sampled * se_sampled + se_hit * se_hit).sqrt();
    assert!(
        (sampled - hit).abs() <= tolerance,
        "light samples give {sampled}, hits {hit} (tolerance {tolerance}): is the light's \
         texture read at the sampled point's uv?"
    );
}
