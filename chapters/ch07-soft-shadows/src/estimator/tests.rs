//! The estimator against the exact irradiance of every shape and strategy, the naive disc's
//! bias, the variance of the strategies, and the extremes where NaN would like to appear.

use std::f32::consts::PI;

use approx::assert_relative_eq;
use common::geometry::{Disc, Parallelogram, Sphere, Triangle};
use rand::SeedableRng;
use rand_pcg::Pcg32;

use super::*;
use crate::area_lights::LightShape;
use crate::disc_warp::DiscWarp;
use crate::reference::{disc_on_axis_irradiance, polygon_irradiance, sphere_irradiance};
use crate::shadow_rays::light_samples;
use crate::test_support::{Estimate, assert_agrees, estimate, terms, uniform_points};

const L: Vec3 = Vec3::new(2.0, 1.0, 0.5);

fn area() -> LightSampling {
    LightSampling::area(DiscWarp::Concentric)
}

/// The estimate of `light`'s irradiance at `x` from `n` independent samples.
fn measure(
    light: &AreaLight,
    x: Vec3,
    normal: Vec3,
    sampling: LightSampling,
    n: usize,
    seed: u64,
) -> Estimate {
    estimate(&terms(x, normal, light, sampling, &uniform_points(n, seed)))
}

/// A square panel of side 1 at height 1 above the origin, facing down, shifted sideways.
fn ceiling_panel() -> Parallelogram {
    Parallelogram::new(Vec3::new(-0.2, 1.0, -0.7), Vec3::X, Vec3::Z)
}

fn quad_vertices(q: &Parallelogram) -> [Vec3; 4] {
    [
        q.corner(),
        q.corner() + q.e1(),
        q.corner() + q.e1() + q.e2(),
        q.corner() + q.e2(),
    ]
}

fn tilted_normal() -> Vec3 {
    Vec3::new(0.3, 1.0, -0.2).normalize()
}

// The exercise: one sample's term.

fn one_sample(p: Vec3, n: Vec3, pdf: f32) -> LightSample {
    LightSample {
        p,
        p_error: Vec3::ZERO,
        n,
        pdf,
        pdf_solid_angle: None,
    }
}

/// What is wrong with `got`, an answer to `area_light_contribution(light, x, n, sample)`
/// whose right value is `expected`, in words; `None` if it is right. The plausible slips are
/// recognised by how far off they are: each leaves out (or doubles) one factor of the
/// geometry, so `got` is `expected` times that factor or its inverse.
fn contribution_mistake(
    light: &AreaLight,
    x: Vec3,
    n: Vec3,
    sample: &LightSample,
    got: Vec3,
    expected: Vec3,
) -> Option<String> {
    let close =
        |a: Vec3, b: Vec3| (a - b).abs().max_element() <= 1e-5 * b.abs().max_element().max(1e-6);
    if close(got, expected) {
        return None;
    }
    // The geometry of the sample: the squared distance, the cosines at the receiver and at
    // the light, and the density.
    let to_light = sample.p - x;
    let d2 = to_light.length_squared();
    let wi = to_light / d2.sqrt();
    let (cos, cos_light) = (n.dot(wi), sample.n.dot(wi).abs());
    let pdf = sample.pdf;
    let slips: [(f32, &str); 6] = [
        (
            1.0 / cos_light,
            "the cosine at the light is missing: a panel seen edge-on sends less light than one \
             seen face-on",
        ),
        (
            1.0 / cos,
            "the cosine at the receiver is missing: light arriving at a slant spreads over more \
             of the surface",
        ),
        (
            d2,
            "the squared distance is missing (or cancelled: are both cosines taken with the \
             unit direction to the light?): a patch of the light covers less of the sky seen \
             from further away",
        ),
        (
            d2.sqrt(),
            "the distance is not squared: the solid angle of a patch falls with the square of \
             the distance",
        ),
        (
            pdf * pdf,
            "multiplied by the density instead of divided: a sample chosen with density p \
             stands for 1 / p of the light's area",
        ),
        (
            pdf,
            "not divided by the density: a sample chosen with density p stands for 1 / p of \
             the light's area",
        ),
    ];
    let towards_light = light.emitted(sample.n, wi);
    let radiance = light.emitted(sample.n, -wi);
    let mistake = match slips
        .iter()
        .find(|(factor, _)| (factor - 1.0).abs() > 1e-3 && close(got, expected * *factor))
    {
        Some((_, mistake)) => (*mistake).to_string(),
        None if cos < 0.0 && got.min_element() < 0.0 => {
            "the cosine at the receiver went negative: light from below its horizon does not \
             reach it, so that cosine is clamped at 0"
                .to_string()
        }
        None if got == Vec3::ZERO && radiance != Vec3::ZERO && towards_light == Vec3::ZERO => {
            "yours is 0, as if the receiver were behind the light: the light's emitted radiance \
             is asked for the direction it leaves in, from the light towards the receiver"
                .to_string()
        }
        None if expected == Vec3::ZERO => {
            "no light arrives here (the receiver faces away, or it is behind the light)".to_string()
        }
        None => format!("the term should be {expected}"),
    };
    Some(format!(
        "{mistake}.\n  receiver at {x} with normal {n}, light point {} with normal {} and density \
         {}: your area_light_contribution gave {got}, expected {expected}",
        sample.p, sample.n, sample.pdf
    ))
}

/// Checks one term against `expected_per_radiance`, the right term for a light of radiance 1
/// in every channel (the panel's radiance `L` scales it).
fn check_contribution(
    light: &AreaLight,
    x: Vec3,
    n: Vec3,
    sample: &LightSample,
    expected_per_radiance: f32,
) {
    let got = area_light_contribution(light, x, n, sample);
    let expected = L * expected_per_radiance;
    if let Some(mistake) = contribution_mistake(light, x, n, sample, got, expected) {
        panic!("area_light_contribution: {mistake}");
    }
}

// The expected terms below were worked out beforehand from the conversion of a patch of the
// light's area into the light arriving at the receiver, to 6 digits, for a light of radiance 1.
// The first, for instance: the point (1, 2, 0) on a light facing down, seen from the origin
// under a receiver facing up, is at distance √5 with both cosines 2/√5, density 1/4.

#[test]
fn exercise_area_light_contribution_turns_area_into_arriving_light() {
    let light = AreaLight::new(ceiling_panel(), L);
    let sample = one_sample(Vec3::new(1.0, 2.0, 0.0), -Vec3::Y, 0.25);
    check_contribution(&light, Vec3::ZERO, Vec3::Y, &sample, 0.64);
    // The two cosines are different things: tilt the receiver, then the light.
    check_contribution(&light, Vec3::ZERO, Vec3::X, &sample, 0.32);
    let n_light = Vec3::new(-1.0, -1.0, 0.0).normalize();
    let turned = one_sample(Vec3::new(1.0, 2.0, 0.0), n_light, 0.25);
    check_contribution(&light, Vec3::ZERO, Vec3::Y, &turned, 0.678_822_5);
    let tilted = one_sample(
        Vec3::new(0.4, 1.3, -0.6),
        Vec3::new(0.2, -1.0, 0.3).normalize(),
        0.7,
    );
    check_contribution(
        &light,
        Vec3::new(0.1, 0.0, 0.2),
        tilted_normal(),
        &tilted,
        0.495_206_4,
    );
}

#[test]
fn exercise_area_light_contribution_divides_by_the_density() {
    let light = AreaLight::new(ceiling_panel(), L);
    for (pdf, expected) in [(1.0, 0.397_217_75), (2.0, 0.198_608_88), (0.1, 3.972_177_5)] {
        check_contribution(
            &light,
            Vec3::ZERO,
            Vec3::Y,
            &one_sample(Vec3::new(0.3, 1.5, 0.2), -Vec3::Y, pdf),
            expected,
        );
    }
    // And falls with the distance along the normal.
    check_contribution(
        &light,
        Vec3::ZERO,
        Vec3::Y,
        &one_sample(Vec3::new(0.0, 3.0, 0.0), -Vec3::Y, 1.0),
        1.0 / 9.0,
    );
}

#[test]
fn exercise_area_light_contribution_is_zero_behind_the_light_and_below_the_horizon() {
    let light = AreaLight::new(ceiling_panel(), L);
    let s = one_sample(Vec3::new(1.0, 2.0, 0.0), -Vec3::Y, 0.25);
    let behind = LightSample { n: Vec3::Y, ..s };
    let got = area_light_contribution(&light, Vec3::ZERO, Vec3::Y, &behind);
    assert!(
        got == Vec3::ZERO,
        "area_light_contribution: the receiver is behind the light (the panel faces away from \
         it), which sends it nothing; yours gave {got}: is the light's own emitted radiance \
         towards the receiver used, asked for the direction from the light to the receiver?"
    );
    check_contribution(&light, Vec3::ZERO, -Vec3::Y, &s, 0.0);
}

#[test]
fn exercise_area_light_contribution_estimates_a_panels_irradiance() {
    let quad = ceiling_panel();
    let light = AreaLight::new(quad, L);
    let points = uniform_points(20_000, 11);
    let mean = points
        .iter()
        .map(|&u| {
            let s = crate::area_sampling::sample_parallelogram_light(&quad, u).unwrap();
            area_light_contribution(&light, Vec3::ZERO, Vec3::Y, &s).x as f64
        })
        .sum::<f64>()
        / points.len() as f64;
    let reference = polygon_irradiance(Vec3::ZERO, Vec3::Y, &quad_vertices(&quad), L).x as f64;
    assert!(
        (mean - reference).abs() <= 0.02 * reference,
        "area_light_contribution: the mean of 20 000 terms over the panel is {mean:.4}, its exact \
         irradiance (Lambert's formula for a polygon) {reference:.4}: the estimator is biased"
    );
}

// The estimator against the exact irradiance.

#[test]
fn parallelogram_light_matches_lamberts_formula() {
    let quad = ceiling_panel();
    let light = AreaLight::new(quad, L);
    for (x, n) in [
        (Vec3::ZERO, Vec3::Y),
        (Vec3::new(0.5, 0.2, 0.1), tilted_normal()),
    ] {
        let reference = polygon_irradiance(x, n, &quad_vertices(&quad), L).x as f64;
        assert_agrees(
            measure(&light, x, n, area(), 40_000, 1),
            reference,
            0.005,
            "parallelogram",
        );
    }
}

#[test]
fn triangle_light_matches_lamberts_formula() {
    let triangle = Triangle::new(
        Vec3::new(-0.5, 1.0, 0.0),
        Vec3::new(0.2, 0.8, -1.0),
        Vec3::new(1.0, 1.2, 0.3),
    );
    let light = AreaLight::new(triangle, L);
    let x = Vec3::new(0.1, 0.0, 0.2);
    let n = tilted_normal();
    let reference = polygon_irradiance(x, n, &triangle.p, L).x as f64;
    assert!(reference > 0.0, "the triangle faces the receiver");
    assert_agrees(
        measure(&light, x, n, area(), 40_000, 2),
        reference,
        0.005,
        "triangle",
    );
}

#[test]
fn disc_light_matches_the_on_axis_formula_with_both_uniform_warps() {
    let disc = Disc::new(Vec3::new(0.0, 1.5, 0.0), -Vec3::Y, 1.0);
    let light = AreaLight::new(disc, L);
    let reference = disc_on_axis_irradiance(L, 1.0, 1.5).x as f64;
    for warp in [DiscWarp::Concentric, DiscWarp::Polar] {
        let e = measure(
            &light,
            Vec3::ZERO,
            Vec3::Y,
            LightSampling::area(warp),
            40_000,
            3,
        );
        assert_agrees(e, reference, 0.005, warp.name());
    }
}

#[test]
fn sphere_light_matches_its_formula_by_area_and_by_solid_angle() {
    let sphere = Sphere::new(Vec3::new(1.0, 2.0, 0.5), 0.6);
    let light = AreaLight::new(sphere, L);
    let x = Vec3::new(0.2, 0.1, 0.0);
    let n = tilted_normal();
    let to_center = sphere.center - x;
    let cos_theta = n.dot(to_center.normalize());
    assert!(
        cos_theta >= 0.6 / to_center.length(),
        "the sphere is above the horizon"
    );
    let reference = sphere_irradiance(L, 0.6, to_center.length(), cos_theta).x as f64;
    assert_agrees(
        measure(&light, x, n, area(), 40_000, 4),
        reference,
        0.01,
        "sphere by area",
    );
    let e = measure(&light, x, n, LightSampling::solid_angle(), 4_000, 4);
    assert_agrees(e, reference, 0.002, "sphere by solid angle");
}

// The references check each other.

#[test]
fn lamberts_formula_agrees_with_the_disc_and_the_sphere() {
    // A 512-gon inscribed in the unit disc has the disc's irradiance up to its missing area.
    let k = 512;
    let polygon: Vec<Vec3> = (0..k)
        .map(|i| {
            let phi = 2.0 * PI * i as f32 / k as f32;
            Vec3::new(phi.cos(), 2.0, phi.sin())
        })
        .collect();
    let disc = disc_on_axis_irradiance(Vec3::ONE, 1.0, 2.0).x;
    let lambert = polygon_irradiance(Vec3::ZERO, Vec3::Y, &polygon, Vec3::ONE).x;
    assert_relative_eq!(lambert, disc, max_relative = 1e-4);
    // Reversed, the polygon faces away: nothing.
    let reversed: Vec<Vec3> = polygon.iter().rev().copied().collect();
    assert_eq!(
        polygon_irradiance(Vec3::ZERO, Vec3::Y, &reversed, Vec3::ONE),
        Vec3::ZERO
    );
    // A sphere looks like the disc that fills the same cone: sin θ_max = R / d = ρ / √(h² + ρ²).
    let sphere = sphere_irradiance(Vec3::ONE, 1.0, 3.0, 1.0).x;
    let rho = 2.0 / 8f32.sqrt(); // h = 2, so ρ / √(4 + ρ²) = 1/3
    assert_relative_eq!(
        sphere,
        disc_on_axis_irradiance(Vec3::ONE, rho, 2.0).x,
        max_relative = 1e-5
    );
}

// The lecture's mistake.

/// The expectation of the area estimator on the axis of a disc sampled with `r = R ξ2` while
/// claiming `1 / (π R²)`: `∫_0^R L h² π R² / (h² + r²)² dr / R`
/// `= (π L R / 2) (R / (h² + R²) + atan(R / h) / h)`.
fn naive_disc_expectation(radius: f64, height: f64) -> f64 {
    let (r, h) = (radius, height);
    std::f64::consts::PI * r / 2.0 * (r / (h * h + r * r) + (r / h).atan() / h)
}

#[test]
fn the_naive_disc_is_biased_by_the_predicted_amount() {
    let disc = Disc::new(Vec3::new(0.0, 1.0, 0.0), -Vec3::Y, 1.0);
    let light = AreaLight::new(disc, Vec3::ONE);
    let reference = disc_on_axis_irradiance(Vec3::ONE, 1.0, 1.0).x as f64;
    let naive = measure(
        &light,
        Vec3::ZERO,
        Vec3::Y,
        LightSampling::area(DiscWarp::Naive),
        40_000,
        5,
    );
    let bias = naive.mean / reference - 1.0;
    println!(
        "naive disc: {} ± {} against {reference}: bias {:+.1} %",
        naive.mean,
        naive.standard_error,
        100.0 * bias
    );
    // (π/2)(1/2 + π/4) against π/2: 28.5 % too bright.
    assert_agrees(
        naive,
        naive_disc_expectation(1.0, 1.0),
        0.005,
        "the naive disc's expectation",
    );
    assert!(
        (naive.mean - reference) / naive.standard_error > 20.0,
        "{naive:?}"
    );
    assert_relative_eq!(bias, 0.285, epsilon = 0.01);
}

// Variance.

#[test]
fn solid_angle_sampling_beats_area_sampling_for_a_distant_small_sphere() {
    let sphere = Sphere::new(Vec3::new(0.0, 10.0, 0.0), 1.0);
    let light = AreaLight::new(sphere, Vec3::ONE);
    let n = Vec3::new(0.2, 1.0, 0.0).normalize();
    let by_area = measure(&light, Vec3::ZERO, n, area(), 20_000, 6);
    let by_solid_angle = measure(
        &light,
        Vec3::ZERO,
        n,
        LightSampling::solid_angle(),
        20_000,
        6,
    );
    let ratio = by_area.variance / by_solid_angle.variance;
    println!(
        "variance per sample: area {:.3e}, solid angle {:.3e}, ratio {ratio:.0}",
        by_area.variance, by_solid_angle.variance
    );
    assert!(ratio > 100.0, "{by_area:?} {by_solid_angle:?}");
    // Both unbiased.
    let reference = sphere_irradiance(Vec3::ONE, 1.0, 10.0, n.y).x as f64;
    assert_agrees(by_area, reference, 0.02, "area");
    assert_agrees(by_solid_angle, reference, 0.001, "solid angle");
}

#[test]
fn stratified_light_samples_reduce_the_noise_of_a_penumbra() {
    // A shadow edge across the panel, off the strata's boundaries: only x < 0.37 is visible.
    let light = AreaLight::new(ceiling_panel(), Vec3::ONE);
    let variance_of_16 = |stratified: bool| {
        let mut rng = Pcg32::seed_from_u64(7);
        let estimates: Vec<f64> = (0..400)
            .map(|_| {
                let u = light_samples(16, stratified, &mut rng);
                estimate_irradiance(Vec3::ZERO, Vec3::Y, &light, &u, area(), |s| s.p.x < 0.37).x
                    as f64
            })
            .collect();
        estimate(&estimates)
    };
    let (independent, jittered) = (variance_of_16(false), variance_of_16(true));
    println!(
        "16 samples: variance independent {:.3e}, jittered {:.3e}",
        independent.variance, jittered.variance
    );
    assert!(
        independent.variance > 2.0 * jittered.variance,
        "{independent:?} {jittered:?}"
    );
    assert_relative_eq!(independent.mean, jittered.mean, max_relative = 0.02);
}

// Extremes: nothing is ever NaN or infinite.

fn every_strategy() -> [LightSampling; 4] {
    [
        LightSampling::area(DiscWarp::Concentric),
        LightSampling::area(DiscWarp::Polar),
        LightSampling::area(DiscWarp::Naive),
        LightSampling::solid_angle(),
    ]
}

fn estimate_all(light: &AreaLight, x: Vec3, n: Vec3, count: usize) -> Vec<Vec3> {
    let points = uniform_points(count, 9);
    every_strategy()
        .into_iter()
        .map(|sampling| {
            let e = estimate_irradiance(x, n, light, &points, sampling, |_| true);
            assert!(
                e.is_finite() && e.cmpge(Vec3::ZERO).all(),
                "{light:?} at {x}: {e}"
            );
            e
        })
        .collect()
}

#[test]
fn lights_without_area_give_zero() {
    let shapes: [LightShape; 5] = [
        Disc::new(Vec3::Y, -Vec3::Y, 0.0).into(),
        Parallelogram::new(Vec3::Y, Vec3::X, 2.0 * Vec3::X).into(),
        Triangle::new(Vec3::Y, Vec3::X, Vec3::X).into(),
        Sphere::new(Vec3::Y, 0.0).into(),
        Sphere::new(Vec3::Y, -1.0).into(),
    ];
    for shape in shapes {
        let light = AreaLight::new(shape, Vec3::splat(1e30));
        for e in estimate_all(&light, Vec3::ZERO, Vec3::Y, 100) {
            assert_eq!(e, Vec3::ZERO, "{shape:?}");
        }
    }
}

#[test]
fn receivers_behind_a_one_sided_light_get_nothing() {
    // Every planar light facing up, the receiver below it facing up.
    let shapes: [LightShape; 3] = [
        Parallelogram::new(Vec3::new(-0.5, 1.0, -0.5), Vec3::Z, Vec3::X).into(),
        Triangle::new(
            Vec3::new(-0.5, 1.0, 0.0),
            Vec3::new(0.0, 1.0, 0.5),
            Vec3::new(0.5, 1.0, 0.0),
        )
        .into(),
        Disc::new(Vec3::Y, Vec3::Y, 0.5).into(),
    ];
    for shape in shapes {
        let light = AreaLight::new(shape, Vec3::ONE);
        for e in estimate_all(&light, Vec3::ZERO, Vec3::Y, 500) {
            assert_eq!(e, Vec3::ZERO, "{shape:?}");
        }
        // The same light turned over lights the receiver.
        let above = estimate_all(&light, 2.0 * Vec3::Y, -Vec3::Y, 500);
        assert!(above.iter().all(|e| e.x > 0.0), "{shape:?}: {above:?}");
    }
}

#[test]
fn receivers_on_the_light_or_touching_it_stay_finite() {
    let quad = Parallelogram::new(Vec3::ZERO, Vec3::Z, Vec3::X); // the floor square, facing up
    let light = AreaLight::new(quad, Vec3::ONE);
    for x in [
        Vec3::new(0.5, 0.0, 0.5),
        Vec3::ZERO,
        Vec3::new(1.0, 0.0, 0.3),
    ] {
        for n in [Vec3::Y, -Vec3::Y, Vec3::X] {
            estimate_all(&light, x, n, 1000);
        }
    }
    // A panel standing on the floor, seen from a point of its bottom edge: edge-on, nothing.
    let standing = AreaLight::new(Parallelogram::new(Vec3::ZERO, Vec3::X, Vec3::Y), Vec3::ONE);
    for e in estimate_all(&standing, Vec3::new(0.5, 0.0, 0.0), Vec3::Y, 1000) {
        assert_eq!(e, Vec3::ZERO);
    }
    // A sphere resting on the floor, at the point of contact and just beside it.
    let sphere = Sphere::new(Vec3::Y, 1.0);
    let light = AreaLight::new(sphere, Vec3::ONE);
    estimate_all(&light, Vec3::ZERO, Vec3::Y, 1000);
    for s in [0.01f32, 0.3] {
        // The sphere touches the horizon: cos θ = sin θ_max = R / d, the formula still holds.
        let x = Vec3::new(s, 0.0, 0.0);
        let d = (1.0 + s * s).sqrt();
        let reference = sphere_irradiance(Vec3::ONE, 1.0, d, 1.0 / d).x as f64;
        let e = measure(&light, x, Vec3::Y, LightSampling::solid_angle(), 20_000, 10);
        assert_agrees(e, reference, 0.005, &format!("resting sphere at {s}"));
    }
}

#[test]
fn huge_and_tiny_lights_match_their_references() {
    // A sphere of radius 1e5 just 1 away: it fills nearly the whole hemisphere.
    let huge = AreaLight::new(Sphere::new(Vec3::new(0.0, 1e5 + 1.0, 0.0), 1e5), Vec3::ONE);
    let reference = sphere_irradiance(Vec3::ONE, 1e5, 1e5 + 1.0, 1.0).x as f64;
    assert_agrees(
        measure(
            &huge,
            Vec3::ZERO,
            Vec3::Y,
            LightSampling::solid_angle(),
            20_000,
            11,
        ),
        reference,
        0.005,
        "huge sphere",
    );
    // A disc of radius 1e5 at height 1, sampled by area: unbiased, but its irradiance comes
    // from the few square units above the receiver, where one sample in 10⁹ lands. The
    // estimate stays finite and non-negative, and with any affordable number of samples it is
    // nearly 0: the case for sampling by solid angle.
    let disc = AreaLight::new(Disc::new(Vec3::Y, -Vec3::Y, 1e5), Vec3::ONE);
    let e = measure(&disc, Vec3::ZERO, Vec3::Y, area(), 20_000, 12);
    let reference = disc_on_axis_irradiance(Vec3::ONE, 1e5, 1.0).x as f64;
    println!(
        "huge disc by area: {} ± {} against {reference}",
        e.mean, e.standard_error
    );
    assert!(
        e.mean.is_finite() && e.mean >= 0.0 && e.mean < reference,
        "{e:?}"
    );
    // Tiny lights, 1e-4 across.
    let tiny_disc = AreaLight::new(Disc::new(Vec3::Y, -Vec3::Y, 1e-4), Vec3::ONE);
    let reference = disc_on_axis_irradiance(Vec3::ONE, 1e-4, 1.0).x as f64;
    assert_agrees(
        measure(&tiny_disc, Vec3::ZERO, Vec3::Y, area(), 2_000, 13),
        reference,
        1e-4,
        "tiny disc",
    );
    let tiny_sphere = AreaLight::new(Sphere::new(Vec3::Y, 1e-4), Vec3::ONE);
    let reference = sphere_irradiance(Vec3::ONE, 1e-4, 1.0, 1.0).x as f64;
    assert_agrees(
        measure(
            &tiny_sphere,
            Vec3::ZERO,
            Vec3::Y,
            LightSampling::solid_angle(),
            2_000,
            14,
        ),
        reference,
        1e-4,
        "tiny sphere",
    );
    assert_agrees(
        measure(&tiny_sphere, Vec3::ZERO, Vec3::Y, area(), 40_000, 14),
        reference,
        0.01,
        "tiny sphere by area",
    );
}

#[test]
fn a_shrinking_light_becomes_a_point_light() {
    // Radiance I / A on a facing disc, or I / (π R²) on a sphere: intensity I towards the
    // receiver, which then gets I cos θ / d² like chapter 01's point light.
    let intensity = 3.0;
    let x = Vec3::ZERO;
    let n = Vec3::new(0.5, 1.0, 0.0).normalize();
    let position = Vec3::new(0.0, 2.0, 0.0);
    let point_light = intensity * n.y / 4.0;
    let r = 1e-3;
    let disc = AreaLight::new(
        Disc::new(position, x - position, r),
        Vec3::splat(intensity / (PI * r * r)),
    );
    let sphere = AreaLight::new(
        Sphere::new(position, r),
        Vec3::splat(intensity / (PI * r * r)),
    );
    let points = uniform_points(1000, 15);
    for (light, sampling) in [
        (disc, area()),
        (sphere, LightSampling::solid_angle()),
        (sphere, area()),
    ] {
        let e = estimate_irradiance(x, n, &light, &points, sampling, |_| true).x;
        let tolerance = if sampling == area() && matches!(light.shape, LightShape::Sphere(_)) {
            0.1
        } else {
            1e-4
        };
        assert_relative_eq!(e, point_light, max_relative = tolerance);
    }
}

#[test]
fn the_estimate_does_not_depend_on_the_scenes_scale() {
    let shapes = |s: f32| -> [LightShape; 4] {
        let o = s * Vec3::new(3.0, -2.0, 7.0);
        [
            Parallelogram::new(o + s * Vec3::new(-0.2, 1.0, -0.7), s * Vec3::X, s * Vec3::Z).into(),
            Triangle::new(
                o + s * Vec3::new(-0.5, 1.0, 0.0),
                o + s * Vec3::new(0.2, 0.8, -1.0),
                o + s * Vec3::new(1.0, 1.2, 0.3),
            )
            .into(),
            Disc::new(
                o + s * Vec3::new(0.3, 1.5, 0.0),
                Vec3::new(0.1, -1.0, 0.0),
                s,
            )
            .into(),
            Sphere::new(o + s * Vec3::new(1.0, 2.0, 0.5), 0.6 * s).into(),
        ]
    };
    let points = uniform_points(2_000, 16);
    let n = tilted_normal();
    for (i, unit) in shapes(1.0).into_iter().enumerate() {
        for sampling in every_strategy() {
            let at_one = estimate_irradiance(
                Vec3::new(3.0, -2.0, 7.0),
                n,
                &AreaLight::new(unit, L),
                &points,
                sampling,
                |_| true,
            );
            assert!(at_one.x > 0.0);
            for s in [1e-4f32, 1e5] {
                let light = AreaLight::new(shapes(s)[i], L);
                let e = estimate_irradiance(
                    s * Vec3::new(3.0, -2.0, 7.0),
                    n,
                    &light,
                    &points,
                    sampling,
                    |_| true,
                );
                assert_relative_eq!(e, at_one, max_relative = 1e-3);
            }
        }
    }
}

#[test]
fn grazing_receivers_match_lamberts_formula() {
    // A panel far to the side, its bottom edge just above the receiver's horizon.
    let quad = Parallelogram::new(Vec3::new(10.0, 0.01, -0.5), Vec3::Z, Vec3::Y);
    // Z × Y = -X: it faces the receiver at the origin.
    let light = AreaLight::new(quad, L);
    let reference = polygon_irradiance(Vec3::ZERO, Vec3::Y, &quad_vertices(&quad), L).x as f64;
    assert!(reference > 0.0);
    assert_agrees(
        measure(&light, Vec3::ZERO, Vec3::Y, area(), 40_000, 17),
        reference,
        0.01,
        "grazing",
    );
    // Exactly edge-on to the receiver's plane, and a receiver normal along the panel.
    let flat = AreaLight::new(
        Parallelogram::new(Vec3::new(10.0, 0.0, -0.5), Vec3::Z, Vec3::X),
        L,
    );
    for e in estimate_all(&flat, Vec3::ZERO, Vec3::Y, 1000) {
        assert_eq!(e, Vec3::ZERO);
    }
    estimate_all(&light, Vec3::ZERO, Vec3::X, 1000);
}

#[test]
fn no_configuration_gives_nan_or_infinity() {
    let mut count = 0;
    let points = uniform_points(64, 18);
    for scale in [1e-4f32, 1.0, 1e5] {
        let centres = [
            Vec3::ZERO,
            Vec3::Y,
            Vec3::new(0.3, 0.0, 0.2),
            Vec3::new(0.0, 1e-7, 0.0),
        ]
        .map(|c| c * scale);
        for c in centres {
            let shapes: [LightShape; 4] = [
                Parallelogram::new(c, scale * Vec3::X, scale * Vec3::Z).into(),
                Triangle::new(c, c + scale * Vec3::X, c + scale * Vec3::Z).into(),
                Disc::new(c, Vec3::new(0.0, -1.0, 0.1), scale).into(),
                Sphere::new(c, scale).into(),
            ];
            for shape in shapes {
                for x in [Vec3::ZERO, Vec3::new(0.1, 0.0, 0.1) * scale, c] {
                    for n in [Vec3::Y, -Vec3::Y, Vec3::X, tilted_normal()] {
                        for sampling in every_strategy() {
                            let light = AreaLight::new(shape, L);
                            let e = estimate_irradiance(x, n, &light, &points, sampling, |_| true);
                            assert!(e.is_finite(), "{shape:?} at {x}, n = {n}: {e}");
                            count += 1;
                        }
                    }
                }
            }
        }
    }
    assert_eq!(count, 3 * 4 * 4 * 3 * 4 * 4);
}

#[test]
fn the_estimate_is_the_mean_of_visible_terms() {
    let light = AreaLight::new(ceiling_panel(), L);
    let points = uniform_points(100, 19);
    assert_eq!(
        estimate_irradiance(Vec3::ZERO, Vec3::Y, &light, &[], area(), |_| true),
        Vec3::ZERO
    );
    assert_eq!(
        estimate_irradiance(Vec3::ZERO, Vec3::Y, &light, &points, area(), |_| false),
        Vec3::ZERO
    );
    let all = estimate_irradiance(Vec3::ZERO, Vec3::Y, &light, &points, area(), |_| true);
    let mut asked = 0;
    let half = estimate_irradiance(Vec3::ZERO, Vec3::Y, &light, &points, area(), |s| {
        asked += 1;
        s.p.x < 0.3
    });
    assert_eq!(asked, 100);
    assert!(half.x > 0.2 * all.x && half.x < 0.8 * all.x);
    assert_relative_eq!(
        matte_reflected_radiance(Vec3::splat(0.5), Vec3::splat(PI)),
        Vec3::splat(0.5),
        max_relative = 1e-6
    );
}
