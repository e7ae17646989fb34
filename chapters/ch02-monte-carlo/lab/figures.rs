//! The chapter's figures: warps side by side, histograms against densities, RANDU's planes,
//! generator speed and evenness, the chi-square table, and error against n and against time.
//!
//! Every number the page quotes from a run is written here into a small Markdown file
//! (`generators.md`, `chi2.md`, `chi2-verdict.md`, `convergence_slopes.md`) that the page
//! includes, so the text always matches the figures, quick or full.

use crate::chi2::{Chi2Result, chi2_test, significance_level};
use crate::estimator::{
    Strategy, convergence, convergence_rate, peaked_quartic, sky_irradiance, x_squared,
};
use crate::lab::plots::save_convergence;
use crate::rng::{
    Generator, consecutive_triples, fraction_on_randu_planes, numbers_per_second,
    randu_plane_index, serial_chi2_3d, serial_threshold, uniformity_chi2,
};
use crate::warps::{Domain, Warp, WarpPoint};
use common::sampler::unit_f32;
use glam::{Vec2, Vec3};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;
use std::f32::consts::TAU;
use std::path::Path;
use workbench::convergence::ConvergenceRecord;
use workbench::figure_set::{FigureSet, Level};
use workbench::output::figures::{histogram_vs_pdf, scatter_plot};
use workbench::output::write_text;

/// Sample counts of the figures: the book's, or small ones for tests and CI.
struct Quality {
    scatter_points: usize,
    histogram_points: usize,
    chi2_samples: usize,
    repetitions: usize,
    generator_numbers: u64,
}

impl Quality {
    fn at(level: Level) -> Self {
        Quality {
            scatter_points: level.pick(1_000, 3_000),
            histogram_points: level.pick(50_000, 1_000_000),
            chi2_samples: level.pick(100_000, 1_000_000),
            repetitions: level.pick(20, 300),
            generator_numbers: level.pick(1_000_000, 50_000_000),
        }
    }
}

/// Writes every figure of the chapter into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch02", out, quick)?;
    let quality = Quality::at(figures.level());
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.make("the warp scatter plots", |out| {
        warp_scatter_plots(out, &quality)
    })?;
    figures.make("the stratified sample sets", stratification)?;
    figures.make("the histogram-against-density maps", |out| {
        histograms(out, &quality)
    })?;
    figures.make("the RANDU plot", |out| randu_planes(out, &quality))?;
    figures.make("the generator table", |out| generators(out, &quality))?;
    figures.make("the chi-square table", |out| chi2_table(out, &quality))?;
    figures.make("the error-against-n and -time figures", |out| {
        estimators(out, &quality)
    })?;
    figures.finish()
}

/// `n` uniform points of the unit square from a fixed seed.
fn uniform_points(n: usize, seed: u64) -> Vec<Vec2> {
    let mut rng = Pcg32::seed_from_u64(seed);
    (0..n)
        .map(|_| Vec2::new(unit_f32(rng.next_u32()), unit_f32(rng.next_u32())))
        .collect()
}

/// The planar point of a warp, or the top view `(x, y)` of a direction.
fn in_plane(point: WarpPoint) -> Vec2 {
    match point {
        WarpPoint::Plane(p) => p,
        WarpPoint::Direction(d) => Vec2::new(d.x, d.y),
    }
}

fn warped(warp: &Warp, points: &[Vec2]) -> (String, Vec<Vec2>) {
    (
        warp.name().to_string(),
        points.iter().map(|&u| in_plane(warp.sample(u))).collect(),
    )
}

/// The same uniform points through each warp: the naive disc next to the correct ones.
fn warp_scatter_plots(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let points = uniform_points(quality.scatter_points, 1);
    let disc = [Vec2::splat(-1.0), Vec2::splat(1.0)];
    let disks = vec![
        (
            "naive: r = ξ2 (wrong)".to_string(),
            warped(&Warp::DiscNaive, &points).1,
        ),
        (
            "polar, corrected".to_string(),
            warped(&Warp::DiscPolar, &points).1,
        ),
        (
            "concentric".to_string(),
            warped(&Warp::DiscConcentric, &points).1,
        ),
    ];
    scatter_plot(
        &out.join("warps_disc.png"),
        "The same points warped onto the unit disc",
        &disks,
        disc,
    )?;
    let plane = vec![
        ("unit square".to_string(), points.clone()),
        warped(&Warp::Parallelogram, &points),
        warped(&Warp::Triangle, &points),
    ];
    scatter_plot(
        &out.join("warps_plane.png"),
        "Parallelogram and triangle (with the fold)",
        &plane,
        [Vec2::ZERO, Vec2::ONE],
    )?;
    let directions = vec![
        (
            "sphere (both halves overlap)".to_string(),
            warped(&Warp::Sphere, &points).1,
        ),
        warped(&Warp::Hemisphere, &points),
        warped(&Warp::CosineHemisphere, &points),
        (
            "cos-lobe, n = 20".to_string(),
            warped(&Warp::CosLobe { exponent: 20.0 }, &points).1,
        ),
        (
            "spherical cap, cos θmax = 0.8".to_string(),
            warped(&Warp::SphericalCap { cos_theta_max: 0.8 }, &points).1,
        ),
    ];
    scatter_plot(
        &out.join("warps_directions.png"),
        "Directions seen from above the pole (x, y)",
        &directions,
        disc,
    )?;
    Ok(())
}

/// 256 independent points against 256 jittered ones, one in each cell of a 16 x 16 grid.
fn stratification(out: &Path) -> anyhow::Result<()> {
    let mut rng = Pcg32::seed_from_u64(5);
    let sets = vec![
        (
            "independent".to_string(),
            crate::stratified::independent_2d(256, &mut rng),
        ),
        (
            "jittered (stratified 16 x 16)".to_string(),
            crate::stratified::jittered_2d(16, &mut rng),
        ),
    ];
    scatter_plot(
        &out.join("stratified.png"),
        "256 points of the unit square",
        &sets,
        [Vec2::ZERO, Vec2::ONE],
    )?;
    Ok(())
}

/// Histograms of warped points against the density each warp claims. Directions are shown in
/// the coordinates `(φ / 2π, cos θ)` over `[0, 1] x [-1, 1]`, where the solid angle is `2π dx dy`.
fn histograms(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let points = uniform_points(quality.histogram_points, 2);
    for name in Warp::NAMES {
        let warp = Warp::from_name(name, None).map_err(anyhow::Error::msg)?;
        let path = out.join(format!("heatmap_{}.png", warp.name()));
        match warp.domain() {
            Domain::Plane { min, max } => {
                let samples: Vec<Vec2> = points.iter().map(|&u| in_plane(warp.sample(u))).collect();
                let pdf = |p: Vec2| f64::from(warp.pdf(WarpPoint::Plane(p)));
                let title = format!("{}: histogram against the claimed density", warp.name());
                histogram_vs_pdf(&path, &title, &samples, &pdf, [min, max], 40)?;
            }
            Domain::Sphere => {
                let to_map = |d: Vec3| Vec2::new(d.y.atan2(d.x).rem_euclid(TAU) / TAU, d.z);
                let samples: Vec<Vec2> = points
                    .iter()
                    .filter_map(|&u| match warp.sample(u) {
                        WarpPoint::Direction(d) => Some(to_map(d)),
                        WarpPoint::Plane(_) => None,
                    })
                    .collect();
                let pdf = |m: Vec2| {
                    let sin_theta = (1.0 - m.y * m.y).max(0.0).sqrt();
                    let phi = m.x * TAU;
                    let d = Vec3::new(sin_theta * phi.cos(), sin_theta * phi.sin(), m.y);
                    f64::from(warp.pdf(WarpPoint::Direction(d))) * std::f64::consts::TAU
                };
                let title = format!(
                    "{}: histogram against the density, in (φ/2π, cos θ)",
                    warp.name()
                );
                histogram_vs_pdf(
                    &path,
                    &title,
                    &samples,
                    &pdf,
                    [Vec2::new(0.0, -1.0), Vec2::ONE],
                    40,
                )?;
            }
        }
    }
    Ok(())
}

/// Consecutive triples `(x, y, z)` plotted as `x` against `9x - 6y + z`: RANDU's take only
/// 15 values, one per plane.
fn randu_planes(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let sets: Vec<(String, Vec<Vec2>)> = [Generator::Randu, Generator::Pcg32]
        .into_iter()
        .map(|generator| {
            let triples = consecutive_triples(&mut generator.new_source(1), quality.scatter_points);
            let points = triples
                .iter()
                .map(|&t| Vec2::new(t[0] as f32, ((randu_plane_index(t) + 6.0) / 16.0) as f32))
                .collect();
            (
                format!("{}: x against (9x - 6y + z + 6) / 16", generator.name()),
                points,
            )
        })
        .collect();
    scatter_plot(
        &out.join("randu_planes.png"),
        "Consecutive triples: RANDU lies on 15 planes",
        &sets,
        [Vec2::ZERO, Vec2::ONE],
    )?;
    Ok(())
}

/// Speed and evenness of each generator, as CSV and as a Markdown table for the book.
///
/// Evenness in 3D is the statistic of [`crate::rng::triples_chi2`] on 100 000 triples in 8³
/// cells, judged against the chi-square distribution with 511 degrees of freedom.
fn generators(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    const CELLS_PER_AXIS: usize = 8;
    const SIGNIFICANCE: f64 = 1e-3;
    let threshold = serial_threshold(CELLS_PER_AXIS, SIGNIFICANCE);
    let mut csv = String::from(
        "generator,nanoseconds_per_number,uniformity_p_value,serial_3d_statistic,serial_3d_p_value,share_on_randu_planes\n",
    );
    let cells = CELLS_PER_AXIS.pow(3);
    let mut table = format!(
        "| generator | nanoseconds per number | uniformity p (1D, 100 bins) | X² of triples ({CELLS_PER_AXIS}³ cells) | p of triples | even at {SIGNIFICANCE} (X² ≤ {threshold:.1}) | triples on RANDU's planes |\n|---|---|---|---|---|---|---|\n"
    );
    for generator in Generator::ALL {
        let nanoseconds = 1e9 / numbers_per_second(generator, quality.generator_numbers);
        let uniform = uniformity_chi2(&mut generator.new_source(3), 200_000, 100);
        let serial = serial_chi2_3d(&mut generator.new_source(3), 100_000, CELLS_PER_AXIS);
        let planes = fraction_on_randu_planes(
            &consecutive_triples(&mut generator.new_source(3), 100_000),
            1e-6,
        );
        csv.push_str(&format!(
            "{},{nanoseconds},{},{},{},{planes}\n",
            generator.name(),
            uniform.p_value,
            serial.statistic,
            serial.p_value
        ));
        table.push_str(&format!(
            "| {} | {nanoseconds:.2} | {:.3} | {:.1} | {:.2e} | {} | {:.1}% |\n",
            generator.name(),
            uniform.p_value,
            serial.statistic,
            serial.p_value,
            if serial.statistic <= threshold {
                "yes"
            } else {
                "no"
            },
            planes * 100.0
        ));
    }
    table.push_str(&format!(
        "\nThe triples' statistic is judged against the chi-square distribution with {} \
         degrees of freedom ({cells} cells less one): an even generator exceeds {threshold:.1} \
         once in {:.0} runs.\n",
        cells - 1,
        1.0 / SIGNIFICANCE
    ));
    write_text(&out.join("generators.csv"), &csv)?;
    write_text(&out.join("generators.md"), &table)?;
    Ok(())
}

/// A row name: the warp's command-line name, with its parameter where it has one.
fn row_name(warp: &Warp) -> String {
    match warp {
        Warp::CosLobe { exponent } => format!("cos-lobe n={exponent}"),
        Warp::SphericalCap { cos_theta_max } => format!("spherical-cap cos={cos_theta_max}"),
        other => other.name().to_string(),
    }
}

/// The chi-square goodness-of-fit test of every warp against the density it claims.
///
/// The grid is as fine as the sample count allows: at most 32 x 32 bins in the plane and
/// 32 x 64 on the sphere, and no finer than about 20 expected samples per bin, so that the
/// pooling of nearly empty bins never swallows the whole test.
pub fn chi2_rows(samples: usize) -> Vec<(String, Chi2Result)> {
    let bins = (samples / 20).max(4);
    let plane_side = (bins as f64).sqrt().floor().clamp(2.0, 32.0) as usize;
    let sphere_side = ((bins / 2) as f64).sqrt().floor().clamp(2.0, 32.0) as usize;
    Warp::all_for_tests()
        .iter()
        .map(|warp| {
            let resolution = match warp.domain() {
                Domain::Plane { .. } => (plane_side, plane_side),
                Domain::Sphere => (sphere_side, 2 * sphere_side),
            };
            (row_name(warp), chi2_test(warp, samples, 7, resolution))
        })
        .collect()
}

fn chi2_table(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let rows = chi2_rows(quality.chi2_samples);
    let level = significance_level(rows.len(), 0.01);
    let mut csv = String::from("warp,statistic,dof,p_value\n");
    let mut failing = Vec::new();
    let mut table = format!(
        "| warp | X² | degrees of freedom | p-value | verdict at {level:.1e} |\n|---|---|---|---|---|\n"
    );
    for (name, result) in &rows {
        csv.push_str(&format!(
            "{name},{},{},{}\n",
            result.statistic, result.dof, result.p_value
        ));
        let verdict = if result.p_value >= level {
            "passes"
        } else {
            failing.push(if result.p_value > 0.0 {
                format!("{name} (p = {:.1e})", result.p_value)
            } else {
                format!("{name} (p = 0 in double precision)")
            });
            "**fails**"
        };
        table.push_str(&format!(
            "| {name} | {:.1} | {} | {:.3e} | {verdict} |\n",
            result.statistic, result.dof, result.p_value
        ));
        println!(
            "chi2 {name:<24} statistic {:>12.1}  dof {:>5}  p {:.3e}",
            result.statistic, result.dof, result.p_value
        );
    }
    write_text(&out.join("chi2.csv"), &csv)?;
    write_text(&out.join("chi2.md"), &table)?;
    write_text(
        &out.join("chi2-verdict.md"),
        &chi2_verdict(rows.len(), &failing, level),
    )?;
    Ok(())
}

/// The chi-square table in one sentence: how many warps pass, and which fail.
fn chi2_verdict(tested: usize, failing: &[String], level: f64) -> String {
    let passing = tested - failing.len();
    let failed = match failing {
        [] => "none fails".to_string(),
        [one] => format!("the one that fails is {one}"),
        many => format!("the ones that fail are {}", many.join(", ")),
    };
    format!(
        "At the corrected significance level {level:.1e}, {passing} of the {tested} warps tested \
         pass; {failed}.\n"
    )
}

/// The fitted slope of each strategy's error against n on each integrand, as a Markdown table:
/// the convergence rates the plots show.
fn slope_table(rows: &[(&str, Vec<ConvergenceRecord>)]) -> String {
    let mut table = String::from("| integrand |");
    let mut rule = String::from("|---|");
    for strategy in Strategy::ALL {
        table.push_str(&format!(" {} |", strategy.name()));
        rule.push_str("---:|");
    }
    table.push('\n');
    table.push_str(&rule);
    table.push('\n');
    for (integrand, records) in rows {
        table.push_str(&format!("| {integrand} |"));
        for strategy in Strategy::ALL {
            let name = strategy.name();
            // An estimator whose every term equals the integral leaves only the rounding of
            // floating point: a relative error near the precision of an f32, with no slope.
            let worst_relative = records
                .iter()
                .filter(|record| record.technique == name)
                .map(|record| record.relmse.sqrt())
                .fold(0.0, f64::max);
            let slope = convergence_rate(records, name);
            if worst_relative < 1e-5 {
                table.push_str(&format!(
                    " exact but for rounding (relative error at most {worst_relative:.0e}) |"
                ));
            } else {
                table.push_str(&format!(" {slope:.2} |"));
            }
        }
        table.push('\n');
    }
    table
}

/// Error against n and against time for uniform, importance and stratified sampling.
fn estimators(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let counts = crate::estimator::SAMPLE_COUNTS;
    let smooth = x_squared();
    let smooth_records = convergence(&smooth, &Strategy::ALL, &counts, quality.repetitions, 11);
    save_convergence(out, "convergence_smooth", smooth.formula, &smooth_records)?;
    let peaked = peaked_quartic();
    let peaked_records = convergence(&peaked, &Strategy::ALL, &counts, quality.repetitions, 12);
    save_convergence(out, "convergence_peaked", peaked.formula, &peaked_records)?;
    let sky = sky_irradiance();
    let sky_records = convergence(&sky, &Strategy::ALL, &counts, quality.repetitions, 13);
    save_convergence(
        out,
        "convergence_sky",
        "Irradiance under a uniform sky",
        &sky_records,
    )?;
    let table = slope_table(&[
        (smooth.formula, smooth_records),
        (peaked.formula, peaked_records),
        ("irradiance under a uniform sky", sky_records),
    ]);
    write_text(&out.join("convergence_slopes.md"), &table)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_chi_square_verdict_names_every_failing_warp() {
        let none = chi2_verdict(3, &[], 1e-3);
        assert!(
            none.contains("3 of the 3 warps tested pass; none fails"),
            "{none}"
        );
        let one = chi2_verdict(3, &["disc-naive (p = 0 in double precision)".into()], 1e-3);
        assert!(one.contains("2 of the 3") && one.contains("the one that fails is disc-naive"));
        let two = chi2_verdict(3, &["a".into(), "b".into()], 1e-3);
        assert!(two.contains("the ones that fail are a, b"), "{two}");
    }

    #[test]
    fn the_slope_table_fits_each_strategy_and_marks_an_exact_one() {
        let records: Vec<ConvergenceRecord> = Strategy::ALL
            .iter()
            .flat_map(|strategy| {
                [4u64, 16, 64].map(|n| {
                    let rmse = match strategy {
                        // Error 1/√n, error 1e-9 (rounding), error 1/n.
                        Strategy::Uniform => 1.0 / (n as f64).sqrt(),
                        Strategy::Importance => 1e-9,
                        Strategy::Stratified => 1.0 / n as f64,
                    };
                    ConvergenceRecord {
                        technique: strategy.name().to_string(),
                        spp: n,
                        seconds: 1e-6,
                        rmse,
                        relmse: rmse * rmse,
                    }
                })
            })
            .collect();
        let table = slope_table(&[("f", records)]);
        let row = table.lines().nth(2).unwrap();
        assert!(
            row.starts_with("| f | -0.50 | exact but for rounding"),
            "{row}"
        );
        assert!(row.ends_with("| -1.00 |"), "{row}");
    }
}
