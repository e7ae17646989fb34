//! The optimal combination on whole renders: no noise where the integrand is a combination of
//! the two densities, and the same image as chapter 08's heuristics elsewhere, on average.

use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch08_path_tracing::MisHeuristic;
use ch10_optimal_mis::{Combination, render_direct};
use common::image::Image;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;

mod support;
use support::{mean, mean_and_error};

/// The scene `text`, ready to trace.
fn world(text: &str) -> MotionScene {
    support::world(text, "test.xml")
}

/// `world` rendered at its film's size with `spp` samples per pixel, combined as `combination`.
fn render(world: &MotionScene, spp: u64, seed: u64, combination: Combination) -> Image {
    let film = world.scene.film;
    let settings = RenderSettings::new(film.width, film.height, spp);
    let sampler = IndependentSampler::new(seed);
    render_direct(world, &Lens::PINHOLE, &settings, &sampler, combination).image
}

/// A matte plane filling the view under a constant sky, nothing between them.
const PLANE_UNDER_SKY: &str = r#"<scene version="3.0.0">
    <sensor type="perspective"><float name="fov" value="40"/>
        <transform name="to_world"><lookat origin="0, 1, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="16"/>
            <rfilter type="box"/></film></sensor>
    <emitter type="constant"><rgb name="radiance" value="2"/></emitter>
    <shape type="rectangle"><transform name="to_world"><scale value="20"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.5, 0.25, 0.125"/></bsdf></shape>
</scene>"#;

/// The largest distance of a pixel from `expected`, over every channel.
fn largest_error(image: &Image, expected: glam::Vec3) -> f32 {
    image
        .pixels
        .iter()
        .map(|p| (*p - expected).abs().max_element())
        .fold(0.0, f32::max)
}

/// Under a constant sky, the BSDF's cosine density is the integrand up to a constant factor
/// (`f = ρ L cos θ / π = ρ L p_BSDF`), so the optimal weights give the BSDF sample everything
/// and every pixel is exactly `ρ L`, from a few samples; the balance and power heuristics give
/// the uniform sky sample a share, and with it noise.
#[test]
fn a_plane_under_a_constant_sky_has_no_noise_with_the_optimal_weights() {
    let world = world(PLANE_UNDER_SKY);
    let expected = glam::Vec3::new(1.0, 0.5, 0.25);
    let optimal = render(&world, 4, 1, Combination::Optimal);
    let error = largest_error(&optimal, expected);
    assert!(
        error < 1e-4,
        "every pixel of the plane should be exactly ρ L = {expected} with the optimal weights, \
         but one is {error} away: is α solved from A and b of the same samples, and the \
         estimate the sum of α?"
    );
    for heuristic in [MisHeuristic::Balance, MisHeuristic::Power] {
        let image = render(&world, 4, 1, Combination::Heuristic(heuristic));
        let error = largest_error(&image, expected);
        assert!(
            error > 1e-2,
            "{heuristic:?} should be noisy here, its largest error is only {error}"
        );
    }
}

/// A sphere light and a dim sky over a plastic floor with a box on it: occlusion, empty
/// samples, and BSDF samples that take the plastic's smooth coat, a delta lobe no light sample
/// can draw (the BSDF technique fails), while the sky makes the BSDF technique's share large;
/// both techniques good somewhere.
const LIT_FLOOR: &str = r#"<scene version="3.0.0">
    <sensor type="perspective"><float name="fov" value="45"/>
        <transform name="to_world"><lookat origin="0, 1, 6" target="0, 0.3, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="16"/>
            <rfilter type="box"/></film></sensor>
    <emitter type="constant"><rgb name="radiance" value="0.5"/></emitter>
    <shape type="sphere"><point name="center" x="0.5" y="2" z="0"/><float name="radius" value="0.4"/>
        <emitter type="area"><rgb name="radiance" value="10"/></emitter></shape>
    <shape type="rectangle"><transform name="to_world"><scale value="4"/><rotate x="1" angle="-90"/></transform>
        <bsdf type="plastic"><rgb name="diffuse_reflectance" value="0.4"/></bsdf></shape>
    <shape type="cube"><transform name="to_world"><scale value="0.5"/><translate x="-1" y="0.5"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.6"/></bsdf></shape>
</scene>"#;

/// A sphere light over a glossy metal floor with a matte box on it, seen from above, the
/// light itself out of view: the BSDF sample is good on the floor's highlight, the light
/// sample on the box.
const GLOSSY_FLOOR: &str = r#"<scene version="3.0.0">
    <sensor type="perspective"><float name="fov" value="45"/>
        <transform name="to_world"><lookat origin="0, 3, 6" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="16"/>
            <rfilter type="box"/></film></sensor>
    <shape type="sphere"><point name="center" x="0.5" y="2" z="0"/><float name="radius" value="0.4"/>
        <emitter type="area"><rgb name="radiance" value="10"/></emitter></shape>
    <shape type="rectangle"><transform name="to_world"><scale value="4"/><rotate x="1" angle="-90"/></transform>
        <bsdf type="roughconductor"><float name="alpha" value="0.15"/></bsdf></shape>
    <shape type="cube"><transform name="to_world"><scale value="0.5"/><translate x="-1" y="0.5"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.6"/></bsdf></shape>
</scene>"#;

/// Consistency: over seeds, the optimal image's mean is the power heuristic's, within their
/// noise. A BSDF sample that takes the plastic's coat is a failed sample of the BSDF
/// technique, so `α` summed without the share of samples that drew a direction moves the mean
/// by far more than the noise.
#[test]
fn the_optimal_combination_estimates_the_heuristics_image() {
    let world = world(LIT_FLOOR);
    let means = |combination| -> Vec<f64> {
        (1..=6)
            .map(|seed| mean(&render(&world, 64, seed, combination)))
            .collect()
    };
    let (power, power_se) = mean_and_error(&means(Combination::Heuristic(MisHeuristic::Power)));
    for combination in [Combination::Optimal, Combination::Progressive] {
        let (optimal, optimal_se) = mean_and_error(&means(combination));
        let tolerance = 4.0 * (optimal_se * optimal_se + power_se * power_se).sqrt();
        assert!(
            (optimal - power).abs() <= tolerance,
            "the {} combination's image has mean {optimal:.5} ± {optimal_se:.5}, the power \
             heuristic's {power:.5} ± {power_se:.5}: is each technique's α scaled by the share \
             of its samples that drew a direction?",
            combination.name()
        );
    }
}

/// At equal samples the optimal weights are less noisy than the balance heuristic they fall
/// back on (measured: 15 to 20 % less mean squared error here), and no noisier than the power
/// heuristic (1 to 4 % less).
#[test]
fn the_optimal_combination_has_less_error_than_the_balance_heuristic() {
    let world = world(GLOSSY_FLOOR);
    let reference = render(
        &world,
        1024,
        99,
        Combination::Heuristic(MisHeuristic::Power),
    );
    let mse = |image: &Image| {
        image
            .pixels
            .iter()
            .zip(&reference.pixels)
            .map(|(a, b)| f64::from((*a - *b).length_squared()))
            .sum::<f64>()
            / image.pixels.len() as f64
    };
    let total = |combination| -> f64 {
        (1..=4)
            .map(|seed| mse(&render(&world, 16, seed, combination)))
            .sum()
    };
    let optimal = total(Combination::Optimal);
    let balance = total(Combination::Heuristic(MisHeuristic::Balance));
    let power = total(Combination::Heuristic(MisHeuristic::Power));
    assert!(
        optimal < 0.95 * balance && optimal < 1.05 * power,
        "mean squared error at 16 samples per pixel: optimal {optimal:.4e}, balance \
         {balance:.4e}, power {power:.4e}"
    );
}
