//! `ch04-depth-of-field`: render through a thin lens, or write the chapter's figures.

use ch03_anti_aliasing::lab::cli::{AntiAliasingArgs, FilmSetup};
use ch04_depth_of_field::lab::CAPABILITIES;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch04_depth_of_field::lab::figures;
use ch04_depth_of_field::lab::scene_file::CameraSide;
use ch04_depth_of_field::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch04_depth_of_field::{Aperture, Lens, render_with};
use common::scene::Scene;
use std::process::ExitCode;
use workbench::capabilities::Capabilities;
use workbench::driver::{ChapterRender, RenderJob, Rendered, drive};

#[derive(clap::Args, Debug)]
struct RenderOptions {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Bokeh, conflicts_with = "scene")]
    builtin: Builtin,
    #[command(flatten)]
    anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    lens: LensArgs,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene through a thin lens.");
    binary.run(drive::<RenderOptions>, figures::write_all)
}

impl ChapterRender for RenderOptions {
    type FromFile = CameraSide;
    type Prepared = (Scene, Lens, FilmSetup);
    const CAPABILITIES: Capabilities = CAPABILITIES;
    const BUILTIN_SPP: u64 = 16;

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        let name = self.builtin.name().to_string();
        Ok((self.builtin.build(DEFAULT_MAX_DEPTH), name))
    }

    fn prepare(
        &self,
        scene: Scene,
        side: Option<CameraSide>,
        job: &RenderJob,
    ) -> anyhow::Result<(Scene, Lens, FilmSetup)> {
        let (film, scene_lens) = match side {
            Some(side) => (Some(side.film), side.lens),
            None => (None, self.builtin.default_lens()),
        };
        let lens = self.lens.lens(scene_lens)?;
        let budget = &job.settings.budget;
        let film = self
            .anti_aliasing
            .film_setup(film.as_ref(), budget, job.seed)?;
        Ok((scene, lens, film))
    }

    fn render(
        &self,
        (scene, lens, film): (Scene, Lens, FilmSetup),
        job: &RenderJob,
    ) -> anyhow::Result<Rendered> {
        let output = render_with(
            &scene,
            &lens,
            &job.settings,
            &film.pixel_sampler,
            &film.filter,
        );
        let aperture = match lens.aperture {
            Aperture::Disc => serde_json::json!("disc"),
            Aperture::Polygon { blades, rotation } => serde_json::json!({
                "polygon": { "blades": blades, "rotation_degrees": rotation.to_degrees() }
            }),
        };
        let mut stats = serde_json::json!({
            "aperture_radius": lens.aperture_radius,
            "focus_distance": lens.focus_distance,
            "aperture": aperture,
            "lens_warp": lens.warp.name(),
        });
        film.record_stats(&mut stats);
        let detail = format!(
            ", aperture radius {}, focus at {}",
            lens.aperture_radius, lens.focus_distance
        );
        Ok(Rendered {
            output,
            stats,
            detail,
        })
    }
}
