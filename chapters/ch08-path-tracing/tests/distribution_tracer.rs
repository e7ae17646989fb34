//! The distribution ray tracer changes how many samples each effect takes, never the mean:
//! with one sample per effect it must agree with chapter 07's tracer, and with indirect
//! diffuse light (or on a scene that has none) with the path tracer. Every comparison goes
//! through the same film positions, the difference of the means within 5 standard errors of
//! the difference.

mod support;

use ch03_anti_aliasing::{FilterKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::CameraRays;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::{TraceOptions, Tracer};
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::LightOptions;
use ch08_path_tracing::{
    DistributionOptions, DistributionTracer, Method, PathOptions, render_distribution,
};
use common::Ray;
use common::render::RenderSettings;
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2, Vec3};

/// The mean green channel of `n` samples through each of `pixels`, and its standard error.
fn estimate(
    scene: &MotionScene,
    pixels: &[Vec2],
    n: u64,
    seed: u64,
    radiance: impl Fn(&Ray, &mut IndependentSampler) -> Vec3,
) -> (f64, f64) {
    let world = scene;
    let film = world.scene.film;
    let rays = CameraRays::new(world, &Lens::PINHOLE, film.width, film.height);
    let mut sampler = IndependentSampler::new(seed);
    let (mut sum, mut sum2, mut count) = (0.0f64, 0.0f64, 0u64);
    for (p, &p_film) in pixels.iter().enumerate() {
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::new(p as u32, 0), i);
            let ray = rays.generate(world, p_film, &mut sampler);
            let l = radiance(&ray, &mut sampler);
            assert!(l.is_finite(), "radiance {l} at {p_film}");
            let x = f64::from(l.y);
            sum += x;
            sum2 += x * x;
            count += 1;
        }
    }
    let mean = sum / count as f64;
    let variance = (sum2 / count as f64 - mean * mean).max(0.0);
    (mean, (variance / count as f64).sqrt())
}

/// A scene file of the chapter with `max_depth` segments (for every tracer).
fn scene_at_depth(name: &str, max_depth: u32) -> support::SceneFile {
    let mut scene = support::scene_file(name);
    scene.world.scene.max_depth = max_depth;
    scene
}

fn assert_agree(what: &str, a: (f64, f64), b: (f64, f64)) {
    let tolerance = 5.0 * (a.1 * a.1 + b.1 * b.1).sqrt();
    assert!(
        (a.0 - b.0).abs() <= tolerance,
        "{what}: {} vs {} (tolerance {tolerance})",
        a.0,
        b.0
    );
}

fn distribution(
    scene: &MotionScene,
    options: DistributionOptions,
) -> impl Fn(&Ray, &mut IndependentSampler) -> Vec3 {
    // Leaked: the tracer borrows the lights, and the closure outlives this function.
    let area_lights = Box::leak(Box::new(AreaLights::of(&scene.scene)));
    let tracer = DistributionTracer::new(scene, area_lights, options);
    move |ray, sampler| tracer.radiance(ray, sampler)
}

fn path(
    scene: &MotionScene,
    options: PathOptions,
) -> impl Fn(&Ray, &mut IndependentSampler) -> Vec3 {
    let method = Method::new(options);
    let area_lights = Box::leak(Box::new(AreaLights::of(&scene.scene)));
    let tracer = ch08_path_tracing::PathTracer {
        world: scene,
        lights: ch08_path_tracing::SceneLights::of(scene, area_lights, method.light_sampling),
        options,
        materials: ch08_path_tracing::LectureMaterials { fuzz: method.fuzz },
    };
    move |ray, sampler| tracer.radiance(ray, sampler)
}

#[test]
fn one_sample_per_effect_is_chapter_07s_tracer() {
    // The Cornell box (mirror, glass, matte, a panel light) at depth 2, where one segment
    // more or less changes the image most (the mirror and the glass show the walls or not),
    // and at depth 5 for mirror-in-glass paths; the glossy plates (four lobes, four sphere
    // lights).
    for (name, depth, k, n) in [
        ("cornell-box.xml", 2, 8, 4000),
        ("cornell-box.xml", 5, 5, 800),
        ("glossy-plates.xml", 3, 6, 800),
    ] {
        let file = scene_at_depth(name, depth);
        let scene = &file.world;
        let film = scene.scene.film;
        let pixels = workbench::test_support::pixel_centre_grid(film.width, film.height, k);
        let area_lights = AreaLights::of(&scene.scene);
        let lighting = area_lights.lighting(LightOptions::default());
        let chapter_07 = Tracer {
            world: scene,
            lighting: &lighting,
            options: TraceOptions::default(),
        };
        let ours = estimate(
            scene,
            &pixels,
            n,
            1,
            distribution(scene, DistributionOptions::cook(depth)),
        );
        let theirs = estimate(scene, &pixels, n, 2, |ray, sampler| {
            chapter_07.trace(ray, 1, sampler)
        });
        assert_agree(&format!("{name}, depth {depth}"), ours, theirs);
    }
}

#[test]
fn branching_with_indirect_diffuse_is_the_path_tracer() {
    // k = m = 2 with indirect diffuse light computes every path up to `max_depth`, as the
    // path tracer does: colour bleeding, light under the glass and all.
    let depth = 4;
    let file = scene_at_depth("cornell-box.xml", depth);
    let scene = &file.world;
    let film = scene.scene.film;
    let pixels = workbench::test_support::pixel_centre_grid(film.width, film.height, 5);
    let options = DistributionOptions::branching(2, depth, true);
    let ours = estimate(scene, &pixels, 1200, 3, distribution(scene, options));
    let pt = PathOptions {
        rr_depth: None,
        ..PathOptions::with_depth(depth)
    };
    let theirs = estimate(scene, &pixels, 4000, 4, path(scene, pt));
    assert_agree("cornell box, depth 4", ours, theirs);
}

#[test]
fn without_indirect_diffuse_on_a_scene_without_it_is_the_path_tracer() {
    // At depth 2 the plates scene has only emission and direct light, glossy and matte: the
    // distribution tracer finds the glossy part by 3 lobe rays per plate, the path tracer by
    // its light and BSDF samples combined. Both are the same light.
    let depth = 2;
    let file = scene_at_depth("glossy-plates.xml", depth);
    let scene = &file.world;
    let film = scene.scene.film;
    let pixels = workbench::test_support::pixel_centre_grid(film.width, film.height, 8);
    let options = DistributionOptions::branching(3, depth, false);
    let ours = estimate(scene, &pixels, 400, 5, distribution(scene, options));
    let theirs = estimate(
        scene,
        &pixels,
        1200,
        6,
        path(scene, PathOptions::with_depth(depth)),
    );
    assert_agree("glossy plates, depth 2", ours, theirs);
}

#[test]
fn the_same_seed_gives_the_same_finite_image_on_any_number_of_threads() {
    let file = scene_at_depth("cornell-box.xml", 4);
    let scene = &file.world;
    let options = DistributionOptions::branching(2, 4, true);
    let filter = ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter");
    let render = |threads| {
        let settings = RenderSettings {
            threads: Some(threads),
            ..RenderSettings::new(24, 24, 2)
        };
        let sampler = IndependentSampler::new(7);
        render_distribution(scene, options, &Lens::PINHOLE, &settings, &sampler, &filter)
    };
    let one = render(1);
    let two = render(2);
    assert_eq!(one.stats.nonfinite_samples, 0);
    assert_eq!(one.stats.rays, two.stats.rays);
    for y in 0..24 {
        for x in 0..24 {
            let (a, b) = (one.image.get(x, y), two.image.get(x, y));
            assert!(a.is_finite(), "pixel ({x}, {y}): {a}");
            assert_eq!(a, b, "pixel ({x}, {y})");
        }
    }
}
