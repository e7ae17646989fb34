//! Statistical tests of lens sampling, with fixed seeds and tolerances from the estimators'
//! variances: the uniform disc warps and the polygon pass, the naive warp fails the same test.

use ch02_monte_carlo::chi2::{Chi2Result, chi2_test_density, significance_level};
use ch02_monte_carlo::warps::{Domain, WarpPoint};
use ch04_depth_of_field::{Aperture, Lens, LensWarp};
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2};

/// `n` lens points of `lens`, each from its own sampler stream as in a render.
fn lens_points(lens: &Lens, n: u64, seed: u64) -> Vec<Vec2> {
    let mut sampler = IndependentSampler::new(seed);
    (0..n)
        .map(|i| {
            sampler.start_pixel_sample(UVec2::new(i as u32 % 97, 0), i);
            lens.sample_point(sampler.get_2d())
        })
        .collect()
}

/// The mean distance of `n` lens points from the centre, and how far it is from `2R/3` in
/// standard errors. For a uniform disc of radius `R`, `r` has density `2r / R²`, so
/// `E[r] = 2R/3`, `E[r²] = R²/2` and `Var[r] = R²/2 - 4R²/9 = R²/18`.
fn radius_z_score(lens: &Lens, n: u64) -> (f64, f64) {
    let points = lens_points(lens, n, 11);
    let mean = points.iter().map(|p| f64::from(p.length())).sum::<f64>() / n as f64;
    let r = f64::from(lens.aperture_radius);
    let standard_error = (r * r / 18.0 / n as f64).sqrt();
    (mean, (mean - 2.0 * r / 3.0) / standard_error)
}

#[test]
fn uniform_disc_warps_have_mean_radius_two_thirds_of_r() {
    for warp in [LensWarp::Concentric, LensWarp::Polar] {
        let lens = Lens::new(0.8, 3.0).unwrap().with_warp(warp);
        let (mean, z) = radius_z_score(&lens, 100_000);
        // 4 standard errors: a correct warp fails this one time in 15 000.
        assert!(z.abs() < 4.0, "{warp:?}: mean radius {mean}, z = {z}");
    }
}

#[test]
fn the_naive_warp_fails_the_mean_radius_test() {
    // Its radius is uniform, so its mean is R/2: far outside the tolerance.
    let lens = Lens::new(0.8, 3.0).unwrap().with_warp(LensWarp::Naive);
    let (mean, z) = radius_z_score(&lens, 100_000);
    assert!(z.abs() > 50.0, "mean radius {mean}, z = {z}");
    assert!((mean - 0.4).abs() < 0.01, "mean radius {mean}");
}

/// Chi-square of a lens's points against the uniform density over its aperture.
fn uniform_chi2(lens: Lens) -> Chi2Result {
    let r = lens.aperture_radius;
    let area = lens.aperture.area() * r * r;
    let uniform = Lens {
        warp: LensWarp::Concentric,
        ..lens
    };
    chi2_test_density(
        Domain::Plane {
            min: Vec2::splat(-r),
            max: Vec2::splat(r),
        },
        200_000,
        5,
        (16, 16),
        |u| WarpPoint::Plane(lens.sample_point(u)),
        |point| match point {
            // The claimed density: uniform inside the aperture (the concentric lens's support).
            WarpPoint::Plane(p) if uniform.sample_point_pdf(p) > 0.0 => 1.0 / area,
            _ => 0.0,
        },
    )
}

#[test]
fn lens_points_are_uniform_over_the_aperture_except_with_the_naive_warp() {
    let level = significance_level(4, 0.01);
    let disc = Lens::new(0.5, 2.0).unwrap();
    for warp in [LensWarp::Concentric, LensWarp::Polar] {
        let result = uniform_chi2(disc.with_warp(warp));
        assert!(result.p_value > level, "{warp:?}: {result:?}");
    }
    let hexagon = disc.with_aperture(Aperture::polygon(6, 0.3).unwrap());
    let result = uniform_chi2(hexagon);
    assert!(result.p_value > level, "hexagon: {result:?}");
    let naive = uniform_chi2(disc.with_warp(LensWarp::Naive));
    assert!(naive.p_value < 1e-9, "the naive warp passed: {naive:?}");
}

#[test]
fn polygon_points_have_the_polygons_second_moment() {
    // A regular n-gon of circumradius R has polar moment of inertia per unit area
    // E[r²] = R² (1 + 2 cos²(π/n)) / 6 (a fan of isosceles triangles). Var[r²] is estimated
    // from the samples themselves.
    let lens = Lens::new(1.0, 2.0)
        .unwrap()
        .with_aperture(Aperture::polygon(5, 0.0).unwrap());
    let n = 100_000;
    let r2: Vec<f64> = lens_points(&lens, n, 3)
        .iter()
        .map(|p| f64::from(p.length_squared()))
        .collect();
    let mean = r2.iter().sum::<f64>() / n as f64;
    let variance = r2.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
    let c = (std::f64::consts::PI / 5.0).cos();
    let expected = (1.0 + 2.0 * c * c) / 6.0;
    let z = (mean - expected) / (variance / n as f64).sqrt();
    assert!(
        z.abs() < 4.0,
        "E[r²] = {mean}, expected {expected}, z = {z}"
    );
}
