//! `ch03-anti-aliasing`: render with a choice of pixel sampler and filter, or write the
//! chapter's figures.

use ch03_anti_aliasing::scene_file::convert;
use ch03_anti_aliasing::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch03_anti_aliasing::{
    FilterKind, PixelSampler, PixelSamplerKind, ReconstructionFilter, figures, render_with,
};
use clap::{Parser, Subcommand};
use common::cli::{FiguresArgs, RenderArgs, report_error};
use common::render::Budget;
use common::scene::load_scene_file;
use std::process::ExitCode;

/// Chapter 03 of the workbook: anti-aliasing.
#[derive(Parser, Debug)]
#[command(name = "ch03-anti-aliasing", version, about)]
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
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Edges, conflicts_with = "scene")]
    builtin: Builtin,
    /// Where the samples of a pixel go.
    #[arg(long, value_enum, default_value_t = PixelSamplerKind::Stratified)]
    sampler: PixelSamplerKind,
    /// How samples are weighted into pixels [default: the scene file's rfilter, or box].
    #[arg(long, value_enum)]
    filter: Option<FilterKind>,
    /// Half-width of the filter in pixels, in (0, 16] [default: the filter's own; for the
    /// Gaussian, four standard deviations].
    #[arg(long, value_name = "PIXELS", value_parser = parse_radius, allow_hyphen_values = true)]
    filter_radius: Option<f32>,
    /// Longest path in segments, counting the camera ray (Mitsuba's max_depth)
    /// [default: the scene file's, or 4].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    max_depth: Option<u32>,
    #[command(flatten)]
    args: RenderArgs,
}

fn parse_radius(text: &str) -> Result<f32, String> {
    let radius: f32 = text
        .parse()
        .map_err(|_| format!("`{text}` is not a number of pixels"))?;
    ch03_anti_aliasing::filters::check_radius(radius)?;
    Ok(radius)
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
    if command.args.scene.is_none() && !command.args.define.is_empty() {
        anyhow::bail!("-D sets a parameter of a scene file; it needs --scene FILE.xml");
    }
    let (mut scene, file_filter, default_spp, scene_name) = match &command.args.scene {
        Some(path) => {
            let loaded = load_scene_file(path, &command.args.define)?;
            for warning in &loaded.warnings {
                eprintln!("{warning}");
            }
            let converted =
                convert(&loaded.scene).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
            for note in &converted.notes {
                eprintln!("note: {note}");
            }
            (
                converted.scene,
                Some(converted.filter),
                converted.spp,
                path.display().to_string(),
            )
        }
        None => (
            command.builtin.build(DEFAULT_MAX_DEPTH),
            None,
            16,
            command.builtin.name().to_string(),
        ),
    };
    if let Some(max_depth) = command.max_depth {
        scene.max_depth = max_depth;
    }
    let filter = match (command.filter, file_filter) {
        (Some(kind), _) => ReconstructionFilter::new(kind, command.filter_radius),
        (None, Some(from_file)) => match command.filter_radius {
            Some(radius) => ReconstructionFilter::new(from_file.kind(), Some(radius)),
            None => Ok(from_file),
        },
        (None, None) => ReconstructionFilter::new(FilterKind::Box, command.filter_radius),
    }
    .map_err(|e| anyhow::anyhow!("--filter-radius: {e}"))?;
    let settings = command
        .args
        .settings((scene.camera.width, scene.camera.height), default_spp)?;
    let spp = match settings.budget {
        Budget::Samples(spp) => spp,
        Budget::Seconds(_) if command.sampler == PixelSamplerKind::Stratified => {
            anyhow::bail!(
                "--sampler stratified lays out a fixed number of strata, so it needs --spp, not --time (random and halton work with --time)"
            )
        }
        // The other samplers do not need to know the count in advance.
        Budget::Seconds(_) => 1,
    };
    let sampler = PixelSampler::new(command.sampler, spp, command.args.seed)
        .map_err(|e| anyhow::anyhow!("--sampler {}: {e}", command.sampler.name()))?;
    command.args.check_outputs()?;
    let rendered = render_with(&scene, &settings, &sampler, &filter);
    let extra = serde_json::json!({
        "scene": scene_name,
        "max_depth": scene.max_depth,
        "sampler": command.sampler.name(),
        "filter": filter.kind().name(),
        "filter_radius": filter.half_width(),
        "seed": command.args.seed,
    });
    command.args.write_outputs(&rendered, extra)?;
    eprintln!(
        "wrote {} ({}x{}, {} spp, {} sampler, {} filter, {:.2} s, {:.0} rays/s)",
        command.args.out.display(),
        rendered.stats.width,
        rendered.stats.height,
        rendered.stats.spp,
        command.sampler.name(),
        filter.kind().name(),
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
