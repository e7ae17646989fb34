//! `ch06-fuzzy-reflections`: render a scene with rough mirrors and frosted glass, or write the
//! chapter's figures.

use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch05_motion_blur::lab::scene_file::{CameraSide, motion_for_render};
use ch05_motion_blur::lab::shot::Shot;
use ch06_fuzzy_reflections::lab::CAPABILITIES;
use ch06_fuzzy_reflections::lab::cli::FuzzyArgs;
use ch06_fuzzy_reflections::lab::figures;
use ch06_fuzzy_reflections::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch06_fuzzy_reflections::{PointLights, render_with};
use common::scene::Scene;
use std::process::ExitCode;
use workbench::capabilities::Capabilities;
use workbench::driver::{ChapterRender, RenderJob, Rendered, drive};

#[derive(clap::Args, Debug)]
struct RenderOptions {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Floor, conflicts_with = "scene")]
    builtin: Builtin,
    #[command(flatten)]
    fuzzy: FuzzyArgs,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    lens: LensArgs,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene with glossy and frosted surfaces.");
    binary.run(drive::<RenderOptions>, figures::write_all)
}

impl ChapterRender for RenderOptions {
    type FromFile = CameraSide;
    type Prepared = Shot;
    const CAPABILITIES: Capabilities = CAPABILITIES;
    const BUILTIN_SPP: u64 = 16;

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        // Built with its own exponent; --exponent replaces it, as in a file.
        let exponent = self.builtin.default_exponent();
        let scene = self.builtin.scene(DEFAULT_MAX_DEPTH, exponent);
        Ok((scene, self.builtin.name().to_string()))
    }

    fn prepare(
        &self,
        scene: Scene,
        side: Option<CameraSide>,
        job: &RenderJob,
    ) -> anyhow::Result<Shot> {
        let world = motion_for_render(self.fuzzy.apply(scene)?, &job.name)?;
        Shot::new(world, side, &self.anti_aliasing, &self.lens, None, job)
    }

    fn render(&self, shot: Shot, job: &RenderJob) -> anyhow::Result<Rendered> {
        let output = render_with(
            &shot.world,
            &PointLights,
            self.fuzzy.options(),
            &shot.lens,
            &job.settings,
            &shot.sampler,
            &shot.film.filter,
        );
        let mut stats = serde_json::json!({ "time_sampling": shot.time_sampling.name() });
        shot.record_stats(&mut stats);
        self.fuzzy.record_stats(&mut stats);
        let detail = format!(", glass {}", self.fuzzy.glass.name());
        Ok(Rendered {
            output,
            stats,
            detail,
        })
    }
}
