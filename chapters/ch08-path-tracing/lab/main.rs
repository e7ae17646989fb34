//! `ch08-path-tracing`: path-trace a scene file, or write the chapter's figures.

use ch05_motion_blur::lab::render_setup::CameraArgs;
use ch06_fuzzy_reflections::lab::cli::FuzzyArgs;
use ch06_fuzzy_reflections::{BelowSurface, GlassStrategy};
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::lab::cli::LightArgs;
use ch08_path_tracing::Method;
use ch08_path_tracing::dimensions::render_counted;
use ch08_path_tracing::lab::CAPABILITIES;
use ch08_path_tracing::lab::cli::PathArgs;
use ch08_path_tracing::lab::figures;
use ch08_path_tracing::lab::scene_file::path_options;
use common::scene::Scene;
use std::process::ExitCode;

#[derive(clap::Args, Debug)]
struct RenderCommand {
    #[command(flatten)]
    path: PathArgs,
    #[command(flatten)]
    lights: LightArgs,
    #[command(flatten)]
    fuzzy: FuzzyArgs,
    #[command(flatten)]
    camera: CameraArgs,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Path-trace a scene file (--scene FILE.xml).");
    binary.run(run_render, figures::write_all)
}

/// The options of chapters 06 and 07 that mean something for a path: a path follows one ray
/// at glass, chosen by Fresnel, drops lobe directions below the surface, and sends one light
/// sample per bounce.
fn check_path_options(command: &RenderCommand) -> anyhow::Result<()> {
    if command.fuzzy.glass != GlassStrategy::Fresnel {
        anyhow::bail!(
            "--glass {}: a path follows one ray per bounce, chosen at glass by the Fresnel term; only --glass fresnel applies",
            command.fuzzy.glass.name()
        );
    }
    if command.fuzzy.below_surface != BelowSurface::Drop {
        anyhow::bail!(
            "--below-surface {}: the path tracer's BSDFs drop lobe directions below the surface; only --below-surface drop applies",
            command.fuzzy.below_surface.name()
        );
    }
    if command.lights.light_samples != 1 {
        anyhow::bail!(
            "--light-samples {}: the path tracer sends one light sample per bounce, to one light picked uniformly",
            command.lights.light_samples
        );
    }
    Ok(())
}

fn run_render(command: RenderCommand) -> anyhow::Result<()> {
    check_path_options(&command)?;
    let builtin = || {
        anyhow::bail!(
            "render needs a scene: --scene FILE.xml (see chapters/ch08-path-tracing/scenes/)"
        )
    };
    // The file's integrator, before --max-depth changes the scene.
    let mut file_options = None;
    let adjust = |scene: Scene| {
        file_options = Some(path_options(&scene));
        command.fuzzy.apply(scene)
    };
    let setup = command.camera.setup(&CAPABILITIES, builtin, adjust, Ok)?;
    let world = &setup.world;
    let options = ch08_path_tracing::PathOptions {
        max_depth: world.scene.max_depth,
        ..command
            .path
            .options(file_options.expect("the scene was read"))
    };
    let args = &command.camera.args;
    args.check_outputs()?;
    let method = Method {
        options,
        light_sampling: command.lights.options().sampling,
        fuzz: command.fuzzy.fuzz,
    };
    // Dimensions are counted only for --stats, where they are written.
    let count = args.stats.is_some();
    let (rendered, dimensions) = render_counted(
        count,
        world,
        method,
        &setup.lens,
        &setup.film.settings,
        &setup
            .sampler(setup.default_time_sampling())
            .map_err(anyhow::Error::msg)?,
        &setup.film.filter,
    );
    let mut extra = setup.stats();
    extra["nee"] = options.nee.into();
    extra["mis"] = options.mis.name().into();
    extra["rr_depth"] = serde_json::json!(options.rr_depth);
    extra["area_lights"] = AreaLights::of(&world.scene).lights.len().into();
    extra["point_lights"] = world.scene.point_lights.len().into();
    command.fuzzy.record_stats(&mut extra);
    if let Some(dimensions) = dimensions {
        // What `--stats` writes of them: `{"mean": .., "max": .., "paths": ..}`.
        extra["dimensions_per_path"] = serde_json::json!({
            "mean": dimensions.mean,
            "max": dimensions.max,
            "paths": dimensions.paths,
        });
    }
    args.write_outputs(&rendered, extra)?;
    args.report_written(&rendered, "");
    Ok(())
}
