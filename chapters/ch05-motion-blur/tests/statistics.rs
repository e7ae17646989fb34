//! Statistical claims, checked with fixed seeds and tolerances derived from the noise.

mod support;

use ch03_anti_aliasing::{PixelSampler, PixelSamplerKind};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::scenes::{Builtin, DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER};
use ch05_motion_blur::world::MotionScene;
use ch05_motion_blur::{Shutter, StratifiedTime, render_with};
use common::film::PixelBoxFilter;
use common::geometry::{Shape, Sphere};
use common::metrics::rmse;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use common::scene::{Camera, CameraFrame, FilmSettings, Material, PointLight, SceneBuilder};
use glam::{Mat4, Vec3};
use support::{average, frozen_at, with_shutter};

/// Motion blur *is* the average over the shutter interval: a blurred render must agree with the
/// mean of still renders at evenly spaced times as well as two blurred renders with different
/// seeds agree with each other. The average of 64 stills at the midpoints of 64 equal strata
/// differs from the integral over time only where an edge crosses a pixel within a stratum,
/// far below the noise at this sample count.
#[test]
fn a_blurred_render_is_the_average_of_still_renders_over_the_shutter() {
    let world = Builtin::Street.build(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
    let settings = RenderSettings::new(32, 20, 256);
    let blurred = |seed: u64| {
        render_with(
            &world,
            &Lens::PINHOLE,
            &settings,
            &StratifiedTime::new(IndependentSampler::new(seed), 256, seed),
            &PixelBoxFilter,
        )
        .image
    };
    let (a, b) = (blurred(1), blurred(2));
    let frames = 64;
    let stills: Vec<_> = (0..frames)
        .map(|i| {
            let time = (i as f32 + 0.5) / frames as f32;
            let still = MotionScene::still(frozen_at(&world, time));
            render_with(
                &still,
                &Lens::PINHOLE,
                &RenderSettings::new(32, 20, 4),
                &IndependentSampler::new(100 + i),
                &PixelBoxFilter,
            )
            .image
        })
        .collect();
    let mean_of_stills = average(&stills);
    let noise = rmse(&a, &b);
    let error = rmse(&a, &mean_of_stills);
    // Both differences are between two independent estimates with 256 samples per pixel each,
    // so they have the same expected size; over 640 pixels and 3 channels the RMSE itself is
    // known to a few per cent, and 1.3 leaves room for the ulp-level object-space rounding.
    assert!(
        error < 1.3 * noise,
        "blurred vs stills {error}, blurred vs blurred {noise}"
    );
    assert!(noise > 0.0);
}

/// A sphere sliding across a black background past the centre of an 8 x 8 image.
fn sliding_edge() -> MotionScene {
    let scene = SceneBuilder::new()
        .light(PointLight {
            position: Vec3::new(0.0, 0.0, 6.0),
            intensity: Vec3::splat(20.0),
        })
        .moving(
            Shape::Sphere(Sphere::new(Vec3::ZERO, 0.5)),
            vec![
                (0.0, Mat4::from_translation(Vec3::new(-1.5, 0.0, 0.0))),
                (1.0, Mat4::from_translation(Vec3::new(1.5, 0.0, 0.0))),
            ],
            Material::diffuse(Vec3::splat(0.8)),
        );
    let frame = CameraFrame::look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
    let scene = scene.build(Camera::pinhole(frame, 30.0), FilmSettings::new(8, 8), 2);
    MotionScene::new(with_shutter(scene, DEFAULT_SHUTTER)).unwrap()
}

/// The sample variance of a pixel's value over renders with different seeds.
fn pixel_variance(values: &[f64]) -> f64 {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)
}

/// Stratified time beats independent time on a pixel a moving edge crosses.
///
/// The pixel samples all go through the pixel centre, so time is the only random dimension.
/// With independent times the pixel is a mean of 16 independent values, each "sphere" for
/// about a third of the shutter; with stratified times every 16th of the shutter is hit once,
/// and only the jitter inside the one or two strata the edge passes through is random. The
/// variance drops by roughly the sample count. Over 200 seeds the ratio of two sample variances
/// is known to about 15 %, so requiring a factor of 4 cannot fail by chance, and fails at once
/// for a sampler that does not stratify (ratio 1).
#[test]
fn stratified_time_has_lower_variance_than_independent_on_a_moving_edge() {
    let world = sliding_edge();
    let spp = 16;
    let settings = RenderSettings::new(8, 8, spp);
    let (mut independent, mut stratified) = (Vec::new(), Vec::new());
    for seed in 0..200 {
        let pixels = PixelSampler::new(PixelSamplerKind::Centre, spp, seed).unwrap();
        let value = |image: &common::image::Image| f64::from(image.get(4, 4).x);
        let plain = render_with(&world, &Lens::PINHOLE, &settings, &pixels, &PixelBoxFilter);
        independent.push(value(&plain.image));
        let strata = StratifiedTime::new(pixels, spp, seed);
        let out = render_with(&world, &Lens::PINHOLE, &settings, &strata, &PixelBoxFilter);
        stratified.push(value(&out.image));
    }
    let (vi, vs) = (pixel_variance(&independent), pixel_variance(&stratified));
    assert!(
        vi > 1e-4,
        "the edge pixel must vary with independent time: {vi}"
    );
    assert!(4.0 * vs < vi, "stratified {vs}, independent {vi}");
    // Both estimate the same pixel: their means agree within the standard errors.
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let difference = (mean(&independent) - mean(&stratified)).abs();
    let standard_error = ((vi + vs) / 200.0).sqrt();
    assert!(
        difference < 4.0 * standard_error,
        "{difference} vs {standard_error}"
    );
}

/// The comparisons above can fail: a shutter open over the first half only shows the first
/// half of the motion, and differs from the whole interval's render by well over the 1.3
/// times the noise allowed there (about 1.9 times, measured).
#[test]
fn the_shutter_interval_decides_which_part_of_the_motion_is_seen() {
    let world = Builtin::Street.build(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
    let first_half = Builtin::Street.build(DEFAULT_MAX_DEPTH, Shutter::new(0.0, 0.5).unwrap());
    let settings = RenderSettings::new(32, 20, 64);
    let render = |w: &MotionScene, seed: u64| {
        render_with(
            w,
            &Lens::PINHOLE,
            &settings,
            &StratifiedTime::new(IndependentSampler::new(seed), 64, seed),
            &PixelBoxFilter,
        )
        .image
    };
    let noise = rmse(&render(&world, 1), &render(&world, 2));
    let difference = rmse(&render(&world, 1), &render(&first_half, 2));
    assert!(difference > 1.5 * noise, "{difference} vs noise {noise}");
}
