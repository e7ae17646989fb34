//! `ch07-soft-shadows`: render a scene with area lights and soft shadows, or write the
//! chapter's figures.

use ch03_anti_aliasing::cli::AntiAliasingArgs;
use ch04_depth_of_field::Lens;
use ch04_depth_of_field::cli::LensArgs;
use ch05_motion_blur::scene_file::{motion_for_render, read_with_camera_side};
use ch05_motion_blur::{StratifiedTime, TimeSampling};
use ch06_fuzzy_reflections::cli::{FuzzyArgs, parse_number};
use ch07_soft_shadows::cli::LightArgs;
use ch07_soft_shadows::scenes::{Builtin, DEFAULT_DEPTH};
use ch07_soft_shadows::{AreaLights, CAPABILITIES};
use ch07_soft_shadows::{figures, render_with};
use common::cli::{ChapterBinary, RenderArgs};
use common::render::Budget;
use std::process::ExitCode;

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
    anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    lens: LensArgs,
    #[command(flatten)]
    args: RenderArgs,
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
    let binary = ChapterBinary {
        name: "ch07-soft-shadows",
        about: env!("CARGO_PKG_DESCRIPTION"),
        render: "Render a scene lit by area lights.",
    };
    binary.run(run_render, figures::write_all)
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    let light_scale = check_light_scale(command.light_scale)?;
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
                command.builtin.build(DEFAULT_DEPTH, light_scale).scene,
                Lens::PINHOLE,
                None,
                None,
                16,
                command.builtin.name().to_string(),
            ),
        };
    let scene = command.fuzzy.apply(scene)?;
    let world = motion_for_render(scene).map_err(|e| anyhow::anyhow!("{scene_name}: {e}"))?;
    let world = &world;
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
    let lights = command.lights.options();
    let shutter = world.shutter;
    let time_sampling = TimeSampling::by_default(world.moves(), &settings.budget);
    let rendered = match (time_sampling, settings.budget) {
        (TimeSampling::Stratified, Budget::Samples(spp)) => {
            let sampler = StratifiedTime::new(pixel_sampler, spp, command.args.seed);
            render_with(world, lights, options, &lens, &settings, &sampler, &filter)
        }
        _ => render_with(
            world,
            lights,
            options,
            &lens,
            &settings,
            &pixel_sampler,
            &filter,
        ),
    };
    let mut extra = serde_json::json!({
        "scene": scene_name,
        "area_lights": AreaLights::of(&world.scene).lights.len(),
        "point_lights": world.scene.point_lights.len(),
        "light_scale": command.args.scene.is_none().then_some(light_scale),
        "light_samples": lights.samples,
        "light_strata": lights.strata.name(),
        "light_sampling": lights.sampling.strategy.name(),
        "disc_warp": lights.sampling.disc_warp.name(),
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
        &format!(", {} shadow ray(s) per light", lights.samples),
    );
    Ok(())
}
