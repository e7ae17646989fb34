//! `ch05-motion-blur`: render a scene in motion through an open shutter, or write the
//! chapter's figures.

use ch05_motion_blur::MotionScene;
use ch05_motion_blur::lab::CAPABILITIES;
use ch05_motion_blur::lab::figures;
use ch05_motion_blur::lab::render_setup::CameraArgs;
use ch05_motion_blur::scenes::{Builtin, DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER};
use ch05_motion_blur::world::DEFAULT_STRETCHES;
use ch05_motion_blur::{Shutter, TimeSampling, render_with};
use std::process::ExitCode;
use workbench::cli::parse_number;

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Street, conflicts_with = "scene")]
    builtin: Builtin,
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
    /// Into how many stretches of the shutter the moving objects' bounds are cut, one BVH each.
    #[arg(long, value_name = "K", default_value_t = DEFAULT_STRETCHES as u32,
          value_parser = clap::value_parser!(u32).range(1..=1024))]
    stretches: u32,
    #[command(flatten)]
    camera: CameraArgs,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene in motion over the shutter interval.");
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let builtin = || {
        let scene = command.builtin.scene(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
        Ok((scene, command.builtin.name().to_string()))
    };
    let adjust_world = |world: MotionScene| {
        let shutter = Shutter::new(
            command.shutter_open.unwrap_or(world.shutter.open),
            command.shutter_close.unwrap_or(world.shutter.close),
        )
        .map_err(|e| anyhow::anyhow!("--shutter-open and --shutter-close: {e}"))?;
        Ok(world.with_shutter(shutter, command.stretches as usize))
    };
    let setup = command
        .camera
        .setup(&CAPABILITIES, builtin, Ok, adjust_world)?;
    let time_sampling = command.time_sampling;
    let sampler = setup
        .sampler(time_sampling)
        .map_err(|e| anyhow::anyhow!("--time-sampling {}: {e}", time_sampling.name()))?;
    let args = &command.camera.args;
    args.check_outputs()?;
    let world = &setup.world;
    let rendered = render_with(
        world,
        &setup.lens,
        &setup.film.settings,
        &sampler,
        &setup.film.filter,
    );
    let mut extra = setup.stats();
    extra["time_sampling"] = command.time_sampling.name().into();
    extra["stretches"] = world.moving.stretches().into();
    args.write_outputs(&rendered, extra)?;
    args.report_written(
        &rendered,
        &format!(
            ", shutter [{}, {}]",
            world.shutter.open, world.shutter.close
        ),
    );
    Ok(())
}
