//! `ch04-depth-of-field`: render through a thin lens, or write the chapter's figures.

use ch03_anti_aliasing::cli::AntiAliasingArgs;
use ch03_anti_aliasing::scene_file::{filter_of, sampler_of};
use ch04_depth_of_field::Aperture;
use ch04_depth_of_field::cli::LensArgs;
use ch04_depth_of_field::scene_file::lens_of;
use ch04_depth_of_field::scenes::{Builtin, DEFAULT_DEPTH};
use ch04_depth_of_field::{CAPABILITIES, figures, render_with};
use common::cli::{ChapterBinary, RenderArgs, print_note, read_scene_file};
use std::process::ExitCode;

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
    #[command(flatten)]
    lens: LensArgs,
    #[command(flatten)]
    args: RenderArgs,
}

fn main() -> ExitCode {
    let binary = ChapterBinary {
        name: "ch04-depth-of-field",
        about: env!("CARGO_PKG_DESCRIPTION"),
        render: "Render a scene through a thin lens.",
    };
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let (mut scene, scene_lens, file_filter, file_sampler, default_spp, scene_name) =
        match command.args.scene_file()? {
            Some(path) => {
                let scene = read_scene_file(path, &command.args.define, &CAPABILITIES)?;
                let unrenderable = |message| common::cli::CliError::Unrenderable {
                    file: path.to_path_buf(),
                    message,
                };
                let lens = lens_of(&scene.camera).map_err(unrenderable)?;
                let filter = filter_of(scene.film.filter).map_err(unrenderable)?;
                let (sampler, note) = sampler_of(&scene.sampler.type_name);
                if let Some(note) = note {
                    print_note(&note);
                }
                let spp = u64::from(scene.sampler.sample_count.max(1));
                (
                    scene,
                    lens,
                    Some(filter),
                    Some(sampler),
                    spp,
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
    let lens = command.lens.lens(scene_lens)?;
    if let Some(max_depth) = command.max_depth {
        scene.max_depth = max_depth;
    }
    let filter = command.anti_aliasing.filter(file_filter)?;
    let sampler_kind = command.anti_aliasing.sampler_kind(file_sampler);
    let settings = command
        .args
        .settings((scene.film.width, scene.film.height), default_spp)?;
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
    command.args.report_written(
        &rendered,
        &format!(
            ", aperture radius {}, focus at {}",
            lens.aperture_radius, lens.focus_distance
        ),
    );
    Ok(())
}
