//! Mitsuba's `direct` integrator with other sample counts than one of each: light samples
//! only, BSDF samples only, or several of both must all estimate the same image as the path
//! tracer cut after one bounce, on Veach's plates, where the two strategies differ most
//! (sharp plates under big lights, rough ones under small lights). A count not divided out,
//! or a heuristic that forgets the counts, moves the mean by far more than its noise.

mod support;
use ch08_path_tracing::{Method, PathOptions};
use common::scene::DirectSamples;
use support::{estimate, grid, scene_file};

#[test]
fn every_sample_count_estimates_the_same_direct_light() {
    let file = scene_file("veach-plates.xml");
    let film = file.world.scene.film;
    // Film positions over the plates and the lights' reflections.
    let pixels: Vec<_> = grid(film.width, film.height, 8)
        .into_iter()
        .filter(|p| p.y > 0.4 * film.height as f32)
        .collect();
    let with = |direct: Option<DirectSamples>| {
        let options = PathOptions {
            direct,
            ..file.options
        };
        estimate(&file.world, Method::new(options), &pixels, 1500, 7)
    };
    let (expected, expected_se) = with(None);
    assert!(expected > 0.0, "the plates are lit");
    for (emitter, bsdf) in [(4, 0), (0, 4), (3, 2), (1, 3)] {
        let (mean, se) = with(Some(DirectSamples { emitter, bsdf }));
        let tolerance = 4.0 * (se * se + expected_se * expected_se).sqrt();
        assert!(
            (mean - expected).abs() <= tolerance,
            "emitter_samples {emitter}, bsdf_samples {bsdf}: mean {mean:.5} ± {se:.5}, but one \
             sample of each gives {expected:.5} ± {expected_se:.5} (ratio {:.3}). Is each \
             sample divided by the count of its kind, and does the heuristic weigh each \
             density by its count?",
            mean / expected
        );
    }
}
