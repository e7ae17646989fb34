//! `ch04-depth-of-field`: render through a thin lens, or write the chapter's figures.

use ch03_anti_aliasing::cli::AntiAliasingArgs;
use ch04_depth_of_field::aperture::{Aperture, LensWarp};
use ch04_depth_of_field::lens::Lens;
use ch04_depth_of_field::scene_file::convert;
use ch04_depth_of_field::scenes::{Builtin, DEFAULT_DEPTH};
use ch04_depth_of_field::{figures, render_with};
use clap::{Parser, Subcommand};
use common::cli::{FiguresArgs, RenderArgs, report_error};
use common::scene::load_scene_file;
use std::process::ExitCode;

/// Chapter 04 of the workbook: depth of field.
#[derive(Parser, Debug)]
#[command(name = "ch04-depth-of-field", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Render a scene through a thin lens.
    Render(RenderCommand),
    /// Write the chapter's comparison images, plots and error-against-time data.
    Figures(FiguresArgs),
}

/// The shapes `--aperture` accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum ApertureShape {
    /// A round hole.
    Disc,
    /// A regular polygon, one corner per diaphragm blade (see --blades).
    Polygon,
}

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Bokeh, conflicts_with = "scene")]
    builtin: Builtin,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    /// Longest path in segments, counting the camera ray (Mitsuba's max_depth)
    /// [default: the scene file's, or 12].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    max_depth: Option<u32>,
    /// Radius of the lens aperture in scene units; 0 is a pinhole
    /// [default: the scene file's, or the built-in scene's].
    #[arg(long, value_name = "R", allow_negative_numbers = true, value_parser = parse_number,
          conflicts_with = "f_number")]
    aperture_radius: Option<f32>,
    /// The f-number N: the aperture's diameter is the focal length over N (needs --focal-length).
    #[arg(long, value_name = "N", allow_negative_numbers = true, value_parser = parse_number,
          requires = "focal_length")]
    f_number: Option<f32>,
    /// Focal length in scene units, for --f-number (the field of view stays the scene's).
    #[arg(long, value_name = "F", allow_negative_numbers = true, value_parser = parse_number,
          requires = "f_number")]
    focal_length: Option<f32>,
    /// Distance of the plane in focus along the viewing axis, in scene units
    /// [default: the scene file's, or the built-in scene's].
    #[arg(long, value_name = "D", allow_negative_numbers = true, value_parser = parse_number)]
    focus_distance: Option<f32>,
    /// Shape of the aperture [default: disc, or polygon when --blades is given].
    #[arg(long, value_enum)]
    aperture: Option<ApertureShape>,
    /// Blades of a polygonal aperture: its number of corners, 3 to 64 [default: 6].
    #[arg(long, allow_negative_numbers = true, value_parser = parse_blades)]
    blades: Option<u32>,
    /// Rotation of a polygonal aperture in degrees.
    #[arg(long, value_name = "DEGREES", allow_negative_numbers = true, value_parser = parse_number)]
    aperture_rotation: Option<f32>,
    /// How a point of a disc aperture is drawn; `naive` is the wrong one, for comparison.
    #[arg(long, value_enum)]
    lens_warp: Option<LensWarp>,
    #[command(flatten)]
    args: RenderArgs,
}

/// Any number; each option's own rule is checked where the lens is built, with the reason.
fn parse_number(text: &str) -> Result<f32, String> {
    text.trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a number"))
}

fn parse_blades(text: &str) -> Result<u32, String> {
    let blades: i64 = text
        .trim()
        .parse()
        .map_err(|_| format!("`{text}` is not a whole number of blades"))?;
    let max = ch04_depth_of_field::aperture::MAX_BLADES;
    if (3..=i64::from(max)).contains(&blades) {
        Ok(blades as u32)
    } else {
        Err(format!(
            "an aperture polygon needs between 3 and {max} blades, not {blades}"
        ))
    }
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

/// The lens the command line asks for, starting from the scene's own.
fn lens_of(command: &RenderCommand, scene_lens: Lens) -> anyhow::Result<Lens> {
    let radius = match (
        command.aperture_radius,
        command.f_number,
        command.focal_length,
    ) {
        (Some(radius), _, _) => {
            Lens::new(radius, 1.0).map_err(|e| anyhow::anyhow!("--aperture-radius: {e}"))?;
            radius
        }
        (None, Some(n), Some(f)) => {
            Lens::from_f_number(f, n, 1.0)
                .map_err(|e| anyhow::anyhow!("--f-number and --focal-length: {e}"))?
                .aperture_radius
        }
        _ => scene_lens.aperture_radius,
    };
    let focus = command.focus_distance.unwrap_or(scene_lens.focus_distance);
    let mut lens =
        Lens::new(radius, focus).map_err(|e| anyhow::anyhow!("--focus-distance: {e}"))?;
    let shape = command.aperture.unwrap_or(if command.blades.is_some() {
        ApertureShape::Polygon
    } else {
        ApertureShape::Disc
    });
    match shape {
        ApertureShape::Disc => {
            if command.blades.is_some() || command.aperture_rotation.is_some() {
                anyhow::bail!(
                    "--blades and --aperture-rotation shape a polygonal aperture; they need --aperture polygon, not disc"
                );
            }
            lens = lens.with_aperture(Aperture::Disc);
        }
        ApertureShape::Polygon => {
            if command.lens_warp.is_some() {
                anyhow::bail!(
                    "--lens-warp chooses how a disc is sampled; a polygonal aperture is always sampled uniformly by its triangles"
                );
            }
            let degrees = command.aperture_rotation.unwrap_or(0.0);
            let aperture = Aperture::polygon(command.blades.unwrap_or(6), degrees.to_radians())
                .map_err(|e| anyhow::anyhow!("--aperture-rotation: {e}"))?;
            lens = lens.with_aperture(aperture);
        }
    }
    if let Some(warp) = command.lens_warp {
        lens = lens.with_warp(warp);
    }
    Ok(lens)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    if command.args.scene.is_none() && !command.args.define.is_empty() {
        anyhow::bail!("-D sets a parameter of a scene file; it needs --scene FILE.xml");
    }
    let (mut scene, scene_lens, file_filter, file_sampler, default_spp, scene_name) =
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
                command.builtin.build(DEFAULT_DEPTH),
                command.builtin.default_lens(),
                None,
                None,
                16,
                command.builtin.name().to_string(),
            ),
        };
    let lens = lens_of(&command, scene_lens)?;
    if let Some(max_depth) = command.max_depth {
        scene.max_depth = max_depth;
    }
    let filter = command.anti_aliasing.filter(file_filter)?;
    let sampler_kind = command.anti_aliasing.sampler_kind(file_sampler);
    let settings = command
        .args
        .settings((scene.camera.width, scene.camera.height), default_spp)?;
    let sampler =
        command
            .anti_aliasing
            .pixel_sampler(sampler_kind, &settings.budget, command.args.seed)?;
    command.args.check_outputs()?;
    let rendered = render_with(&scene, &lens, &settings, &sampler, &filter);
    let aperture = match lens.aperture {
        Aperture::Disc => serde_json::json!("disc"),
        Aperture::Polygon { blades, rotation } => serde_json::json!({
            "polygon": { "blades": blades, "rotation_degrees": rotation.to_degrees() }
        }),
    };
    let extra = serde_json::json!({
        "scene": scene_name,
        "max_depth": scene.max_depth,
        "sampler": sampler_kind.name(),
        "filter": filter.kind().name(),
        "filter_radius": filter.half_width(),
        "aperture_radius": lens.aperture_radius,
        "focus_distance": lens.focus_distance,
        "aperture": aperture,
        "lens_warp": lens.warp.name(),
        "seed": command.args.seed,
    });
    command.args.write_outputs(&rendered, extra)?;
    eprintln!(
        "wrote {} ({}x{}, {} spp, aperture radius {}, focus at {}, {:.2} s, {:.0} rays/s)",
        command.args.out.display(),
        rendered.stats.width,
        rendered.stats.height,
        rendered.stats.spp,
        lens.aperture_radius,
        lens.focus_distance,
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
