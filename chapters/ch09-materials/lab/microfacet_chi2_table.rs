//! The chi-square test of the normal samplers, for the page: each sampler's normals, projected
//! straight down onto the unit disc (where the visible-normal figure shows them), against the
//! density it claims there, with chapter 02's test. One row samples visible normals but claims
//! the plain density `D(m) cos θ_m`, to show what a mismatch looks like.
//!
//! The book's table is a summary; `tests/microfacet_sampling` tests every sampler and BSDF on
//! charts fitted to each lobe, from `alpha = 0.02` to 1 and anisotropic.

use super::microfacet_figures::{in_plane, name_of};
use crate::microfacet::distribution::NormalDistribution;
use ch02_monte_carlo::chi2::{Chi2Result, chi2_test_density, significance_level};
use ch02_monte_carlo::warps::{Domain, WarpPoint};
use common::scene::MicrofacetDistribution;
use glam::{Vec2, Vec3};

/// What a row samples, and which density it claims.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Claim {
    /// Visible normals from a direction, against `D_w(m)`.
    Visible,
    /// Plain normals, against `D(m) cos θ_m`.
    Plain,
    /// Visible normals, against `D(m) cos θ_m`: the wrong density.
    VisibleClaimedPlain,
}

/// One test of the table.
#[derive(Clone, Debug)]
pub struct Chi2Row {
    /// What the table calls it.
    pub name: String,
    /// Whether the row is meant to fail.
    pub claim: Claim,
    /// The test's outcome.
    pub result: Chi2Result,
}

/// The unit normal above the point `p` of the unit disc, `None` outside it.
fn lift(p: Vec2) -> Option<Vec3> {
    let z2 = 1.0 - p.length_squared();
    (z2 > 0.0).then(|| p.extend(z2.sqrt()))
}

/// One sampler's test: `samples` normals, `draw` turning two uniform numbers into a normal,
/// `density` the density per unit solid angle it claims.
fn test(samples: usize, draw: impl Fn(Vec2) -> Vec3, density: impl Fn(Vec3) -> f32) -> Chi2Result {
    chi2_test_density(
        Domain::Plane {
            min: Vec2::splat(-1.0),
            max: Vec2::splat(1.0),
        },
        samples,
        11,
        (32, 32),
        |u| WarpPoint::Plane(draw(u).truncate()),
        // Projected onto the disc, a solid angle shrinks by `cos θ_m`.
        |point| match point {
            WarpPoint::Plane(p) => lift(p).map_or(0.0, |m| density(m) / m.z),
            WarpPoint::Direction(_) => 0.0,
        },
    )
}

/// Both distributions at `alphas`: visible normals seen from each of `views` degrees, plain
/// normals, and the one mismatched row (GGX, the first roughness, the last view).
pub fn rows(samples: usize, alphas: &[f32], views: &[f64]) -> Vec<Chi2Row> {
    let mut rows = Vec::new();
    for kind in [
        MicrofacetDistribution::Ggx,
        MicrofacetDistribution::Beckmann,
    ] {
        for &alpha in alphas {
            let d = NormalDistribution::isotropic(kind, alpha);
            let name = name_of(kind);
            for &view in views {
                let w = in_plane(view);
                rows.push(Chi2Row {
                    name: format!("{name}, α = {alpha}, visible from {view}°"),
                    claim: Claim::Visible,
                    result: test(
                        samples,
                        |u| d.sample_visible_normal(w, u),
                        |m| d.visible_normal_pdf(w, m),
                    ),
                });
            }
            rows.push(Chi2Row {
                name: format!("{name}, α = {alpha}, all normals"),
                claim: Claim::Plain,
                result: test(samples, |u| d.sample_normal(u), |m| d.normal_pdf(m)),
            });
        }
    }
    if let (Some(&alpha), Some(&view)) = (alphas.first(), views.last()) {
        let d = NormalDistribution::isotropic(MicrofacetDistribution::Ggx, alpha);
        let w = in_plane(view);
        rows.push(Chi2Row {
            name: format!("GGX, α = {alpha}, visible from {view}°, claimed to be D(m) cos θ_m"),
            claim: Claim::VisibleClaimedPlain,
            result: test(
                samples,
                |u| d.sample_visible_normal(w, u),
                |m| d.normal_pdf(m),
            ),
        });
    }
    rows
}

/// The level each row is held to: all the correct rows together fail by chance with
/// probability 1 %.
pub fn level(rows: &[Chi2Row]) -> f64 {
    let correct = rows
        .iter()
        .filter(|r| r.claim != Claim::VisibleClaimedPlain)
        .count();
    significance_level(correct.max(1), 0.01)
}

/// The table of [`rows`], with each row's verdict at [`level`].
pub fn markdown(rows: &[Chi2Row], samples: usize) -> String {
    let level = level(rows);
    let mut table = format!(
        "{samples} normals per test on a 32 × 32 grid over the disc, each test held to the \
         level {level:.1e}:\n\n\
         | sampler | X² | degrees of freedom | p-value | verdict |\n|---|---|---|---|---|\n"
    );
    for row in rows {
        let r = &row.result;
        let verdict = if r.p_value > level {
            "passes"
        } else {
            "**fails**"
        };
        table += &format!(
            "| {} | {:.1} | {} | {:.2e} | {verdict} |\n",
            row.name, r.statistic, r.dof, r.p_value
        );
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The correct samplers pass and the mismatched one fails, at the book's roughnesses.
    #[test]
    fn the_samplers_pass_and_the_wrong_density_fails() {
        let rows = rows(20_000, &[0.3, 1.0], &[0.0, 70.0]);
        let level = level(&rows);
        for row in &rows {
            let failed = row.result.p_value <= level;
            let meant_to_fail = row.claim == Claim::VisibleClaimedPlain;
            assert_eq!(failed, meant_to_fail, "{}: {:?}", row.name, row.result);
        }
        assert!(markdown(&rows, 20_000).contains("**fails**"));
    }
}
