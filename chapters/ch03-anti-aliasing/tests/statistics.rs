//! Statistical tests with fixed seeds and tolerances derived from the estimators' variances.

use ch02_monte_carlo::chi2::{chi2_test_density, significance_level};
use ch02_monte_carlo::warps::{Domain, WarpPoint};
use ch03_anti_aliasing::coverage::{HalfPlane, coverage_mse, estimate_coverage};
use ch03_anti_aliasing::pixel_samplers::HaltonSampler;
use ch03_anti_aliasing::{PixelSampler, PixelSamplerKind};
use glam::{UVec2, Vec2};

/// An edge crossing the pixel at a slant, covering 47.5% of it.
const EDGE: HalfPlane = HalfPlane {
    slope: 0.35,
    intercept: 0.3,
};

#[test]
fn random_coverage_has_the_binomial_variance() {
    // With random positions the count below the edge is binomial: variance c (1 - c) / n.
    let (n, repetitions) = (16u64, 4000u64);
    let c = EDGE.coverage();
    let expected = c * (1.0 - c) / n as f64;
    let measured = coverage_mse(PixelSamplerKind::Random, n, repetitions, EDGE);
    // The mean of R squared errors has relative standard deviation about sqrt(2 / R) (a bit
    // less for a binomial): 2.2% here; allow five of them.
    let tolerance = 5.0 * (2.0 / repetitions as f64).sqrt() * expected;
    assert!(
        (measured - expected).abs() < tolerance,
        "measured {measured}, expected {expected} +- {tolerance}"
    );
}

#[test]
fn stratified_coverage_has_less_variance_than_random() {
    // The variance of the mean of R squared errors is at most about 2 sigma^4 / R, so the
    // random estimate below is within 5 * sqrt(2 / R) = 11% of its value. Stratification
    // with 16 strata leaves only the ~4 strata the edge crosses noisy: a variance of at most
    // about 4 / 4 / 16^2 = 1/256, against c (1 - c) / 16 = 1/64 for random. A factor of two
    // is far inside that gap and far outside the noise of either estimate.
    let (n, repetitions) = (16u64, 2000u64);
    let random = coverage_mse(PixelSamplerKind::Random, n, repetitions, EDGE);
    let stratified = coverage_mse(PixelSamplerKind::Stratified, n, repetitions, EDGE);
    assert!(
        stratified < 0.5 * random,
        "stratified {stratified} vs random {random}"
    );
    // And both are unbiased: the mean estimate is the exact coverage, within 5 sigma.
    for kind in [PixelSamplerKind::Random, PixelSamplerKind::Stratified] {
        let mean: f64 = (0..repetitions)
            .map(|seed| estimate_coverage(kind, n, seed, UVec2::new(3, 5), EDGE))
            .sum::<f64>()
            / repetitions as f64;
        let sigma = (random / repetitions as f64).sqrt();
        assert!(
            (mean - EDGE.coverage()).abs() < 5.0 * sigma,
            "{kind:?}: mean {mean} vs {}",
            EDGE.coverage()
        );
    }
}

#[test]
fn the_centre_sample_is_biased_whatever_the_count() {
    let error = |n| coverage_mse(PixelSamplerKind::Centre, n, 10, EDGE);
    assert_eq!(error(1), error(256));
    assert!(error(256) > 0.2);
}

fn uniform_square() -> Domain {
    Domain::Plane {
        min: Vec2::ZERO,
        max: Vec2::ONE,
    }
}

#[test]
fn halton_points_of_a_pixel_are_uniform() {
    // The chi-square test against the uniform density: Halton points are spread *more* evenly
    // than random ones, so X² is small and the p-value large. Base 2 in both coordinates (a
    // diagonal line of points) would fail with p = 0.
    let alpha = significance_level(2, 0.01);
    let mut sampler = PixelSampler::new(PixelSamplerKind::Halton, 1, 4).unwrap();
    let mut index = 0;
    let result = chi2_test_density(
        uniform_square(),
        20_000,
        0,
        (10, 10),
        |_| {
            use common::sampler::Sampler;
            sampler.start_pixel_sample(UVec2::new(5, 8), index);
            index += 1;
            WarpPoint::Plane(sampler.get_pixel_2d())
        },
        |_| 1.0,
    );
    assert!(result.p_value > alpha, "{result:?}");
    assert_eq!(result.impossible_samples, 0);
    // The per-pixel shifts themselves are uniform over the pixel.
    let mut pixel = 0u32;
    let shifts = chi2_test_density(
        uniform_square(),
        20_000,
        0,
        (10, 10),
        |_| {
            pixel += 1;
            WarpPoint::Plane(HaltonSampler::pixel_shift(
                9,
                UVec2::new(pixel % 200, pixel / 200),
            ))
        },
        |_| 1.0,
    );
    assert!(shifts.p_value > alpha, "{shifts:?}");
}
