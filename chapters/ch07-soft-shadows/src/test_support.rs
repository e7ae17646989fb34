//! What the tests share: uniform points from a fixed seed, the mean and standard error of an
//! estimator, and chi-square tests of light samplers in the light's own plane.

use ch02_monte_carlo::chi2::{Chi2Result, chi2_test_density, significance_level};
use ch02_monte_carlo::warps::{Domain, WarpPoint};
use common::sampler::unit_f32;
use glam::{Vec2, Vec3};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;

use crate::area_lights::AreaLight;
use crate::estimator::light_sample_contribution;
use crate::light_sample::LightSample;
use crate::strategy::LightSampling;

/// Samples per chi-square test, and its grid in the plane.
pub const CHI2_SAMPLES: usize = 200_000;
/// The chi-square grid for planar lights.
pub const PLANE_BINS: (usize, usize) = (20, 20);

/// Whether a chi-square result passes: the level is set so that the crate's dozen tests of
/// correct samplers fail together with probability 1 %.
pub fn passes(result: &Chi2Result) -> bool {
    result.p_value > significance_level(12, 0.01)
}

/// `n` independent uniform points of `[0, 1)^2` from a PCG generator seeded by `seed`.
pub fn uniform_points(n: usize, seed: u64) -> Vec<Vec2> {
    let mut rng = Pcg32::seed_from_u64(seed);
    (0..n)
        .map(|_| Vec2::new(unit_f32(rng.next_u32()), unit_f32(rng.next_u32())))
        .collect()
}

/// The mean of independent terms and its standard error `√(s² / n)`, from the sample variance
/// `s²`, in `f64`.
#[derive(Clone, Copy, Debug)]
pub struct Estimate {
    pub mean: f64,
    pub variance: f64,
    pub standard_error: f64,
}

pub fn estimate(terms: &[f64]) -> Estimate {
    let n = terms.len() as f64;
    let mean = terms.iter().sum::<f64>() / n;
    let variance = terms.iter().map(|t| (t - mean).powi(2)).sum::<f64>() / (n - 1.0);
    Estimate {
        mean,
        variance,
        standard_error: (variance / n).sqrt(),
    }
}

/// The unoccluded terms of the estimator (first colour channel) for the points `points`.
pub fn terms(
    x: Vec3,
    n: Vec3,
    light: &AreaLight,
    sampling: LightSampling,
    points: &[Vec2],
) -> Vec<f64> {
    points
        .iter()
        .map(|&u| {
            let term = light_sample_contribution(x, n, light, u, sampling, &mut |_| true);
            assert!(term.is_finite(), "u = {u}: {term}");
            term.x as f64
        })
        .collect()
}

/// Asserts that `estimate` agrees with `reference` within five standard errors (plus a
/// relative `1e-5` for the `f32` arithmetic), and that the test has power: its standard error
/// is at most `max_relative_error` of the reference.
pub fn assert_agrees(estimate: Estimate, reference: f64, max_relative_error: f64, what: &str) {
    let Estimate {
        mean,
        standard_error,
        ..
    } = estimate;
    assert!(
        mean.is_finite() && standard_error.is_finite(),
        "{what}: {estimate:?}"
    );
    let tolerance = 5.0 * standard_error + 1e-5 * reference.abs();
    assert!(
        (mean - reference).abs() <= tolerance,
        "{what}: estimate {mean} ± {standard_error}, reference {reference} ({:.2} standard errors off)",
        (mean - reference) / standard_error
    );
    assert!(
        standard_error <= max_relative_error * reference.abs(),
        "{what}: standard error {standard_error} too large against {reference} for the test to mean anything"
    );
}

/// An orthonormal frame in a light's plane: coordinates of its points in scene units, where a
/// density per unit area of the light is a density per unit area of the coordinates.
#[derive(Clone, Copy, Debug)]
pub struct PlaneFrame {
    pub origin: Vec3,
    pub t: Vec3,
    pub b: Vec3,
}

impl PlaneFrame {
    pub fn new(origin: Vec3, normal: Vec3) -> Self {
        let (t, b) = normal.normalize().any_orthonormal_pair();
        Self { origin, t, b }
    }

    pub fn coordinates(&self, p: Vec3) -> Vec2 {
        let d = p - self.origin;
        Vec2::new(d.dot(self.t), d.dot(self.b))
    }
}

/// The chi-square test of a planar light sampler: its points in `frame`'s coordinates against
/// the density `pdf` (per unit area, as a function of those coordinates) on the rectangle
/// `[min, max]`.
pub fn chi2_on_plane(
    frame: PlaneFrame,
    (min, max): (Vec2, Vec2),
    seed: u64,
    sample: impl Fn(Vec2) -> Option<LightSample>,
    pdf: impl Fn(Vec2) -> f32,
) -> Chi2Result {
    chi2_test_density(
        Domain::Plane { min, max },
        CHI2_SAMPLES,
        seed,
        PLANE_BINS,
        |u| WarpPoint::Plane(sample(u).map_or(Vec2::NAN, |s| frame.coordinates(s.p))),
        |point| match point {
            WarpPoint::Plane(q) => pdf(q),
            WarpPoint::Direction(_) => 0.0,
        },
    )
}

/// The bounding rectangle of `points` in `frame`, grown by 1 % so no sample sits on its edge.
pub fn bounds_in(frame: PlaneFrame, points: &[Vec3]) -> (Vec2, Vec2) {
    let coordinates: Vec<Vec2> = points.iter().map(|&p| frame.coordinates(p)).collect();
    let min = coordinates.iter().fold(Vec2::INFINITY, |m, &c| m.min(c));
    let max = coordinates
        .iter()
        .fold(Vec2::NEG_INFINITY, |m, &c| m.max(c));
    let margin = 0.01 * (max - min);
    (min - margin, max + margin)
}
