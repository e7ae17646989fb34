//! Every BSDF sampler with a density delivers the density it claims.
//!
//! The path tracer divides by `Bsdf::pdf` (in the weight, and in every MIS weight), so a
//! sampler that draws from another density biases every image silently. Chapter 02's
//! chi-square test catches that: many directions from `Bsdf::sample`, counted in bins, against
//! the counts the claimed density predicts. The bins lie on a [`chart`] around each lobe, so
//! a lobe a hundredth of a radian wide is resolved as well as a cosine, and one row of bins
//! counts the samples that give no direction, whose share must be what `∫ pdf dω` leaves
//! below 1. Each sample's weight is checked against `eval / pdf` on the way.
//!
//! Mirrors, smooth glass and infinite exponents are deltas, with no density to test; the
//! unit tests of `bsdf` check their Fresnel split.
//!
//! The samplers are correct, so the tests fail only by chance; Šidák's correction sets the
//! level so that all of them together fail with probability 1 %. Seeds are fixed.

mod cases;
mod chart;
mod check;
mod quadrature;
mod strip_chart;

use cases::TESTS;
use ch02_monte_carlo::chi2::significance_level;
use check::{Case, SAMPLES, run};

/// Runs every case, prints what it measured, and fails with all the failures listed.
fn assert_all_deliver(cases: &[Case]) {
    let level = significance_level(TESTS, 0.01);
    let mut failures = Vec::new();
    for case in cases {
        let o = run(case, 7);
        let c = &o.chi2;
        let lost = (1.0 - o.integral).max(0.0);
        eprintln!(
            "{}: X² {:.1}, dof {}, p {:.3e} (level {level:.1e}); ∫pdf {:.5} ± {:.1e}, no direction {:.5}",
            case.name, c.statistic, c.dof, c.p_value, o.integral, o.integral_error, o.dropped
        );
        if c.impossible_samples > 0 {
            failures.push(format!(
                "{}: {} samples where the density is 0",
                case.name, c.impossible_samples
            ));
        }
        if c.p_value <= level {
            failures.push(format!(
                "{}: p = {:.3e} ≤ {level:.1e}",
                case.name, c.p_value
            ));
        }
        // What the quadrature and the `f32` density may be off by.
        let slack = o.integral_error + o.rounding;
        if o.integral > 1.0 + slack {
            failures.push(format!("{}: ∫ pdf = {} > 1", case.name, o.integral));
        }
        // The share of no direction is binomial: five standard errors.
        let se = (lost * (1.0 - lost) / SAMPLES as f64).sqrt();
        if (o.dropped - lost).abs() > 5.0 * se + slack {
            failures.push(format!(
                "{}: {} of the samples give no direction, but ∫ pdf leaves {lost}",
                case.name, o.dropped
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn matte_surfaces_sample_the_cosine() {
    assert_all_deliver(&cases::diffuse());
}

#[test]
fn glossy_lobes_deliver_their_density_from_exponent_0_to_10000() {
    assert_all_deliver(&cases::glossy());
}

#[test]
fn the_disc_fuzz_delivers_its_density() {
    assert_all_deliver(&cases::disc());
}

#[test]
fn frosted_glass_reflects_and_transmits_with_its_density() {
    assert_all_deliver(&cases::rough_glass());
}

#[test]
fn rough_plastic_samples_its_base_and_its_coat_with_their_density() {
    assert_all_deliver(&cases::rough_plastic());
}

#[test]
fn microfacet_metals_and_glass_deliver_their_density_at_the_hit() {
    assert_all_deliver(&cases::microfacet());
}
