//! `ch07-soft-shadows`: render a scene with area lights and soft shadows, or write the
//! chapter's figures.

use ch05_motion_blur::lab::render_setup::CameraArgs;
use ch06_fuzzy_reflections::lab::cli::FuzzyArgs;
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::lab::CAPABILITIES;
use ch07_soft_shadows::lab::cli::LightArgs;
use ch07_soft_shadows::lab::figures;
use ch07_soft_shadows::render_with;
use ch07_soft_shadows::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use std::process::ExitCode;
use workbench::cli::parse_number;

#[derive(clap::Args, Debug)]
struct RenderCommand {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Small, conflicts_with = "scene")]
    builtin: Builtin,
    /// Grow (above 1) or shrink (below 1) every area light of the built-in scene about its
    /// centre, its power kept: the shadows soften or harden, the brightness stays.
    #[arg(long, value_name = "S", default_value_t = 1.0, allow_hyphen_values = true,
          value_parser = parse_number, conflicts_with = "scene")]
    light_scale: f32,
    #[command(flatten)]
    lights: LightArgs,
    #[command(flatten)]
    fuzzy: FuzzyArgs,
    #[command(flatten)]
    camera: CameraArgs,
}

/// The light scale must keep every light a light: positive, finite, and within a range where
/// the radiance `L / S²` stays a normal float.
fn check_light_scale(scale: f32) -> anyhow::Result<f32> {
    if scale.is_finite() && (1e-4..=1e4).contains(&scale) {
        Ok(scale)
    } else {
        anyhow::bail!("--light-scale must be a number from 1e-4 to 1e4, found {scale}")
    }
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene lit by area lights.");
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let light_scale = check_light_scale(command.light_scale)?;
    let builtin = || {
        let scene = command.builtin.build(DEFAULT_MAX_DEPTH, light_scale).scene;
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
    let lights = command.lights.options();
    let time_sampling = setup.default_time_sampling();
    let world = &setup.world;
    let rendered = render_with(
        world,
        lights,
        command.fuzzy.options(),
        &setup.lens,
        &setup.film.settings,
        &setup.sampler(time_sampling).map_err(anyhow::Error::msg)?,
        &setup.film.filter,
    );
    let mut extra = setup.stats();
    extra["area_lights"] = AreaLights::of(&world.scene).lights.len().into();
    extra["point_lights"] = world.scene.point_lights.len().into();
    extra["light_scale"] = serde_json::json!(args.scene.is_none().then_some(light_scale));
    extra["light_samples"] = lights.samples.into();
    extra["light_strata"] = lights.strata.name().into();
    extra["light_sampling"] = lights.sampling.strategy.name().into();
    extra["disc_warp"] = lights.sampling.disc_warp.name().into();
    extra["time_sampling"] = time_sampling.name().into();
    command.fuzzy.record_stats(&mut extra);
    args.write_outputs(&rendered, extra)?;
    args.report_written(
        &rendered,
        &format!(", {} shadow ray(s) per light", lights.samples),
    );
    Ok(())
}
