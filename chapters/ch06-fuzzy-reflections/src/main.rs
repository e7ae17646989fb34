//! `ch06-fuzzy-reflections`: render a scene with rough mirrors and frosted glass, or write the
//! chapter's figures.

use ch03_anti_aliasing::cli::AntiAliasingArgs;
use ch04_depth_of_field::Lens;
use ch04_depth_of_field::cli::LensArgs;
use ch05_motion_blur::{Shutter, StratifiedTime, TimeSampling};
use ch06_fuzzy_reflections::material::check_exponent;
use ch06_fuzzy_reflections::scene_file::convert;
use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_DEPTH};
use ch06_fuzzy_reflections::{
    BelowSurface, FuzzMethod, GlassStrategy, PointLights, TraceOptions, figures, render_with,
};
use clap::{Parser, Subcommand};
use common::cli::{FiguresArgs, RenderArgs, report_error};
use common::render::Budget;
use common::scene::load_scene_file;
use std::process::ExitCode;

/// Chapter 06 of the workbook: fuzzy reflections and refractions.
#[derive(Parser, Debug)]
#[command(name = "ch06-fuzzy-reflections", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Render a scene with glossy and frosted surfaces.
    Render(Box<RenderCommand>),
    /// Write the chapter's comparison images, plots, tables and error-against-time data.
    Figures(FiguresArgs),
}

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Floor, conflicts_with = "scene")]
    builtin: Builtin,
    /// The exponent n of every cos^n lobe: 0 is a hemisphere, 1e6 almost a mirror
    /// [default: the scene's].
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = parse_number)]
    exponent: Option<f32>,
    /// Which ray to trace at glass: both, one with probability 1/2, or one by the Fresnel term.
    #[arg(long, value_enum, default_value_t = GlassStrategy::Fresnel)]
    glass: GlassStrategy,
    /// How fuzzy surfaces spread their rays: the cos^n lobe, or the empirical disc.
    #[arg(long, value_enum, default_value_t = FuzzMethod::Lobe)]
    fuzz: FuzzMethod,
    /// What to do with a spread ray that points below the surface.
    #[arg(long, value_enum, default_value_t = BelowSurface::Drop)]
    below_surface: BelowSurface,
    /// Longest path in segments, counting the camera ray (Mitsuba's max_depth)
    /// [default: the scene file's, or 12].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    max_depth: Option<u32>,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    lens: LensArgs,
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
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(command) => run_render(*command),
        Command::Figures(args) => figures::write_all(&args.out, args.quick),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => report_error(error.as_ref()),
    }
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    if command.args.scene.is_none() && !command.args.define.is_empty() {
        anyhow::bail!("-D sets a parameter of a scene file; it needs --scene FILE.xml");
    }
    let exponent = command
        .exponent
        .map(check_exponent)
        .transpose()
        .map_err(|e| anyhow::anyhow!("--exponent: {e}"))?;
    let (scene, scene_lens, file_filter, file_sampler, default_spp, scene_name) =
        match &command.args.scene {
            Some(path) => {
                let loaded = load_scene_file(path, &command.args.define)?;
                for warning in &loaded.warnings {
                    eprintln!("{warning}");
                }
                let converted = convert(&loaded.scene)
                    .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
                for note in &converted.notes {
                    eprintln!("note: {note}");
                }
                (
                    converted.scene,
                    converted.lens,
                    Some(converted.filter),
                    Some(converted.sampler),
                    converted.spp,
                    path.display().to_string(),
                )
            }
            None => (
                // Built with its own exponent; --exponent replaces it below, as in a file.
                command
                    .builtin
                    .build(DEFAULT_DEPTH, command.builtin.default_exponent()),
                Lens::PINHOLE,
                None,
                None,
                16,
                command.builtin.name().to_string(),
            ),
        };
    let mut scene = match exponent {
        Some(exponent) => scene.with_exponent(exponent),
        None => scene,
    };
    if let Some(max_depth) = command.max_depth {
        scene.world.scene.max_depth = max_depth;
    }
    // A pinhole scene given an aperture on the command line focuses 5 units away unless told.
    let scene_lens = if scene_lens.is_pinhole() {
        Lens {
            focus_distance: 5.0,
            ..scene_lens
        }
    } else {
        scene_lens
    };
    let lens = command.lens.lens(scene_lens)?;
    let filter = command.anti_aliasing.filter(file_filter)?;
    let sampler_kind = command.anti_aliasing.sampler_kind(file_sampler);
    let camera = scene.world.scene.camera;
    let settings = command
        .args
        .settings((camera.width, camera.height), default_spp)?;
    let pixel_sampler =
        command
            .anti_aliasing
            .pixel_sampler(sampler_kind, &settings.budget, command.args.seed)?;
    command.args.check_outputs()?;
    let options = TraceOptions {
        glass: command.glass,
        fuzz: command.fuzz,
        below: command.below_surface,
    };
    // Stratified time when something moves and the budget is a sample count (chapter 05's
    // default); without motion no time is drawn and the choice changes nothing.
    let shutter: Shutter = scene.world.shutter;
    let rendered = match settings.budget {
        Budget::Samples(spp) if scene.world.moves() => {
            let sampler = StratifiedTime::new(pixel_sampler, spp, command.args.seed);
            render_with(
                &scene,
                &PointLights,
                options,
                &lens,
                &settings,
                &sampler,
                &filter,
            )
        }
        _ => render_with(
            &scene,
            &PointLights,
            options,
            &lens,
            &settings,
            &pixel_sampler,
            &filter,
        ),
    };
    let time_sampling = if scene.world.moves() && matches!(settings.budget, Budget::Samples(_)) {
        TimeSampling::Stratified
    } else {
        TimeSampling::Independent
    };
    let extra = serde_json::json!({
        "scene": scene_name,
        "max_depth": scene.world.scene.max_depth,
        "sampler": sampler_kind.name(),
        "filter": filter.kind().name(),
        "filter_radius": filter.half_width(),
        "aperture_radius": lens.aperture_radius,
        "focus_distance": lens.focus_distance,
        "shutter_open": shutter.open,
        "shutter_close": shutter.close,
        "time_sampling": time_sampling.name(),
        "glass": command.glass.name(),
        "fuzz": command.fuzz.name(),
        "below_surface": command.below_surface.name(),
        "exponent": exponent,
        "seed": command.args.seed,
    });
    command.args.write_outputs(&rendered, extra)?;
    eprintln!(
        "wrote {} ({}x{}, {} spp, glass {}, {:.2} s, {:.0} rays/s)",
        command.args.out.display(),
        rendered.stats.width,
        rendered.stats.height,
        rendered.stats.spp,
        command.glass.name(),
        rendered.stats.seconds,
        rendered.stats.rays_per_second
    );
    if rendered.stats.nonfinite_samples > 0 {
        eprintln!(
            "warning: {} samples were not finite and were left out",
            rendered.stats.nonfinite_samples
        );
    }
    Ok(())
}
