//! `ch01-whitted`: render the chapter's scenes, or write its figures.

use ch01_whitted::lab::CAPABILITIES;
use ch01_whitted::lab::figures;
use ch01_whitted::scenes::{Builtin, DEFAULT_MAX_DEPTH};
use ch01_whitted::{PixelPattern, render};
use common::render::Budget;
use common::scene::Scene;
use std::process::ExitCode;
use workbench::capabilities::Capabilities;
use workbench::driver::{ChapterRender, RenderJob, Rendered, drive};

#[derive(clap::Args, Debug)]
struct RenderOptions {
    /// The built-in scene to render (when no --scene file is given).
    #[arg(long, value_enum, default_value_t = Builtin::Spheres, conflicts_with = "scene")]
    builtin: Builtin,
    /// Where the samples of a pixel go. Whitted's tracer is deterministic: several samples at
    /// the centre give the same image as one; `grid` supersamples (with a square --spp).
    /// [default: centre; for a scene file asking for a square number of samples, grid]
    #[arg(long, value_enum)]
    pixel: Option<PixelPattern>,
}

fn main() -> ExitCode {
    let binary = workbench::chapter_binary!("Render a scene to an image.");
    binary.run(drive::<RenderOptions>, figures::write_all)
}

impl ChapterRender for RenderOptions {
    type FromFile = ();
    type Prepared = (Scene, PixelPattern);
    const CAPABILITIES: Capabilities = CAPABILITIES;
    // Whitted's tracer is deterministic: one sample at the centre is the image.
    const BUILTIN_SPP: u64 = 1;

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        let name = self.builtin.name().to_string();
        Ok((self.builtin.build(DEFAULT_MAX_DEPTH), name))
    }

    fn prepare(
        &self,
        scene: Scene,
        from_file: Option<()>,
        job: &RenderJob,
    ) -> anyhow::Result<(Scene, PixelPattern)> {
        let budget = job.settings.budget;
        let pixel = self.pixel.unwrap_or_else(|| {
            // A scene file that asks for several samples per pixel expects them spread over
            // the pixel, as Mitsuba spreads them; Whitted's own choice is the centre.
            let square = |n: u64| (n as f64).sqrt().round().powi(2) as u64 == n;
            match budget {
                Budget::Samples(spp) if from_file.is_some() && spp > 1 && square(spp) => {
                    PixelPattern::Grid
                }
                _ => PixelPattern::Centre,
            }
        });
        if pixel == PixelPattern::Grid && matches!(budget, Budget::Seconds(_)) {
            anyhow::bail!(
                "--pixel grid needs a fixed --spp (a square such as 4, 16 or 64), not --time"
            );
        }
        Ok((scene, pixel))
    }

    fn render(
        &self,
        (scene, pixel): (Scene, PixelPattern),
        job: &RenderJob,
    ) -> anyhow::Result<Rendered> {
        let Some(output) = render(&scene, &job.settings, pixel, job.seed) else {
            anyhow::bail!(
                "--pixel grid places the samples of a pixel on a k x k grid, so --spp must be a square (1, 4, 9, 16, ...)"
            );
        };
        Ok(Rendered {
            output,
            stats: serde_json::json!({ "pixel": format!("{pixel:?}").to_lowercase() }),
            detail: String::new(),
        })
    }
}
