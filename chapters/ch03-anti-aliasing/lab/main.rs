//! `ch03-anti-aliasing`: render with a choice of pixel sampler and filter, or write the
//! chapter's figures.

use ch03_anti_aliasing::lab::CAPABILITIES;
use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch03_anti_aliasing::lab::figures;
use ch03_anti_aliasing::lab::scene_file::read_with_film_side;
use ch03_anti_aliasing::render_with;
use ch03_anti_aliasing::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use std::process::ExitCode;
use workbench::cli::RenderArgs;

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Edges, conflicts_with = "scene")]
    builtin: Builtin,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    args: RenderArgs,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene to an image.");
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let (scene, film, scene_name) = command.args.scene_or_builtin(
        |path| {
            Ok(read_with_film_side(
                path,
                &command.args.define,
                &CAPABILITIES,
            )?)
        },
        || {
            let name = command.builtin.name().to_string();
            Ok((command.builtin.build(DEFAULT_MAX_DEPTH), name))
        },
    )?;
    let scene = command.args.with_max_depth(scene);
    let size = (scene.film.width, scene.film.height);
    let film = command
        .anti_aliasing
        .film_setup(film.as_ref(), &command.args, size)?;
    command.args.check_outputs()?;
    let rendered = render_with(&scene, &film.settings, &film.pixel_sampler, &film.filter);
    let mut extra = serde_json::json!({
        "scene": scene_name,
        "max_depth": scene.max_depth,
        "seed": command.args.seed,
    });
    film.record_stats(&mut extra);
    command.args.write_outputs(&rendered, extra)?;
    command.args.report_written(
        &rendered,
        &format!(
            ", {} sampler, {} filter",
            film.sampler_kind.name(),
            film.filter.kind().name()
        ),
    );
    Ok(())
}
