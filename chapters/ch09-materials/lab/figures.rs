//! The crate's figures, for the page "Beyond the lecture: Mitsuba's materials":
//!
//! - the diagrams (`diagrams/`, [`crate::lab::diagrams`]): the facets and the half vector,
//!   GGX's density for two roughnesses, and the visible normals projected;
//! - chapter 06's `cos^n` lobe against GGX and Beckmann of the same roughness
//!   (`microfacet-lobes.png`, the exponents in `microfacet-lobes.md`);
//! - the white furnace of a rough mirror (`microfacet-furnace.png`/`.md`);
//! - the visible normals against their density (`microfacet-visible-normals.png`) and the
//!   chi-square test of the normal samplers (`microfacet-chi2.md`);
//! - the comparison with Mitsuba 3 on scenes with its materials (`mitsuba.md` and its images).

use crate::lab::agreement::AGREEMENT;
use crate::lab::microfacet_chi2_table as chi2_table;
use crate::lab::microfacet_figures as mf_figures;
use common::scene::MicrofacetDistribution;
use std::path::Path;
use workbench::figure_set::{FigureSet, Level};
use workbench::output::write_text;

/// Writes every figure into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch09", out, quick)?;
    let level = figures.level();
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.make(
        "microfacets: the cos^n lobe against GGX and Beckmann",
        microfacet_lobes,
    )?;
    figures.make("microfacets: the white furnace", |out| {
        microfacet_furnace(out, level)
    })?;
    figures.make(
        "microfacets: visible normals and the chi-square test",
        |out| microfacet_sampling(out, level),
    )?;
    figures.agreement(&AGREEMENT)?;
    figures.finish()
}

/// The roughnesses of the lobe figure: a sharp and a rough one.
const LOBE_ALPHAS: [f32; 2] = [0.1, 0.4];

/// Chapter 06's `cos^n` lobe beside GGX and Beckmann of the same `alpha`, light from 40°.
fn microfacet_lobes(out: &Path) -> anyhow::Result<()> {
    mf_figures::lobes(&out.join("microfacet-lobes.png"), &LOBE_ALPHAS, 40.0)?;
    let mut text = String::from("| α | the exponent n = 2/α² − 2 |\n|---|---|\n");
    for alpha in LOBE_ALPHAS {
        text += &format!("| {alpha} | {:.0} |\n", mf_figures::lobe_exponent(alpha));
    }
    write_text(&out.join("microfacet-lobes.md"), &text)?;
    Ok(())
}

/// The white furnace of a rough white mirror: albedo against roughness, the table at three
/// roughnesses.
fn microfacet_furnace(out: &Path, level: Level) -> anyhow::Result<()> {
    // The table's roughnesses are among the curves' at both levels.
    let alphas: Vec<f32> = level.pick(
        vec![0.1, 0.25, 0.5, 0.75, 1.0],
        (1..=20).map(|i| i as f32 * 0.05).collect(),
    );
    let incidences = level.pick(&[0.0, 70.0, 85.0][..], &[0.0, 45.0, 70.0, 85.0]);
    let curves = mf_figures::furnace(&out.join("microfacet-furnace.png"), incidences, &alphas)?;
    write_text(
        &out.join("microfacet-furnace.md"),
        &mf_figures::furnace_markdown(&curves, &[0.1, 0.5, 1.0]),
    )?;
    Ok(())
}

/// GGX's visible normals against their density, and the chi-square table of the samplers.
fn microfacet_sampling(out: &Path, level: Level) -> anyhow::Result<()> {
    let samples = level.pick(50_000, 400_000);
    mf_figures::visible_normals(
        &out.join("microfacet-visible-normals.png"),
        MicrofacetDistribution::Ggx,
        0.5,
        60.0,
        samples,
    )?;
    let samples = level.pick(20_000, 200_000);
    let rows = chi2_table::rows(samples, &[0.3, 1.0], &[0.0, 60.0, 85.0]);
    write_text(
        &out.join("microfacet-chi2.md"),
        &chi2_table::markdown(&rows, samples),
    )?;
    Ok(())
}
