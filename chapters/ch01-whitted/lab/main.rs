//! `ch01-whitted`: render the chapter's scenes, or write its figures.

use ch01_whitted::lab::CAPABILITIES;
use ch01_whitted::lab::figures;
use ch01_whitted::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch01_whitted::{PixelPattern, render};
use common::render::Budget;
use std::process::ExitCode;
use workbench::cli::{RenderArgs, read_scene_file};

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Spheres, conflicts_with = "scene")]
    builtin: Builtin,
    /// Where the samples of a pixel go. Whitted's tracer is deterministic: several samples at
    /// the centre give the same image as one; `grid` supersamples (with a square --spp).
    /// [default: centre; for a scene file asking for a square number of samples, grid]
    #[arg(long, value_enum)]
    pixel: Option<PixelPattern>,
    #[command(flatten)]
    args: RenderArgs,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene to an image.");
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let args = &command.args;
    let (scene, file_spp, scene_name) = args.scene_or_builtin(
        |path| {
            let scene = read_scene_file(path, &args.define, &CAPABILITIES)?;
            let spp = u64::from(scene.sampler.sample_count.max(1));
            Ok((scene, spp))
        },
        || {
            let name = command.builtin.name().to_string();
            Ok((command.builtin.build(DEFAULT_MAX_DEPTH), name))
        },
    )?;
    let default_spp = file_spp.unwrap_or(1);
    let scene = args.with_max_depth(scene);
    let settings = args.settings((scene.film.width, scene.film.height), default_spp)?;
    let pixel = command.pixel.unwrap_or_else(|| {
        // A scene file that asks for several samples per pixel expects them spread over the
        // pixel, as Mitsuba spreads them; Whitted's own choice is the centre.
        let square = |n: u64| (n as f64).sqrt().round().powi(2) as u64 == n;
        match settings.budget {
            Budget::Samples(spp) if args.scene.is_some() && spp > 1 && square(spp) => {
                PixelPattern::Grid
            }
            _ => PixelPattern::Centre,
        }
    });
    if pixel == PixelPattern::Grid && args.time.is_some() {
        anyhow::bail!(
            "--pixel grid needs a fixed --spp (a square such as 4, 16 or 64), not --time"
        );
    }
    args.check_outputs()?;
    let Some(rendered) = render(&scene, &settings, pixel, args.seed) else {
        anyhow::bail!(
            "--pixel grid places the samples of a pixel on a k x k grid, so --spp must be a square (1, 4, 9, 16, ...)"
        );
    };
    let extra = serde_json::json!({
        "scene": scene_name,
        "max_depth": scene.max_depth,
        "pixel": format!("{pixel:?}").to_lowercase(),
        "seed": args.seed,
    });
    args.write_outputs(&rendered, extra)?;
    args.report_written(&rendered, "");
    Ok(())
}
