//! `ch01-whitted`: render the chapter's scenes, or write its figures.

use ch01_whitted::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch01_whitted::{PixelPattern, figures, render};
use clap::{Parser, Subcommand};
use common::cli::{FiguresArgs, RenderArgs, report_error};
use std::process::ExitCode;

/// Chapter 01 of the workbook: Whitted ray tracing.
#[derive(Parser, Debug)]
#[command(name = "ch01-whitted", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Render a scene to an image.
    Render(RenderCommand),
    /// Write the chapter's comparison images, plots and error-against-time data.
    Figures(FiguresArgs),
}

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render.
    #[arg(long, value_enum, default_value_t = Builtin::Spheres)]
    builtin: Builtin,
    /// Longest path in segments, counting the camera ray (Mitsuba's max_depth): 1 shows only
    /// the background, 2 adds direct light, each step more one more mirror or glass bounce.
    #[arg(long, default_value_t = DEFAULT_MAX_DEPTH, value_parser = clap::value_parser!(u32).range(1..=1000))]
    max_depth: u32,
    /// Where the samples of a pixel go. Whitted's tracer is deterministic: several samples at
    /// the centre give the same image as one; `grid` supersamples (with a square --spp).
    #[arg(long, value_enum, default_value_t = PixelPattern::Centre)]
    pixel: PixelPattern,
    #[command(flatten)]
    args: RenderArgs,
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(command) => run_render(command),
        Command::Figures(args) => figures::write_all(&args.out, args.quick),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => report_error(error.as_ref()),
    }
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let scene = command.builtin.build(command.max_depth);
    let settings = command
        .args
        .settings((scene.camera.width, scene.camera.height), 1)?;
    if command.pixel == PixelPattern::Grid && command.args.time.is_some() {
        anyhow::bail!(
            "--pixel grid needs a fixed --spp (a square such as 4, 16 or 64), not --time"
        );
    }
    command.args.check_outputs()?;
    let Some(rendered) = render(&scene, &settings, command.pixel, command.args.seed) else {
        anyhow::bail!(
            "--pixel grid places the samples of a pixel on a k x k grid, so --spp must be a square (1, 4, 9, 16, ...)"
        );
    };
    let extra = serde_json::json!({
        "scene": command.builtin.name(),
        "max_depth": command.max_depth,
        "pixel": format!("{:?}", command.pixel).to_lowercase(),
        "seed": command.args.seed,
    });
    command.args.write_outputs(&rendered, extra)?;
    eprintln!(
        "wrote {} ({}x{}, {} spp, {:.2} s, {:.0} rays/s)",
        command.args.out.display(),
        rendered.stats.width,
        rendered.stats.height,
        rendered.stats.spp,
        rendered.stats.seconds,
        rendered.stats.rays_per_second
    );
    Ok(())
}
