//! `ch05-motion-blur`: render a scene in motion through an open shutter, or write the
//! chapter's figures.

use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch05_motion_blur::lab::CAPABILITIES;
use ch05_motion_blur::lab::figures;
use ch05_motion_blur::lab::scene_file::{CameraSide, motion_for_render};
use ch05_motion_blur::lab::shot::Shot;
use ch05_motion_blur::scenes::{Builtin, DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER};
use ch05_motion_blur::world::DEFAULT_STRETCHES;
use ch05_motion_blur::{Shutter, TimeSampling, render_with};
use common::scene::Scene;
use std::process::ExitCode;
use workbench::capabilities::Capabilities;
use workbench::cli::parse_number;
use workbench::driver::{ChapterRender, RenderJob, Rendered, drive};

#[derive(clap::Args, Debug)]
struct RenderOptions {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Street, conflicts_with = "scene")]
    builtin: Builtin,
    /// When the shutter opens [default: the scene file's shutter_open, or 0].
    #[arg(long, value_name = "T0", allow_hyphen_values = true, value_parser = parse_number)]
    shutter_open: Option<f32>,
    /// When the shutter closes; equal to --shutter-open for no blur
    /// [default: the scene file's shutter_close, or 1].
    #[arg(long, value_name = "T1", allow_hyphen_values = true, value_parser = parse_number)]
    shutter_close: Option<f32>,
    /// How the times of a pixel's samples are drawn.
    #[arg(long, value_enum, default_value_t = TimeSampling::Stratified)]
    time_sampling: TimeSampling,
    /// Into how many stretches of the shutter the moving objects' bounds are cut, one BVH each.
    #[arg(long, value_name = "K", default_value_t = DEFAULT_STRETCHES as u32,
          value_parser = clap::value_parser!(u32).range(1..=1024))]
    stretches: u32,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    lens: LensArgs,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene in motion over the shutter interval.");
    binary.run(drive::<RenderOptions>, figures::write_all)
}

impl ChapterRender for RenderOptions {
    type FromFile = CameraSide;
    type Prepared = Shot;
    const CAPABILITIES: Capabilities = CAPABILITIES;
    const BUILTIN_SPP: u64 = 16;

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        let scene = self.builtin.scene(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
        Ok((scene, self.builtin.name().to_string()))
    }

    fn prepare(
        &self,
        scene: Scene,
        side: Option<CameraSide>,
        job: &RenderJob,
    ) -> anyhow::Result<Shot> {
        let world = motion_for_render(scene, &job.name)?;
        let shutter = Shutter::new(
            self.shutter_open.unwrap_or(world.shutter.open),
            self.shutter_close.unwrap_or(world.shutter.close),
        )
        .map_err(|e| anyhow::anyhow!("--shutter-open and --shutter-close: {e}"))?;
        let world = world.with_shutter(shutter, self.stretches as usize);
        let time_sampling = Some(self.time_sampling);
        Shot::new(
            world,
            side,
            &self.anti_aliasing,
            &self.lens,
            time_sampling,
            job,
        )
    }

    fn render(&self, shot: Shot, job: &RenderJob) -> anyhow::Result<Rendered> {
        let world = &shot.world;
        let output = render_with(
            world,
            &shot.lens,
            &job.settings,
            &shot.sampler,
            &shot.film.filter,
        );
        let mut stats = serde_json::json!({
            "time_sampling": shot.time_sampling.name(),
            "stretches": world.moving.stretches(),
        });
        shot.record_stats(&mut stats);
        let shutter = world.shutter;
        let detail = format!(", shutter [{}, {}]", shutter.open, shutter.close);
        Ok(Rendered {
            output,
            stats,
            detail,
        })
    }
}
