//! The capstone's check: the estimate against the exact irradiance, within the estimator's
//! own noise as theory gives it, and its standard error against that noise. Where the mean is
//! off, the usual slips each have an expected value of their own (worked out below by
//! quadrature), and the check names the one the estimate lands on.

use std::f64::consts::PI;

use common::sampler::unit_f32;
use glam::Vec2;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;

use super::*;
use crate::warps::{sample_uniform_hemisphere, uniform_hemisphere_pdf};

/// A sky whose sun gives about three quarters of the irradiance from 2 % of the hemisphere.
const SKY: SunAndSky = SunAndSky {
    sky: 0.5,
    sun: 40.0,
    sun_cos_theta_max: 0.98,
};

const MIXTURE: DirectionSampling = DirectionSampling::SunOrSky {
    cos_theta_max: 0.98,
    sun_probability: 0.5,
};

/// How many standard errors an estimate may stray from its expectation (fixed seeds: the
/// checks are deterministic, and a right answer passes by a wide margin).
const STANDARD_ERRORS: f64 = 5.0;

/// `n` uniform numbers of the square from a PCG seeded by `seed`.
fn uniform_numbers(seed: u64) -> impl FnMut() -> Vec2 {
    let mut rng = Pcg32::seed_from_u64(seed);
    move || Vec2::new(unit_f32(rng.next_u32()), unit_f32(rng.next_u32()))
}

/// `∫ g dω` over the hemisphere for a `g` that depends on `z = cos θ` alone
/// (`dω = 2π dz`), split at the sun's edge, where the integrands jump.
fn over_hemisphere(g: impl Fn(f64) -> f64) -> f64 {
    let m = f64::from(SKY.sun_cos_theta_max);
    let midpoint = |a: f64, b: f64| {
        let nodes = 100_000;
        let h = (b - a) / nodes as f64;
        (0..nodes).map(|i| g(a + (i as f64 + 0.5) * h)).sum::<f64>() * h
    };
    2.0 * PI * (midpoint(0.0, m) + midpoint(m, 1.0))
}

/// The sky's radiance times `cos θ`, the integrand, at height `z`.
fn integrand(z: f64) -> f64 {
    let radiance = if z >= f64::from(SKY.sun_cos_theta_max) {
        SKY.sun
    } else {
        SKY.sky
    };
    radiance * z
}

/// The density of a direction at height `z` under `sampling`, and the densities of the two
/// warps of the mixture.
fn density(sampling: DirectionSampling, z: f64) -> f64 {
    let (cap, cosine) = mixture_parts(z);
    match sampling {
        DirectionSampling::Uniform => 0.5 / PI,
        DirectionSampling::Cosine => cosine,
        DirectionSampling::SunOrSky {
            sun_probability, ..
        } => {
            let p = f64::from(sun_probability);
            p * cap + (1.0 - p) * cosine
        }
    }
}

fn mixture_parts(z: f64) -> (f64, f64) {
    let m = f64::from(SKY.sun_cos_theta_max);
    let cap = if z >= m {
        1.0 / (2.0 * PI * (1.0 - m))
    } else {
        0.0
    };
    (cap, z / PI)
}

/// The standard deviation of one term `f / p` under `sampling`: `√(∫ f²/p dω - E²)`.
fn sigma(sampling: DirectionSampling) -> f64 {
    let second_moment = over_hemisphere(|z| integrand(z).powi(2) / density(sampling, z));
    (second_moment - SKY.irradiance().powi(2)).max(0.0).sqrt()
}

/// The usual slips, each with the value its estimate tends to under `sampling`.
fn slips(sampling: DirectionSampling) -> Vec<(String, f64)> {
    let e = SKY.irradiance();
    let mut slips = vec![(
        "each term is f without dividing by its density p: a direction that was likely to be \
         drawn must count for less"
            .to_string(),
        over_hemisphere(|z| integrand(z) * density(sampling, z)),
    )];
    if sampling == DirectionSampling::Cosine {
        slips.push((
            "the directions are cosine-weighted but divided by the uniform density 1/(2π): \
             the density must be the one of the warp that drew the direction"
                .to_string(),
            over_hemisphere(|z| integrand(z) * 2.0 * PI * z / PI),
        ));
    }
    if let DirectionSampling::SunOrSky {
        sun_probability, ..
    } = sampling
    {
        let p = f64::from(sun_probability);
        let m = f64::from(SKY.sun_cos_theta_max);
        let in_cap = |z: f64| if z >= m { integrand(z) } else { 0.0 };
        slips.push((
            "each direction is divided by the density of the warp that drew it alone: but the \
             other warp could have drawn it too (the cosine can land in the sun's cap), so its \
             density is the mixture of both, each weighted by the chance of its warp"
                .to_string(),
            p * over_hemisphere(in_cap) + (1.0 - p) * e,
        ));
        slips.push((
            "the two densities are added without the chances of their warps: the mixture's \
             density is p_sun · cap + (1 - p_sun) · cosine"
                .to_string(),
            over_hemisphere(|z| {
                let (cap, cosine) = mixture_parts(z);
                integrand(z) * density(sampling, z) / (cap + cosine)
            }),
        ));
        slips.push((
            "every direction is divided by the cosine density alone: the directions from the \
             sun's cap have a density of their own"
                .to_string(),
            over_hemisphere(|z| integrand(z) * density(sampling, z) / (z / PI)),
        ));
        let whole_cap = 1.0 / (2.0 * PI * (1.0 - m));
        slips.push((
            "the cap's density is counted for directions outside the cap too: the cap's warp \
             never draws those, so its density there is 0"
                .to_string(),
            over_hemisphere(|z| {
                integrand(z) * density(sampling, z) / (p * whole_cap + (1.0 - p) * z / PI)
            }),
        ));
    }
    for (factor, words) in [
        (2.0, "2"),
        (0.5, "1/2"),
        (PI, "π"),
        (1.0 / PI, "1/π"),
        (2.0 * PI, "2π"),
        (0.5 / PI, "1/(2π)"),
    ] {
        slips.push((
            format!(
                "the estimate is {words} times the integral: a density off by a constant \
                 factor (1/π where 1/(2π) is meant, or the other way round)?"
            ),
            factor * e,
        ));
    }
    slips
}

fn name(sampling: DirectionSampling) -> &'static str {
    match sampling {
        DirectionSampling::Uniform => "uniform directions",
        DirectionSampling::Cosine => "cosine-weighted directions",
        DirectionSampling::SunOrSky { .. } => "the sun-or-sky mixture",
    }
}

/// Checks the mean of one estimate with `n` directions under `sampling`, naming the slip.
fn check_unbiased(sampling: DirectionSampling, n: usize, seed: u64) {
    let estimate =
        estimate_irradiance(|d| SKY.radiance(d), sampling, n, &mut uniform_numbers(seed));
    let e = SKY.irradiance();
    let tolerance = STANDARD_ERRORS * sigma(sampling) / (n as f64).sqrt() + 1e-9 * e;
    if (estimate.mean - e).abs() <= tolerance {
        return;
    }
    let slip = slips(sampling)
        .into_iter()
        // A slip's own noise can be larger than the right estimator's: a few per cent.
        .find(|(_, value)| (estimate.mean - value).abs() <= tolerance.max(0.06 * value.abs()));
    let what = match slip {
        Some((words, _)) => words,
        None => format!(
            "the estimate is {:.4} times the integral, further off than its noise allows",
            estimate.mean / e
        ),
    };
    panic!(
        "estimate_irradiance with {}: {what}.\n  {n} directions gave {}, the irradiance is \
         {e:.5} and the estimate's own noise is about ±{:.5}",
        name(sampling),
        estimate.mean,
        tolerance / STANDARD_ERRORS
    );
}

#[test]
fn exercise_sun_and_sky_is_unbiased_with_uniform_directions() {
    check_unbiased(DirectionSampling::Uniform, 20_000, 1);
}

#[test]
fn exercise_sun_and_sky_is_unbiased_with_cosine_weighted_directions() {
    check_unbiased(DirectionSampling::Cosine, 20_000, 2);
}

#[test]
fn exercise_sun_and_sky_is_unbiased_with_the_mixture() {
    check_unbiased(MIXTURE, 20_000, 3);
    // Mostly the sun, and mostly the sky: the density must hold for every mixing chance.
    for (p, seed) in [(0.9f32, 4), (0.1, 5)] {
        check_unbiased(
            DirectionSampling::SunOrSky {
                cos_theta_max: SKY.sun_cos_theta_max,
                sun_probability: p,
            },
            20_000,
            seed,
        );
    }
}

#[test]
fn exercise_sun_and_sky_reports_its_standard_error() {
    // Five directions, drawn uniformly: the terms are worked out here, one by one.
    let us = [
        Vec2::new(0.1, 0.01),
        Vec2::new(0.7, 0.3),
        Vec2::new(0.4, 0.015),
        Vec2::new(0.9, 0.8),
        Vec2::new(0.25, 0.5),
    ];
    let terms: Vec<f64> = us
        .iter()
        .map(|&u| {
            let d = sample_uniform_hemisphere(u);
            SKY.radiance(d) * f64::from(d.z) / f64::from(uniform_hemisphere_pdf())
        })
        .collect();
    let n = terms.len() as f64;
    let mean = terms.iter().sum::<f64>() / n;
    let squares = terms.iter().map(|t| (t - mean).powi(2)).sum::<f64>();
    let variance = squares / (n - 1.0);
    let expected = (variance / n).sqrt();
    let mut given = us.into_iter();
    let mine = estimate_irradiance(
        |d| SKY.radiance(d),
        DirectionSampling::Uniform,
        us.len(),
        &mut || given.next().expect("one u per direction"),
    );
    let near = |a: f64, b: f64| (a - b).abs() <= 1e-6 * b.abs();
    assert!(
        near(mine.mean, mean),
        "estimate_irradiance: for these five uniform directions the mean of the terms \
         f / p is {mean}, yours {}: a uniform direction is sample_uniform_hemisphere(u), one for \
         each u of next_u in turn, and its term is L cos θ over uniform_hemisphere_pdf()",
        mine.mean
    );
    if near(mine.standard_error, expected) {
        return;
    }
    let se = mine.standard_error;
    let mistake = if near(se, (squares / n / n).sqrt()) {
        "the squared deviations are divided by n: measured from the samples' own mean they \
         come out too small, and the unbiased variance divides by n - 1"
    } else if near(se, variance.sqrt()) {
        "that is the standard deviation of one term: the mean of n independent terms varies \
         √n times less"
    } else if near(se, variance / n) || near(se, variance) {
        "that is a variance: the standard error is in the units of the estimate, a square root"
    } else if near(se, variance.sqrt() / n) {
        "it is divided by n: the standard deviation of a mean of n terms is σ / √n"
    } else {
        "it should be the standard deviation of the mean of the terms"
    };
    panic!(
        "estimate_irradiance: the standard error is {se}, expected {expected}: {mistake}.\n  \
         The terms were {terms:?}"
    );
}

#[test]
fn exercise_sun_and_sky_standard_error_is_the_noise_of_the_estimate() {
    for (sampling, seed) in [
        (DirectionSampling::Uniform, 11),
        (DirectionSampling::Cosine, 12),
        (MIXTURE, 13),
    ] {
        let n = 20_000;
        let estimate =
            estimate_irradiance(|d| SKY.radiance(d), sampling, n, &mut uniform_numbers(seed));
        let theory = sigma(sampling) / (n as f64).sqrt();
        let ratio = estimate.standard_error / theory;
        assert!(
            (ratio - 1.0).abs() < 0.1,
            "estimate_irradiance with {}: the standard error {} should be close to the \
             estimator's noise σ/√n = {theory:.5} (from the variance of one term, σ² = ∫ f²/p \
             dω - E²); it is {ratio:.3} times that",
            name(sampling),
            estimate.standard_error
        );
    }
}

#[test]
fn exercise_sun_and_sky_is_exact_where_the_density_follows_the_integrand() {
    // A uniform sky, cosine-weighted directions: every term is π L.
    let estimate = estimate_irradiance(
        |_| 1.3,
        DirectionSampling::Cosine,
        100,
        &mut uniform_numbers(21),
    );
    assert!(
        (estimate.mean - 1.3 * PI).abs() < 1e-5 && estimate.standard_error < 1e-5,
        "estimate_irradiance: under a uniform sky of radiance 1.3, cosine-weighted directions \
         make every term f / p the same, 1.3 π = {}: the estimate is exact and its standard \
         error 0; yours gave {} ± {}",
        1.3 * PI,
        estimate.mean,
        estimate.standard_error
    );
}

#[test]
fn exercise_sun_and_sky_of_a_direction_on_the_horizon() {
    // ξ1 = 0 puts the concentric map's point on the rim of the disc: lifted, it lies on the
    // horizon, where the cosine-weighted density is 0 (and so is the integrand).
    let mut on_the_rim = [Vec2::new(0.0, 0.3), Vec2::new(0.5, 0.5)].into_iter();
    let estimate = estimate_irradiance(|_| 1.0, DirectionSampling::Cosine, 2, &mut || {
        on_the_rim.next().expect("one u per direction")
    });
    assert!(
        estimate.mean.is_finite() && (estimate.mean - PI / 2.0).abs() < 1e-5,
        "estimate_irradiance: of two cosine-weighted directions, one lies on the horizon, where \
         its density is 0: 0 / 0 is not a number, and such a direction contributes nothing \
         (the other gives π). The estimate should be π/2, yours is {}",
        estimate.mean
    );
}

#[test]
fn exercise_sun_and_sky_of_no_directions_is_nan() {
    let estimate = workbench::test_support::catch_panic(|| {
        estimate_irradiance(
            |_| 1.0,
            DirectionSampling::Uniform,
            0,
            &mut uniform_numbers(1),
        )
    })
    .unwrap_or_else(|message| {
        panic!(
            "estimate_irradiance: with n = 0 it panicked ({message}): no directions give no \
             estimate, and both numbers are NaN"
        )
    });
    assert!(
        estimate.mean.is_nan() && estimate.standard_error.is_nan(),
        "estimate_irradiance: no directions give no estimate: both numbers are NaN, not {} ± {}",
        estimate.mean,
        estimate.standard_error
    );
}

#[test]
fn the_exact_irradiance_is_the_quadrature_of_the_integrand() {
    let quadrature = over_hemisphere(integrand);
    assert!((quadrature / SKY.irradiance() - 1.0).abs() < 1e-8);
}
