//! Statistical tests: the random choices are unbiased, and the lobes have the densities
//! they claim.
//!
//! Choosing one ray at glass instead of both changes the noise, never the expected image. The
//! test renders the same pixel positions (the first dimension of every sample, so the same
//! for every strategy) both ways and checks that the mean per-pixel difference is zero within
//! five standard errors of that mean: a reflection weighted three quarters of what it should
//! be moves it by far more.

mod support;

use ch02_monte_carlo::chi2::chi2_test_density;
use ch02_monte_carlo::warps::{Domain, WarpPoint};
use ch06_fuzzy_reflections::fuzz::{disc_perturbation_pdf, disc_radius_for_exponent};
use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch06_fuzzy_reflections::{FuzzMethod, GlassStrategy, TraceOptions};
use glam::Vec3;
use support::render;

/// The mean over pixels of `a - b` (luminance) and its standard error.
fn mean_difference(
    builtin: Builtin,
    exponent: f32,
    a: GlassStrategy,
    b: GlassStrategy,
    spp: u64,
) -> (f64, f64) {
    let scene = builtin.build(DEFAULT_MAX_DEPTH, exponent);
    let with = |glass| TraceOptions {
        glass,
        ..TraceOptions::default()
    };
    let (w, h) = (40, 30);
    let image_a = render(&scene, with(a), w, h, spp, 7).image;
    let image_b = render(&scene, with(b), w, h, spp, 7).image;
    let luminance = |p: Vec3| f64::from(0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z);
    let d: Vec<f64> = image_a
        .pixels
        .iter()
        .zip(&image_b.pixels)
        .map(|(&p, &q)| luminance(p) - luminance(q))
        .collect();
    let n = d.len() as f64;
    let mean = d.iter().sum::<f64>() / n;
    let variance = d.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (variance / n).sqrt())
}

#[test]
fn picking_one_ray_at_smooth_glass_is_unbiased() {
    for strategy in [GlassStrategy::Half, GlassStrategy::Fresnel] {
        let (mean, se) = mean_difference(Builtin::Panes, 1.0, strategy, GlassStrategy::Both, 4);
        assert!(
            mean.abs() < 5.0 * se,
            "{strategy:?} - both: {mean} (se {se})"
        );
        assert!(se > 0.0, "{strategy:?}: the choice must add noise");
    }
}

#[test]
fn picking_one_ray_at_frosted_glass_is_unbiased() {
    for strategy in [GlassStrategy::Half, GlassStrategy::Fresnel] {
        let (mean, se) = mean_difference(Builtin::Frosted, 10.0, strategy, GlassStrategy::Both, 4);
        assert!(
            mean.abs() < 5.0 * se,
            "{strategy:?} - both: {mean} (se {se})"
        );
    }
}

/// The chi-square test of `method`'s directions around +z against its claimed density.
fn lobe_p_value(method: FuzzMethod, exponent: f32, claimed: impl Fn(f32) -> f32) -> f64 {
    chi2_test_density(
        Domain::Sphere,
        200_000,
        3,
        (16, 256),
        |u| WarpPoint::Direction(method.sample(Vec3::Z, exponent, u)),
        |point| match point {
            WarpPoint::Direction(d) => claimed(d.z),
            WarpPoint::Plane(_) => 0.0,
        },
    )
    .p_value
}

#[test]
fn the_lobe_and_the_disc_deliver_their_densities() {
    for exponent in [0.0f32, 1.0, 4.0, 20.0] {
        for method in FuzzMethod::ALL {
            let p = lobe_p_value(method, exponent, |cos| method.pdf(cos, exponent));
            assert!(p > 1e-3, "{method:?} n={exponent}: p = {p}");
        }
    }
}

#[test]
fn the_disc_is_not_the_lobe() {
    // The chi-square test tells the two apart: the empirical disc does not deliver the lobe's
    // density, at any exponent, even sized to the same spread.
    for exponent in [0.0f32, 1.0, 4.0] {
        let p = lobe_p_value(FuzzMethod::Disc, exponent, |cos| {
            FuzzMethod::Lobe.pdf(cos, exponent)
        });
        assert!(p < 1e-9, "n={exponent}: p = {p}");
        // Nor a disc of another radius.
        let wrong = 1.2 * disc_radius_for_exponent(exponent);
        let p = lobe_p_value(FuzzMethod::Disc, exponent, |cos| {
            disc_perturbation_pdf(cos, wrong)
        });
        assert!(p < 1e-9, "n={exponent}, radius {wrong}: p = {p}");
    }
}
