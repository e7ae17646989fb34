//! What every `render` from chapter 05 on does before it traces: take the scene (a file,
//! checked against the chapter's capabilities, or a built-in one), let the chapter adjust it,
//! make its motion ready, and settle the lens, filter, pixel sampler and render settings from
//! the file and the command line. A chapter's `main.rs` then holds only its own options and
//! what its tracer does with them.

use crate::lab::scene_file::{motion_for_render, read_with_camera_side};
use crate::time_sampling::{StratifiedTime, TimeSampling};
use crate::world::MotionScene;
use ch03_anti_aliasing::PixelSampler;
use ch03_anti_aliasing::lab::cli::{AntiAliasingArgs, FilmSetup};
use ch04_depth_of_field::Lens;
use ch04_depth_of_field::lab::cli::LensArgs;
use common::scene::Scene;
use workbench::capabilities::Capabilities;
use workbench::cli::{CliError, RenderArgs};

/// The options every `render` from chapter 05 on shares: the pixel sampler and filter
/// (chapter 03), the lens (chapter 04), and the scene, budget and outputs (`common`).
#[derive(clap::Args, Debug)]
pub struct CameraArgs {
    // Doc comments on flattened options would become clap's help text, so these say it here:
    // the pixel sampler and filter, the lens, and the scene, budget, outputs.
    #[allow(missing_docs)]
    #[command(flatten)]
    pub anti_aliasing: AntiAliasingArgs,
    #[allow(missing_docs)]
    #[command(flatten)]
    pub lens: LensArgs,
    #[allow(missing_docs)]
    #[command(flatten)]
    pub args: RenderArgs,
}

/// A render's scene in motion and everything about its camera side, settled.
pub struct RenderSetup {
    /// The scene, its motion ready.
    pub world: MotionScene,
    /// The scene file's path, or the built-in scene's name.
    pub name: String,
    /// The lens: the command line's, else the file's.
    pub lens: Lens,
    /// The filter, the pixel sampler and the render settings: the command line's, else the
    /// file's.
    pub film: FilmSetup,
    /// The seed of every random number of the render.
    pub seed: u64,
}

impl CameraArgs {
    /// The render's setup: the `--scene` file (read with `-D`, checked against `capabilities`,
    /// its notes printed) or `builtin`'s scene and name (with a pinhole, Mitsuba's defaults for
    /// the rest and 16 samples per pixel); then `adjust` (the chapter's options on the scene),
    /// `--max-depth`, the motion made ready, `adjust_world` (the chapter's options on the
    /// motion).
    pub fn setup(
        &self,
        capabilities: &Capabilities,
        builtin: impl FnOnce() -> anyhow::Result<(Scene, String)>,
        adjust: impl FnOnce(Scene) -> anyhow::Result<Scene>,
        adjust_world: impl FnOnce(MotionScene) -> anyhow::Result<MotionScene>,
    ) -> anyhow::Result<RenderSetup> {
        let (scene, side, name) = self.args.scene_or_builtin(
            |path| {
                Ok(read_with_camera_side(
                    path,
                    &self.args.define,
                    capabilities,
                )?)
            },
            builtin,
        )?;
        let scene = self.args.with_max_depth(adjust(scene)?);
        let world = motion_for_render(scene).map_err(|message| CliError::Unrenderable {
            file: name.clone().into(),
            message,
        })?;
        let world = adjust_world(world)?;
        let lens = self
            .lens
            .lens_or_pinhole(side.as_ref().map_or(Lens::PINHOLE, |side| side.lens))?;
        let film = world.scene.film;
        let film = self.anti_aliasing.film_setup(
            side.as_ref().map(|side| &side.film),
            &self.args,
            (film.width, film.height),
        )?;
        Ok(RenderSetup {
            world,
            name,
            lens,
            film,
            seed: self.args.seed,
        })
    }
}

impl RenderSetup {
    /// The time sampling of a render that offers no choice: stratified when the scene moves
    /// and the budget is a sample count ([`TimeSampling::by_default`]).
    pub fn default_time_sampling(&self) -> TimeSampling {
        TimeSampling::by_default(self.world.moves(), &self.film.settings.budget)
    }

    /// The render's sampler: the pixel sampler, drawing the shutter time as `time_sampling`
    /// says.
    pub fn sampler(
        &self,
        time_sampling: TimeSampling,
    ) -> Result<StratifiedTime<PixelSampler>, String> {
        let film = &self.film;
        time_sampling.sampler(film.pixel_sampler.clone(), &film.settings.budget, self.seed)
    }

    /// What every render's statistics record of its setup; a chapter adds its own entries.
    pub fn stats(&self) -> serde_json::Value {
        let shutter = self.world.shutter;
        let mut stats = serde_json::json!({
            "scene": self.name,
            "max_depth": self.world.scene.max_depth,
            "aperture_radius": self.lens.aperture_radius,
            "focus_distance": self.lens.focus_distance,
            "shutter_open": shutter.open,
            "shutter_close": shutter.close,
            "seed": self.seed,
        });
        self.film.record_stats(&mut stats);
        stats
    }
}
