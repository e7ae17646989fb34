//! The combinations along whole paths, per depth: the power heuristic renders chapter 08's
//! image sample for sample, and the optimal combinations estimate the same image.

use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::lab::scene_file::path_options;
use ch08_path_tracing::{Method, MisHeuristic, render_with_materials};
use ch09_materials::SceneMaterials;
use ch10_optimal_mis::{Combination, render_direct_with, render_path_with};
use common::film::PixelBoxFilter;
use common::image::Image;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;

/// A small closed room under a ceiling lamp, every surface matte, paths of up to seven
/// segments with roulette from the fourth.
const ROOM: &str = r#"<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value="7"/><integer name="rr_depth" value="4"/></integrator>
    <sensor type="perspective"><float name="fov" value="60"/>
        <transform name="to_world"><lookat origin="0, 1, 0.95" target="0, 0.9, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="12"/><integer name="height" value="9"/>
            <rfilter type="box"/></film></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="0.3"/><rotate x="1" angle="90"/><translate y="1.99"/></transform>
        <emitter type="area"><rgb name="radiance" value="12"/></emitter></shape>
    <shape type="cube"><transform name="to_world"><scale x="1" y="1" z="1"/><translate y="1"/></transform>
        <bsdf type="twosided"><bsdf type="diffuse"><rgb name="reflectance" value="0.7, 0.6, 0.5"/></bsdf></bsdf></shape>
    <shape type="cube"><transform name="to_world"><scale value="0.3"/><translate x="0.3" y="0.3" z="-0.2"/></transform>
        <bsdf type="diffuse"/></shape>
    <shape type="rectangle"><transform name="to_world"><scale value="0.99"/><rotate x="1" angle="-90"/><translate y="0.01"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.4"/></bsdf></shape>
</scene>"#;

/// An open scene: a plastic floor with a matte box and a rough metal box under a small sphere
/// light and a dim sky, so that roulette and the failed samples (the plastic's coat) take
/// part. Most paths leave for the sky after a bounce or two, so a pixel's paths
/// reach the deeper vertices only now and then, some first after many samples.
const OPEN: &str = r#"<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value="6"/><integer name="rr_depth" value="3"/></integrator>
    <sensor type="perspective"><float name="fov" value="45"/>
        <transform name="to_world"><lookat origin="0, 1, 6" target="0, 0.3, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="12"/><integer name="height" value="8"/>
            <rfilter type="box"/></film></sensor>
    <emitter type="constant"><rgb name="radiance" value="0.3"/></emitter>
    <shape type="sphere"><point name="center" x="0.5" y="2" z="0"/><float name="radius" value="0.4"/>
        <emitter type="area"><rgb name="radiance" value="10"/></emitter></shape>
    <shape type="rectangle"><transform name="to_world"><scale value="4"/><rotate x="1" angle="-90"/></transform>
        <bsdf type="plastic"><rgb name="diffuse_reflectance" value="0.4"/></bsdf></shape>
    <shape type="cube"><transform name="to_world"><scale value="0.5"/><translate x="-1" y="0.5"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.8"/></bsdf></shape>
    <shape type="cube"><transform name="to_world"><scale value="0.4"/><translate x="0.9" y="0.4" z="0.5"/></transform>
        <bsdf type="roughconductor"><float name="alpha" value="0.1"/></bsdf></shape>
</scene>"#;

mod support;
use support::{mean, mean_and_error};

/// The scene `text`, ready to trace.
fn world(text: &str) -> MotionScene {
    support::world(text, "room.xml")
}

fn settings(world: &MotionScene, spp: u64) -> RenderSettings {
    let film = world.scene.film;
    RenderSettings::new(film.width, film.height, spp)
}

/// `world`'s paths with `spp` samples per pixel, combined as `combination` at every depth.
fn paths(world: &MotionScene, spp: u64, seed: u64, combination: Combination) -> Image {
    let materials = SceneMaterials::of(&world.scene, FuzzMethod::Lobe);
    let options = path_options(&world.scene);
    let sampler = IndependentSampler::new(seed);
    let settings = settings(world, spp);
    render_path_with(
        world,
        materials,
        options,
        &Lens::PINHOLE,
        &settings,
        &sampler,
        combination,
    )
    .image
}

/// The largest difference between two images, relative to the brighter pixel (and to 1e-3).
fn largest_relative_difference(a: &Image, b: &Image) -> f32 {
    a.pixels
        .iter()
        .zip(&b.pixels)
        .map(|(a, b)| ((*a - *b).abs() / a.max(*b).max(glam::Vec3::splat(1e-3))).max_element())
        .fold(0.0, f32::max)
}

/// `world`'s image by chapter 08's path tracer, each pixel from its own samples.
fn chapter_08(world: &MotionScene, spp: u64, seed: u64) -> Image {
    let materials = SceneMaterials::of(&world.scene, FuzzMethod::Lobe);
    let method = Method::new(path_options(&world.scene));
    let sampler = IndependentSampler::new(seed);
    let settings = settings(world, spp);
    render_with_materials(
        world,
        method,
        materials,
        &Lens::PINHOLE,
        &settings,
        &sampler,
        &PixelBoxFilter,
    )
    .image
}

/// With the power heuristic at every vertex, the paths draw chapter 08's random numbers in
/// chapter 08's order and weigh its samples with its weights: in a matte room every pixel is
/// chapter 08's, up to rounding (the floats are multiplied in another order, measured 0.4 % at
/// most, where it decides a roulette the other way). A light sample without the throughput
/// that reaches its vertex changes pixels by more than half.
#[test]
fn the_power_heuristic_along_paths_renders_chapter_08s_image() {
    let world = world(ROOM);
    let power = paths(&world, 16, 7, Combination::Heuristic(MisHeuristic::Power));
    let chapter_08 = chapter_08(&world, 16, 7);
    assert!(
        mean(&chapter_08) > 0.05,
        "the room is dark ({}): is the camera inside it?",
        mean(&chapter_08)
    );
    let difference = largest_relative_difference(&power, &chapter_08);
    assert!(
        difference < 0.02,
        "a pixel of the power heuristic along paths differs from chapter 08's by {difference} \
         (relative): are the light sample and the BSDF sample taken at every vertex, with the \
         throughput that reaches it, and the depth counted as chapter 08 counts it?"
    );
}

/// Cut after one bounce, the paths are chapter 10's direct light.
#[test]
fn paths_of_two_segments_are_the_direct_light() {
    let world = world(&ROOM.replace(r#"value="7""#, r#"value="2""#));
    let materials = SceneMaterials::of(&world.scene, FuzzMethod::Lobe);
    let options = path_options(&world.scene);
    assert_eq!(options.max_depth, 2);
    for combination in Combination::ALL {
        let sampler = IndependentSampler::new(3);
        let direct = render_direct_with(
            &world,
            materials.clone(),
            options,
            &Lens::PINHOLE,
            &settings(&world, 16),
            &sampler,
            combination,
        )
        .image;
        let along_paths = paths(&world, 16, 3, combination);
        let difference = largest_relative_difference(&along_paths, &direct);
        assert!(
            difference < 1e-4,
            "{}: paths of two segments differ from the direct light by {difference}",
            combination.name()
        );
    }
}

/// Over seeds, the combinations along paths give chapter 08's image, within their noise (the
/// plastic's BSDF technique weighs its samples with its density `pdf`, chapter 08 with the
/// density its sample reports, so the power heuristic is not chapter 08's sample for sample
/// here). A depth that a pixel's paths first reach late must count the earlier samples as
/// samples that drew nothing there; without them its `α` is scaled by too large a share and the
/// deep light comes out too bright.
#[test]
fn the_optimal_combinations_along_paths_estimate_the_same_image() {
    let world = world(OPEN);
    let means = |combination| -> Vec<f64> {
        (1..=8)
            .map(|seed| mean(&paths(&world, 32, seed, combination)))
            .collect()
    };
    let chapter_08: Vec<f64> = (1..=8)
        .map(|seed| mean(&chapter_08(&world, 32, seed + 100)))
        .collect();
    let (expected, expected_se) = mean_and_error(&chapter_08);
    let power = Combination::Heuristic(MisHeuristic::Power);
    for combination in [power, Combination::Optimal, Combination::Progressive] {
        let (mean, se) = mean_and_error(&means(combination));
        let tolerance = 4.0 * (se * se + expected_se * expected_se).sqrt();
        assert!(
            (mean - expected).abs() <= tolerance,
            "the {} combination along paths has mean {mean:.5} ± {se:.5}, chapter 08's paths \
             {expected:.5} ± {expected_se:.5}: does every depth count every pixel sample, also \
             those whose path ended before it, and each technique's α the share of its samples \
             that drew?",
            combination.name()
        );
    }
}
