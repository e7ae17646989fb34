//! `ch03-anti-aliasing`: render with a choice of pixel sampler and filter, or write the
//! chapter's figures.

use ch03_anti_aliasing::cli::AntiAliasingArgs;
use ch03_anti_aliasing::scene_file::{filter_of, sampler_of};
use ch03_anti_aliasing::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch03_anti_aliasing::{CAPABILITIES, figures, render_with};
use common::cli::{ChapterBinary, RenderArgs, print_note, read_scene_file};
use std::process::ExitCode;

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Edges, conflicts_with = "scene")]
    builtin: Builtin,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    /// Longest path in segments, counting the camera ray (Mitsuba's max_depth)
    /// [default: the scene file's, or 4].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    max_depth: Option<u32>,
    #[command(flatten)]
    args: RenderArgs,
}

fn main() -> ExitCode {
    let binary = ChapterBinary {
        name: "ch03-anti-aliasing",
        about: env!("CARGO_PKG_DESCRIPTION"),
        render: "Render a scene to an image.",
    };
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let (mut scene, file_filter, file_sampler, default_spp, scene_name) =
        match command.args.scene_file()? {
            Some(path) => {
                let scene = read_scene_file(path, &command.args.define, &CAPABILITIES)?;
                let filter = filter_of(scene.film.filter).map_err(|message| {
                    common::cli::CliError::Unrenderable {
                        file: path.to_path_buf(),
                        message,
                    }
                })?;
                let (sampler, note) = sampler_of(&scene.sampler.type_name);
                if let Some(note) = note {
                    print_note(&note);
                }
                let spp = u64::from(scene.sampler.sample_count.max(1));
                (
                    scene,
                    Some(filter),
                    Some(sampler),
                    spp,
                    path.display().to_string(),
                )
            }
            None => (
                command.builtin.build(DEFAULT_MAX_DEPTH),
                None,
                None,
                16,
                command.builtin.name().to_string(),
            ),
        };
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
    let rendered = render_with(&scene, &settings, &sampler, &filter);
    let extra = serde_json::json!({
        "scene": scene_name,
        "max_depth": scene.max_depth,
        "sampler": sampler_kind.name(),
        "filter": filter.kind().name(),
        "filter_radius": filter.half_width(),
        "seed": command.args.seed,
    });
    command.args.write_outputs(&rendered, extra)?;
    command.args.report_written(
        &rendered,
        &format!(
            ", {} sampler, {} filter",
            sampler_kind.name(),
            filter.kind().name()
        ),
    );
    Ok(())
}
