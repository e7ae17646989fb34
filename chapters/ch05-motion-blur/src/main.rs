//! `ch05-motion-blur`: render a scene in motion through an open shutter, or write the
//! chapter's figures.

use ch03_anti_aliasing::cli::AntiAliasingArgs;
use ch04_depth_of_field::Lens;
use ch04_depth_of_field::cli::LensArgs;
use ch05_motion_blur::scene_file::{motion_for_render, read_with_camera_side};
use ch05_motion_blur::scenes::{Builtin, DEFAULT_DEPTH, DEFAULT_SHUTTER};
use ch05_motion_blur::world::DEFAULT_STRETCHES;
use ch05_motion_blur::{CAPABILITIES, Shutter, StratifiedTime, TimeSampling, figures, render_with};
use common::cli::{ChapterBinary, CliError, RenderArgs};
use common::render::Budget;
use std::process::ExitCode;

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Street, conflicts_with = "scene")]
    builtin: Builtin,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    /// Longest path in segments, counting the camera ray (Mitsuba's max_depth)
    /// [default: the scene file's, or 12].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    max_depth: Option<u32>,
    /// When the shutter opens [default: the scene file's shutter_open, or 0].
    #[arg(long, value_name = "T0", allow_hyphen_values = true, value_parser = parse_number)]
    shutter_open: Option<f32>,
    /// When the shutter closes; equal to --shutter-open for no blur
    /// [default: the scene file's shutter_close, or 1].
    #[arg(long, value_name = "T1", allow_hyphen_values = true, value_parser = parse_number)]
    shutter_close: Option<f32>,
    /// How the times of a pixel's samples are drawn.
    #[arg(long, value_enum, default_value_t = TimeSampling::Stratified)]
    time_sampling: TimeSampling,
    #[command(flatten)]
    lens: LensArgs,
    /// Into how many stretches of the shutter the moving objects' bounds are cut, one BVH each.
    #[arg(long, value_name = "K", default_value_t = DEFAULT_STRETCHES as u32,
          value_parser = clap::value_parser!(u32).range(1..=1024))]
    stretches: u32,
    #[command(flatten)]
    args: RenderArgs,
}

/// Any number, including NaN and infinities: each option's own rule is checked where it is
/// used, with the reason.
fn parse_number(text: &str) -> Result<f32, String> {
    text.trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number"))
}

fn main() -> ExitCode {
    let binary = ChapterBinary {
        name: "ch05-motion-blur",
        about: env!("CARGO_PKG_DESCRIPTION"),
        render: "Render a scene in motion over the shutter interval.",
    };
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let (world, scene_lens, file_filter, file_sampler, default_spp, scene_name) =
        match command.args.scene_file()? {
            Some(path) => {
                let (scene, side) =
                    read_with_camera_side(path, &command.args.define, &CAPABILITIES)?;
                let world = motion_for_render(scene).map_err(|message| CliError::Unrenderable {
                    file: path.to_path_buf(),
                    message,
                })?;
                (
                    world,
                    side.lens,
                    Some(side.filter),
                    Some(side.sampler),
                    side.spp,
                    path.display().to_string(),
                )
            }
            None => (
                command.builtin.build(DEFAULT_DEPTH, DEFAULT_SHUTTER),
                Lens::PINHOLE,
                None,
                None,
                16,
                command.builtin.name().to_string(),
            ),
        };
    let shutter = Shutter::new(
        command.shutter_open.unwrap_or(world.shutter.open),
        command.shutter_close.unwrap_or(world.shutter.close),
    )
    .map_err(|e| anyhow::anyhow!("--shutter-open and --shutter-close: {e}"))?;
    let lens = command.lens.lens_or_pinhole(scene_lens)?;
    let mut world = world.with_shutter(shutter, command.stretches as usize);
    if let Some(max_depth) = command.max_depth {
        world.scene.max_depth = max_depth;
    }
    let filter = command.anti_aliasing.filter(file_filter)?;
    let sampler_kind = command.anti_aliasing.sampler_kind(file_sampler);
    let film = world.scene.film;
    let settings = command
        .args
        .settings((film.width, film.height), default_spp)?;
    let pixel_sampler =
        command
            .anti_aliasing
            .pixel_sampler(sampler_kind, &settings.budget, command.args.seed)?;
    let rendered = match (command.time_sampling, settings.budget) {
        (TimeSampling::Independent, _) => {
            command.args.check_outputs()?;
            render_with(&world, &lens, &settings, &pixel_sampler, &filter)
        }
        (TimeSampling::Stratified, Budget::Samples(spp)) => {
            command.args.check_outputs()?;
            let sampler = StratifiedTime::new(pixel_sampler, spp, command.args.seed);
            render_with(&world, &lens, &settings, &sampler, &filter)
        }
        (TimeSampling::Stratified, Budget::Seconds(_)) => anyhow::bail!(
            "--time-sampling stratified cuts the shutter into one stratum per sample, so it needs --spp, not --time (use --time-sampling independent with --time)"
        ),
    };
    let extra = serde_json::json!({
        "scene": scene_name,
        "max_depth": world.scene.max_depth,
        "sampler": sampler_kind.name(),
        "filter": filter.kind().name(),
        "filter_radius": filter.half_width(),
        "aperture_radius": lens.aperture_radius,
        "focus_distance": lens.focus_distance,
        "shutter_open": shutter.open,
        "shutter_close": shutter.close,
        "time_sampling": command.time_sampling.name(),
        "stretches": world.moving.stretches(),
        "seed": command.args.seed,
    });
    command.args.write_outputs(&rendered, extra)?;
    command.args.report_written(
        &rendered,
        &format!(", shutter [{}, {}]", shutter.open, shutter.close),
    );
    Ok(())
}
