//! `ch08-path-tracing`: path-trace a scene file, or write the chapter's figures.

use anyhow::Context;
use ch03_anti_aliasing::cli::AntiAliasingArgs;
use ch04_depth_of_field::cli::LensArgs;
use ch05_motion_blur::scene_file::{motion_for_render, read_with_camera_side};
use ch05_motion_blur::{StratifiedTime, TimeSampling};
use ch06_fuzzy_reflections::cli::FuzzyArgs;
use ch06_fuzzy_reflections::{BelowSurface, GlassStrategy};
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::cli::LightArgs;
use ch08_path_tracing::cli::PathArgs;
use ch08_path_tracing::dimensions::render_counted;
use ch08_path_tracing::scene_file::path_options;
use ch08_path_tracing::{CAPABILITIES, Method, figures};
use common::cli::{ChapterBinary, RenderArgs};
use common::render::Budget;
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
    anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    lens: LensArgs,
    #[command(flatten)]
    args: RenderArgs,
}

fn main() -> ExitCode {
    let binary = ChapterBinary {
        name: "ch08-path-tracing",
        about: env!("CARGO_PKG_DESCRIPTION"),
        render: "Path-trace a scene file (--scene FILE.xml).",
    };
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
    let Some(path) = &command.args.scene else {
        anyhow::bail!(
            "render needs a scene: --scene FILE.xml (see chapters/ch08-path-tracing/scenes/)"
        );
    };
    let (scene, side) = read_with_camera_side(path, &command.args.define, &CAPABILITIES)?;
    let file_options = path_options(&scene);
    let scene = command.fuzzy.apply(scene)?;
    let options = ch08_path_tracing::PathOptions {
        max_depth: scene.max_depth,
        ..command.path.options(file_options)
    };
    let world = motion_for_render(scene).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    let world = &world;
    let lens = command.lens.lens_or_pinhole(side.lens)?;
    let filter = command.anti_aliasing.filter(Some(side.filter))?;
    let sampler_kind = command.anti_aliasing.sampler_kind(Some(side.sampler));
    let film = world.scene.film;
    let settings = command.args.settings((film.width, film.height), side.spp)?;
    let pixel_sampler =
        command
            .anti_aliasing
            .pixel_sampler(sampler_kind, &settings.budget, command.args.seed)?;
    command.args.check_outputs()?;
    let method = Method {
        options,
        light_sampling: command.lights.options().sampling,
        fuzz: command.fuzzy.fuzz,
    };
    // Dimensions are counted only for --stats, where they are written.
    let count = command.args.stats.is_some();
    let time_sampling = TimeSampling::by_default(world.moves(), &settings.budget);
    let (rendered, dimensions) = match (time_sampling, settings.budget) {
        (TimeSampling::Stratified, Budget::Samples(spp)) => {
            let sampler = StratifiedTime::new(pixel_sampler, spp, command.args.seed);
            render_counted(count, world, method, &lens, &settings, &sampler, &filter)
        }
        _ => render_counted(
            count,
            world,
            method,
            &lens,
            &settings,
            &pixel_sampler,
            &filter,
        ),
    };
    let mut extra = serde_json::json!({
        "scene": path.display().to_string(),
        "nee": options.nee,
        "mis": options.mis.name(),
        "rr_depth": options.rr_depth,
        "max_depth": options.max_depth,
        "area_lights": AreaLights::of(&world.scene).lights.len(),
        "point_lights": world.scene.point_lights.len(),
        "sampler": sampler_kind.name(),
        "filter": filter.kind().name(),
        "aperture_radius": lens.aperture_radius,
        "seed": command.args.seed,
    });
    extra
        .as_object_mut()
        .context("a JSON object")?
        .extend(command.fuzzy.stats());
    if let Some(dimensions) = dimensions {
        extra["dimensions_per_path"] = dimensions.to_json();
    }
    command.args.write_outputs(&rendered, extra)?;
    command.args.report_written(&rendered, "");
    Ok(())
}
