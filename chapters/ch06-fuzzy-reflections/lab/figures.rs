//! The chapter's figures: roughness series for reflection and refraction, the empirical disc
//! against the `cos^n` lobe, the below-surface policies (images, energy, and where their
//! directions go), lobe samples, the ray count of "trace both" against the depth, the three
//! glass strategies at equal time, error against time, and the agreement with Mitsuba 3.

use crate::below_surface::BelowSurface;
use crate::furnace::{incoming, mean_radiance, white_floor};
use crate::fuzz::FuzzMethod;
use crate::glass_choice::GlassStrategy;
use crate::lab::agreement::AGREEMENT;
use crate::lighting::PointLights;
use crate::render_with;
use crate::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use crate::tracer::TraceOptions;
use ch01_whitted::optics::reflect;
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use common::image::Image;
use common::render::{Budget, RenderOutput, RenderSettings};
use common::sampler::{IndependentSampler, Sampler};
use common::scene::Material;
use glam::{UVec2, Vec2, Vec3};
use std::path::Path;
use workbench::convergence::{
    Technique, plot_error_vs_spp, plot_error_vs_time, run_convergence, write_convergence_csv,
};
use workbench::figure_set::{FigureSet, Level, RenderQuality};
use workbench::output::figures::{
    Axes, Series, SeriesStyle, comparison_grid, line_plot, scatter_plot,
};
use workbench::output::write_text;

/// Image sizes and budgets: the book's, or small ones for tests and CI.
fn quality(level: Level) -> RenderQuality {
    RenderQuality {
        width: level.pick(96, 320),
        height: level.pick(72, 240),
        spp: level.pick(8, 64),
        budgets: level.pick(&[1, 4, 16], &[1, 4, 16, 64]),
        reference_spp: level.pick(256, 2048),
    }
}

/// Writes every figure of the chapter into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch06", out, quick)?;
    let level = figures.level();
    let quality = quality(level);
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.make("the roughness series", |out| {
        roughness_series(out, &quality)
    })?;
    figures.make("the disc against the lobe", |out| {
        disc_against_lobe(out, &quality)
    })?;
    figures.make("the below-surface comparison", |out| {
        below_surface(out, &quality, level)
    })?;
    figures.make("the plates", |out| inter_reflections(out, &quality))?;
    figures.make("the lobe-sample plots", lobe_samples)?;
    figures.make("the ray-count growth", |out| ray_growth(out, &quality))?;
    figures.make("the cost per sample", |out| speed(out, &quality, level))?;
    figures.make("the equal-time comparison", |out| {
        equal_time(out, &quality, level)
    })?;
    figures.make("the error-against-time figures", |out| {
        convergence(out, &quality)
    })?;
    figures.agreement(&AGREEMENT)?;
    figures.finish()
}

fn box_filter() -> ReconstructionFilter {
    ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter")
}

/// Renders `scene` with stratified pixel positions, box-filtered.
fn render(
    scene: &MotionScene,
    options: TraceOptions,
    settings: &RenderSettings,
    seed: u64,
) -> RenderOutput {
    let spp = match settings.budget {
        Budget::Samples(spp) => spp,
        Budget::Seconds(_) => 1,
    };
    let kind = match settings.budget {
        Budget::Samples(_) => PixelSamplerKind::Stratified,
        // A timed render does not know its sample count: independent positions.
        Budget::Seconds(_) => PixelSamplerKind::Random,
    };
    let pixels = PixelSampler::new(kind, spp, seed).expect("a positive count");
    render_with(
        scene,
        &PointLights,
        options,
        &Lens::PINHOLE,
        settings,
        &pixels,
        &box_filter(),
    )
}

/// The exponent as a caption: "n = 1e6" rather than "n = 1000000".
fn exponent_label(exponent: f32) -> String {
    if exponent >= 1e4 {
        format!("n = 1e{}", exponent.log10().round())
    } else {
        format!("n = {exponent}")
    }
}

/// The glossy floor and the frosted pane from rough to smooth.
fn roughness_series(out: &Path, quality: &RenderQuality) -> anyhow::Result<()> {
    let settings = quality.gallery();
    let options = TraceOptions::default();
    let exponents = [1.0f32, 10.0, 100.0, 1e3, 1e6];
    let mut reflection = Vec::new();
    for exponent in exponents {
        let scene = Builtin::Floor.build(DEFAULT_MAX_DEPTH, exponent);
        reflection.push((
            format!("glossy floor, {}", exponent_label(exponent)),
            render(&scene, options, &settings, 0).image,
        ));
    }
    let mut mirror = Builtin::Floor.build(DEFAULT_MAX_DEPTH, 1.0);
    mirror.scene.surfaces[0].material = Material::Mirror {
        reflectance: Vec3::splat(0.8),
    };
    let mirror_image = render(&mirror, options, &settings, 0).image;
    // How far each floor is from the mirror, rendered at the same pixel positions.
    let share_of = |exponent: f32| {
        let i = exponents
            .iter()
            .position(|&e| e == exponent)
            .expect("a rendered exponent");
        share_differing(&reflection[i].1, &mirror_image, MIRROR_TOLERANCE)
    };
    write_text(
        &out.join("roughness.md"),
        &format!(
            "Rendered at the same pixel positions as the mirror, the floor of $n = 10^6$ \
             differs from it by more than {MIRROR_TOLERANCE} in {:.1} % of the pixels, the \
             floor of $n = 10$ in {:.1} %.\n",
            100.0 * share_of(1e6),
            100.0 * share_of(10.0),
        ),
    )?;
    reflection.push(("perfect mirror (chapter 01)".to_string(), mirror_image));
    comparison_grid(&out.join("roughness_reflection.png"), &reflection, 3, 1)?;

    let mut refraction = Vec::new();
    for exponent in [0.0f32, 1.0, 10.0, 100.0, 1e3] {
        let scene = Builtin::Frosted.build(DEFAULT_MAX_DEPTH, exponent);
        refraction.push((
            format!("frosted pane, {}", exponent_label(exponent)),
            render(&scene, options, &settings, 0).image,
        ));
    }
    let mut smooth = Builtin::Frosted.build(DEFAULT_MAX_DEPTH, 1.0);
    for surface in &mut smooth.scene.surfaces {
        if matches!(surface.material, Material::RoughGlass(_)) {
            surface.material = Material::glass(1.5);
        }
    }
    refraction.push((
        "smooth glass (chapter 01)".to_string(),
        render(&smooth, options, &settings, 0).image,
    ));
    comparison_grid(&out.join("roughness_refraction.png"), &refraction, 3, 1)?;
    Ok(())
}

/// The difference in any colour channel above which [`roughness_series`] counts a pixel of a
/// glossy floor as differing from the mirror's (the bound `tests/extremes.rs` uses).
const MIRROR_TOLERANCE: f32 = 0.02;

/// The share of the pixels of `a` and `b` (of the same size) that differ by more than
/// `tolerance` in some colour channel.
fn share_differing(a: &Image, b: &Image, tolerance: f32) -> f64 {
    let (width, height) = (a.width, a.height);
    let mut differing = 0u64;
    for y in 0..height {
        for x in 0..width {
            if (a.get(x, y) - b.get(x, y)).abs().max_element() > tolerance {
                differing += 1;
            }
        }
    }
    differing as f64 / (f64::from(width) * f64::from(height))
}

/// The empirical disc and the `cos^n` lobe, sized to the same spread.
fn disc_against_lobe(out: &Path, quality: &RenderQuality) -> anyhow::Result<()> {
    let settings = quality.gallery();
    let mut cells = Vec::new();
    for exponent in [10.0f32, 300.0] {
        let scene = Builtin::Floor.build(DEFAULT_MAX_DEPTH, exponent);
        for fuzz in FuzzMethod::ALL {
            let options = TraceOptions {
                fuzz,
                ..TraceOptions::default()
            };
            let caption = match fuzz {
                FuzzMethod::Lobe => format!("cos^n lobe, {}", exponent_label(exponent)),
                FuzzMethod::Disc => format!(
                    "empirical disc, radius {:.2} (about as wide)",
                    crate::fuzz::disc_radius_for_exponent(exponent)
                ),
            };
            cells.push((caption, render(&scene, options, &settings, 0).image));
        }
    }
    comparison_grid(&out.join("disc_vs_lobe.png"), &cells, 2, 1)?;
    Ok(())
}

/// The three below-surface policies: in the plates scene at a low exponent, in the furnace
/// (reflected energy against the angle of incidence), and in a table.
fn below_surface(out: &Path, quality: &RenderQuality, level: Level) -> anyhow::Result<()> {
    // Rays traced per point of the furnace curves.
    let furnace_samples = level.pick(500, 20_000);
    let settings = quality.gallery();
    let scene = Builtin::Floor.build(DEFAULT_MAX_DEPTH, 3.0);
    let cells: Vec<(String, Image)> = BelowSurface::ALL
        .iter()
        .map(|&below| {
            let options = TraceOptions {
                below,
                ..TraceOptions::default()
            };
            (
                format!("n = 3, stray rays: {}", below.name()),
                render(&scene, options, &settings, 0).image,
            )
        })
        .collect();
    comparison_grid(&out.join("below_surface.png"), &cells, 3, 1)?;

    // Albedo in the furnace against the angle of incidence.
    let angles: Vec<f32> = (0..=18)
        .map(|i| 5.0 * i as f32)
        .map(|a| a.min(89.9))
        .collect();
    let mut series = Vec::new();
    let mut csv = String::from("exponent,fuzz,below_surface,degrees,albedo,standard_error\n");
    // The table the page includes: the albedo at a few of the angles, in percent.
    let table_angles = [0.0f32, 45.0, 75.0, 89.9];
    let mut table = String::from("| floor | stray rays |");
    for degrees in table_angles {
        table.push_str(&format!(" {degrees}° |"));
    }
    table.push_str("\n|---|---|");
    table.push_str(&"---:|".repeat(table_angles.len()));
    table.push('\n');
    for exponent in [1.0f32, 10.0] {
        let floor = white_floor(exponent);
        for below in BelowSurface::ALL {
            let options = TraceOptions {
                below,
                ..TraceOptions::default()
            };
            let mut points = Vec::new();
            for &degrees in &angles {
                let (albedo, se) =
                    mean_radiance(&floor, options, &incoming(degrees), furnace_samples);
                csv.push_str(&format!(
                    "{exponent},lobe,{},{degrees},{albedo},{se}\n",
                    below.name()
                ));
                points.push((f64::from(degrees), albedo));
            }
            table.push_str(&format!("| $n = {exponent}$ | {} |", below.name()));
            for degrees in table_angles {
                let (_, albedo) = points
                    .iter()
                    .find(|(d, _)| *d == f64::from(degrees))
                    .expect("a table angle is one of the plotted angles");
                table.push_str(&format!(" {:.0} % |", 100.0 * albedo));
            }
            table.push('\n');
            let style = if exponent == 1.0 {
                SeriesStyle::LineAndPoints
            } else {
                SeriesStyle::Dashed
            };
            series.push(Series::new(
                format!("n = {exponent}, {}", below.name()),
                points,
                style,
            ));
        }
    }
    write_text(&out.join("below_surface_energy.csv"), &csv)?;
    table.push_str(&format!(
        "\nReflected radiance as a share of the incoming radiance 1, each the mean of \
         {furnace_samples} rays, against the angle of incidence.\n"
    ));
    write_text(&out.join("below_surface_energy.md"), &table)?;
    line_plot(
        &out.join("below_surface_energy.png"),
        "A white glossy floor in a furnace of radiance 1",
        &Axes::linear(
            "angle of incidence (degrees)",
            "reflected radiance (albedo)",
        ),
        &series,
    )?;
    Ok(())
}

/// Two glossy plates facing each other: reflections of reflections, blurring as they repeat.
fn inter_reflections(out: &Path, quality: &RenderQuality) -> anyhow::Result<()> {
    let settings = quality.gallery();
    let cells: Vec<(String, Image)> = [1e5f32, 1e3, 100.0]
        .iter()
        .map(|&exponent| {
            let scene = Builtin::Plates.build(DEFAULT_MAX_DEPTH, exponent);
            (
                format!("plates, {}", exponent_label(exponent)),
                render(&scene, TraceOptions::default(), &settings, 0).image,
            )
        })
        .collect();
    comparison_grid(&out.join("plates.png"), &cells, 3, 1)?;
    Ok(())
}

/// Where a lobe's directions go: around its own axis for each method and exponent, and at
/// grazing incidence, seen from above the surface, as each below-surface policy leaves them.
fn lobe_samples(out: &Path) -> anyhow::Result<()> {
    let n = 2000;
    let uniforms: Vec<Vec2> = {
        let mut sampler = IndependentSampler::new(5);
        (0..n)
            .map(|i| {
                sampler.start_pixel_sample(UVec2::ZERO, i);
                sampler.get_2d()
            })
            .collect()
    };
    // Around +z, projected on the plane perpendicular to the axis: (x, y) = sin α (cos φ, sin φ).
    let mut sets = Vec::new();
    for exponent in [1.0f32, 10.0, 100.0] {
        for method in FuzzMethod::ALL {
            let points = uniforms
                .iter()
                .map(|&u| method.sample(Vec3::Z, exponent, u).truncate())
                .collect();
            sets.push((format!("{}, n = {exponent}", method.name()), points));
        }
    }
    scatter_plot(
        &out.join("lobe_samples.png"),
        "Lobe directions seen along the lobe's axis",
        &sets,
        [Vec2::splat(-1.0), Vec2::ONE],
    )?;

    // A ray arriving 75 degrees from the normal +y: the mirror direction is 15 degrees above
    // the surface, and a lobe of n = 10 reaches well below it.
    let incident = incoming(75.0).dir;
    let mirror = reflect(incident, Vec3::Y);
    let exponent = 10.0;
    let mut sampler = IndependentSampler::new(6);
    // Seen from far along the mirror direction: x across it, y the height above the floor.
    let side_view = |d: Vec3| Vec2::new(d.z, d.y);
    let drawn = (0..n)
        .map(|i| {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            side_view(FuzzMethod::Lobe.sample(mirror, exponent, sampler.get_2d()))
        })
        .collect();
    let mut sets = vec![("as drawn: below the floor where y < 0".to_string(), drawn)];
    for below in BelowSurface::ALL {
        let mut points = Vec::new();
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            if let Some(d) = below.scatter(Vec3::Y, &mut sampler, |u| {
                FuzzMethod::Lobe.sample(mirror, exponent, u)
            }) {
                points.push(side_view(d));
            }
        }
        sets.push((
            format!("{}: {} of {n} kept", below.name(), points.len()),
            points,
        ));
    }
    scatter_plot(
        &out.join("below_surface_samples.png"),
        "Lobe n = 10 at 75 degrees incidence, side view (y < 0: below the floor)",
        &sets,
        [Vec2::splat(-1.0), Vec2::ONE],
    )?;
    Ok(())
}

/// Rays per camera ray against the depth limit, for each glass strategy, in the panes scene.
fn ray_growth(out: &Path, quality: &RenderQuality) -> anyhow::Result<()> {
    let (width, height) = (quality.width / 4, quality.height / 4);
    let spp = 2;
    let depths: Vec<u32> = (1..=14).collect();
    let mut csv = String::from("strategy,max_depth,rays_per_camera_ray,seconds\n");
    let mut series = Vec::new();
    // Per strategy: rays per camera ray at the deepest limit.
    let mut deepest = Vec::new();
    for glass in GlassStrategy::ALL {
        let mut points = Vec::new();
        for &depth in &depths {
            let scene = Builtin::Panes.build(depth, 1e6);
            let options = TraceOptions {
                glass,
                ..TraceOptions::default()
            };
            let rendered = render(&scene, options, &RenderSettings::new(width, height, spp), 0);
            let camera_rays = u64::from(width * height) * spp;
            let per_ray = rendered.stats.rays as f64 / camera_rays as f64;
            csv.push_str(&format!(
                "{},{depth},{per_ray},{}\n",
                glass.name(),
                rendered.stats.seconds
            ));
            points.push((f64::from(depth), per_ray));
        }
        deepest.push(points.last().expect("at least one depth").1);
        series.push(Series::new(
            glass.name(),
            points,
            SeriesStyle::LineAndPoints,
        ));
    }
    write_text(&out.join("ray_growth.csv"), &csv)?;
    let max_depth = depths.last().expect("at least one depth");
    let [both, half, fresnel] = [0, 1, 2].map(|i| deepest[i]);
    write_text(
        &out.join("ray_growth.md"),
        &format!(
            "At the depth limit {max_depth}, tracing both rays costs {both:.0} rays per camera \
             ray; choosing one costs {half:.1} with probability ½ and {fresnel:.1} with the \
             Fresnel choice.\n"
        ),
    )?;
    line_plot(
        &out.join("ray_growth.png"),
        "Rays per camera ray against the depth limit",
        &Axes {
            log_y: true,
            ..Axes::linear(
                "max_depth (segments, camera ray included)",
                "rays per camera ray",
            )
        },
        &series,
    )?;
    Ok(())
}

/// What a sample of the panes costs with each glass strategy, at the default depth limit: rays
/// per camera ray, time, and rays per second, as a table for the Speed appendix.
fn speed(out: &Path, quality: &RenderQuality, level: Level) -> anyhow::Result<()> {
    let (width, height) = (quality.width / 4, quality.height / 4);
    // Enough samples that thread start-up does not dominate the time.
    let spp = level.pick(2, 16);
    let scene = Builtin::Panes.build(DEFAULT_MAX_DEPTH, 1e6);
    let mut table = String::from(
        "| at glass | rays per camera ray | milliseconds | million rays per second |\n\
         |---|---:|---:|---:|\n",
    );
    let mut threads = 1;
    for glass in GlassStrategy::ALL {
        let options = TraceOptions {
            glass,
            ..TraceOptions::default()
        };
        let rendered = render(&scene, options, &RenderSettings::new(width, height, spp), 0);
        let camera_rays = u64::from(width * height) * spp;
        table.push_str(&format!(
            "| {} | {:.1} | {:.1} | {:.1} |\n",
            glass.name(),
            rendered.stats.rays as f64 / camera_rays as f64,
            1e3 * rendered.stats.seconds,
            rendered.stats.rays_per_second / 1e6,
        ));
        threads = rendered.stats.threads;
    }
    table.push_str(&format!(
        "\nThe panes at the depth limit {DEFAULT_MAX_DEPTH}, {width} × {height} pixels, {spp} samples \
         per pixel, {threads} threads, on the machine that built this site; shadow rays count \
         as rays.\n"
    ));
    write_text(&out.join("speed.md"), &table)?;
    Ok(())
}

/// The panes scene with each glass strategy, given the same time. Tracing both rays goes
/// first: a timed render always finishes one sample per pixel, and if that takes longer than
/// the budget, the others get as long as it took.
fn equal_time(out: &Path, quality: &RenderQuality, level: Level) -> anyhow::Result<()> {
    let scene = Builtin::Panes.build(DEFAULT_MAX_DEPTH, 1e6);
    let mut cells = Vec::new();
    // Seconds each glass strategy gets.
    let mut seconds = level.pick(0.2, 2.0);
    for glass in GlassStrategy::ALL {
        let settings = RenderSettings {
            budget: Budget::Seconds(seconds),
            ..RenderSettings::new(quality.width, quality.height, 1)
        };
        let options = TraceOptions {
            glass,
            ..TraceOptions::default()
        };
        let rendered = render(&scene, options, &settings, 0);
        seconds = seconds.max(rendered.stats.seconds);
        cells.push((
            format!(
                "{}: {} spp in {:.1} s",
                glass.name(),
                rendered.stats.spp,
                rendered.stats.seconds
            ),
            rendered.image,
        ));
    }
    comparison_grid(&out.join("strategies_equal_time.png"), &cells, 3, 1)?;
    Ok(())
}

/// Error against time of the three glass strategies, on smooth panes and on a frosted pane.
fn convergence(out: &Path, quality: &RenderQuality) -> anyhow::Result<()> {
    let (width, height) = (quality.width / 4, quality.height / 4);
    for (builtin, exponent, name) in [
        (Builtin::Panes, 1e6, "convergence"),
        (Builtin::Frosted, 10.0, "convergence_frosted"),
    ] {
        let scene = builtin.build(DEFAULT_MAX_DEPTH, exponent);
        let with = |glass| TraceOptions {
            glass,
            ..TraceOptions::default()
        };
        // The reference: the Fresnel choice (unbiased, and the fastest per sample), long.
        let reference = render(
            &scene,
            with(GlassStrategy::Fresnel),
            &RenderSettings {
                progress: true,
                ..RenderSettings::new(width, height, quality.reference_spp)
            },
            1_000,
        )
        .image;
        let techniques: Vec<Technique> = GlassStrategy::ALL
            .iter()
            .map(|&glass| {
                let scene = &scene;
                Technique::new(glass.name(), move |spp| {
                    render(
                        scene,
                        with(glass),
                        &RenderSettings::new(width, height, spp),
                        0,
                    )
                    .image
                })
            })
            .collect();
        let records = run_convergence(&techniques, quality.budgets, &reference);
        write_convergence_csv(&out.join(format!("{name}.csv")), &records)?;
        write_text(&out.join(format!("{name}.md")), &time_to_error(&records))?;
        let what = match builtin {
            Builtin::Panes => "smooth glass panes",
            _ => "frosted pane",
        };
        plot_error_vs_time(
            &out.join(format!("{name}.png")),
            &format!("Error against time: which ray at glass ({what})"),
            &records,
        )?;
        plot_error_vs_spp(
            &out.join(format!("{name}_spp.png")),
            &format!("Error against spp: which ray at glass ({what})"),
            &records,
        )?;
    }
    Ok(())
}

/// How the glass strategies are named in a generated sentence.
fn strategy_words(name: &str) -> &'static str {
    match name {
        "both" => "tracing both rays",
        "half" => "choosing one with probability ½",
        _ => "choosing one by the Fresnel term",
    }
}

/// A table of the time each glass strategy needs to reach a given error, relative to tracing
/// both rays, and a sentence naming the quickest and the slowest.
///
/// An unbiased estimator's mean squared error falls as one over the time spent, so the product
/// `MSE × seconds` is the time it needs per unit of inverse squared error; the geometric mean
/// over the budgets evens out the noise of any single render.
fn time_to_error(records: &[workbench::convergence::ConvergenceRecord]) -> String {
    let cost = |glass: GlassStrategy| {
        let products: Vec<f64> = records
            .iter()
            .filter(|r| r.technique == glass.name())
            .map(|r| (r.rmse * r.rmse * r.seconds).max(f64::MIN_POSITIVE).ln())
            .collect();
        (products.iter().sum::<f64>() / products.len().max(1) as f64).exp()
    };
    let costs: Vec<(GlassStrategy, f64)> = GlassStrategy::ALL
        .iter()
        .map(|&glass| (glass, cost(glass)))
        .collect();
    let both = costs[0].1;
    let mut text = String::from(
        "| at glass | time to reach a given error, relative to tracing both |\n|---|---:|\n",
    );
    for (glass, cost) in &costs {
        text.push_str(&format!("| {} | {:.2} |\n", glass.name(), cost / both));
    }
    let by_cost = |a: &&(GlassStrategy, f64), b: &&(GlassStrategy, f64)| a.1.total_cmp(&b.1);
    let quickest = costs.iter().min_by(by_cost).expect("three strategies").0;
    let slowest = costs.iter().max_by(by_cost).expect("three strategies").0;
    text.push_str(&format!(
        "\nHere the quickest to a given error is {}, and the slowest {}.\n",
        strategy_words(quickest.name()),
        strategy_words(slowest.name()),
    ));
    text
}

#[cfg(test)]
mod tests {
    use super::*;
    use workbench::convergence::ConvergenceRecord;

    #[test]
    fn share_differing_counts_pixels_beyond_the_tolerance_in_any_channel() {
        let a = Image::filled(4, 2, Vec3::splat(0.5));
        let mut b = a.clone();
        b.set(0, 0, Vec3::new(0.5, 0.6, 0.5)); // beyond in green only
        b.set(1, 0, Vec3::splat(0.51)); // within
        b.set(3, 1, Vec3::splat(0.0)); // beyond in all
        assert_eq!(share_differing(&a, &b, 0.02), 2.0 / 8.0);
        assert_eq!(share_differing(&a, &a, 0.0), 0.0);
    }

    fn record(technique: &str, spp: u64, seconds: f64, rmse: f64) -> ConvergenceRecord {
        ConvergenceRecord {
            technique: technique.to_string(),
            spp,
            seconds,
            rmse,
            relmse: rmse,
        }
    }

    #[test]
    fn time_to_error_is_relative_to_both_and_names_the_quickest_and_the_slowest() {
        // MSE × seconds: both 1e-2, half 4e-2, fresnel 2.5e-3, at every budget.
        let records = [
            record("both", 1, 1.0, 0.1),
            record("both", 4, 4.0, 0.05),
            record("half", 1, 0.25, 0.4),
            record("half", 4, 1.0, 0.2),
            record("fresnel", 1, 0.25, 0.1),
            record("fresnel", 4, 1.0, 0.05),
        ];
        let text = time_to_error(&records);
        assert!(text.contains("| both | 1.00 |"), "{text}");
        assert!(text.contains("| half | 4.00 |"), "{text}");
        assert!(text.contains("| fresnel | 0.25 |"), "{text}");
        assert!(
            text.contains("quickest to a given error is choosing one by the Fresnel term"),
            "{text}"
        );
        assert!(
            text.contains("slowest choosing one with probability ½"),
            "{text}"
        );

        // The words follow the numbers when the order flips.
        let flipped = [
            record("both", 1, 1.0, 0.01),
            record("half", 1, 1.0, 0.2),
            record("fresnel", 1, 1.0, 0.1),
        ];
        let text = time_to_error(&flipped);
        assert!(
            text.contains("quickest to a given error is tracing both rays"),
            "{text}"
        );
    }
}
