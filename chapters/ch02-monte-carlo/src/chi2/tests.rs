//! The chi-square test at work: correct warps pass, broken ones fail, and the p-values of a
//! correct warp are uniform, as they must be if the test is calibrated.

use super::*;
use crate::warps::disc::polar_to_cartesian;
use crate::warps::{
    cos_lobe_pdf, cosine_hemisphere_pdf, sample_cos_lobe, sample_uniform_hemisphere,
    uniform_disc_pdf,
};
use approx::assert_relative_eq;
use std::time::Instant;

const SAMPLES: usize = 1_000_000;
const PLANE_RESOLUTION: (usize, usize) = (32, 32);
/// 32 bins in φ, 64 in cos θ: the lobe with n = 100 still spans several rows.
const SPHERE_RESOLUTION: (usize, usize) = (32, 64);

fn resolution(domain: Domain) -> (usize, usize) {
    match domain {
        Domain::Plane { .. } => PLANE_RESOLUTION,
        Domain::Sphere => SPHERE_RESOLUTION,
    }
}

fn describe(warp: &Warp) -> String {
    match warp {
        Warp::CosLobe { exponent } => format!("{} n={exponent}", warp.name()),
        Warp::SphericalCap { cos_theta_max } => {
            format!("{} cos={cos_theta_max}", warp.name())
        }
        _ => warp.name().to_string(),
    }
}

#[test]
fn every_correct_warp_passes() {
    let warps: Vec<Warp> = Warp::all_for_tests()
        .into_iter()
        .filter(Warp::delivers_claimed_density)
        .collect();
    let level = significance_level(warps.len(), 0.01);
    println!("significance level per warp: {level:.3e}");
    println!(
        "{:<26} {:>10} {:>5} {:>8} {:>7}",
        "warp", "X²", "dof", "p", "pooled"
    );
    let mut failures = Vec::new();
    for (seed, warp) in warps.iter().enumerate() {
        let start = Instant::now();
        let result = chi2_test(warp, SAMPLES, seed as u64, resolution(warp.domain()));
        println!(
            "{:<26} {:>10.1} {:>5} {:>8.4} {:>7}   ({:.2} s)",
            describe(warp),
            result.statistic,
            result.dof,
            result.p_value,
            result.pooled_bins,
            start.elapsed().as_secs_f64()
        );
        if result.p_value <= level {
            failures.push((describe(warp), result));
        }
    }
    assert!(failures.is_empty(), "rejected: {failures:#?}");
}

#[test]
fn the_naive_disc_fails_its_uniform_claim() {
    let result = chi2_test(&Warp::DiscNaive, SAMPLES, 0, PLANE_RESOLUTION);
    assert!(result.p_value < 1e-12, "{result:?}");
    // Fewer samples are enough: the clustering is no subtle effect.
    let result = chi2_test(&Warp::DiscNaive, 10_000, 0, (8, 8));
    assert!(result.p_value < 1e-12, "{result:?}");
}

/// Tests a deliberately broken warp with the settings of the real ones.
fn broken(
    domain: Domain,
    sample: impl FnMut(Vec2) -> WarpPoint,
    pdf: impl Fn(WarpPoint) -> f32,
) -> Chi2Result {
    chi2_test_density(domain, SAMPLES, 1, resolution(domain), sample, pdf)
}

fn unit_disc() -> Domain {
    Warp::DiscPolar.domain()
}

fn uniform_disc(point: WarpPoint) -> f32 {
    Warp::DiscPolar.pdf(point)
}

#[test]
fn a_slightly_wrong_radius_is_caught() {
    // The radius a little too far out for every ξ2 (a slightly smaller power of ξ2 than the
    // right one), a mistake too small to see in a scatter plot.
    let result = broken(
        unit_disc(),
        |u| {
            WarpPoint::Plane(polar_to_cartesian(
                u.y.powf(0.45),
                std::f32::consts::TAU * u.x,
            ))
        },
        uniform_disc,
    );
    assert!(result.p_value < 1e-6, "{result:?}");
}

#[test]
fn a_uniform_hemisphere_is_no_cosine_hemisphere() {
    let result = broken(
        Domain::Sphere,
        |u| WarpPoint::Direction(sample_uniform_hemisphere(u)),
        |point| match point {
            WarpPoint::Direction(d) => cosine_hemisphere_pdf(d.z),
            WarpPoint::Plane(_) => 0.0,
        },
    );
    assert!(result.p_value < 1e-12, "{result:?}");
}

#[test]
fn a_lobe_off_by_one_in_its_exponent_is_caught() {
    // Sampled with n = 10, claimed as n = 11.
    let result = broken(
        Domain::Sphere,
        |u| WarpPoint::Direction(sample_cos_lobe(u, 10.0)),
        |point| match point {
            WarpPoint::Direction(d) => cos_lobe_pdf(d.z, 11.0),
            WarpPoint::Plane(_) => 0.0,
        },
    );
    assert!(result.p_value < 1e-6, "{result:?}");
}

#[test]
fn a_triangle_without_the_fold_leaves_the_triangle() {
    let result = broken(Warp::Triangle.domain(), WarpPoint::Plane, |point| {
        Warp::Triangle.pdf(point)
    });
    assert!(
        result.impossible_samples > 0 && result.p_value == 0.0,
        "{result:?}"
    );
}

#[test]
fn a_density_off_by_a_constant_factor_is_caught() {
    // The right samples, with the density of the triangle's unit square: half too small.
    let result = broken(
        Warp::Triangle.domain(),
        |u| Warp::Triangle.sample(u),
        |point| 0.5 * Warp::Triangle.pdf(point),
    );
    assert!(result.p_value < 1e-12, "{result:?}");
}

#[test]
fn points_outside_the_grid_or_off_the_sphere_are_impossible() {
    let outside = broken(
        unit_disc(),
        |u| WarpPoint::Plane(2.0 * u),
        |_| uniform_disc_pdf(),
    );
    assert!(outside.impossible_samples > 0 && outside.p_value == 0.0);
    let too_long = broken(
        Domain::Sphere,
        |u| WarpPoint::Direction(1.01 * sample_uniform_hemisphere(u)),
        |point| Warp::Hemisphere.pdf(point),
    );
    assert_eq!(too_long.impossible_samples, SAMPLES);
}

#[test]
fn expected_counts_add_up_to_the_number_of_samples() {
    // Every claimed density integrates to 1, so the bins' expectations must add up to
    // the number of samples: a check of the adaptive integration.
    for warp in Warp::all_for_tests() {
        let grid = BinGrid::new(warp.domain(), resolution(warp.domain()));
        let total: f64 = expected_counts(&grid, &|p| warp.pdf(p), SAMPLES)
            .iter()
            .sum();
        assert_relative_eq!(total / SAMPLES as f64, 1.0, epsilon = 1e-4);
    }
}

#[test]
fn the_significance_level_follows_sidak() {
    assert_relative_eq!(significance_level(1, 0.01), 0.01, max_relative = 1e-12);
    let level = significance_level(10, 0.01);
    assert_relative_eq!(1.0 - (1.0 - level).powi(10), 0.01, max_relative = 1e-9);
    assert!(level > 0.001 && level < 0.01 / 9.0);
    // Tiny levels keep their digits.
    assert_relative_eq!(significance_level(1000, 1e-9), 1e-12, max_relative = 1e-6);
}

#[test]
fn p_values_of_a_correct_warp_are_uniform() {
    // If the test is calibrated, a correct warp's p-values over many seeds are uniform in
    // [0, 1]: about a tenth fall below 0.1 and about half below 0.5.
    let runs = 200;
    let p_values: Vec<f64> = (0..runs)
        .map(|seed| chi2_test(&Warp::DiscConcentric, 5_000, seed, (8, 8)).p_value)
        .collect();
    let below = |level: f64| p_values.iter().filter(|&&p| p < level).count();
    // Binomial(200, 0.1) has mean 20 and standard deviation 4.2; (200, 0.5) 100 and 7.1.
    assert!(
        (8..=32).contains(&below(0.1)),
        "{} of {runs} below 0.1",
        below(0.1)
    );
    assert!(
        (79..=121).contains(&below(0.5)),
        "{} of {runs} below 0.5",
        below(0.5)
    );
}

#[test]
#[ignore = "slow: about half a minute; run with --ignored when changing the integration"]
fn p_values_of_every_correct_warp_are_uniform() {
    // The calibration of the whole machinery at full size: the p-values of every correct
    // warp over twenty seeds each, pooled, must pass a Kolmogorov-Smirnov test of uniformity.
    let seeds = 20;
    let mut all = Vec::new();
    let warps = Warp::all_for_tests()
        .into_iter()
        .filter(Warp::delivers_claimed_density);
    for (index, warp) in warps.enumerate() {
        // Seeds of their own: the hemisphere and the lobe with n = 0 are the same map, and
        // with the same seeds their p-values would be the same too.
        let first_seed = 1000 * (index as u64 + 1);
        let mut p_values: Vec<f64> = (first_seed..first_seed + seeds)
            .map(|seed| chi2_test(&warp, SAMPLES, seed, resolution(warp.domain())).p_value)
            .collect();
        p_values.sort_by(f64::total_cmp);
        println!(
            "{:<26} {:?}",
            describe(&warp),
            p_values
                .iter()
                .map(|p| (p * 100.0).round() / 100.0)
                .collect::<Vec<_>>()
        );
        all.extend(p_values);
    }
    all.sort_by(f64::total_cmp);
    // Kolmogorov-Smirnov distance from the uniform distribution.
    let n = all.len() as f64;
    let ks = all
        .iter()
        .enumerate()
        .map(|(i, &p)| (p - i as f64 / n).abs().max(((i + 1) as f64 / n - p).abs()))
        .fold(0.0, f64::max);
    println!(
        "{} p-values, KS distance {ks:.4} (1% critical value {:.4})",
        all.len(),
        1.63 / n.sqrt()
    );
    assert!(ks < 1.63 / n.sqrt());
}
