//! The chapter's figures: the diagrams (`diagrams/`), every sampler at growing sample counts,
//! zoomed edges, the filters on the checkerboard, where the samples of a pixel land, the filter
//! profiles, the error of one edge pixel, and error against time. Every number the chapter's
//! page quotes from a run is written here too, as a small Markdown file the page includes
//! (`edge_pixel.md`, `convergence.md`, `mitsuba_wider_tent.md`), so that the text and the
//! figures always agree.

use crate::coverage::{HalfPlane, coverage_mse};
use crate::filters::{FilterKind, ReconstructionFilter};
use crate::pixel_samplers::{PixelSampler, PixelSamplerKind};
use crate::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch02_monte_carlo::estimator::log_log_slope;
use common::film::Filter;
use common::image::Image;
use common::render::RenderSettings;
use common::scene::Scene;
use glam::{UVec2, Vec2};
use std::path::Path;
use workbench::convergence::{
    Technique, plot_error_vs_spp, plot_error_vs_time, run_convergence, write_convergence_csv,
};
use workbench::figure_set::{FigureSet, Level};
use workbench::output::figures::{
    Axes, Series, SeriesStyle, comparison_grid, crop, line_plot, scatter_plot,
};
use workbench::output::write_text;

/// Image sizes and budgets: the book's, or small ones for tests and CI.
struct Quality {
    /// Size of the sampler and filter comparisons.
    width: u32,
    height: u32,
    /// Sample counts of the sampler comparison.
    spp_steps: &'static [u64],
    /// Samples per pixel of the reference renders.
    reference_spp: u64,
    /// Size of the error-against-time renders.
    convergence_size: (u32, u32),
    /// Sample counts of the error-against-time runs.
    budgets: &'static [u64],
    /// Seeds averaged for the edge-pixel error.
    repetitions: u64,
}

impl Quality {
    fn at(level: Level) -> Self {
        Quality {
            width: level.pick(80, 320),
            height: level.pick(60, 240),
            spp_steps: level.pick(&[1, 4, 16], &[1, 4, 16, 64]),
            reference_spp: level.pick(256, 1024),
            convergence_size: level.pick((32, 24), (80, 60)),
            budgets: level.pick(&[1, 4, 16], &[1, 4, 16, 64, 256]),
            repetitions: level.pick(200, 2000),
        }
    }
}

/// Writes every figure of the chapter into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch03", out, quick)?;
    let quality = Quality::at(figures.level());
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.make("the sampler comparison", |out| samplers(out, &quality))?;
    figures.make("the filter comparison", |out| filters(out, &quality))?;
    figures.make("the sample-position plots", pixel_samples)?;
    figures.make("the filter profiles", filter_profiles)?;
    figures.make("the edge-pixel error plot", |out| edge_pixel(out, &quality))?;
    figures.make("the error-against-time figures", |out| {
        convergence(out, &quality)
    })?;
    figures.agreement(&crate::lab::agreement::AGREEMENT)?;
    figures.make("the wider tent against Mitsuba 3", wider_tent)?;
    figures.finish()
}

/// A rectangle of the image, in pixels.
#[derive(Clone, Copy, Debug)]
struct Window {
    min: UVec2,
    size: UVec2,
}

impl Window {
    /// The window covering the fractions `[x0, x1] x [y0, y1]` of a `width x height` image.
    fn fraction(width: u32, height: u32, [x0, x1, y0, y1]: [f32; 4]) -> Self {
        let min = UVec2::new((x0 * width as f32) as u32, (y0 * height as f32) as u32);
        let max = UVec2::new((x1 * width as f32) as u32, (y1 * height as f32) as u32);
        Window {
            min,
            size: (max - min).max(UVec2::ONE),
        }
    }

    fn crop(&self, image: &Image) -> Image {
        crop(image, self.min.x, self.min.y, self.size.x, self.size.y)
    }
}

/// The thin bars and the steep bar of the edge scene, where they cross.
const EDGE_DETAIL: [f32; 4] = [0.08, 0.38, 0.36, 0.6];

/// Renders `scene` at `width x height` with `spp` samples of `kind` and `filter`.
fn render(
    scene: &Scene,
    (width, height): (u32, u32),
    kind: PixelSamplerKind,
    spp: u64,
    filter: &dyn Filter,
) -> Image {
    let settings = RenderSettings::new(width, height, spp);
    let sampler = PixelSampler::new(kind, spp, 0).expect("every figure asks for samples");
    let out = crate::render_with(scene, &settings, &sampler, filter);
    debug_assert_eq!(out.stats.nonfinite_samples, 0);
    out.image
}

/// Only `window` of the `full`-size image, so that a dense reference of a detail stays cheap.
fn render_window(
    scene: &Scene,
    full: (u32, u32),
    window: Window,
    kind: PixelSamplerKind,
    spp: u64,
) -> Image {
    let camera = ch01_whitted::camera::PinholeCamera::of(&scene.camera, full.0, full.1);
    let offset = window.min.as_vec2();
    let settings = RenderSettings::new(window.size.x, window.size.y, spp);
    let sampler = PixelSampler::new(kind, spp, 0).expect("every figure asks for samples");
    common::render::render(
        &settings,
        &sampler,
        &common::film::PixelBoxFilter,
        |p_film, _s: &mut PixelSampler| {
            ch01_whitted::tracer::trace(scene, &camera.generate_ray(p_film + offset), 1)
        },
    )
    .image
}

/// Every sampler at every sample count (`samplers.png`), and the detail of the thin bars
/// enlarged (`edges_zoom.png`).
fn samplers(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let scene = Builtin::Edges.build(DEFAULT_MAX_DEPTH);
    let size = (quality.width, quality.height);
    let window = Window::fraction(size.0, size.1, EDGE_DETAIL);
    let box_filter = ReconstructionFilter::new(FilterKind::Box, None).expect("the default box");
    let mut cells = Vec::new();
    let mut zoomed = Vec::new();
    // The detail at 4 samples per pixel, where the samplers still differ visibly.
    let zoom_spp = 4;
    for kind in PixelSamplerKind::ALL {
        for &spp in quality.spp_steps {
            let image = render(&scene, size, kind, spp, &box_filter);
            let zoom = match kind {
                PixelSamplerKind::Centre => spp == 1,
                _ => spp == zoom_spp,
            };
            if zoom {
                zoomed.push((format!("{}, {spp} spp", kind.name()), window.crop(&image)));
            }
            cells.push((format!("{}, {spp} spp", kind.name()), image));
        }
    }
    comparison_grid(
        &out.join("samplers.png"),
        &cells,
        quality.spp_steps.len(),
        1,
    )?;
    let reference = render_window(
        &scene,
        size,
        window,
        PixelSamplerKind::Stratified,
        quality.reference_spp,
    );
    zoomed.push((
        format!("reference, {} spp", quality.reference_spp),
        reference,
    ));
    let scale = (320 / window.size.x).max(1);
    comparison_grid(&out.join("edges_zoom.png"), &zoomed, 3, scale)?;
    Ok(())
}

/// The four filters on the checkerboard (`filters.png`) and its horizon enlarged
/// (`filters_horizon.png`).
fn filters(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let scene = Builtin::Checkerboard.build(DEFAULT_MAX_DEPTH);
    let size = (quality.width, quality.height);
    let spp = 16;
    let horizon = Window::fraction(size.0, size.1, [0.35, 0.65, 0.38, 0.6]);
    let mut cells = Vec::new();
    let mut zoomed = Vec::new();
    let centre = render(
        &scene,
        size,
        PixelSamplerKind::Centre,
        1,
        &ReconstructionFilter::new(FilterKind::Box, None).expect("the default box"),
    );
    zoomed.push(("1 sample at the centre".to_string(), horizon.crop(&centre)));
    for kind in FilterKind::ALL {
        let filter = ReconstructionFilter::new(kind, None).expect("the default filter");
        let image = render(&scene, size, PixelSamplerKind::Stratified, spp, &filter);
        let label = format!("{}, radius {}", kind.name(), filter.half_width());
        zoomed.push((label.clone(), horizon.crop(&image)));
        cells.push((format!("{label}, {spp} spp stratified"), image));
    }
    comparison_grid(&out.join("filters.png"), &cells, 2, 1)?;
    let scale = (216 / horizon.size.x).max(1);
    comparison_grid(&out.join("filters_horizon.png"), &zoomed, 5, scale)?;
    Ok(())
}

/// Where the samples of one pixel land, per sampler, at 16 and at 256 samples.
fn pixel_samples(out: &Path) -> anyhow::Result<()> {
    for spp in [16u64, 256] {
        let sets: Vec<(String, Vec<Vec2>)> = PixelSamplerKind::ALL
            .into_iter()
            .map(|kind| {
                let mut sampler = PixelSampler::new(kind, spp, 0).expect("spp > 0");
                let points = sampler.positions(UVec2::new(7, 3), spp);
                (kind.name().to_string(), points)
            })
            .collect();
        scatter_plot(
            &out.join(format!("pixel_samples_{spp}.png")),
            &format!("{spp} sample positions in one pixel"),
            &sets,
            [Vec2::ZERO, Vec2::ONE],
        )?;
    }
    Ok(())
}

/// The 1-D profiles of the four filters at their default radii.
fn filter_profiles(out: &Path) -> anyhow::Result<()> {
    let series: Vec<Series> = FilterKind::ALL
        .into_iter()
        .map(|kind| {
            let filter = ReconstructionFilter::new(kind, None).expect("the default filter");
            let points = (-300..=300)
                .map(|i| {
                    let x = i as f32 * 0.01;
                    (f64::from(x), f64::from(filter.evaluate_1d(x)))
                })
                .collect();
            Series::new(
                format!("{} (radius {})", kind.name(), filter.half_width()),
                points,
                SeriesStyle::Line,
            )
        })
        .collect();
    line_plot(
        &out.join("filter_profiles.png"),
        "Reconstruction filters, one-dimensional profile",
        &Axes::linear("offset from the pixel centre (pixels)", "weight f(x)"),
        &series,
    )?;
    Ok(())
}

/// The RMSE (root mean squared error) of one pixel's coverage by an edge against samples per
/// pixel: the slopes of random (-1/2), stratified (-3/4) and Halton sampling, and the centre's
/// fixed error. RMSE, like the error-against-time figures, so that the page speaks of one
/// measure of error throughout.
fn edge_pixel(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let edge = HalfPlane {
        slope: 0.35,
        intercept: 0.3,
    };
    let counts = [1u64, 4, 16, 64, 256];
    let series: Vec<Series> = PixelSamplerKind::ALL
        .into_iter()
        .map(|kind| {
            let points = counts
                .iter()
                .map(|&n| {
                    let mse = coverage_mse(kind, n, quality.repetitions, edge);
                    (n as f64, mse.sqrt())
                })
                .collect();
            Series::new(kind.name(), points, SeriesStyle::LineAndPoints)
        })
        .collect();
    line_plot(
        &out.join("edge_pixel.png"),
        "Error of one pixel cut by an edge",
        &Axes::log_log("samples per pixel", "RMSE of the coverage"),
        &series,
    )?;
    write_text(&out.join("edge_pixel.md"), &edge_pixel_table(&series))?;
    Ok(())
}

/// The slope the theory predicts for the RMSE of one edge pixel with `kind`.
fn predicted_edge_slope(kind: &str) -> &'static str {
    match kind {
        "centre" => "0 (a fixed error)",
        "random" => "-1/2",
        "stratified" => "-3/4",
        _ => "about -3/4",
    }
}

/// The Markdown table of the fitted slopes of the edge pixel's error, one row per sampler.
fn edge_pixel_table(series: &[Series]) -> String {
    let mut table = String::from(
        "| sampler | fitted slope of log RMSE against log n | the theory's slope | RMSE at the largest n |\n\
         |---|---:|---|---:|\n",
    );
    for s in series {
        let slope = log_log_slope(s.points.iter().copied());
        let last = s.points.last().map_or(f64::NAN, |p| p.1);
        table.push_str(&format!(
            "| {} | {slope:.2} | {} | {last:.1e} |\n",
            s.label,
            predicted_edge_slope(&s.label)
        ));
    }
    table
}

/// Error against time and against samples for every sampler, on the edge scene.
fn convergence(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let scene = Builtin::Edges.build(DEFAULT_MAX_DEPTH);
    let size = quality.convergence_size;
    let box_filter = ReconstructionFilter::new(FilterKind::Box, None).expect("the default box");
    // Sixteen times the densest budget: the reference's own error is far below the errors
    // being measured.
    let reference_spp = 16 * quality.budgets.last().copied().unwrap_or(1);
    let reference = render(
        &scene,
        size,
        PixelSamplerKind::Stratified,
        reference_spp,
        &box_filter,
    );
    let techniques: Vec<Technique> = PixelSamplerKind::ALL
        .into_iter()
        .map(|kind| {
            let scene = &scene;
            let filter = &box_filter;
            Technique::new(kind.name(), move |spp| {
                render(scene, size, kind, spp, filter)
            })
        })
        .collect();
    let records = run_convergence(&techniques, quality.budgets, &reference);
    write_convergence_csv(&out.join("convergence.csv"), &records)?;
    plot_error_vs_time(
        &out.join("convergence.png"),
        "Error against time (edges)",
        &records,
    )?;
    plot_error_vs_spp(
        &out.join("convergence_spp.png"),
        "Error against samples per pixel (edges)",
        &records,
    )?;
    write_text(&out.join("convergence.md"), &convergence_table(&records))?;
    Ok(())
}

/// What a doubling of samples and of time did to each sampler's RMSE in this run: the fitted
/// slopes of log RMSE against log spp and against log seconds, and the factor `2^-slope` by
/// which a doubling divides the error.
fn convergence_table(records: &[workbench::convergence::ConvergenceRecord]) -> String {
    let mut table = String::from(
        "| sampler | slope against spp | RMSE divided per doubling of spp | slope against time | RMSE divided per doubling of time | RMSE at the largest budget |\n\
         |---|---:|---:|---:|---:|---:|\n",
    );
    for kind in PixelSamplerKind::ALL {
        let mine: Vec<_> = records
            .iter()
            .filter(|r| r.technique == kind.name())
            .collect();
        let by_spp: Vec<(f64, f64)> = mine.iter().map(|r| (r.spp as f64, r.rmse)).collect();
        let by_time: Vec<(f64, f64)> = mine.iter().map(|r| (r.seconds, r.rmse)).collect();
        let (slope_spp, slope_time) = (log_log_slope(by_spp), log_log_slope(by_time));
        let last = mine
            .iter()
            .max_by_key(|r| r.spp)
            .map_or(String::from("–"), |r| {
                format!("{:.2e} at {} spp", r.rmse, r.spp)
            });
        table.push_str(&format!(
            "| {} | {slope_spp:.2} | {:.2} | {slope_time:.2} | {:.2} | {last} |\n",
            kind.name(),
            2f64.powf(-slope_spp),
            2f64.powf(-slope_time),
        ));
    }
    table
}

/// The file's tent (radius 1.5) and a tent one tenth wider, both measured against Mitsuba 3's
/// stored renders of `tent-spheres.xml`: the comparison is sharp enough to reject a filter
/// that is only slightly too wide, as Mitsuba's tabulated filter is (`mitsuba_wider_tent.md`).
fn wider_tent(out: &Path) -> anyhow::Result<()> {
    use workbench::agreement::ReferenceRenders;
    let set = &crate::lab::agreement::AGREEMENT;
    let scene_entry = set
        .scenes
        .iter()
        .find(|s| s.name == "tent-spheres")
        .ok_or_else(|| anyhow::anyhow!("the agreement set has no tent-spheres scene"))?;
    let path = set.file(scene_entry);
    let renders = ReferenceRenders::load(&set.stored_renders_dir(), scene_entry.name)?;
    let (scene, film, settings, sampler) =
        crate::lab::scene_file::for_agreement(&path, &crate::lab::CAPABILITIES)
            .map_err(anyhow::Error::msg)?;
    let radius = film.filter.half_width();
    let wider = ReconstructionFilter::new(film.filter.kind(), Some(1.1 * radius))
        .map_err(anyhow::Error::msg)?;
    let measure = |filter: &ReconstructionFilter| {
        renders.agreement(&crate::render_with(&scene, &settings, &sampler, filter).image)
    };
    let (own, widened) = (measure(&film.filter), measure(&wider));
    let verdict = |a: &workbench::agreement::Agreement| if a.holds() { "passes" } else { "fails" };
    let text = format!(
        "| tent radius | RMSE ours | RMSE Mitsuba | bias_blocks ours | bias_blocks Mitsuba | the check |\n\
         |---:|---:|---:|---:|---:|---|\n\
         | {radius} (the file's) | {:.2e} | {:.2e} | {:.3} | {:.3} | {} |\n\
         | {:.2} (one tenth wider) | {:.2e} | {:.2e} | {:.3} | {:.3} | {} |\n",
        own.ours.rmse,
        own.other.rmse,
        own.ours.bias_blocks,
        own.other.bias_blocks,
        verdict(&own),
        wider.half_width(),
        widened.ours.rmse,
        widened.other.rmse,
        widened.ours.bias_blocks,
        widened.other.bias_blocks,
        verdict(&widened),
    );
    write_text(&out.join("mitsuba_wider_tent.md"), &text)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use workbench::convergence::ConvergenceRecord;

    #[test]
    fn the_convergence_table_says_what_a_doubling_divides_the_error_by() {
        let record = |technique: &str, spp: u64, rmse: f64| ConvergenceRecord {
            technique: technique.to_string(),
            spp,
            seconds: spp as f64,
            rmse,
            relmse: rmse,
        };
        let records = [
            record("random", 1, 0.4),
            record("random", 4, 0.2),
            record("random", 16, 0.1),
        ];
        let table = convergence_table(&records);
        let row = table
            .lines()
            .find(|l| l.starts_with("| random"))
            .expect("a row for the random sampler");
        assert!(
            row.contains("| -0.50 | 1.41 | -0.50 | 1.41 |"),
            "RMSE halving per 4x samples is a slope of -1/2, divided by sqrt 2 per doubling: {row}"
        );
        assert!(row.contains("1.00e-1 at 16 spp"), "{row}");
    }

    /// One budget fits no line: chapter 02's slope is NaN there, and the table shows it
    /// rather than a slope of 0, which would claim the error does not fall at all.
    #[test]
    fn a_sampler_with_one_budget_has_no_slope_in_the_table() {
        let records = [ConvergenceRecord {
            technique: "random".to_string(),
            spp: 4,
            seconds: 1.0,
            rmse: 0.2,
            relmse: 0.2,
        }];
        let table = convergence_table(&records);
        let row = table
            .lines()
            .find(|l| l.starts_with("| random"))
            .expect("a row for the random sampler");
        assert!(row.contains("| NaN | NaN | NaN | NaN |"), "{row}");
    }
}
