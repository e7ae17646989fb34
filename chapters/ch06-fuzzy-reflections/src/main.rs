//! `ch06-fuzzy-reflections`: render a scene with rough mirrors and frosted glass, or write the
//! chapter's figures.

use ch03_anti_aliasing::cli::AntiAliasingArgs;
use ch04_depth_of_field::Lens;
use ch04_depth_of_field::cli::LensArgs;
use ch05_motion_blur::scene_file::{motion_for_render, read_with_camera_side};
use ch05_motion_blur::{Shutter, StratifiedTime, TimeSampling};
use ch06_fuzzy_reflections::cli::FuzzyArgs;
use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_DEPTH};
use ch06_fuzzy_reflections::{CAPABILITIES, PointLights, figures, render_with};
use common::cli::{ChapterBinary, RenderArgs};
use common::render::Budget;
use std::process::ExitCode;

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Floor, conflicts_with = "scene")]
    builtin: Builtin,
    #[command(flatten)]
    fuzzy: FuzzyArgs,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    lens: LensArgs,
    #[command(flatten)]
    args: RenderArgs,
}

fn main() -> ExitCode {
    let binary = ChapterBinary {
        name: "ch06-fuzzy-reflections",
        about: env!("CARGO_PKG_DESCRIPTION"),
        render: "Render a scene with glossy and frosted surfaces.",
    };
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let (scene, scene_lens, file_filter, file_sampler, default_spp, scene_name) =
        match command.args.scene_file()? {
            Some(path) => {
                let (scene, side) =
                    read_with_camera_side(path, &command.args.define, &CAPABILITIES)?;
                (
                    scene,
                    side.lens,
                    Some(side.filter),
                    Some(side.sampler),
                    side.spp,
                    path.display().to_string(),
                )
            }
            None => (
                // Built with its own exponent; --exponent replaces it below, as in a file.
                command
                    .builtin
                    .scene(DEFAULT_DEPTH, command.builtin.default_exponent()),
                Lens::PINHOLE,
                None,
                None,
                16,
                command.builtin.name().to_string(),
            ),
        };
    let scene = command.fuzzy.apply(scene)?;
    let world = motion_for_render(scene).map_err(|e| anyhow::anyhow!("{scene_name}: {e}"))?;
    let lens = command.lens.lens_or_pinhole(scene_lens)?;
    let filter = command.anti_aliasing.filter(file_filter)?;
    let sampler_kind = command.anti_aliasing.sampler_kind(file_sampler);
    let film = world.scene.film;
    let settings = command
        .args
        .settings((film.width, film.height), default_spp)?;
    let pixel_sampler =
        command
            .anti_aliasing
            .pixel_sampler(sampler_kind, &settings.budget, command.args.seed)?;
    command.args.check_outputs()?;
    let options = command.fuzzy.options();
    let shutter: Shutter = world.shutter;
    let time_sampling = TimeSampling::by_default(world.moves(), &settings.budget);
    let rendered = match (time_sampling, settings.budget) {
        (TimeSampling::Stratified, Budget::Samples(spp)) => {
            let sampler = StratifiedTime::new(pixel_sampler, spp, command.args.seed);
            render_with(
                &world,
                &PointLights,
                options,
                &lens,
                &settings,
                &sampler,
                &filter,
            )
        }
        _ => render_with(
            &world,
            &PointLights,
            options,
            &lens,
            &settings,
            &pixel_sampler,
            &filter,
        ),
    };
    let mut extra = serde_json::json!({
        "scene": scene_name,
        "max_depth": world.scene.max_depth,
        "sampler": sampler_kind.name(),
        "filter": filter.kind().name(),
        "filter_radius": filter.half_width(),
        "aperture_radius": lens.aperture_radius,
        "focus_distance": lens.focus_distance,
        "shutter_open": shutter.open,
        "shutter_close": shutter.close,
        "time_sampling": time_sampling.name(),
        "seed": command.args.seed,
    });
    extra
        .as_object_mut()
        .expect("a JSON object")
        .extend(command.fuzzy.stats());
    command.args.write_outputs(&rendered, extra)?;
    command.args.report_written(
        &rendered,
        &format!(", glass {}", command.fuzzy.glass.name()),
    );
    Ok(())
}
