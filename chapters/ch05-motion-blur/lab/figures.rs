//! The chapter's figures: the diagrams (`diagrams/`: the shutter's opening over time and a
//! moving sphere at stratified times); a fast and a slow object, a spinning one and a moving
//! camera; the shutter from short to long; where time samples land; error against time for
//! independent and stratified time; the streak of a shutter that opens over a while; and what
//! motion bounds cost a BVH.

use crate::scenes::{Builtin, DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER, swarm};
use crate::shutter_opening::{sample_trapezoid_opening, trapezoid_opening_pdf};
use crate::time_sampling::{StratifiedTime, TimeSampler};
use crate::world::MotionScene;
use crate::{Shutter, render_with};
use ch01_whitted::camera::PinholeCamera;
use ch03_anti_aliasing::{FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use common::image::Image;
use common::render::RenderSettings;
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2};
use std::path::Path;
use std::time::Instant;
use workbench::convergence::{
    ConvergenceRecord, Technique, plot_error_vs_spp, plot_error_vs_time, run_convergence,
    write_convergence_csv,
};
use workbench::figure_set::{FigureSet, Level, RenderQuality};
use workbench::output::figures::{
    Axes, Series, SeriesStyle, bar_chart, comparison_grid, line_plot, scatter_plot,
};
use workbench::output::write_text;

/// Image sizes and budgets: the book's, or small ones for tests and CI.
fn quality(level: Level) -> RenderQuality {
    RenderQuality {
        width: level.pick(128, 320),
        height: level.pick(80, 200),
        spp: level.pick(16, 32),
        budgets: level.pick(&[1, 4, 16], &[1, 4, 16, 64, 256]),
        reference_spp: level.pick(256, 1024),
    }
}

/// Writes every figure of the chapter into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch05", out, quick)?;
    let level = figures.level();
    let quality = quality(level);
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.make("the gallery of motions", |out| gallery(out, &quality))?;
    figures.make("the shutter series", |out| shutter_lengths(out, &quality))?;
    figures.make("the time-sample plot", time_samples)?;
    figures.make("the shutter-opening profiles", |out| {
        shutter_opening(out, level)
    })?;
    figures.make("the error-against-time figures", |out| {
        convergence(out, &quality)
    })?;
    figures.make("the motion-bounds table", |out| bvh_cost(out, level))?;
    figures.finish()
}

/// Renders `world` with stratified pixel positions and stratified time, box-filtered.
fn render(world: &MotionScene, settings: &RenderSettings, seed: u64) -> Image {
    let spp = match settings.budget {
        common::render::Budget::Samples(spp) => spp,
        common::render::Budget::Seconds(_) => 1,
    };
    let pixels =
        PixelSampler::new(PixelSamplerKind::Stratified, spp, seed).expect("a positive count");
    let sampler = StratifiedTime::new(pixels, spp, seed);
    render_with(world, &Lens::PINHOLE, settings, &sampler, &box_filter()).image
}

fn box_filter() -> ReconstructionFilter {
    ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter")
}

fn shutter(open: f32, close: f32) -> Shutter {
    Shutter::new(open, close).expect("the figures' shutters are valid")
}

/// The four kinds of motion, each against the still image.
fn gallery(out: &Path, quality: &RenderQuality) -> anyhow::Result<()> {
    let settings = quality.gallery();
    let street_still = Builtin::Street.build(DEFAULT_MAX_DEPTH, shutter(0.0, 0.0));
    let street = Builtin::Street.build(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
    let spinner = Builtin::Spinner.build(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
    let pan_still = Builtin::Pan.build(DEFAULT_MAX_DEPTH, shutter(0.0, 0.0));
    let pan = Builtin::Pan.build(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
    let spinner_settings = RenderSettings::new(quality.height, quality.height, quality.spp);
    let cells = vec![
        (
            "shutter closed: the objects at time 0".to_string(),
            render(&street_still, &settings, 0),
        ),
        (
            "shutter open [0, 1]: fast sphere, slow sphere, spinning cube".to_string(),
            render(&street, &settings, 0),
        ),
        (
            "moving camera, shutter closed".to_string(),
            render(&pan_still, &settings, 0),
        ),
        (
            "moving camera, shutter open [0, 1]".to_string(),
            render(&pan, &settings, 0),
        ),
    ];
    comparison_grid(&out.join("motions.png"), &cells, 2, 1)?;
    let spin = vec![
        (
            "a cube at rest".to_string(),
            render(
                &Builtin::Spinner.build(DEFAULT_MAX_DEPTH, shutter(0.0, 0.0)),
                &spinner_settings,
                0,
            ),
        ),
        (
            "spinning 1.25 turns while the shutter is open".to_string(),
            render(&spinner, &spinner_settings, 0),
        ),
    ];
    comparison_grid(&out.join("spinner.png"), &spin, 2, 1)?;
    Ok(())
}

/// The same motion seen through shutters from an instant to the whole motion, centred on the
/// middle of the motion.
fn shutter_lengths(out: &Path, quality: &RenderQuality) -> anyhow::Result<()> {
    let settings = quality.gallery();
    let cells: Vec<(String, Image)> = [0.0, 0.05, 0.2, 0.5, 1.0]
        .iter()
        .map(|&length: &f32| {
            let open = 0.5 - 0.5 * length;
            let world = Builtin::Street.build(DEFAULT_MAX_DEPTH, shutter(open, open + length));
            (
                format!("shutter open for {length} of the motion"),
                render(&world, &settings, 0),
            )
        })
        .collect();
    comparison_grid(&out.join("shutter_lengths.png"), &cells, 3, 1)?;
    Ok(())
}

/// The times of one pixel's samples: independent ones clump, stratified ones cover the
/// shutter one stratum each. Each set is shown twice: in the order drawn (y = sample index),
/// and sorted by time (y = rank), where even coverage is a straight diagonal.
fn time_samples(out: &Path) -> anyhow::Result<()> {
    let n = 32u64;
    let pixel = UVec2::new(7, 4);
    let draw =
        |sampler: &mut dyn FnMut(u64) -> f32| -> Vec<f32> { (0..n).map(&mut *sampler).collect() };
    let mut independent = IndependentSampler::new(3);
    let mut stratified = StratifiedTime::new(IndependentSampler::new(3), n, 3);
    let independent_times = draw(&mut |i| {
        independent.start_pixel_sample(pixel, i);
        independent.get_pixel_2d();
        independent.get_time_1d()
    });
    let stratified_times = draw(&mut |i| {
        stratified.start_pixel_sample(pixel, i);
        stratified.get_pixel_2d();
        stratified.get_time_1d()
    });
    let by_index = |times: &[f32]| -> Vec<Vec2> {
        times
            .iter()
            .enumerate()
            .map(|(i, &t)| Vec2::new(t, (i as f32 + 0.5) / n as f32))
            .collect()
    };
    let by_rank = |times: &[f32]| -> Vec<Vec2> {
        let mut sorted = times.to_vec();
        sorted.sort_by(f32::total_cmp);
        by_index(&sorted)
    };
    let sets = vec![
        (
            format!("{n} independent times"),
            by_index(&independent_times),
        ),
        (format!("{n} stratified times"), by_index(&stratified_times)),
        (
            "independent, sorted by time".to_string(),
            by_rank(&independent_times),
        ),
        (
            "stratified, sorted by time".to_string(),
            by_rank(&stratified_times),
        ),
    ];
    scatter_plot(
        &out.join("time_samples.png"),
        "One pixel's time samples (x: time in the shutter; y: sample index, or rank)",
        &sets,
        [Vec2::ZERO, Vec2::ONE],
    )?;
    Ok(())
}

/// Error against time for independent and stratified time on the street scene.
fn convergence(out: &Path, quality: &RenderQuality) -> anyhow::Result<()> {
    let (width, height) = (quality.width / 4, quality.height / 4);
    let world = Builtin::Street.build(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
    // Random pixel positions in both: the techniques differ only in how time is drawn.
    let render_time = |stratify: bool, spp: u64, seed: u64| {
        let settings = RenderSettings::new(width, height, spp);
        let pixels =
            PixelSampler::new(PixelSamplerKind::Random, spp, seed).expect("a positive count");
        if stratify {
            let sampler = StratifiedTime::new(pixels, spp, seed);
            render_with(&world, &Lens::PINHOLE, &settings, &sampler, &box_filter()).image
        } else {
            render_with(&world, &Lens::PINHOLE, &settings, &pixels, &box_filter()).image
        }
    };
    let reference = render(
        &world,
        &RenderSettings {
            progress: true,
            ..RenderSettings::new(width, height, quality.reference_spp)
        },
        1_000,
    );
    let techniques = vec![
        Technique::new("independent time", |spp| render_time(false, spp, 0)),
        Technique::new("stratified time", |spp| render_time(true, spp, 0)),
    ];
    let records = run_convergence(&techniques, quality.budgets, &reference);
    write_convergence_csv(&out.join("convergence.csv"), &records)?;
    write_text(
        &out.join("convergence.md"),
        &stratified_time_sentence(&records),
    )?;
    plot_error_vs_time(
        &out.join("convergence.png"),
        "Error against time: time sampling (street scene)",
        &records,
    )?;
    plot_error_vs_spp(
        &out.join("convergence_spp.png"),
        "Error against samples per pixel: time sampling (street scene)",
        &records,
    )?;
    Ok(())
}

/// The sentence the page shows under the error plots: at how many of the sample counts
/// stratified time has the lower error, and the two errors at the largest count.
fn stratified_time_sentence(records: &[ConvergenceRecord]) -> String {
    let of = |name: &str| -> Vec<&ConvergenceRecord> {
        records.iter().filter(|r| r.technique == name).collect()
    };
    let (independent, stratified) = (of("independent time"), of("stratified time"));
    let pairs: Vec<(&ConvergenceRecord, &ConvergenceRecord)> = independent
        .iter()
        .filter_map(|i| Some((*i, *stratified.iter().find(|s| s.spp == i.spp)?)))
        .collect();
    let lower = pairs.iter().filter(|(i, s)| s.rmse < i.rmse).count();
    let Some((last_i, last_s)) = pairs.iter().max_by_key(|(i, _)| i.spp) else {
        return "No error was measured.\n".to_string();
    };
    let share = match lower {
        n if n == pairs.len() => format!("at every one of the {} sample counts", pairs.len()),
        0 => format!("at none of the {} sample counts", pairs.len()),
        n => format!("at {n} of the {} sample counts", pairs.len()),
    };
    let word = if last_s.rmse < last_i.rmse {
        "lower"
    } else {
        "not lower"
    };
    format!(
        "In this run stratified time has the lower error {share}; at {} spp its RMSE is {:.4} \
         against {:.4} for independent time ({word}: {:.2} times the error), in {:.1} ms against \
         {:.1} ms.\n",
        last_i.spp,
        last_s.rmse,
        last_i.rmse,
        last_s.rmse / last_i.rmse,
        1e3 * last_s.seconds,
        1e3 * last_i.seconds,
    )
}

/// How long the shutter takes to open (and to close) in the trapezoid of the profile figure,
/// as a fraction of the exposure.
pub const PROFILE_RAMP: f32 = 0.25;

/// The streak a sphere leaves when the shutter opens at once (the lecture's box) and when it
/// takes a quarter of the exposure to open and a quarter to close (a trapezoid). A sphere of
/// radius 1/4 crosses from x = -1 to x = 1 while the shutter is open; along the line its centre
/// follows, a point's brightness is the share of the shutter's weight during which the sphere
/// covers it. Each share is estimated as the renderer would: times drawn by the warp from
/// stratified `u`, each counted once.
fn shutter_opening(out: &Path, level: Level) -> anyhow::Result<()> {
    let n = level.pick(256, 4096);
    let radius = 0.25f32;
    let covered_share = |x: f32, ramp: f32| -> f64 {
        let hits = (0..n)
            .filter(|&i| {
                let s = sample_trapezoid_opening((i as f32 + 0.5) / n as f32, ramp);
                let centre = -1.0 + 2.0 * s;
                (x - centre).abs() < radius
            })
            .count();
        hits as f64 / n as f64
    };
    let xs: Vec<f32> = (0..=240).map(|i| -1.5 + 3.0 * i as f32 / 240.0).collect();
    let profile = |ramp: f32| -> Vec<(f64, f64)> {
        xs.iter()
            .map(|&x| (f64::from(x), covered_share(x, ramp)))
            .collect()
    };
    let opening = |ramp: f32| -> Vec<(f64, f64)> {
        (0..=200)
            .map(|i| {
                let s = i as f32 / 200.0;
                // The weight over the exposure, drawn over the sphere's path: s = 0 at x = -1.
                (
                    f64::from(-1.0 + 2.0 * s),
                    f64::from(trapezoid_opening_pdf(s, ramp)) / 4.0,
                )
            })
            .collect()
    };
    let series = vec![
        Series::new("streak, box shutter", profile(0.0), SeriesStyle::Line),
        Series::new(
            format!("streak, trapezoid shutter (ramps of {PROFILE_RAMP})"),
            profile(PROFILE_RAMP),
            SeriesStyle::Line,
        ),
        Series::new("box opening / 4", opening(0.0), SeriesStyle::Dashed),
        Series::new(
            "trapezoid opening / 4",
            opening(PROFILE_RAMP),
            SeriesStyle::Dashed,
        ),
    ];
    line_plot(
        &out.join("shutter_opening.png"),
        "A moving sphere's streak under two shutters",
        &Axes::linear(
            "position along the path (the centre moves from -1 to 1)",
            "brightness (weighted share of the exposure covered)",
        ),
        &series,
    )?;
    Ok(())
}

/// One row of the motion-bounds table.
struct CostRow {
    stretches: usize,
    build_seconds: f64,
    rays_per_second: f64,
    tests_per_ray: f64,
}

/// Measures the BVH over moving spheres with the shutter cut into 1 (one box for the whole
/// sweep), 2, 4, ... stretches: build time, render speed and how many spheres a camera ray
/// has to intersect because their box could not rule them out.
fn bvh_cost(out: &Path, level: Level) -> anyhow::Result<()> {
    // Spheres per row of the swarm, and samples per pixel of the timing renders.
    let (swarm_rows, swarm_spp) = level.pick((10, 2), (20, 4));
    let base = swarm(swarm_rows, 4.0, DEFAULT_SHUTTER);
    let (width, height) = (base.scene.film.width, base.scene.film.height);
    let mut world = base;
    let mut rows = Vec::new();
    for stretches in [1usize, 2, 4, 8, 16, 32] {
        let start = Instant::now();
        world = world.with_shutter(DEFAULT_SHUTTER, stretches);
        let build_seconds = start.elapsed().as_secs_f64();
        let settings = RenderSettings::new(width, height, swarm_spp);
        let pixels =
            PixelSampler::new(PixelSamplerKind::Random, swarm_spp, 0).expect("a positive count");
        let rendered = render_with(
            &world,
            &Lens::PINHOLE,
            &settings,
            &StratifiedTime::new(pixels, swarm_spp, 0),
            &box_filter(),
        );
        // The camera rays again, counted: how many moving spheres each must intersect.
        let camera = PinholeCamera::of(&world.scene.camera, width, height);
        let mut tests = 0u64;
        let mut rays = 0u64;
        let mut sampler = IndependentSampler::new(1);
        for y in (0..height).step_by(2) {
            for x in (0..width).step_by(2) {
                sampler.start_pixel_sample(UVec2::new(x, y), 0);
                let p_film = UVec2::new(x, y).as_vec2() + sampler.get_pixel_2d();
                let time = DEFAULT_SHUTTER.time_at(sampler.get_1d());
                let ray = camera.generate_ray(p_film).with_time(time);
                world.moving.intersect_counting(&ray, &mut tests);
                rays += 1;
            }
        }
        rows.push(CostRow {
            stretches,
            build_seconds,
            rays_per_second: rendered.stats.rays_per_second,
            tests_per_ray: tests as f64 / rays as f64,
        });
    }
    let mut csv =
        String::from("stretches,build_seconds,rays_per_second,sphere_tests_per_camera_ray\n");
    for row in &rows {
        csv.push_str(&format!(
            "{},{},{},{}\n",
            row.stretches, row.build_seconds, row.rays_per_second, row.tests_per_ray
        ));
    }
    write_text(&out.join("bvh_cost.csv"), &csv)?;
    let mut table = String::from(
        "| stretches of the shutter | build (ms) | rays per second | spheres tested per camera ray |\n|---:|---:|---:|---:|\n",
    );
    for row in &rows {
        table.push_str(&format!(
            "| {} | {:.2} | {:.0} | {:.2} |\n",
            row.stretches,
            1e3 * row.build_seconds,
            row.rays_per_second,
            row.tests_per_ray
        ));
    }
    write_text(&out.join("bvh_cost.md"), &table)?;
    let bars = |value: fn(&CostRow) -> f64| -> Vec<(String, f64)> {
        rows.iter()
            .map(|row| (format!("{} stretch(es)", row.stretches), value(row)))
            .collect()
    };
    bar_chart(
        &out.join("bvh_tests.png"),
        &format!(
            "{} moving spheres: spheres intersected per camera ray",
            swarm_rows * swarm_rows
        ),
        "sphere tests per camera ray",
        &bars(|row| row.tests_per_ray),
        false,
    )?;
    bar_chart(
        &out.join("bvh_speed.png"),
        "Render speed against stretches of the shutter",
        "rays per second",
        &bars(|row| row.rays_per_second),
        false,
    )?;
    let swarm_settings = RenderSettings::new(width, height, swarm_spp.max(8));
    comparison_grid(
        &out.join("swarm.png"),
        &[(
            "the motion-bounds scene".to_string(),
            render(&world, &swarm_settings, 0),
        )],
        1,
        1,
    )?;
    Ok(())
}
