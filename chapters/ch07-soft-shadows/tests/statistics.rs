//! The renderer's estimates against exact values and against each other, through the whole
//! tracer: camera ray, matte hit, shadow rays. Seeds are fixed; every tolerance is a number of
//! standard errors of the estimate itself, and each test also asks that its standard error be
//! small enough for the test to mean something.

mod support;

use ch05_motion_blur::MotionScene;
use ch07_soft_shadows::reference::{
    disc_on_axis_irradiance, polygon_irradiance, sphere_irradiance,
};
use ch07_soft_shadows::scenes::{Builder, camera, floor, matte};
use ch07_soft_shadows::{DiscWarp, LightOptions, LightStrata, Strategy};
use common::Ray;
use common::geometry::{Disc, Parallelogram, Shape, Sphere, Triangle};
use glam::Vec3;
use std::f32::consts::FRAC_1_PI;
use support::{ALBEDO, mean_radiance, panel, relative_rmse, render, scene_with_light};

/// A floor of albedo [`ALBEDO`] lit by `light` alone.
fn floor_under(light: Shape, radiance: Vec3) -> MotionScene {
    Builder::new()
        .shape(floor(6.0), matte(Vec3::splat(ALBEDO)))
        .area_light(light, radiance)
        .build(camera(Vec3::new(0.0, 5.0, 5.0), Vec3::ZERO, 40.0), 12)
}

/// The camera ray straight down onto the floor point `(x, 0, z)`, from `height`.
fn down_at(x: f32, z: f32, height: f32) -> Ray {
    Ray::new(Vec3::new(x, height, z), -Vec3::Y)
}

fn assert_unbiased(
    scene: &MotionScene,
    ray: &Ray,
    irradiance: Vec3,
    options: LightOptions,
    what: &str,
) {
    let expected = f64::from(ALBEDO * FRAC_1_PI * irradiance.y);
    let (mean, se) = mean_radiance(scene, options, ray, 4000, 11);
    assert!(
        (mean - expected).abs() <= 5.0 * se + 1e-5 * expected,
        "{what} {options:?}: {mean} ± {se}, exact {expected} ({:.1} standard errors)",
        (mean - expected) / se
    );
    assert!(
        se <= 0.03 * expected,
        "{what}: standard error {se} too large against {expected}"
    );
}

fn every_unbiased_option() -> Vec<LightOptions> {
    let mut all = Vec::new();
    for samples in [1, 3, 4] {
        for strata in [LightStrata::Stratified, LightStrata::Independent] {
            for strategy in [Strategy::Area, Strategy::SolidAngle] {
                for warp in [DiscWarp::Concentric, DiscWarp::Polar] {
                    all.push(
                        LightOptions::with_samples(samples)
                            .with_strata(strata)
                            .with_strategy(strategy)
                            .with_disc_warp(warp),
                    );
                }
            }
        }
    }
    all
}

#[test]
fn the_floor_under_each_light_shape_has_its_exact_brightness() {
    let radiance = Vec3::splat(3.0);
    let x = Vec3::new(0.7, 0.0, 0.4);
    // A panel and a triangle (Lambert's formula), off their axis.
    let quad = Parallelogram::new(Vec3::new(-0.5, 2.0, -0.5), Vec3::X, Vec3::Z);
    let corners = [
        quad.corner(),
        quad.corner() + quad.e1(),
        quad.corner() + quad.e1() + quad.e2(),
        quad.corner() + quad.e2(),
    ];
    let triangle = Triangle::new(
        Vec3::new(-0.5, 1.5, 0.5),
        Vec3::new(0.0, 1.5, -0.6),
        Vec3::new(0.6, 1.5, 0.3),
    );
    // A disc seen on its axis, and a sphere.
    let disc = Disc::new(Vec3::new(0.0, 2.0, 0.0), -Vec3::Y, 0.6);
    let sphere = Sphere::new(Vec3::new(0.5, 2.0, 0.0), 0.4);
    let to_sphere = sphere.center - x;
    let cases = [
        (
            Shape::Parallelogram(quad),
            x,
            polygon_irradiance(x, Vec3::Y, &corners, radiance),
        ),
        (
            Shape::Triangle(triangle),
            x,
            polygon_irradiance(x, Vec3::Y, &triangle.p, radiance),
        ),
        (
            Shape::Disc(disc),
            Vec3::ZERO,
            disc_on_axis_irradiance(radiance, 0.6, 2.0),
        ),
        (
            Shape::Sphere(sphere),
            x,
            sphere_irradiance(radiance, 0.4, to_sphere.length(), to_sphere.normalize().y),
        ),
    ];
    for (light, at, irradiance) in cases {
        assert!(irradiance.y > 0.0, "{light:?}");
        let scene = floor_under(light, radiance);
        for options in every_unbiased_option() {
            assert_unbiased(
                &scene,
                &down_at(at.x, at.z, 0.5),
                irradiance,
                options,
                &format!("{light:?}"),
            );
        }
    }
}

/// The variance of the one-ray estimate at a floor point in the ball's penumbra, with 16
/// shadow rays per hit, independent or stratified: the penumbra is where the points disagree,
/// and where spreading them over the light pays.
#[test]
fn stratified_light_samples_beat_independent_ones_in_a_penumbra() {
    let light = panel(1.0, 1.0);
    let scene = scene_with_light(1.0, Some((light, Vec3::splat(3.0))), None);
    let ray = down_at(-1.3, 0.0, 0.3);
    let variance = |strata| {
        let (mean, se) = mean_radiance(
            &scene,
            LightOptions::with_samples(16).with_strata(strata),
            &ray,
            2000,
            3,
        );
        (mean, se * se * 2000.0)
    };
    let (independent_mean, independent) = variance(LightStrata::Independent);
    let (stratified_mean, stratified) = variance(LightStrata::Stratified);
    // In the penumbra: the light is partly hidden.
    let Shape::Parallelogram(q) = light else {
        unreachable!()
    };
    let corners = [
        q.corner(),
        q.corner() + q.e1(),
        q.corner() + q.e1() + q.e2(),
        q.corner() + q.e2(),
    ];
    let exact = polygon_irradiance(
        Vec3::new(-1.3, 0.0, 0.0),
        Vec3::Y,
        &corners,
        Vec3::splat(3.0),
    );
    let unoccluded = f64::from(ALBEDO * FRAC_1_PI * exact.y);
    assert!(
        (0.1 * unoccluded..0.9 * unoccluded).contains(&independent_mean),
        "not in the penumbra: {independent_mean} against about {unoccluded} unoccluded"
    );
    assert!((independent_mean - stratified_mean).abs() < 0.05 * independent_mean);
    // With 2000 samples each variance is known to about 5 %: a ratio below 0.6 is certain.
    let ratio = stratified / independent;
    eprintln!("penumbra variance, stratified / independent: {ratio:.3}");
    assert!(ratio < 0.6, "variance ratio {ratio}");
}

/// A small distant sphere light over the test scene, in an image: sampling its cone sends
/// every shadow ray to its visible side, sampling its area wastes half of them on its back.
#[test]
fn solid_angle_sampling_beats_area_sampling_for_a_small_distant_sphere() {
    let light = Shape::Sphere(Sphere::new(Vec3::new(0.5, 3.0, 0.5), 0.15));
    let scene = scene_with_light(1.0, Some((light, Vec3::splat(200.0))), None);
    let reference = render(&scene, LightOptions::with_samples(16), 64, 48, 64, 100).image;
    let error = |strategy| {
        let image = render(
            &scene,
            LightOptions::with_samples(4).with_strategy(strategy),
            64,
            48,
            4,
            1,
        )
        .image;
        relative_rmse(&image, &reference)
    };
    let area = error(Strategy::Area);
    let cone = error(Strategy::SolidAngle);
    eprintln!("relative RMSE at 4 spp: area {area:.4}, solid angle {cone:.4}");
    assert!(area > 2.0 * cone, "area {area}, solid angle {cone}");
}

/// The naive disc (`r = ξ`) crowds the centre of the light yet claims the uniform density: a
/// receiver close under the disc, where the light's middle matters most, comes out far too
/// bright, while the uniform warps agree with the exact value.
#[test]
fn the_naive_disc_is_biased_and_the_uniform_ones_are_not() {
    let radiance = Vec3::splat(1.0);
    let disc = Disc::new(Vec3::new(0.0, 0.3, 0.0), -Vec3::Y, 0.6);
    let scene = floor_under(Shape::Disc(disc), radiance);
    let ray = down_at(0.0, 0.0, 0.15);
    let exact = f64::from(ALBEDO * FRAC_1_PI * disc_on_axis_irradiance(radiance, 0.6, 0.3).y);
    for warp in [DiscWarp::Concentric, DiscWarp::Polar] {
        assert_unbiased(
            &scene,
            &ray,
            disc_on_axis_irradiance(radiance, 0.6, 0.3),
            LightOptions::default().with_disc_warp(warp),
            "disc",
        );
    }
    let (naive, se) = mean_radiance(
        &scene,
        LightOptions::default().with_disc_warp(DiscWarp::Naive),
        &ray,
        4000,
        11,
    );
    let z = (naive - exact) / se;
    eprintln!("naive disc: {naive:.4} against exact {exact:.4}, {z:.0} standard errors");
    assert!(z > 20.0, "naive {naive} ± {se}, exact {exact}");
}
