//! `ch04-depth-of-field`: render through a thin lens, or write the chapter's figures.

use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch04_depth_of_field::Aperture;
use ch04_depth_of_field::lab::CAPABILITIES;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch04_depth_of_field::lab::figures;
use ch04_depth_of_field::lab::scene_file::read_with_camera_side;
use ch04_depth_of_field::render_with;
use ch04_depth_of_field::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use std::process::ExitCode;
use workbench::cli::RenderArgs;

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Bokeh, conflicts_with = "scene")]
    builtin: Builtin,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    lens: LensArgs,
    #[command(flatten)]
    args: RenderArgs,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene through a thin lens.");
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let (scene, from_file, scene_name) = command.args.scene_or_builtin(
        |path| {
            Ok(read_with_camera_side(
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
    let (film, scene_lens) = match from_file {
        Some(side) => (Some(side.film), side.lens),
        None => (None, command.builtin.default_lens()),
    };
    let lens = command.lens.lens(scene_lens)?;
    let scene = command.args.with_max_depth(scene);
    let size = (scene.film.width, scene.film.height);
    let film = command
        .anti_aliasing
        .film_setup(film.as_ref(), &command.args, size)?;
    command.args.check_outputs()?;
    let rendered = render_with(
        &scene,
        &lens,
        &film.settings,
        &film.pixel_sampler,
        &film.filter,
    );
    let aperture = match lens.aperture {
        Aperture::Disc => serde_json::json!("disc"),
        Aperture::Polygon { blades, rotation } => serde_json::json!({
            "polygon": { "blades": blades, "rotation_degrees": rotation.to_degrees() }
        }),
    };
    let mut extra = serde_json::json!({
        "scene": scene_name,
        "max_depth": scene.max_depth,
        "aperture_radius": lens.aperture_radius,
        "focus_distance": lens.focus_distance,
        "aperture": aperture,
        "lens_warp": lens.warp.name(),
        "seed": command.args.seed,
    });
    film.record_stats(&mut extra);
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
