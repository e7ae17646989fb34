//! `ch08-path-tracing`: path-trace a scene file, or write the chapter's figures.

use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch05_motion_blur::lab::scene_file::motion_for_render;
use ch05_motion_blur::lab::shot::Shot;
use ch06_fuzzy_reflections::lab::cli::FuzzyArgs;
use ch06_fuzzy_reflections::{BelowSurface, GlassStrategy};
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::lab::cli::LightArgs;
use ch08_path_tracing::dimensions::render_counted;
use ch08_path_tracing::lab::CAPABILITIES;
use ch08_path_tracing::lab::cli::PathArgs;
use ch08_path_tracing::lab::figures;
use ch08_path_tracing::lab::scene_file::PathSide;
use ch08_path_tracing::{Method, PathOptions};
use common::scene::Scene;
use std::process::ExitCode;
use workbench::capabilities::Capabilities;
use workbench::driver::{ChapterRender, RenderCommand, RenderJob, Rendered, drive};

#[derive(clap::Args, Debug)]
struct RenderOptions {
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
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Path-trace a scene file (--scene FILE.xml).");
    binary.run(run_render, figures::write_all)
}

/// The options of chapters 06 and 07 that mean something for a path: a path follows one ray
/// at glass, chosen by Fresnel, drops lobe directions below the surface, and sends one light
/// sample per bounce.
fn check_path_options(options: &RenderOptions) -> anyhow::Result<()> {
    if options.fuzzy.glass != GlassStrategy::Fresnel {
        anyhow::bail!(
            "--glass {}: a path follows one ray per bounce, chosen at glass by the Fresnel term; only --glass fresnel applies",
            options.fuzzy.glass.name()
        );
    }
    if options.fuzzy.below_surface != BelowSurface::Drop {
        anyhow::bail!(
            "--below-surface {}: the path tracer's BSDFs drop lobe directions below the surface; only --below-surface drop applies",
            options.fuzzy.below_surface.name()
        );
    }
    if options.lights.light_samples != 1 {
        anyhow::bail!(
            "--light-samples {}: the path tracer sends one light sample per bounce, to one light picked uniformly",
            options.lights.light_samples
        );
    }
    Ok(())
}

fn run_render(command: RenderCommand<RenderOptions>) -> anyhow::Result<()> {
    check_path_options(&command.chapter)?;
    drive(command)
}

impl ChapterRender for RenderOptions {
    type FromFile = PathSide;
    type Prepared = (Shot, PathOptions);
    const CAPABILITIES: Capabilities = CAPABILITIES;
    // Never used: the chapter renders scene files only.
    const BUILTIN_SPP: u64 = 16;

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        anyhow::bail!(
            "render needs a scene: --scene FILE.xml (see chapters/ch08-path-tracing/scenes/)"
        )
    }

    fn prepare(
        &self,
        scene: Scene,
        from_file: Option<PathSide>,
        job: &RenderJob,
    ) -> anyhow::Result<(Shot, PathOptions)> {
        let side = from_file.expect("the scene was read from a file");
        let world = motion_for_render(self.fuzzy.apply(scene)?, &job.name)?;
        let options = PathOptions {
            max_depth: world.scene.max_depth,
            ..self.path.options(side.options)
        };
        let shot = Shot::new(
            world,
            Some(side.camera),
            &self.anti_aliasing,
            &self.lens,
            None,
            job,
        )?;
        Ok((shot, options))
    }

    fn render(
        &self,
        (shot, options): (Shot, PathOptions),
        job: &RenderJob,
    ) -> anyhow::Result<Rendered> {
        let method = Method {
            options,
            light_sampling: self.lights.options().sampling,
            fuzz: self.fuzzy.fuzz,
        };
        let world = &shot.world;
        // Dimensions are counted only for --stats, where they are written.
        let (output, dimensions) = render_counted(
            job.writes_stats,
            world,
            method,
            &shot.lens,
            &job.settings,
            &shot.sampler,
            &shot.film.filter,
        );
        let mut stats = serde_json::json!({
            "nee": options.nee,
            "mis": options.mis.name(),
            "rr_depth": options.rr_depth,
            "area_lights": AreaLights::of(&world.scene).lights.len(),
            "point_lights": world.scene.point_lights.len(),
        });
        shot.record_stats(&mut stats);
        self.fuzzy.record_stats(&mut stats);
        if let Some(dimensions) = dimensions {
            // What `--stats` writes of them: `{"mean": .., "max": .., "paths": ..}`.
            stats["dimensions_per_path"] = serde_json::json!({
                "mean": dimensions.mean,
                "max": dimensions.max,
                "paths": dimensions.paths,
            });
        }
        Ok(Rendered {
            output,
            stats,
            detail: String::new(),
        })
    }
}
