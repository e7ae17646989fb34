//! `ch08-path-tracing`: path-trace a scene file, or write the chapter's figures.

use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch05_motion_blur::lab::scene_file::{CameraSide, motion_for_render, read_with_camera_side};
use ch05_motion_blur::lab::shot::Shot;
use ch06_fuzzy_reflections::lab::cli::FuzzyArgs;
use ch06_fuzzy_reflections::{BelowSurface, GlassStrategy};
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::lab::cli::LightArgs;
use ch08_path_tracing::dimensions::render_counted;
use ch08_path_tracing::lab::CAPABILITIES;
use ch08_path_tracing::lab::cli::PathArgs;
use ch08_path_tracing::lab::figures;
use ch08_path_tracing::lab::scene_file::path_options;
use ch08_path_tracing::{Method, PathOptions};
use common::scene::Scene;
use std::path::Path;
use std::process::ExitCode;
use workbench::cli::{CliError, RenderArgs};
use workbench::driver::{ChapterRender, RenderJob, Rendered, drive};

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
    drive(command)
}

impl ChapterRender for RenderCommand {
    /// The camera side, and the file's integrator, read before --max-depth changes the scene.
    type FromFile = (CameraSide, PathOptions);
    type Prepared = (Shot, PathOptions);
    // Never used: the chapter renders scene files only.
    const BUILTIN_SPP: u64 = 16;

    fn args(&self) -> &RenderArgs {
        &self.args
    }

    fn read_scene_file(
        &self,
        path: &Path,
        defines: &[(String, String)],
    ) -> Result<(Scene, (CameraSide, PathOptions)), CliError> {
        let (scene, side) = read_with_camera_side(path, defines, &CAPABILITIES)?;
        let options = path_options(&scene);
        Ok((scene, (side, options)))
    }

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        anyhow::bail!(
            "render needs a scene: --scene FILE.xml (see chapters/ch08-path-tracing/scenes/)"
        )
    }

    fn prepare(
        &self,
        scene: Scene,
        from_file: Option<(CameraSide, PathOptions)>,
        job: &RenderJob,
    ) -> anyhow::Result<(Shot, PathOptions)> {
        let (side, file_options) = from_file.expect("the scene was read from a file");
        let world = motion_for_render(self.fuzzy.apply(scene)?, &job.name)?;
        let options = PathOptions {
            max_depth: world.scene.max_depth,
            ..self.path.options(file_options)
        };
        let shot = Shot::new(
            world,
            Some(side),
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
