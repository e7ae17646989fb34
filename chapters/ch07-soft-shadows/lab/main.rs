//! `ch07-soft-shadows`: render a scene with area lights and soft shadows, or write the
//! chapter's figures.

use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch05_motion_blur::lab::scene_file::{CameraSide, motion_for_render};
use ch05_motion_blur::lab::shot::Shot;
use ch06_fuzzy_reflections::lab::cli::FuzzyArgs;
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::lab::CAPABILITIES;
use ch07_soft_shadows::lab::cli::LightArgs;
use ch07_soft_shadows::lab::figures;
use ch07_soft_shadows::render_with;
use ch07_soft_shadows::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use common::scene::Scene;
use std::process::ExitCode;
use workbench::capabilities::Capabilities;
use workbench::cli::parse_number;
use workbench::driver::{ChapterRender, RenderCommand, RenderJob, Rendered, drive};

#[derive(clap::Args, Debug)]
struct RenderOptions {
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

fn run_render(command: RenderCommand<RenderOptions>) -> anyhow::Result<()> {
    check_light_scale(command.chapter.light_scale)?;
    drive(command)
}

impl ChapterRender for RenderOptions {
    type FromFile = CameraSide;
    /// The shot, and the light scale of a built-in scene (`None` for a file's).
    type Prepared = (Shot, Option<f32>);
    const CAPABILITIES: Capabilities = CAPABILITIES;
    const BUILTIN_SPP: u64 = 16;

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        let scene = self
            .builtin
            .build(DEFAULT_MAX_DEPTH, self.light_scale)
            .scene;
        Ok((scene, self.builtin.name().to_string()))
    }

    fn prepare(
        &self,
        scene: Scene,
        side: Option<CameraSide>,
        job: &RenderJob,
    ) -> anyhow::Result<(Shot, Option<f32>)> {
        let light_scale = side.is_none().then_some(self.light_scale);
        let world = motion_for_render(self.fuzzy.apply(scene)?, &job.name)?;
        let shot = Shot::new(world, side, &self.anti_aliasing, &self.lens, None, job)?;
        Ok((shot, light_scale))
    }

    fn render(
        &self,
        (shot, light_scale): (Shot, Option<f32>),
        job: &RenderJob,
    ) -> anyhow::Result<Rendered> {
        let lights = self.lights.options();
        let world = &shot.world;
        let output = render_with(
            world,
            lights,
            self.fuzzy.options(),
            &shot.lens,
            &job.settings,
            &shot.sampler,
            &shot.film.filter,
        );
        let mut stats = serde_json::json!({
            "area_lights": AreaLights::of(&world.scene).lights.len(),
            "point_lights": world.scene.point_lights.len(),
            "light_scale": light_scale,
            "light_samples": lights.samples,
            "light_strata": lights.strata.name(),
            "light_sampling": lights.sampling.strategy.name(),
            "disc_warp": lights.sampling.disc_warp.name(),
            "time_sampling": shot.time_sampling.name(),
        });
        shot.record_stats(&mut stats);
        self.fuzzy.record_stats(&mut stats);
        let detail = format!(", {} shadow ray(s) per light", lights.samples);
        Ok(Rendered {
            output,
            stats,
            detail,
        })
    }
}
