//! The figures of the microfacet page: chapter 06's `cos^n` lobe beside GGX and Beckmann of
//! the same roughness, and the white furnace of a rough mirror.

use super::albedo;
use super::distribution::NormalDistribution;
use super::rough_conductor::RoughConductor;
use ch02_monte_carlo::warps::lobe::cos_lobe_pdf;
use common::output::OutputError;
use common::output::figures::{Axes, Series, SeriesStyle, histogram_vs_pdf, line_plot};
use common::sampler::{IndependentSampler, Sampler};
use common::scene::MicrofacetDistribution;
use glam::{UVec2, Vec2, Vec3};
use std::path::Path;

/// A rough conductor that reflects everything at every facet (Mitsuba's default `eta = 0`,
/// `k = 1`): what is lost is lost to shadowing alone.
pub fn white_conductor(kind: MicrofacetDistribution, alpha: f32) -> RoughConductor {
    RoughConductor {
        distribution: NormalDistribution::isotropic(kind, alpha),
        eta: Vec3::ZERO,
        k: Vec3::ONE,
        specular_reflectance: Vec3::ONE,
    }
}

/// The unit direction at `degrees` from the normal in the `xz` plane (negative: towards `-x`).
pub fn in_plane(degrees: f64) -> Vec3 {
    let (sin, cos) = degrees.to_radians().sin_cos();
    Vec3::new(sin as f32, 0.0, cos as f32)
}

/// The `cos^n` exponent chapter 06 stands in for the roughness `alpha`: `2 / alpha² - 2`.
pub fn lobe_exponent(alpha: f32) -> f32 {
    (2.0 / (alpha * alpha) - 2.0).max(0.0)
}

/// `f cos θ_i` in the plane of incidence, light from `incidence` degrees on one side and the
/// outgoing angle swept over the other, for chapter 06's lobe (reflectance 1) and both
/// distributions (a white rough mirror), at each of `alphas`. The lobe is drawn dashed.
pub fn lobes(path: &Path, alphas: &[f32], incidence: f64) -> Result<(), OutputError> {
    let wo = in_plane(-incidence);
    let angles: Vec<f64> = (0..=180).map(|i| f64::from(i) / 2.0).collect();
    let mut series = Vec::new();
    for &alpha in alphas {
        let n = lobe_exponent(alpha);
        let mirror = in_plane(incidence);
        let lobe = angles
            .iter()
            .map(|&a| (a, f64::from(cos_lobe_pdf(in_plane(a).dot(mirror), n))))
            .collect();
        series.push(Series::new(
            format!("cos^n, n = {n:.0} (alpha {alpha})"),
            lobe,
            SeriesStyle::Dashed,
        ));
        for (name, kind) in [
            ("GGX", MicrofacetDistribution::Ggx),
            ("Beckmann", MicrofacetDistribution::Beckmann),
        ] {
            let bsdf = white_conductor(kind, alpha);
            let points = angles
                .iter()
                .map(|&a| (a, f64::from(bsdf.eval(wo, in_plane(a)).x)))
                .collect();
            series.push(Series::new(
                format!("{name}, alpha {alpha}"),
                points,
                SeriesStyle::Line,
            ));
        }
    }
    line_plot(
        path,
        &format!("f cos θ in the plane of incidence, light at {incidence}°"),
        &Axes::linear("outgoing angle from the normal (degrees)", "f cos θ (1/sr)"),
        &series,
    )
}

/// The white furnace of a rough mirror that reflects everything: its albedo `∫ f cos θ_i dω_i`
/// against the roughness, one curve per angle of incidence, for GGX (lines) and Beckmann
/// (dashed). Below 1 by what the facets shadow: Smith's model scatters once.
pub fn furnace(path: &Path, incidences: &[f64]) -> Result<(), OutputError> {
    let alphas: Vec<f32> = (1..=20).map(|i| i as f32 * 0.05).collect();
    let mut series = Vec::new();
    for (name, kind, style) in [
        ("GGX", MicrofacetDistribution::Ggx, SeriesStyle::Line),
        (
            "Beckmann",
            MicrofacetDistribution::Beckmann,
            SeriesStyle::Dashed,
        ),
    ] {
        for &incidence in incidences {
            let wo = in_plane(incidence);
            let points = alphas
                .iter()
                .map(|&alpha| {
                    let bsdf = white_conductor(kind, alpha);
                    let albedo = albedo::reflected(wo, alpha, |wi| bsdf.eval(wo, wi));
                    (f64::from(alpha), albedo.x)
                })
                .collect();
            series.push(Series::new(format!("{name}, {incidence}°"), points, style));
        }
    }
    line_plot(
        path,
        "White furnace of a rough mirror",
        &Axes::linear("roughness alpha", "albedo"),
        &series,
    )
}

/// The visible normals of `kind` at roughness `alpha` seen from `incidence` degrees: where
/// `samples` normals drawn by [`NormalDistribution::sample_visible_normal`] fall, projected
/// straight down onto the unit disc, beside the density they should have there,
/// `D_w(m) / cos θ_m` (the projection shrinks a solid angle by `cos θ_m`).
pub fn visible_normals(
    path: &Path,
    kind: MicrofacetDistribution,
    alpha: f32,
    incidence: f64,
    samples: u64,
) -> Result<(), OutputError> {
    let d = NormalDistribution::isotropic(kind, alpha);
    let w = in_plane(incidence);
    let mut sampler = IndependentSampler::new(1);
    let points: Vec<Vec2> = (0..samples)
        .map(|i| {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            d.sample_visible_normal(w, sampler.get_2d()).truncate()
        })
        .collect();
    let pdf = |p: Vec2| {
        let z2 = 1.0 - p.length_squared();
        if z2 <= 0.0 {
            return 0.0;
        }
        let m = p.extend(z2.sqrt());
        f64::from(d.visible_normal_pdf(w, m) / m.z)
    };
    let name = match kind {
        MicrofacetDistribution::Beckmann => "Beckmann",
        MicrofacetDistribution::Ggx => "GGX",
    };
    histogram_vs_pdf(
        path,
        &format!("Visible normals, {name} alpha {alpha}, seen from {incidence}°"),
        &points,
        &pdf,
        [Vec2::splat(-1.0), Vec2::splat(1.0)],
        40,
    )
}
