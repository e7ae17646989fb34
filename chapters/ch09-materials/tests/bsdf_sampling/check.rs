//! One chi-square test of one BSDF seen from one direction: the directions `Bsdf::sample`
//! draws against the density `Bsdf::pdf` claims, on the case's [`Chart`], with every sample's
//! weight checked on the way.

use crate::chart::Chart;
use ch02_monte_carlo::chi2::{Chi2Result, chi2_test_density};
use ch02_monte_carlo::warps::WarpPoint;
use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::{BsdfSample, SurfaceBsdf};
use ch09_materials::SceneBsdf;
use ch09_materials::microfacet::coating::Coatings;
use common::geometry::SurfaceHit;
use common::sampler::{IndependentSampler, Sampler};
use common::scene::Material;
use glam::{UVec2, Vec2, Vec3};

/// Samples per test: enough that a lobe sampled at exponent `n + 1` but claimed at `n` fails
/// for `n` up to about 20 (and one sampled at `1.1 n` at every `n ≥ 1`), few enough for a debug
/// build.
pub const SAMPLES: usize = 100_000;

/// A material seen from `wo`, and where its lobes are.
pub struct Case {
    /// What the report calls it.
    pub name: String,
    /// The material.
    pub material: Material,
    /// The lobe family of glossy and frosted materials.
    pub fuzz: FuzzMethod,
    /// The unit direction towards where the path came from.
    pub wo: Vec3,
    /// The lobes' axes and sides.
    pub chart: Chart,
}

/// What one test measured.
pub struct Outcome {
    /// The chi-square test, "no direction" included.
    pub chi2: Chi2Result,
    /// `∫ pdf dω` over the sphere: at most 1, less by what the sampler drops.
    pub integral: f64,
    /// An estimate of the quadrature error of `integral`.
    pub integral_error: f64,
    /// How far, relatively, the `f32` density itself may be off (see [`Chart::rounding`]).
    pub rounding: f64,
    /// The share of samples that gave no direction.
    pub dropped: f64,
}

/// A hit at the origin of the floor `y = 0`, normal +y.
pub fn floor_hit() -> SurfaceHit {
    SurfaceHit {
        t: 1.0,
        p: Vec3::ZERO,
        p_error: Vec3::ZERO,
        n: Vec3::Y,
        shading_n: Vec3::Y,
        uv: Vec2::ZERO,
        shape: 0,
    }
}

/// A sample's density and weight must be the BSDF's own: `pdf(wi)` and `eval(wi) / pdf(wi)`.
/// (The chi-square test checks that the density is the one the directions follow; this, that
/// the path tracer's throughput is the one that density implies.)
fn assert_weight(bsdf: &SceneBsdf, wo: Vec3, s: &BsdfSample, name: &str) {
    assert!(
        !s.is_delta(),
        "{name}: a lobe sample must have a density: {s:?}"
    );
    let pdf = bsdf.pdf(wo, s.wi);
    assert!(
        (pdf - s.pdf).abs() <= 1e-3 * s.pdf,
        "{name}: the sample claims pdf {} but pdf(wi) is {pdf}",
        s.pdf
    );
    let expected = bsdf.eval(wo, s.wi) / pdf;
    assert!(
        (expected - s.weight).abs().max_element() <= 1e-3 * s.weight.max_element(),
        "{name}: weight {} but eval / pdf is {expected}",
        s.weight
    );
}

/// Runs `case`'s test with the BSDF's numbers from an independent sampler seeded by `seed`.
pub fn run(case: &Case, seed: u64) -> Outcome {
    let hit = floor_hit();
    let bsdf = SceneBsdf {
        material: &case.material,
        hit: &hit,
        fuzz: case.fuzz,
        coatings: &Coatings::of_materials([&case.material]),
    };
    let pdf = |wi: Vec3| bsdf.pdf(case.wo, wi);
    let (integral, integral_error) = case.chart.integral(&pdf);
    let no_direction = (1.0 - integral).max(0.0);

    let mut sampler = IndependentSampler::new(seed);
    let (mut index, mut dropped) = (0u64, 0usize);
    let chi2 = chi2_test_density(
        case.chart.domain(),
        SAMPLES,
        seed,
        case.chart.resolution(),
        |u| {
            // The BSDF draws its own numbers, as in the path tracer; `u` only places a
            // "no direction" in its row.
            sampler.start_pixel_sample(UVec2::ZERO, index);
            index += 1;
            let sample = bsdf.sample(case.wo, &mut sampler);
            match &sample {
                Some(s) => assert_weight(&bsdf, case.wo, s, &case.name),
                None => dropped += 1,
            }
            WarpPoint::Plane(case.chart.point(sample.map(|s| s.wi), u))
        },
        |point| match point {
            WarpPoint::Plane(q) => case.chart.density(q, &pdf, no_direction) as f32,
            WarpPoint::Direction(_) => 0.0,
        },
    );
    Outcome {
        chi2,
        integral,
        integral_error,
        rounding: (0..case.chart.lobes.len())
            .map(|k| case.chart.rounding(k))
            .fold(0.0, f64::max),
        dropped: dropped as f64 / SAMPLES as f64,
    }
}
