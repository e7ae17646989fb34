//! The guided path tracer: unbiased whatever it learnt, chapter 08's path when it has learnt
//! nothing, the same image on any number of threads.

use ch01_whitted::world::World;
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::FuzzMethod;
use ch07_soft_shadows::{AreaLights, LightSampling};
use ch08_path_tracing::{LectureMaterials, PathOptions, PathTracer, SceneLights};
use ch11_path_guiding::spatial::SpatialTree;
use ch11_path_guiding::{
    GuidedPathTracer, GuidingOptions, GuidingTarget, PassWeighting, render_guided,
};
use common::Ray;
use common::film::PixelBoxFilter;
use common::render::RenderSettings;
use common::sampler::{IndependentSampler, Sampler};
use common::scene::Material;
use glam::{UVec2, Vec3};

const MATERIALS: LectureMaterials = LectureMaterials {
    fuzz: FuzzMethod::Lobe,
};

fn tracer<'a>(
    world: &'a MotionScene,
    area_lights: &'a AreaLights,
    options: PathOptions,
) -> PathTracer<'a> {
    PathTracer {
        world,
        lights: SceneLights::of(world, area_lights, LightSampling::solid_angle()),
        options,
        materials: MATERIALS,
    }
}

/// The door-gap room, its camera and its settings at `width x height`.
fn door_gap(width: u32, height: u32) -> (MotionScene, Lens, RenderSettings, PathOptions) {
    let path = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/door-gap.xml"));
    let (world, side, mut settings, _) = ch05_motion_blur::lab::scene_file::for_agreement(
        path,
        &ch11_path_guiding::lab::CAPABILITIES,
    )
    .expect("the shipped scene reads");
    settings.width = width;
    settings.height = height;
    let options = ch08_path_tracing::lab::scene_file::path_options(&world.scene);
    (world, side.lens, settings, options)
}

#[test]
fn with_nothing_learnt_the_path_is_chapter_08s() {
    let (world, _, _, options) = door_gap(8, 6);
    let area_lights = AreaLights::of(&world.scene);
    let plain = tracer(&world, &area_lights, options);
    let guides = SpatialTree::new(world.scene.geometry.bounds());
    let guided = GuidedPathTracer {
        tracer: &plain,
        guides: &guides,
        bsdf_fraction: Some(0.5),
    };
    let eye = Vec3::new(-1.6, 1.3, 1.7);
    let mut sampler = IndependentSampler::new(5);
    let mut lit = 0;
    for i in 0..2000u64 {
        let target = Vec3::new(
            2.0 - 0.002 * i as f32,
            0.2 + 0.0008 * i as f32,
            -1.5 + 0.001 * i as f32,
        );
        let ray = Ray::new(eye, (target - eye).normalize());
        sampler.start_pixel_sample(UVec2::ZERO, i);
        let theirs = plain.radiance(&ray, &mut sampler.clone());
        let ours = guided.radiance(&ray, &mut sampler, None);
        assert_eq!(
            ours.to_array().map(f32::to_bits),
            theirs.to_array().map(f32::to_bits),
            "path {i}: with no guide learnt, the guided path drew other numbers or added \
             other light than chapter 08's ({ours} against {theirs})"
        );
        lit += usize::from(theirs != Vec3::ZERO);
    }
    assert!(lit > 15, "the paths found light ({lit} of 2000)");
}

/// The mean and standard error of the green radiance along `ray` over `n` guided paths.
fn mean_radiance(guided: &GuidedPathTracer<'_, LectureMaterials>, ray: &Ray, n: u64) -> (f64, f64) {
    let mut sampler = IndependentSampler::new(17);
    let (mut sum, mut sum2) = (0.0f64, 0.0f64);
    for i in 0..n {
        sampler.start_pixel_sample(UVec2::new(3, 4), i);
        let l = f64::from(guided.radiance(ray, &mut sampler, None).y);
        assert!(l.is_finite() && l >= 0.0, "path {i} brought back {l}");
        sum += l;
        sum2 += l * l;
    }
    let mean = sum / n as f64;
    (
        mean,
        ((sum2 / n as f64 - mean * mean).max(0.0) / n as f64).sqrt(),
    )
}

#[test]
fn guided_paths_are_unbiased_whatever_the_guides_learnt() {
    // A grey sphere (albedo 0.5) under a sky of 1: convex, so it sends back exactly 0.5.
    let world = ch08_path_tracing::furnace::spheres(&[Material::diffuse(Vec3::splat(0.5))], 6);
    let area_lights = AreaLights::of(&world.scene);
    for nee in [true, false] {
        let options = PathOptions {
            nee,
            ..PathOptions::with_depth(6)
        };
        let plain = tracer(&world, &area_lights, options);
        for target in [GuidingTarget::Radiance, GuidingTarget::Variance] {
            let settings = RenderSettings::new(24, 24, 64);
            let trained = render_guided(
                &world,
                MATERIALS,
                options,
                Some(GuidingOptions::for_image(target, 24 * 24)),
                &Lens::PINHOLE,
                &settings,
                &IndependentSampler::new(3),
                &PixelBoxFilter,
            )
            .training
            .expect("guided");
            for bsdf_fraction in [Some(0.5), None] {
                let guided = GuidedPathTracer {
                    tracer: &plain,
                    guides: &trained.guides,
                    bsdf_fraction,
                };
                let eye = Vec3::new(0.0, 0.5, 4.0);
                let ray = Ray::new(eye, (Vec3::new(0.1, 0.3, 0.0) - eye).normalize());
                let hit_guide = trained.guides.guide_of(Vec3::new(0.05, 0.3, 0.95));
                // Under the sky a convex sphere has direct light only: with the light sample on,
                // that is the light sample's to find and the guide learns nothing; without it the
                // guide learns the sky.
                let learnt = trained.guides.guides[hit_guide as usize].sampling.total() > 0.0;
                assert_eq!(
                    learnt,
                    !nee,
                    "nee {nee}: the guide at the sphere's front learnt {}",
                    if learnt { "something" } else { "nothing" }
                );
                let (mean, error) = mean_radiance(&guided, &ray, 40_000);
                assert!(
                    (mean - 0.5).abs() < 4.0 * error + 1e-4,
                    "{} guiding, nee {nee}, fraction {bsdf_fraction:?}: the sphere sends \
                     back {mean} ± {error}, not 0.5",
                    target.name()
                );
            }
            // The fractions learnt stay probabilities, and where there was light to learn
            // (no light sample) they moved from a half.
            let fractions: Vec<f32> = trained
                .guides
                .guides
                .iter()
                .map(|g| g.fraction.fraction())
                .collect();
            assert!(
                fractions.iter().all(|&f| f > 0.0 && f < 1.0),
                "{fractions:?}"
            );
            if !nee {
                assert!(fractions.iter().any(|&f| f != 0.5), "{fractions:?}");
            }
        }
    }
}

#[test]
fn a_guided_render_is_the_same_on_any_number_of_threads() {
    let (world, lens, settings, options) = door_gap(40, 30);
    let render = |threads| {
        let mut settings = settings.clone();
        settings.threads = Some(threads);
        settings.budget = common::render::Budget::Samples(16);
        render_guided(
            &world,
            MATERIALS,
            options,
            Some(GuidingOptions {
                passes: PassWeighting::ByMeasuredNoise,
                ..GuidingOptions::for_image(GuidingTarget::Variance, 1200)
            }),
            &lens,
            &settings,
            &IndependentSampler::new(9),
            &PixelBoxFilter,
        )
    };
    let (one, two) = (render(1), render(2));
    assert_eq!(one.output.image.pixels, two.output.image.pixels);
    let (a, b) = (one.training.unwrap(), two.training.unwrap());
    assert_eq!(
        a.guides, b.guides,
        "the guides learnt depend on the threads"
    );
    assert!(a.iterations.len() >= 2 && one.output.stats.spp == 16);
    assert_eq!(one.pass_weights, two.pass_weights);
    assert_eq!(one.pass_weights.len(), a.iterations.len() + 1);
}

#[test]
fn guided_paths_with_the_light_sample_agree_with_chapter_08s() {
    // Two grey spheres side by side under the sky: each lights the other, so there is
    // indirect light to learn, and the light sample's MIS weights take the mixture's density.
    let grey = Material::diffuse(Vec3::splat(0.5));
    let world = ch08_path_tracing::furnace::spheres(&[grey.clone(), grey], 6);
    let area_lights = AreaLights::of(&world.scene);
    let options = PathOptions::with_depth(6);
    let plain = tracer(&world, &area_lights, options);
    let settings = RenderSettings::new(32, 24, 64);
    let trained = render_guided(
        &world,
        MATERIALS,
        options,
        Some(GuidingOptions::for_image(GuidingTarget::Variance, 32 * 24)),
        &Lens::PINHOLE,
        &settings,
        &IndependentSampler::new(3),
        &PixelBoxFilter,
    )
    .training
    .expect("guided");
    // A ray to the left sphere's side that faces the right one.
    let eye = Vec3::new(0.0, 0.5, 5.5);
    let ray = Ray::new(eye, (Vec3::new(-0.3, 0.0, 0.6) - eye).normalize());
    let hit = world
        .intersect(&ray)
        .expect("the ray meets the left sphere");
    let guide = trained.guides.guide_of(hit.p);
    assert!(
        trained.guides.guides[guide as usize].sampling.total() > 0.0,
        "the guide where the spheres face each other learnt the indirect light"
    );
    let guided = GuidedPathTracer {
        tracer: &plain,
        guides: &trained.guides,
        bsdf_fraction: None,
    };
    let unguided_tree = SpatialTree::new(world.scene.geometry.bounds());
    let unguided = GuidedPathTracer {
        guides: &unguided_tree,
        ..guided
    };
    let (a, error_a) = mean_radiance(&guided, &ray, 40_000);
    let (b, error_b) = mean_radiance(&unguided, &ray, 40_000);
    let error = (error_a * error_a + error_b * error_b).sqrt();
    assert!(
        (a - b).abs() < 4.0 * error,
        "guided {a} ± {error_a} against chapter 08's {b} ± {error_b}"
    );
}

/// The mean over an image's pixels (green).
fn image_mean(image: &common::image::Image) -> f64 {
    image.pixels.iter().map(|p| f64::from(p.y)).sum::<f64>() / image.pixels.len() as f64
}

#[test]
fn the_training_and_final_passes_averaged_stay_unbiased() {
    // The grey sphere under the sky without the light sample, so that the guides learn the
    // sky and the fractions move: every guided render's image, all its passes averaged by
    // their samples, by what their guides learnt from or by their measured noise, has the
    // mean of chapter 08's long render.
    let world = ch08_path_tracing::furnace::spheres(&[Material::diffuse(Vec3::splat(0.5))], 6);
    let options = PathOptions {
        nee: false,
        ..PathOptions::with_depth(6)
    };
    let render = |seed, spp, guiding: Option<(GuidingTarget, PassWeighting)>| {
        render_guided(
            &world,
            MATERIALS,
            options,
            guiding.map(|(t, passes)| GuidingOptions {
                passes,
                ..GuidingOptions::for_image(t, 24 * 24)
            }),
            &Lens::PINHOLE,
            &RenderSettings::new(24, 24, spp),
            &IndependentSampler::new(seed),
            &PixelBoxFilter,
        )
    };
    let reference = image_mean(&render(1000, 4096, None).output.image);
    for (target, passes) in [
        (GuidingTarget::Radiance, PassWeighting::BySamples),
        (GuidingTarget::Variance, PassWeighting::BySamples),
        (GuidingTarget::Radiance, PassWeighting::ByLearning),
        (GuidingTarget::Variance, PassWeighting::ByLearning),
        (GuidingTarget::Radiance, PassWeighting::ByMeasuredNoise),
        (GuidingTarget::Variance, PassWeighting::ByMeasuredNoise),
    ] {
        let means: Vec<f64> = (0..12)
            .map(|seed| {
                let rendered = render(seed, 32, Some((target, passes)));
                assert_eq!(rendered.output.stats.spp, 32);
                assert_eq!(
                    rendered.pass_weights.len(),
                    5,
                    "training 1, 2, 4, 8; final 17"
                );
                image_mean(&rendered.output.image)
            })
            .collect();
        let n = means.len() as f64;
        let mean = means.iter().sum::<f64>() / n;
        let spread = means.iter().map(|m| (m - mean).powi(2)).sum::<f64>() / (n - 1.0);
        let error = (spread / n).sqrt();
        assert!(
            (mean - reference).abs() < 4.0 * error + 1e-4,
            "{} guiding, {passes:?}: the averaged images' mean is {mean} ± {error}, chapter 08's \
             {reference}",
            target.name()
        );
    }
}
