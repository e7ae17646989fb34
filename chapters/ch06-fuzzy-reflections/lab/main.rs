//! `ch06-fuzzy-reflections`: render a scene with rough mirrors and frosted glass, or write the
//! chapter's figures.

use ch05_motion_blur::lab::render_setup::CameraArgs;
use ch06_fuzzy_reflections::lab::CAPABILITIES;
use ch06_fuzzy_reflections::lab::cli::FuzzyArgs;
use ch06_fuzzy_reflections::lab::figures;
use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch06_fuzzy_reflections::{PointLights, render_with};
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
    let binary = workbench::chapter_binary!("Render a scene with glossy and frosted surfaces.");
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    // Built with its own exponent; --exponent replaces it, as in a file.
    let builtin = || {
        let scene = command
            .builtin
            .scene(DEFAULT_MAX_DEPTH, command.builtin.default_exponent());
        Ok((scene, command.builtin.name().to_string()))
    };
    let setup = command.camera.setup(
        &CAPABILITIES,
        builtin,
        |scene| command.fuzzy.apply(scene),
        Ok,
    )?;
    let args = &command.camera.args;
    args.check_outputs()?;
    let time_sampling = setup.default_time_sampling();
    let rendered = render_with(
        &setup.world,
        &PointLights,
        command.fuzzy.options(),
        &setup.lens,
        &setup.film.settings,
        &setup.sampler(time_sampling).map_err(anyhow::Error::msg)?,
        &setup.film.filter,
    );
    let mut extra = setup.stats();
    extra["time_sampling"] = time_sampling.name().into();
    command.fuzzy.record_stats(&mut extra);
    args.write_outputs(&rendered, extra)?;
    args.report_written(
        &rendered,
        &format!(", glass {}", command.fuzzy.glass.name()),
    );
    Ok(())
}
