//! The chapter's figures, in the order of the page:
//!
//! - the diagrams (`diagrams/`, [`crate::lab::diagrams`]): Cook's ray tree against a path,
//!   and the densities of a light sample and a BSDF sample at one vertex;
//! - the ray tree: rays per camera ray against the depth limit for branching factors 1, 2
//!   and 4 (`ray-tree.csv`/`.png`), the worst case counted by `rays_by_depth` against one path
//!   (`ray-tree-growth.md`), and the share of the pixel carried by each depth
//!   (`depth-shares.csv`/`.png`);
//! - distribution ray tracing against path tracing of the same scene at equal time
//!   (`drt-vs-pt.png`), with error against time (`drt-vs-pt-convergence.*`), and the
//!   lecture's final comparison, Cook's tracer against the path tracer (`final-comparison.png`);
//! - NEE, MIS and Russian roulette on the Cornell box (`bsdf-only.png`, `nee.png`, ...,
//!   `roulette.png`, `convergence.*`) and on Veach's glossy plates (`mis-plates.png`,
//!   `plates-convergence.*`);
//! - chapter 03's samplers, placing every dimension of a path, against independent numbers
//!   on the Cornell box and the glossy plates (`samplers-cornell.*`, `samplers-plates.*`,
//!   `samplers.md`);
//! - the numbers each path draws in the agreement scenes (`dimensions.md`), and the static
//!   pinhole scene timed against chapter 03's tracer (`static-pinhole.md`), for the Speed
//!   appendix;
//! - the comparison with Mitsuba 3 (`mitsuba.md` and its images).
//!
//! Beside each CSV a small Markdown file (a table or a sentence) holds the numbers the page
//! quotes, so that the text and the figures always agree.
//!
//! The quick level renders thumbnails at few samples, for CI.

use crate::LectureMaterials;
use crate::dimensions::render_counted;
use crate::distribution_tracer::ray_tree::{
    LightCounts, Surface, depth_shares, rays_by_depth, rays_per_camera_ray, render_small,
    total_rays,
};
use crate::distribution_tracer::{DistributionOptions, render_distribution};
use crate::lab::agreement::AGREEMENT;
use crate::lab::scene_file::path_options;
use crate::mis::MisHeuristic;
use crate::options::PathOptions;
use crate::{Method, render_with};
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::{MotionScene, TimeSampler};
use common::film::PixelBoxFilter;
use common::image::Image;
use common::metrics::rmse;
use common::render::{Budget, RenderOutput, RenderSettings};
use common::sampler::IndependentSampler;
use common::scene::{Material, Scene};
use std::path::Path;
use std::time::Instant;
use workbench::convergence::{
    Technique, convergence_markdown, plot_error_vs_spp, plot_error_vs_time, run_convergence,
    write_convergence_csv,
};
use workbench::figure_set::{FigureSet, Level};
use workbench::output::figures::{Axes, Series, SeriesStyle, comparison_grid, line_plot};
use workbench::output::{write_image, write_text};

/// The techniques compared, by name.
pub fn techniques(file: PathOptions) -> Vec<(&'static str, PathOptions)> {
    let mitsuba = PathOptions {
        nee: true,
        mis: MisHeuristic::Power,
        ..file
    };
    vec![
        (
            "bsdf-only",
            PathOptions {
                nee: false,
                ..mitsuba
            },
        ),
        (
            "nee",
            PathOptions {
                mis: MisHeuristic::None,
                ..mitsuba
            },
        ),
        (
            "nee-mis-balance",
            PathOptions {
                mis: MisHeuristic::Balance,
                ..mitsuba
            },
        ),
        ("nee-mis-power", mitsuba),
        (
            "nee-mis-power-no-rr",
            PathOptions {
                rr_depth: None,
                ..mitsuba
            },
        ),
    ]
}

/// The box filter every figure uses: one sample lands in one pixel.
fn box_filter() -> ReconstructionFilter {
    ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter")
}

/// Path-traces `scene` with `options` under `budget`, independent samples, box filter.
fn path_trace(
    scene: &MotionScene,
    options: PathOptions,
    size: (u32, u32),
    budget: Budget,
    seed: u64,
) -> RenderOutput {
    path_trace_sampled(scene, options, size, budget, &IndependentSampler::new(seed))
}

/// Path-traces `scene` with `options` under `budget`, numbers from `sampler`, box filter.
fn path_trace_sampled<S: TimeSampler>(
    scene: &MotionScene,
    options: PathOptions,
    size: (u32, u32),
    budget: Budget,
    sampler: &S,
) -> RenderOutput {
    let settings = RenderSettings {
        budget,
        ..RenderSettings::new(size.0, size.1, 1)
    };
    render_with(
        scene,
        Method::new(options),
        &Lens::PINHOLE,
        &settings,
        sampler,
        &box_filter(),
    )
}

/// Renders `scene` with `options` at `spp`, independent samples, box filter.
pub fn render(
    scene: &MotionScene,
    options: PathOptions,
    size: (u32, u32),
    spp: u64,
    seed: u64,
) -> Image {
    path_trace(scene, options, size, Budget::Samples(spp), seed).image
}

/// A chapter scene file, made ready for the path tracer, with its path options.
struct SceneFile {
    world: MotionScene,
    options: crate::PathOptions,
}

/// The chapter scene file `name`, loaded.
fn load(name: &str) -> anyhow::Result<SceneFile> {
    let file = AGREEMENT.scenes_dir().join(name);
    let loaded = workbench::scene_file::load_scene_file(&file, &[])?;
    crate::lab::CAPABILITIES
        .check(&loaded.scene)
        .map_err(anyhow::Error::msg)?;
    let options = path_options(&loaded.scene);
    let world = MotionScene::new(loaded.scene).map_err(anyhow::Error::msg)?;
    Ok(SceneFile { world, options })
}

/// Sizes and sample counts: thumbnails at the quick level, the scene files' own sizes in the
/// book.
struct Quality {
    level: Level,
    /// Samples per pixel of the converged references.
    reference_spp: u64,
    /// Sample counts of the error-against-time runs.
    budgets: &'static [u64],
}

impl Quality {
    fn at(level: Level) -> Self {
        Quality {
            level,
            reference_spp: level.pick(64, 1024),
            budgets: level.pick(&[1, 4], &[1, 4, 16, 64]),
        }
    }

    fn size(&self, scene: &MotionScene, quick_size: (u32, u32)) -> (u32, u32) {
        let film = scene.scene.film;
        self.level.pick(quick_size, (film.width, film.height))
    }
}

/// Writes every figure into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch08", out, quick)?;
    let quality = Quality::at(figures.level());
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.make("the ray-tree figures", |out| ray_tree(out, &quality))?;
    figures.make("distribution against path tracing", |out| {
        distribution_vs_path(out, &quality)
    })?;
    figures.make("NEE, MIS and roulette on the Cornell box", |out| {
        cornell_techniques(out, &quality)
    })?;
    figures.make("MIS on the glossy plates", |out| {
        glossy_plates(out, &quality)
    })?;
    figures.make("the samplers on the path tracer", |out| {
        samplers_on_paths(out, &quality)
    })?;
    figures.make("dimensions drawn per path", |out| dimensions(out, &quality))?;
    figures.make("the static pinhole scene against chapter 03", |out| {
        static_pinhole(out, &quality)
    })?;
    figures.agreement(&AGREEMENT)?;
    figures.finish()
}

// ANCHOR: ray_tree
/// Rays per camera ray against the depth limit, for branching factors 1, 2 and 4 with
/// indirect diffuse light and 4 without (Cook's tracer), and the share of the image each
/// depth carries, on the Cornell box.
fn ray_tree(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let file = load("cornell-box.xml")?;
    let scene = &file.world;
    let size = (16, 16);
    let deepest = quality.level.pick(4, 6);
    let mut csv = String::from("branching,indirect_diffuse,max_depth,rays_per_camera_ray\n");
    let mut series = Vec::new();
    let configurations = [(1, true), (2, true), (4, true), (4, false)];
    // rays[configuration][depth - 1], for the Markdown table.
    let mut rays_table = Vec::new();
    for (branching, indirect) in configurations {
        let mut points = Vec::new();
        for depth in 1..=deepest {
            let options = DistributionOptions::branching(branching, depth, indirect);
            let rays = rays_per_camera_ray(&render_small(scene, options, size, 1, 1));
            csv += &format!("{branching},{indirect},{depth},{rays:.2}\n");
            points.push((f64::from(depth), rays));
        }
        rays_table.push(points.iter().map(|&(_, rays)| rays).collect::<Vec<_>>());
        let label = if indirect {
            format!("k = m = {branching}, indirect diffuse")
        } else {
            format!("k = m = {branching}, Cook 1984 (no indirect)")
        };
        series.push(Series::new(label, points, SeriesStyle::LineAndPoints));
    }
    write_text(&out.join("ray-tree.csv"), &csv)?;
    let mut table = format!(
        "Counted on the Cornell box ({} × {} pixels, 1 sample each), rays of every kind per \
         camera ray, against the depth limit:\n\n\
         | `max_depth` | k = m = 1 | k = m = 2 | k = m = 4 | k = m = 4, Cook (no indirect) |\n\
         |---|---|---|---|---|\n",
        size.0, size.1
    );
    for depth in 1..=deepest {
        table += &format!("| {depth} |");
        for column in &rays_table {
            table += &format!(" {} |", rays_number(column[depth as usize - 1]));
        }
        table += "\n";
    }
    write_text(&out.join("ray-tree.md"), &table)?;
    write_text(&out.join("ray-tree-growth.md"), &ray_tree_growth(deepest))?;
    let log_y = Axes {
        log_y: true,
        ..Axes::linear(
            "max_depth (segments, the camera ray is 1)",
            "rays per camera ray",
        )
    };
    line_plot(
        &out.join("ray-tree.png"),
        "Cornell box: the ray tree grows exponentially with depth",
        &log_y,
        &series,
    )?;

    let spp = quality.level.pick(16, 256);
    let share_size = (32, 32);
    let shares = depth_shares(
        scene,
        DistributionOptions::branching(1, 8, true),
        share_size,
        spp,
        2,
    );
    let mut csv = String::from("depth,share\n");
    for &(depth, share) in &shares {
        csv += &format!("{depth},{share:.5}\n");
    }
    write_text(&out.join("depth-shares.csv"), &csv)?;
    let mut table = format!(
        "Measured on the Cornell box at {} × {} pixels, {}, `max_depth` up to 8, \
         $k = m = 1$:\n\n| depth |",
        share_size.0,
        share_size.1,
        samples_per_pixel(spp)
    );
    for &(depth, _) in &shares {
        table += &format!(" {depth} |");
    }
    table += "\n|---|";
    table += &"---|".repeat(shares.len());
    table += "\n| share |";
    for &(_, share) in &shares {
        table += &format!(" {share:.3} |");
    }
    table += "\n";
    write_text(&out.join("depth-shares.md"), &table)?;
    let points = shares.iter().map(|&(d, s)| (f64::from(d), s)).collect();
    let log_y = Axes {
        log_y: true,
        ..Axes::linear(
            "depth of the ray (segment)",
            "share of the image's radiance",
        )
    };
    line_plot(
        &out.join("depth-shares.png"),
        "Cornell box: what the rays of each depth carry",
        &log_y,
        &[Series::new("share", points, SeriesStyle::LineAndPoints)],
    )?;
    Ok(())
}
// ANCHOR_END: ray_tree

/// The worst case counted by [`rays_by_depth`]: a closed matte room lit by one area light,
/// `k = m = 2` with indirect diffuse light, against one path (`k = m = 1`) to the same depth.
fn ray_tree_growth(deepest: u32) -> String {
    let lights = LightCounts { area: 1, point: 0 };
    let tree = rays_by_depth(
        Surface::Matte,
        DistributionOptions::branching(2, deepest, true),
        lights,
    );
    let mut table = String::from(
        "| depth | rays | shadow rays | the tree to this depth | one path to this depth | tree / path |\n\
         |---|---|---|---|---|---|\n",
    );
    for count in &tree {
        let depth = count.depth;
        let tree_total = total_rays(&rays_by_depth(
            Surface::Matte,
            DistributionOptions::branching(2, depth, true),
            lights,
        ));
        let path_total = total_rays(&rays_by_depth(
            Surface::Matte,
            DistributionOptions::branching(1, depth, true),
            lights,
        ));
        table += &format!(
            "| {depth} | {} | {} | {tree_total} | {path_total} | {} |\n",
            count.rays,
            count.shadow_rays,
            rays_number(tree_total as f64 / path_total.max(1) as f64)
        );
    }
    table
}

// ANCHOR: distribution_vs_path
/// The Cornell box at depth 4 by distribution ray tracing (k = m = 2, indirect diffuse
/// light: the same light as the path tracer computes) and by path tracing in the same time.
fn distribution_vs_path(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let depth = 4;
    let file = load("cornell-box.xml")?;
    let scene = &file.world;
    let size = quality.size(scene, (32, 32));
    let pt_options = PathOptions::with_depth(depth);
    let reference = render(scene, pt_options, size, quality.reference_spp, 99);
    let drt = |options: DistributionOptions, spp: u64| {
        let settings = RenderSettings::new(size.0, size.1, spp);
        let sampler = IndependentSampler::new(1);
        render_distribution(
            scene,
            options,
            &Lens::PINHOLE,
            &settings,
            &sampler,
            &box_filter(),
        )
    };
    let branching = DistributionOptions::branching(2, depth, true);
    let tree = drt(branching, quality.level.pick(1, 4));
    let seconds = tree.stats.seconds;
    let paths = path_trace(scene, pt_options, size, Budget::Seconds(seconds), 1);
    let caption = |name: &str, output: &RenderOutput| {
        format!(
            "{name}: {} spp, {:.2} s, RMSE {:.4}",
            output.stats.spp,
            output.stats.seconds,
            rmse(&output.image, &reference)
        )
    };
    let cells = vec![
        (caption("distribution k=m=2", &tree), tree.image.clone()),
        (caption("path", &paths), paths.image.clone()),
    ];
    comparison_grid(&out.join("drt-vs-pt.png"), &cells, 2, 3)?;
    eprintln!("drt-vs-pt: {} | {}", cells[0].0, cells[1].0);
    // The path tracer at the tree's own sample count, to compare one sample with one sample.
    let paths_at_tree_spp = path_trace(scene, pt_options, size, Budget::Samples(tree.stats.spp), 1);
    let (tree_error, path_error) = (
        rmse(&tree.image, &reference),
        rmse(&paths.image, &reference),
    );
    let path_error_per_sample = rmse(&paths_at_tree_spp.image, &reference);
    let per_sample = |output: &RenderOutput| output.stats.seconds / output.stats.spp.max(1) as f64;
    write_text(
        &out.join("drt-vs-pt.md"),
        &format!(
            "At {w} × {h} pixels the tree with $k = m = 2$ took {tree_s:.3} s for {tree_spp} \
             and reached an RMSE of {tree_error:.3} against a path-traced reference of \
             {reference_spp}. The path tracer, given the same time, took {path_spp} in \
             {path_s:.3} s and reached {path_error:.3}, {verdict} the tree's. Sample for \
             sample, the tree's error is {sample_verdict} the path tracer's ({tree_error:.3} \
             against {path_error_per_sample:.3}, both at {tree_spp}), and one of its samples \
             cost {cost:.1} times as much as a path.\n",
            w = size.0,
            h = size.1,
            tree_s = tree.stats.seconds,
            tree_spp = samples_per_pixel(tree.stats.spp),
            reference_spp = samples_per_pixel(quality.reference_spp),
            path_spp = samples_per_pixel(paths.stats.spp),
            path_s = paths.stats.seconds,
            verdict = lower_or_higher(path_error, tree_error),
            sample_verdict = lower_or_higher(tree_error, path_error_per_sample),
            cost = per_sample(&tree) / per_sample(&paths_at_tree_spp).max(f64::MIN_POSITIVE),
        ),
    )?;

    let runs = vec![
        Technique::new("distribution k=m=1", move |spp| {
            drt(DistributionOptions::branching(1, depth, true), spp).image
        }),
        Technique::new("distribution k=m=2", move |spp| drt(branching, spp).image),
        Technique::new("path", move |spp| render(scene, pt_options, size, spp, 1)),
    ];
    // The tree's renders are the dearest: one budget fewer.
    let budgets = &quality.budgets[..quality.budgets.len() - 1];
    let records = run_convergence(&runs, budgets, &reference);
    write_convergence_csv(&out.join("drt-vs-pt-convergence.csv"), &records)?;
    write_text(
        &out.join("drt-vs-pt-convergence.md"),
        &convergence_markdown(&records, "samples per pixel"),
    )?;
    plot_error_vs_time(
        &out.join("drt-vs-pt-convergence.png"),
        "Cornell box, depth 4: the tree against the path",
        &records,
    )?;

    // The lecture's last slide: Cook's tracer (no indirect diffuse light) against the path
    // tracer, both converged, at the scene's own depth.
    let full = file.options.max_depth;
    let spp = quality.level.pick(16, 256);
    let cook = drt(DistributionOptions::branching(1, full, false), spp);
    let path_image = render(scene, file.options, size, spp, 2);
    comparison_grid(
        &out.join("final-comparison.png"),
        &[
            (format!("distribution (Cook 1984), {spp} spp"), cook.image),
            (format!("path tracing, {spp} spp"), path_image),
        ],
        2,
        3,
    )?;
    Ok(())
}
// ANCHOR_END: distribution_vs_path

/// NEE, MIS and roulette on the Cornell box at the file's depth: one image each at 16 spp,
/// roulette on and off with their times, and error against time.
fn cornell_techniques(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let file = load("cornell-box.xml")?;
    let scene = &file.world;
    let size = quality.size(scene, (32, 32));
    let reference = render(scene, file.options, size, quality.reference_spp, 99);
    let techniques = techniques(file.options);
    for &(name, options) in &techniques {
        let image = render(scene, options, size, 16, 1);
        write_image(&out.join(format!("{name}.png")), &image)?;
    }
    let roulette_from = match file.options.rr_depth {
        Some(depth) => format!("roulette from {depth}"),
        None => "roulette as in the file".to_string(),
    };
    let mut roulette_md =
        String::from("| 64 samples per pixel | seconds | RMSE |\n|---|---|---|\n");
    let roulette: Vec<(String, Image)> = [
        (roulette_from.as_str(), file.options),
        ("no roulette", {
            PathOptions {
                rr_depth: None,
                ..file.options
            }
        }),
    ]
    .into_iter()
    .map(|(name, options)| {
        let output = path_trace(scene, options, size, Budget::Samples(64), 1);
        let error = rmse(&output.image, &reference);
        let caption = format!(
            "{name}: 64 spp, {:.2} s, RMSE {error:.4}",
            output.stats.seconds,
        );
        roulette_md += &format!("| {name} | {:.3} | {error:.4} |\n", output.stats.seconds);
        (caption, output.image)
    })
    .collect();
    comparison_grid(&out.join("roulette.png"), &roulette, 2, 3)?;
    write_text(&out.join("roulette.md"), &roulette_md)?;
    let runs: Vec<Technique> = techniques
        .iter()
        .map(|&(name, options)| {
            Technique::new(name, move |spp| render(scene, options, size, spp, 1))
        })
        .collect();
    let records = run_convergence(&runs, quality.budgets, &reference);
    write_convergence_csv(&out.join("convergence.csv"), &records)?;
    write_text(
        &out.join("convergence.md"),
        &convergence_markdown(&records, "samples per pixel"),
    )?;
    plot_error_vs_time(
        &out.join("convergence.png"),
        "Cornell box: error against time",
        &records,
    )?;
    plot_error_vs_spp(
        &out.join("convergence-spp.png"),
        "Cornell box: error against samples",
        &records,
    )?;
    Ok(())
}

// ANCHOR: glossy_plates
/// Veach's glossy plates at depth 2 (direct light only): BSDF sampling alone, light sampling
/// alone, and both combined by the balance and the power heuristic, at equal samples.
fn glossy_plates(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let file = load("glossy-plates.xml")?;
    let scene = &file.world;
    let size = quality.size(scene, (96, 64));
    let direct = PathOptions {
        rr_depth: None,
        ..PathOptions::with_depth(2)
    };
    let reference = render(scene, direct, size, quality.reference_spp, 99);
    // Light sampling alone: NEE whose BSDF-found light is dropped (MIS `None`) is exactly
    // that at depth 2, where a BSDF direction that finds a light ends the path.
    let variants = [
        (
            "BSDF sampling",
            PathOptions {
                nee: false,
                ..direct
            },
        ),
        (
            "light sampling",
            PathOptions {
                mis: MisHeuristic::None,
                ..direct
            },
        ),
        (
            "MIS, balance",
            PathOptions {
                mis: MisHeuristic::Balance,
                ..direct
            },
        ),
        ("MIS, power", direct),
    ];
    let spp = 4;
    let mut cells = Vec::new();
    let mut errors = Vec::new();
    for &(name, options) in &variants {
        let image = render(scene, options, size, spp, 1);
        let error = rmse(&image, &reference);
        eprintln!("plates {name}: RMSE {error:.4} at {spp} spp");
        cells.push((format!("{name}, {spp} spp, RMSE {error:.3}"), image));
        errors.push((name, error));
    }
    let mut table = format!(
        "At {spp} samples per pixel ({} × {} pixels), against a reference of {}:\n\n\
         | technique | RMSE |\n|---|---|\n",
        size.0,
        size.1,
        samples_per_pixel(quality.reference_spp)
    );
    for &(name, error) in &errors {
        table += &format!("| {name} | {error:.3} |\n");
    }
    let error_of = |wanted: &str| {
        errors
            .iter()
            .find(|(name, _)| *name == wanted)
            .map_or(f64::NAN, |&(_, error)| error)
    };
    let (balance, power) = (error_of("MIS, balance"), error_of("MIS, power"));
    let (bsdf, light) = (error_of("BSDF sampling"), error_of("light sampling"));
    table += &format!(
        "\nHere the balance heuristic's error is {} the power heuristic's, and the better of \
         the two MIS renders has an error {} that of the better single technique.\n",
        lower_or_higher(balance, power),
        lower_or_higher(balance.min(power), bsdf.min(light)),
    );
    write_text(&out.join("mis-plates.md"), &table)?;
    cells.push((
        format!("reference, {} spp", quality.reference_spp),
        reference.clone(),
    ));
    comparison_grid(&out.join("mis-plates.png"), &cells, 2, 2)?;
    let runs: Vec<Technique> = variants
        .iter()
        .map(|&(name, options)| {
            Technique::new(name, move |spp| render(scene, options, size, spp, 1))
        })
        .collect();
    let records = run_convergence(&runs, quality.budgets, &reference);
    write_convergence_csv(&out.join("plates-convergence.csv"), &records)?;
    write_text(
        &out.join("plates-convergence.md"),
        &convergence_markdown(&records, "samples per pixel"),
    )?;
    plot_error_vs_time(
        &out.join("plates-convergence.png"),
        "Glossy plates: error against time",
        &records,
    )?;
    Ok(())
}
// ANCHOR_END: glossy_plates

// ANCHOR: samplers_on_paths
/// Chapter 03's samplers, which place every dimension of a path, against independent numbers:
/// error against time on the Cornell box (every bounce, the file's depth) and on Veach's
/// glossy plates (direct light only, where a path draws few dimensions), each sampler's render
/// of the pixel, lens, light and BSDF numbers with the power heuristic.
fn samplers_on_paths(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let kinds = [
        PixelSamplerKind::Random,
        PixelSamplerKind::Stratified,
        PixelSamplerKind::MultiJitter,
        PixelSamplerKind::Sobol,
    ];
    let plates = PathOptions {
        rr_depth: None,
        ..PathOptions::with_depth(2)
    };
    let mut summary = String::from(
        "| sampler | Cornell box: RMSE | against random | glossy plates: RMSE | against random |\n\
         |---|---:|---:|---:|---:|\n",
    );
    let mut last_errors = Vec::new();
    for (name, file_name, quick_size, depth) in [
        ("cornell", "cornell-box.xml", (32, 32), None),
        ("plates", "glossy-plates.xml", (96, 64), Some(plates)),
    ] {
        let file = load(file_name)?;
        let scene = &file.world;
        let options = depth.unwrap_or(file.options);
        let size = quality.size(scene, quick_size);
        let reference = render(scene, options, size, quality.reference_spp, 99);
        let runs: Vec<Technique> = kinds
            .iter()
            .map(|&kind| {
                Technique::new(kind.name(), move |spp| {
                    let sampler = PixelSampler::new(kind, spp, 1).expect("a sample count");
                    path_trace_sampled(scene, options, size, Budget::Samples(spp), &sampler).image
                })
            })
            .collect();
        let records = run_convergence(&runs, quality.budgets, &reference);
        write_convergence_csv(&out.join(format!("samplers-{name}.csv")), &records)?;
        write_text(
            &out.join(format!("samplers-{name}.md")),
            &convergence_markdown(&records, "samples per pixel"),
        )?;
        plot_error_vs_time(
            &out.join(format!("samplers-{name}.png")),
            &format!("{file_name}: samplers, error against time"),
            &records,
        )?;
        // The errors at the largest count, in the order of `kinds`.
        let most = quality.budgets.last().copied().unwrap_or(1);
        last_errors.push(
            records
                .iter()
                .filter(|r| r.spp == most)
                .map(|r| r.rmse)
                .collect::<Vec<f64>>(),
        );
    }
    for (k, kind) in kinds.iter().enumerate() {
        let cell = |errors: &Vec<f64>| {
            let ratio = errors[k] / errors[0];
            format!("{:.3e} | {ratio:.2}", errors[k])
        };
        summary += &format!(
            "| {} | {} | {} |\n",
            kind.name(),
            cell(&last_errors[0]),
            cell(&last_errors[1])
        );
    }
    let most = quality.budgets.last().copied().unwrap_or(1);
    summary += &format!("\nAt {}.\n", samples_per_pixel(most));
    write_text(&out.join("samplers.md"), &summary)?;
    Ok(())
}
// ANCHOR_END: samplers_on_paths

/// "lower than", "higher than" or "the same as", for `a` compared with `b`, as printed to
/// three decimals: the generated sentences say what the numbers beside them say.
fn lower_or_higher(a: f64, b: f64) -> &'static str {
    let (a, b) = ((a * 1e3).round(), (b * 1e3).round());
    if a < b {
        "lower than"
    } else if a > b {
        "higher than"
    } else {
        "the same as"
    }
}

/// "1 sample per pixel", "4 samples per pixel".
fn samples_per_pixel(spp: u64) -> String {
    if spp == 1 {
        "1 sample per pixel".to_string()
    } else {
        format!("{spp} samples per pixel")
    }
}

/// A count of rays per camera ray, to two or three significant figures.
fn rays_number(rays: f64) -> String {
    if rays < 10.0 {
        format!("{rays:.1}")
    } else {
        format!("{rays:.0}")
    }
}

/// How many numbers a path draws on average in the agreement scenes, counted by
/// [`CountingSampler`](crate::dimensions::CountingSampler) (`dimensions.md`).
fn dimensions(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let mut table = String::from(
        "| scene | `max_depth` | numbers drawn per path, mean | most in one path |\n|---|---|---|---|\n",
    );
    for name in ["cornell-box", "point-and-sky"] {
        let file = load(&format!("{name}.xml"))?;
        let scene = &file.world;
        let size = quality.size(scene, (32, 32));
        let settings = RenderSettings::new(size.0, size.1, quality.level.pick(4, 16));
        let (_, stats) = render_counted(
            true,
            scene,
            Method::new(file.options),
            LectureMaterials::default(),
            &Lens::PINHOLE,
            &settings,
            &IndependentSampler::new(1),
            &box_filter(),
        );
        let stats = stats.expect("counted");
        table += &format!(
            "| `{name}.xml` | {} | {:.1} | {} |\n",
            file.options.max_depth, stats.mean, stats.max
        );
    }
    write_text(&out.join("dimensions.md"), &table)?;
    Ok(())
}

/// Chapter 01's Whitted tracer through the film that chapters 04 to 08 render with, as chapter
/// 03 rendered before its pixels were gathered one by one (its `render_with` now draws each
/// pixel with the student's `filtered_pixel`, a slower way to the same image): the baseline
/// the path tracer's overhead is measured against.
pub fn whitted_through_the_film(scene: &Scene, settings: &RenderSettings) -> RenderOutput {
    let camera =
        ch01_whitted::camera::PinholeCamera::of(&scene.camera, settings.width, settings.height);
    common::render::render(
        settings,
        &IndependentSampler::new(1),
        &PixelBoxFilter,
        |p_film, _| ch01_whitted::tracer::trace(scene, &camera.generate_ray(p_film), 1),
    )
}

/// What the path tracer's generality costs where it is not used: chapter 01's Cornell box
/// with matte spheres at `max_depth` 2, where chapter 03's tracer and this one trace the same
/// rays, timed alternately on one thread (`static-pinhole.md`; `benches/static_pinhole.rs`
/// measures the same with more care).
fn static_pinhole(out: &Path, quality: &Quality) -> anyhow::Result<()> {
    let side = quality.level.pick(32, 128);
    let spp = 4;
    let runs = quality.level.pick(3, 15);
    let mut scene = ch01_whitted::scenes::Builtin::Cornell.build(2);
    for surface in &mut scene.surfaces {
        if matches!(
            surface.material,
            Material::Mirror { .. } | Material::Dielectric { .. }
        ) {
            surface.material = Material::diffuse(glam::Vec3::splat(0.73));
        }
    }
    let settings = RenderSettings {
        threads: Some(1),
        ..RenderSettings::new(side, side, spp)
    };
    let world = MotionScene::still(scene.clone());
    let method = Method::new(PathOptions::with_depth(2));
    let (mut whitted, mut path) = (Vec::new(), Vec::new());
    // One untimed run of each first, so that neither pays for cold caches.
    for run in 0..=runs {
        let started = Instant::now();
        let _ = whitted_through_the_film(&scene, &settings);
        let whitted_seconds = started.elapsed().as_secs_f64();
        let started = Instant::now();
        let _ = render_with(
            &world,
            method,
            &Lens::PINHOLE,
            &settings,
            &IndependentSampler::new(1),
            &PixelBoxFilter,
        );
        let path_seconds = started.elapsed().as_secs_f64();
        if run > 0 {
            whitted.push(whitted_seconds);
            path.push(path_seconds);
        }
    }
    let fastest = |times: &[f64]| times.iter().copied().fold(f64::INFINITY, f64::min);
    let median = |times: &mut Vec<f64>| {
        times.sort_by(f64::total_cmp);
        times[times.len() / 2]
    };
    let (whitted_fastest, path_fastest) = (fastest(&whitted), fastest(&path));
    let (whitted_median, path_median) = (median(&mut whitted), median(&mut path));
    write_text(
        &out.join("static-pinhole.md"),
        &format!(
            "At {side} × {side} pixels, {spp} samples per pixel, on one thread, the fastest of \
             {runs} alternating runs took {:.1} ms with chapter 03's tracer and {:.1} ms with \
             this chapter's: {:.2} times as long (the ratio of the medians, {:.1} ms and \
             {:.1} ms: {:.2}).\n",
            whitted_fastest * 1e3,
            path_fastest * 1e3,
            path_fastest / whitted_fastest,
            whitted_median * 1e3,
            path_median * 1e3,
            path_median / whitted_median,
        ),
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comparative_words_follow_the_printed_numbers() {
        assert_eq!(lower_or_higher(0.1, 0.2), "lower than");
        assert_eq!(lower_or_higher(0.2, 0.1), "higher than");
        // Equal to three decimals, as the sentence prints them.
        assert_eq!(lower_or_higher(0.1231, 0.1229), "the same as");
    }

    #[test]
    fn sample_counts_are_spelled_for_their_number() {
        assert_eq!(samples_per_pixel(1), "1 sample per pixel");
        assert_eq!(samples_per_pixel(16), "16 samples per pixel");
    }
}
