//! `ch03-anti-aliasing`: render with a choice of pixel sampler and filter, or write the
//! chapter's figures.

use ch03_anti_aliasing::lab::CAPABILITIES;
use ch03_anti_aliasing::lab::cli::{AntiAliasingArgs, FilmSetup};
use ch03_anti_aliasing::lab::figures;
use ch03_anti_aliasing::lab::scene_file::FilmSide;
use ch03_anti_aliasing::render_with;
use ch03_anti_aliasing::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use common::scene::Scene;
use std::process::ExitCode;
use workbench::capabilities::Capabilities;
use workbench::driver::{ChapterRender, RenderJob, Rendered, drive};

#[derive(clap::Args, Debug)]
struct RenderOptions {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Edges, conflicts_with = "scene")]
    builtin: Builtin,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene to an image.");
    binary.run(drive::<RenderOptions>, figures::write_all)
}

impl ChapterRender for RenderOptions {
    type FromFile = FilmSide;
    type Prepared = (Scene, FilmSetup);
    const CAPABILITIES: Capabilities = CAPABILITIES;
    const BUILTIN_SPP: u64 = 16;

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        let name = self.builtin.name().to_string();
        Ok((self.builtin.build(DEFAULT_MAX_DEPTH), name))
    }

    fn prepare(
        &self,
        scene: Scene,
        film: Option<FilmSide>,
        job: &RenderJob,
    ) -> anyhow::Result<(Scene, FilmSetup)> {
        let budget = &job.settings.budget;
        let film = self
            .anti_aliasing
            .film_setup(film.as_ref(), budget, job.seed)?;
        Ok((scene, film))
    }

    fn render(
        &self,
        (scene, film): (Scene, FilmSetup),
        job: &RenderJob,
    ) -> anyhow::Result<Rendered> {
        let output = render_with(&scene, &job.settings, &film.pixel_sampler, &film.filter);
        let mut stats = serde_json::json!({});
        film.record_stats(&mut stats);
        let detail = format!(
            ", {} sampler, {} filter",
            film.sampler_kind.name(),
            film.filter.kind().name()
        );
        Ok(Rendered {
            output,
            stats,
            detail,
        })
    }
}
