//! `ch06-fuzzy-reflections`: render a scene with rough mirrors and frosted glass, or write the
//! chapter's figures.

use ch05_motion_blur::render_setup::{CameraArgs, RenderSetup};
use ch05_motion_blur::{StratifiedTime, TimeSampling};
use ch06_fuzzy_reflections::cli::FuzzyArgs;
use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_DEPTH};
use ch06_fuzzy_reflections::{CAPABILITIES, PointLights, figures, render_with};
use common::cli::ChapterBinary;
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
    camera: CameraArgs,
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
    // Built with its own exponent; --exponent replaces it, as in a file.
    let builtin = || {
        let scene = command
            .builtin
            .scene(DEFAULT_DEPTH, command.builtin.default_exponent());
        Ok((scene, command.builtin.name().to_string()))
    };
    let setup = command.camera.setup(
        &CAPABILITIES,
        builtin,
        |scene| command.fuzzy.apply(scene),
        Ok,
    )?;
    let RenderSetup {
        world,
        lens,
        filter,
        pixel_sampler,
        settings,
        ..
    } = &setup;
    let args = &command.camera.args;
    args.check_outputs()?;
    let options = command.fuzzy.options();
    let time_sampling = TimeSampling::by_default(world.moves(), &settings.budget);
    let rendered = match (time_sampling, settings.budget) {
        (TimeSampling::Stratified, Budget::Samples(spp)) => {
            let sampler = StratifiedTime::new(pixel_sampler.clone(), spp, args.seed);
            render_with(
                world,
                &PointLights,
                options,
                lens,
                settings,
                &sampler,
                filter,
            )
        }
        _ => render_with(
            world,
            &PointLights,
            options,
            lens,
            settings,
            pixel_sampler,
            filter,
        ),
    };
    let mut extra = setup.stats(args.seed);
    extra["time_sampling"] = time_sampling.name().into();
    extra
        .as_object_mut()
        .expect("a JSON object")
        .extend(command.fuzzy.stats());
    args.write_outputs(&rendered, extra)?;
    args.report_written(
        &rendered,
        &format!(", glass {}", command.fuzzy.glass.name()),
    );
    Ok(())
}
