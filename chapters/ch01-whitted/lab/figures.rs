//! The chapter's figures: what recursion adds, what one ray per pixel misses, Fresnel's
//! curves, how the ray tree grows, and error against time; and, for the appendices, the
//! agreement with Mitsuba 3, the tracer's speed and the BVH's cost against its size.
//!
//! Every number the book's prose quotes from a run is written here into a small Markdown file
//! (`ray_tree.md`, `convergence.md`, `speed.md`, `mitsuba-noise.md`, `bvh-cost.md`) that the
//! pages include, so the text always matches the figures beside it, quick or full.

use crate::lab::agreement::AGREEMENT;
use crate::optics::fresnel_dielectric;
use crate::pixel::{CentreSampler, GridSampler};
use crate::scenes::Builtin;
use crate::{PixelPattern, render, render_with};
use common::image::Image;
use common::render::RenderSettings;
use glam::Vec2;
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
struct Quality {
    /// One ray per pixel for the gallery; the reference of the error-against-time runs has
    /// 16 times the largest budget.
    render: RenderQuality,
    /// Supersampling grid side of the reference images.
    reference_grid: u64,
}

impl Quality {
    fn at(level: Level) -> Self {
        let budgets: &'static [u64] = level.pick(&[1, 4, 16], &[1, 4, 16, 64]);
        let render = RenderQuality {
            width: level.pick(96, 480),
            height: level.pick(72, 360),
            spp: 1,
            budgets,
            reference_spp: 16 * budgets.last().copied().unwrap_or(1),
        };
        Quality {
            render,
            reference_grid: level.pick(12, 16),
        }
    }
}

/// Writes every figure of the chapter into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch01", out, quick)?;
    let level = figures.level();
    let quality = Quality::at(level);
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.make("the recursion-depth figure", |out| {
        recursion_depth(out, &quality)
    })?;
    figures.make("the aliasing figure", |out| aliasing(out, &quality))?;
    figures.make("the pixel-sample plot", pixel_samples)?;
    figures.make("the Fresnel plot", fresnel_curves)?;
    figures.make("the ray-tree plot", |out| ray_tree(out, level))?;
    figures.make("the error-against-time figures", |out| {
        convergence(out, &quality)
    })?;
    figures.agreement(&AGREEMENT)?;
    figures.make("the Mitsuba noise sentence", mitsuba_noise)?;
    figures.make("the BVH's cost against its size", |out| {
        bvh_cost(out, level)
    })?;
    figures.finish()
}

fn centre_render(builtin: Builtin, max_depth: u32, settings: &RenderSettings) -> Image {
    let scene = builtin.build(max_depth);
    render_with(&scene, settings, &CentreSampler::new(0)).image
}

/// The same scene at recursion depths 1, 2, 5 and 10: each level adds one more generation of
/// reflected and refracted rays.
fn recursion_depth(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let settings = quality.render.settings(1);
    let cells: Vec<(String, Image)> = [1u32, 2, 5, 10]
        .into_iter()
        .map(|depth| {
            // Recursion depth d allows d surface interactions: d + 1 segments in Mitsuba's count.
            let image = centre_render(Builtin::Spheres, depth + 1, &settings);
            let bounces = if depth == 1 { "bounce" } else { "bounces" };
            (
                format!(
                    "recursion depth {depth}: {depth} {bounces}, max_depth {}",
                    depth + 1
                ),
                image,
            )
        })
        .collect();
    comparison_grid(&out.join("depth.png"), &cells, 2, 1)?;
    Ok(())
}

/// One ray through each pixel centre against supersampling, enlarged around edges.
fn aliasing(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let scene = Builtin::Spheres.build(crate::scenes::DEFAULT_MAX_DEPTH);
    let full = render(&scene, &quality.render.settings(1), PixelPattern::Centre, 0)
        .expect("centre sampling always renders");
    write_speed(out, &full.stats)?;
    comparison_grid(
        &out.join("render.png"),
        &[("one ray per pixel".to_string(), full.image)],
        1,
        1,
    )?;
    // A window on the glass sphere's silhouette, the checkerboard seen through it and the
    // shadow edges, rendered alone so that a dense reference stays cheap.
    let window = Window {
        x: quality.render.width * 5 / 8,
        y: quality.render.height * 3 / 8,
        width: quality.render.width / 4,
        height: quality.render.height / 4,
    };
    let reference_spp = quality.reference_grid * quality.reference_grid;
    let cells: Vec<(String, Image)> = [
        (1, "1 ray per pixel, at its centre"),
        (16, "16 rays per pixel, regular grid"),
        (reference_spp, "reference"),
    ]
    .into_iter()
    .map(|(spp, label)| {
        let grid = GridSampler::for_spp(spp, 0).expect("square sample counts");
        let label = if spp == reference_spp {
            format!("{label}, {spp} rays per pixel")
        } else {
            label.to_string()
        };
        (label, render_window(&scene, quality, window, &grid, spp))
    })
    .collect();
    let scale = (480 / window.width).max(1);
    comparison_grid(&out.join("aliasing.png"), &cells, 3, scale)?;
    Ok(())
}

/// A rectangle of the image, in pixels.
#[derive(Clone, Copy)]
struct Window {
    x: u32,
    y: u32,
    width: u32,
    height: u32,
}

/// Renders only `window` of the full-size image, with `spp` samples per pixel.
fn render_window(
    scene: &common::scene::Scene,
    quality: &Quality,
    window: Window,
    sampler: &GridSampler,
    spp: u64,
) -> Image {
    let camera = crate::camera::PinholeCamera::of(
        &scene.camera,
        quality.render.width,
        quality.render.height,
    );
    let offset = Vec2::new(window.x as f32, window.y as f32);
    let settings = RenderSettings {
        progress: true,
        ..RenderSettings::new(window.width, window.height, spp)
    };
    common::render::render(
        &settings,
        sampler,
        &common::film::PixelBoxFilter,
        |p_film, _s: &mut GridSampler| {
            crate::tracer::trace(scene, &camera.generate_ray(p_film + offset), 1)
        },
    )
    .image
}

/// Where the rays of a 4 x 4 patch of pixels go: the centres, and a 4 x 4 grid per pixel.
fn pixel_samples(out: &Path) -> anyhow::Result<()> {
    use common::sampler::Sampler;
    let positions = |sampler: &mut dyn FnMut(glam::UVec2, u64) -> Vec2, spp: u64| {
        let mut points = Vec::new();
        for y in 0..4 {
            for x in 0..4 {
                for i in 0..spp {
                    let pixel = glam::UVec2::new(x, y);
                    points.push(pixel.as_vec2() + sampler(pixel, i));
                }
            }
        }
        points
    };
    let mut centre = CentreSampler::new(0);
    let mut grid = GridSampler::new(4, 0);
    let sets = vec![
        (
            "pixel centres (1 per pixel)".to_string(),
            positions(
                &mut |p, i| {
                    centre.start_pixel_sample(p, i);
                    centre.get_pixel_2d()
                },
                1,
            ),
        ),
        (
            "regular 4 x 4 grid per pixel".to_string(),
            positions(
                &mut |p, i| {
                    grid.start_pixel_sample(p, i);
                    grid.get_pixel_2d()
                },
                16,
            ),
        ),
    ];
    scatter_plot(
        &out.join("pixel_samples.png"),
        "Sample positions in a 4 x 4 pixel patch",
        &sets,
        [Vec2::ZERO, Vec2::splat(4.0)],
    )?;
    Ok(())
}

/// Fresnel reflectance against the angle of incidence, entering and leaving denser media.
fn fresnel_curves(out: &Path) -> anyhow::Result<()> {
    let curve = |eta_i: f32, eta_t: f32| -> Vec<(f64, f64)> {
        (0..=900)
            .map(|i| {
                let degrees = i as f32 * 0.1;
                let f = fresnel_dielectric(degrees.to_radians().cos(), eta_i / eta_t);
                (f64::from(degrees), f64::from(f))
            })
            .collect()
    };
    let critical_degrees = (1.0f32 / 1.5).asin().to_degrees();
    let series = vec![
        Series::new("air to water (1.33)", curve(1.0, 1.33), SeriesStyle::Line),
        Series::new("air to glass (1.5)", curve(1.0, 1.5), SeriesStyle::Line),
        Series::new("air to diamond (2.42)", curve(1.0, 2.42), SeriesStyle::Line),
        Series::new(
            format!("glass to air: total reflection past {critical_degrees:.1}°"),
            curve(1.5, 1.0),
            SeriesStyle::Line,
        ),
        Series::new(
            "index 1: no interface",
            curve(1.0, 1.0),
            SeriesStyle::Dashed,
        ),
    ];
    let axes = Axes::linear("angle of incidence (degrees)", "reflectance F");
    line_plot(
        &out.join("fresnel.png"),
        "Fresnel reflectance of a smooth dielectric",
        &axes,
        &series,
    )?;
    Ok(())
}

/// Rays per pixel against the depth limit: with glass every hit spawns two rays.
fn ray_tree(out: &Path, level: Level) -> anyhow::Result<()> {
    let (width, height) = level.pick((32, 24), (128, 96));
    let settings = RenderSettings::new(width, height, 1);
    let mut series = Vec::new();
    let mut growth = Vec::new();
    for builtin in Builtin::ALL {
        let points: Vec<(f64, f64)> = (1..=12)
            .map(|max_depth| {
                let scene = builtin.build(max_depth);
                let stats = render_with(&scene, &settings, &CentreSampler::new(0)).stats;
                (
                    f64::from(max_depth),
                    stats.rays as f64 / (width * height) as f64,
                )
            })
            .collect();
        let at = |max_depth: f64| {
            points
                .iter()
                .find(|p| p.0 == max_depth)
                .map_or(f64::NAN, |p| p.1)
        };
        growth.push((builtin.name(), at(2.0), at(12.0)));
        series.push(Series::new(
            builtin.name(),
            points,
            SeriesStyle::LineAndPoints,
        ));
    }
    write_text(&out.join("ray_tree.md"), &ray_tree_sentence(&growth))?;
    let axes = Axes {
        log_y: true,
        ..Axes::linear(
            "max_depth (segments, counting the camera ray)",
            "rays per pixel",
        )
    };
    line_plot(
        &out.join("ray_tree.png"),
        "Size of the ray tree",
        &axes,
        &series,
    )?;
    Ok(())
}

/// How much the ray tree grew from `max_depth` 2 to 12 in each scene, against the growth of a
/// tree that splits in two at every level: `(scene, rays per pixel at 2, rays per pixel at 12)`.
fn ray_tree_sentence(growth: &[(&str, f64, f64)]) -> String {
    let full = 2f64.powi(10);
    let parts: Vec<String> = growth
        .iter()
        .map(|&(name, shallow, deep)| {
            let factor = deep / shallow;
            let word = if factor < full { "less" } else { "more" };
            format!(
                "the {name} scene's tree grew from {shallow:.2} to {deep:.2} rays per pixel, \
                 {factor:.1} times ({word} than a tree that doubles)"
            )
        })
        .collect();
    format!(
        "From `max_depth` 2 to 12 a tree that split in two at every level would grow \
         {full:.0} times. In the runs behind the plot above, {}.\n",
        parts.join("; ")
    )
}

/// The speed of the default render, for the Speed appendix.
fn write_speed(out: &Path, stats: &common::render::RenderStats) -> anyhow::Result<()> {
    let pixels = u64::from(stats.width) * u64::from(stats.height);
    let text = format!(
        "The default scene at {} x {} pixels, one ray through each pixel centre and \
         `max_depth` {}, cast {} rays ({:.2} per pixel, shadow rays included) in {:.3} s: \
         {:.2} million rays per second, on the machine and with the build that made these \
         figures.\n",
        stats.width,
        stats.height,
        crate::scenes::DEFAULT_MAX_DEPTH,
        stats.rays,
        stats.rays as f64 / pixels as f64,
        stats.seconds,
        stats.rays_per_second / 1e6,
    );
    write_text(&out.join("speed.md"), &text)?;
    Ok(())
}

/// Whether our render is less noisy than Mitsuba's second render at the same sample count, on
/// each scene of the agreement set: the comparative words of the Mitsuba appendix.
fn mitsuba_noise(out: &Path) -> anyhow::Result<()> {
    let mut lower = Vec::new();
    let mut not_lower = Vec::new();
    for scene in AGREEMENT.scenes {
        let (_, _, agreement) = AGREEMENT.stored(scene).map_err(anyhow::Error::msg)?;
        if agreement.ours.rmse < agreement.other.rmse {
            lower.push(scene.name);
        } else {
            not_lower.push(scene.name);
        }
    }
    let list = |names: &[&str]| names.join(", ");
    let text = match (lower.is_empty(), not_lower.is_empty()) {
        (false, true) => format!(
            "On every scene ({}) our RMSE is lower than that of Mitsuba's second render.\n",
            list(&lower)
        ),
        (true, false) => format!(
            "On every scene ({}) our RMSE is no lower than that of Mitsuba's second render.\n",
            list(&not_lower)
        ),
        _ => format!(
            "Our RMSE is lower than that of Mitsuba's second render on {} and no lower on {}.\n",
            list(&lower),
            list(&not_lower)
        ),
    };
    write_text(&out.join("mitsuba-noise.md"), &text)?;
    Ok(())
}

/// Error against time: more rays at the pixel centre buy nothing; a grid converges.
fn convergence(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let scene = Builtin::Spheres.build(crate::scenes::DEFAULT_MAX_DEPTH);
    let (width, height) = (quality.render.width / 3, quality.render.height / 3);
    let settings = |spp| RenderSettings::new(width, height, spp);
    // Four times as many grid cells per side as the densest technique: its own error is
    // far below the differences being measured.
    let reference_spp = quality.render.reference_spp;
    let reference = render(&scene, &settings(reference_spp), PixelPattern::Grid, 0)
        .expect("a square")
        .image;
    let techniques = vec![
        Technique {
            name: "pixel centre".to_string(),
            render: Box::new(|spp| {
                render(&scene, &settings(spp), PixelPattern::Centre, 0)
                    .expect("centre")
                    .image
            }),
        },
        Technique {
            name: "regular grid".to_string(),
            render: Box::new(|spp| {
                render(&scene, &settings(spp), PixelPattern::Grid, 0)
                    .expect("square budgets")
                    .image
            }),
        },
    ];
    let records = run_convergence(&techniques, quality.render.budgets, &reference);
    write_convergence_csv(&out.join("convergence.csv"), &records)?;
    write_text(
        &out.join("convergence.md"),
        &workbench::convergence::convergence_markdown(&records, "camera rays per pixel"),
    )?;
    plot_error_vs_time(
        &out.join("convergence.png"),
        "Error against time (spheres)",
        &records,
    )?;
    plot_error_vs_spp(
        &out.join("convergence_spp.png"),
        "Error against samples per pixel (spheres)",
        &records,
    )?;
    Ok(())
}

/// Spot, Keenan Crane's cow (CC0 1.0; see `data/README.md`): a model made by a person, the
/// real mesh the appendix measures beside the generated ones.
const SPOT_PLY: &[u8] = include_bytes!("../data/spot.ply");

/// The BVH's build time, memory and time per ray against the number of triangles, for the
/// appendix on acceleration structures: generated bumpy spheres of 10^3 to 10^6 triangles, and
/// a real model, Spot, at its own 5 856 triangles and split in four up to four times (1.5
/// million); quick figures stop at 10^5. Each beside the slope its structure promises.
fn bvh_cost(out: &Path, level: Level) -> anyhow::Result<()> {
    use common::geometry::{BvhCost, TriangleMesh, measure_bvh_cost};
    let sizes: &[usize] = level.pick(
        &[1_000, 10_000, 100_000],
        &[1_000, 10_000, 100_000, 1_000_000],
    );
    let splits = level.pick(2, 4);
    let rays = level.pick(20_000, 200_000);
    let mut costs: Vec<(&str, BvhCost)> = sizes
        .iter()
        .map(|&n| {
            (
                "bumpy sphere",
                measure_bvh_cost(&TriangleMesh::bumpy_sphere(n), rays, 1),
            )
        })
        .collect();
    let mut spot = workbench::scene_file::parse_ply(SPOT_PLY)
        .map_err(|error| anyhow::anyhow!("the built-in Spot mesh: {error}"))?;
    for split in 0..=splits {
        if split > 0 {
            spot = spot.split_in_four();
        }
        costs.push(("Spot", measure_bvh_cost(&spot, rays, 1)));
    }

    let mut csv = String::from(
        "mesh,triangles,build_seconds_1_thread,build_seconds_2_threads,bytes_per_triangle,\
         nanoseconds_per_ray,\
         rays_per_second_1_thread,rays_per_second_2_threads,hit_fraction,nodes_per_ray,\
         leaves_per_ray\n",
    );
    let mut table = String::from(
        "| mesh | triangles | build, 1 thread | 2 threads | bytes per triangle | nodes per ray | per ray, 1 thread | rays per second, 1 thread | 2 threads |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for (mesh, c) in &costs {
        csv += &format!(
            "{mesh},{},{:.6e},{:.6e},{:.1},{:.1},{:.0},{:.0},{:.4},{:.3},{:.3}\n",
            c.triangles,
            c.build_seconds[0],
            c.build_seconds[1],
            c.bytes_per_triangle,
            c.nanoseconds_per_ray,
            c.rays_per_second[0],
            c.rays_per_second[1],
            c.hit_fraction,
            c.nodes_per_ray,
            c.leaves_per_ray
        );
        table += &format!(
            "| {mesh} | {} | {:.2} ms | {:.2} ms | {:.0} | {:.1} | {:.0} ns | {:.2} M | {:.2} M |\n",
            c.triangles,
            1e3 * c.build_seconds[0],
            1e3 * c.build_seconds[1],
            c.bytes_per_triangle,
            c.nodes_per_ray,
            c.nanoseconds_per_ray,
            c.rays_per_second[0] / 1e6,
            c.rays_per_second[1] / 1e6
        );
    }
    write_text(&out.join("bvh-cost.csv"), &csv)?;
    write_text(&out.join("bvh-cost.md"), &table)?;

    // A reference curve through the middle measurement, with the shape `shape(n)`.
    let reference = |measured: &[(f64, f64)], shape: &dyn Fn(f64) -> f64| {
        let (n_mid, y_mid) = measured[measured.len() / 2];
        let scale = y_mid / shape(n_mid);
        measured
            .iter()
            .map(|&(n, _)| (n, scale * shape(n)))
            .collect::<Vec<_>>()
    };
    let of_mesh = |mesh: &str, value: &dyn Fn(&BvhCost) -> f64| -> Vec<(f64, f64)> {
        costs
            .iter()
            .filter(|(name, _)| *name == mesh)
            .map(|(_, c)| (c.triangles as f64, value(c)))
            .collect()
    };
    let build = |mesh: &str, threads: usize| of_mesh(mesh, &|c| c.build_seconds[threads]);
    line_plot(
        &out.join("bvh-build.png"),
        "Building the BVH",
        &Axes::log_log("triangles", "build time (s)"),
        &[
            Series::new(
                "bumpy sphere, 1 thread",
                build("bumpy sphere", 0),
                SeriesStyle::LineAndPoints,
            ),
            Series::new(
                "bumpy sphere, 2 threads",
                build("bumpy sphere", 1),
                SeriesStyle::LineAndPoints,
            ),
            Series::new(
                "Spot, 1 thread",
                build("Spot", 0),
                SeriesStyle::LineAndPoints,
            ),
            Series::new(
                "Spot, 2 threads",
                build("Spot", 1),
                SeriesStyle::LineAndPoints,
            ),
            Series::new(
                "n log n",
                reference(&build("bumpy sphere", 0), &|n| n * n.log2()),
                SeriesStyle::Dashed,
            ),
        ],
    )?;
    // The walk's steps on a logarithmic count axis: `a + b log n` is a straight line there.
    let steps = |mesh: &str| of_mesh(mesh, &|c| c.nodes_per_ray);
    line_plot(
        &out.join("bvh-steps.png"),
        "Nodes a ray is tested against",
        &Axes {
            log_y: false,
            ..Axes::log_log("triangles", "nodes per ray")
        },
        &[
            Series::new(
                "bumpy sphere",
                steps("bumpy sphere"),
                SeriesStyle::LineAndPoints,
            ),
            Series::new("Spot", steps("Spot"), SeriesStyle::LineAndPoints),
            Series::new(
                "a + b log n, fitted",
                fitted_log_line(&steps("bumpy sphere")),
                SeriesStyle::Dashed,
            ),
        ],
    )?;
    let per_ray = |mesh: &str, threads: usize| of_mesh(mesh, &|c| 1e9 / c.rays_per_second[threads]);
    line_plot(
        &out.join("bvh-trace.png"),
        "Nearest hit through the BVH",
        &Axes::log_log("triangles", "time per ray (ns)"),
        &[
            Series::new(
                "bumpy sphere, 1 thread",
                per_ray("bumpy sphere", 0),
                SeriesStyle::LineAndPoints,
            ),
            Series::new(
                "bumpy sphere, 2 threads",
                per_ray("bumpy sphere", 1),
                SeriesStyle::LineAndPoints,
            ),
            Series::new(
                "Spot, 1 thread",
                per_ray("Spot", 0),
                SeriesStyle::LineAndPoints,
            ),
            Series::new(
                "Spot, 2 threads",
                per_ray("Spot", 1),
                SeriesStyle::LineAndPoints,
            ),
            Series::new(
                "log n",
                reference(&per_ray("bumpy sphere", 0), &|n| n.log2()),
                SeriesStyle::Dashed,
            ),
        ],
    )?;
    Ok(())
}

/// The least-squares line `y = a + b log n` through `points` (`(n, y)`), at their `n`s.
fn fitted_log_line(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let count = points.len() as f64;
    let x: Vec<f64> = points.iter().map(|&(n, _)| n.ln()).collect();
    let mean_x = x.iter().sum::<f64>() / count;
    let mean_y = points.iter().map(|&(_, y)| y).sum::<f64>() / count;
    let covariance: f64 = x
        .iter()
        .zip(points)
        .map(|(x, &(_, y))| (x - mean_x) * (y - mean_y))
        .sum();
    let variance: f64 = x.iter().map(|x| (x - mean_x).powi(2)).sum();
    let slope = if variance > 0.0 {
        covariance / variance
    } else {
        0.0
    };
    points
        .iter()
        .zip(&x)
        .map(|(&(n, _), x)| (n, mean_y + slope * (x - mean_x)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fitted_line_goes_through_points_on_a_log_line() {
        let on_line: Vec<(f64, f64)> = [1e3, 1e4, 1e5, 1e6]
            .iter()
            .map(|&n: &f64| (n, 2.0 + 0.5 * n.ln()))
            .collect();
        for ((n, y), (fitted_n, fitted_y)) in on_line.iter().zip(fitted_log_line(&on_line)) {
            assert_eq!(*n, fitted_n);
            assert!((y - fitted_y).abs() < 1e-9, "{y} against {fitted_y}");
        }
        let flat = fitted_log_line(&[(10.0, 3.0), (10.0, 5.0)]);
        assert!(flat.iter().all(|&(_, y)| y == 4.0), "{flat:?}");
    }

    #[test]
    fn the_built_in_spot_is_the_whole_closed_model() {
        let spot = workbench::scene_file::parse_ply(SPOT_PLY).unwrap();
        assert_eq!((spot.positions.len(), spot.indices.len()), (2_930, 5_856));
        // Closed: every edge lies between exactly two triangles, so rays from outside meet
        // its surface as they would meet a solid.
        let uses = spot.edge_uses();
        assert!(uses.values().all(|&count| count == 2));
    }

    #[test]
    fn the_ray_tree_sentence_says_less_or_more_as_the_numbers_say() {
        let sentence = ray_tree_sentence(&[("slow", 2.0, 6.0), ("bushy", 1.0, 2048.0)]);
        assert!(
            sentence.contains(
                "the slow scene's tree grew from 2.00 to 6.00 rays per pixel, 3.0 times (less"
            ),
            "{sentence}"
        );
        assert!(
            sentence.contains("2048.0 times (more than a tree that doubles)"),
            "{sentence}"
        );
    }
}
