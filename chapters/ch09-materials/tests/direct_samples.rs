//! Mitsuba's `direct` integrator with other sample counts than one of each: light samples
//! only, BSDF samples only, or several of both must all estimate the same image as the path
//! tracer cut after one bounce, on Veach's plates, where the two strategies differ most
//! (sharp plates under big lights, rough ones under small lights). A count not divided out,
//! or a heuristic that forgets the counts, moves the mean by far more than its noise.

mod support;
use ch08_path_tracing::{Method, PathOptions};
use common::scene::DirectSamples;
use support::{estimate, render_text, scene_file};
use workbench::test_support::pixel_centre_grid;

#[test]
fn every_sample_count_estimates_the_same_direct_light() {
    let file = scene_file("veach-plates.xml");
    let film = file.world.scene.film;
    // Film positions over the plates and the lights' reflections.
    let pixels: Vec<_> = pixel_centre_grid(film.width, film.height, 8)
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

/// A matte floor under one point light, rendered by the binary with `emitter_samples` light
/// samples and no BSDF sample; the image's mean.
fn point_lit_floor(emitter_samples: u32) -> f64 {
    let image = render_text(&format!(
        r#"<scene version="3.0.0">
    <integrator type="direct"><integer name="emitter_samples" value="{emitter_samples}"/>
        <integer name="bsdf_samples" value="0"/></integrator>
    <sensor type="perspective"><float name="fov" value="40"/>
        <transform name="to_world"><lookat origin="0, 2, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
        <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
        <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="12"/>
            <rfilter type="box"/></film></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.5"/></bsdf></shape>
    <emitter type="point"><point name="position" x="0" y="2" z="0"/><rgb name="intensity" value="5"/></emitter>
</scene>"#
    ));
    image.pixels.iter().map(|p| f64::from(p.y)).sum::<f64>() / image.pixels.len() as f64
}

#[test]
fn point_lights_count_once_per_emitter_sample_as_in_mitsuba() {
    // Mitsuba 3.9.1 renders this floor 4.00 times as bright with 4 emitter samples as with
    // 1: it weighs a point light's sample by 1 where other lights' are divided by the count.
    // Files written for Mitsuba are lit for what it shows, so chapter 08 does the same.
    let (one, four) = (point_lit_floor(1), point_lit_floor(4));
    assert!(one > 0.0, "the floor is lit");
    assert!(
        (four / one - 4.0).abs() < 1e-4,
        "4 emitter samples give {four}, 1 gives {one}: Mitsuba's point lights are counted at \
         every emitter sample (ratio 4), found ratio {}",
        four / one
    );
}
