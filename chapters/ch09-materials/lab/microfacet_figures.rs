//! The figures of the microfacet page: chapter 06's `cos^n` lobe beside GGX and Beckmann of
//! the same roughness, and the white furnace of a rough mirror; the
//! visible normals' histogram; the chi-square test of the normal samplers.

use crate::microfacet::albedo;
use crate::microfacet::distribution::NormalDistribution;
use crate::microfacet::rough_conductor::RoughConductor;
use ch02_monte_carlo::warps::lobe::cos_lobe_pdf;
use common::sampler::{IndependentSampler, Sampler};
use common::scene::MicrofacetDistribution;
use glam::{UVec2, Vec2, Vec3};
use std::path::Path;
use workbench::output::OutputError;
use workbench::output::figures::{Axes, Series, SeriesStyle, histogram_vs_pdf, line_plot};

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
        for kind in [
            MicrofacetDistribution::Ggx,
            MicrofacetDistribution::Beckmann,
        ] {
            let name = name_of(kind);
            let bsdf = RoughConductor::white(kind, alpha);
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
/// against the roughness `alphas`, one curve per angle of incidence, for GGX (lines) and
/// Beckmann (dashed). Below 1 by what the facets shadow: Smith's model scatters once.
/// Returns the albedos plotted, for [`furnace_markdown`].
pub fn furnace(
    path: &Path,
    incidences: &[f64],
    alphas: &[f32],
) -> Result<Vec<FurnaceCurve>, OutputError> {
    let mut curves = Vec::new();
    let mut series = Vec::new();
    for (kind, style) in [
        (MicrofacetDistribution::Ggx, SeriesStyle::Line),
        (MicrofacetDistribution::Beckmann, SeriesStyle::Dashed),
    ] {
        for &incidence in incidences {
            let wo = in_plane(incidence);
            let albedos: Vec<(f32, f64)> = alphas
                .iter()
                .map(|&alpha| {
                    let bsdf = RoughConductor::white(kind, alpha);
                    let albedo = albedo::reflected(wo, alpha, |wi| bsdf.eval(wo, wi));
                    (alpha, albedo.x)
                })
                .collect();
            let points = albedos.iter().map(|&(a, v)| (f64::from(a), v)).collect();
            series.push(Series::new(
                format!("{}, {incidence}°", name_of(kind)),
                points,
                style,
            ));
            curves.push(FurnaceCurve {
                kind,
                incidence,
                albedos,
            });
        }
    }
    line_plot(
        path,
        "White furnace of a rough mirror",
        &Axes::linear("roughness alpha", "albedo"),
        &series,
    )?;
    Ok(curves)
}

/// One curve of the furnace figure: a distribution seen from one angle.
#[derive(Clone, Debug, PartialEq)]
pub struct FurnaceCurve {
    /// Beckmann or GGX.
    pub kind: MicrofacetDistribution,
    /// The angle of incidence in degrees.
    pub incidence: f64,
    /// `(alpha, albedo)` along the curve.
    pub albedos: Vec<(f32, f64)>,
}

/// The furnace's numbers at the roughnesses `shown` (those the curves hold), one row per
/// distribution and angle, for the page to include: the share of the light a white rough
/// mirror keeps.
pub fn furnace_markdown(curves: &[FurnaceCurve], shown: &[f32]) -> String {
    let mut table = String::from("| distribution | incidence |");
    for alpha in shown {
        table += &format!(" α = {alpha} |");
    }
    table += "\n|---|---|";
    table += &"---|".repeat(shown.len());
    table += "\n";
    for curve in curves {
        table += &format!("| {} | {}° |", name_of(curve.kind), curve.incidence);
        for &alpha in shown {
            match curve.albedos.iter().find(|(a, _)| (a - alpha).abs() < 1e-4) {
                Some(&(_, albedo)) => table += &format!(" {albedo:.3} |"),
                None => table += " |",
            }
        }
        table += "\n";
    }
    table
}

/// "GGX" or "Beckmann".
pub fn name_of(kind: MicrofacetDistribution) -> &'static str {
    match kind {
        MicrofacetDistribution::Beckmann => "Beckmann",
        MicrofacetDistribution::Ggx => "GGX",
    }
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
    histogram_vs_pdf(
        path,
        &format!(
            "Visible normals, {} alpha {alpha}, seen from {incidence}°",
            name_of(kind)
        ),
        &points,
        &pdf,
        [Vec2::splat(-1.0), Vec2::splat(1.0)],
        40,
    )
}
