//! What a render from chapter 05 on traces once its scene moves: the scene in motion seen
//! through chapter 04's lens, its samples placed by chapter 03's pixel sampler, each drawing
//! its shutter time. The later chapters' `render` commands flatten chapter 03's and chapter
//! 04's options into theirs and settle them here, so that a lens or a filter is asked for the
//! same way in every chapter.

use crate::time_sampling::{StratifiedTime, TimeSampling};
use crate::world::MotionScene;
use ch03_anti_aliasing::PixelSampler;
use ch03_anti_aliasing::lab::cli::{AntiAliasingArgs, FilmSetup};
use ch04_depth_of_field::Lens;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch04_depth_of_field::lab::scene_file::CameraSide;
use workbench::driver::RenderJob;

/// A scene in motion and its camera side, settled.
pub struct Shot {
    /// The scene, its motion ready.
    pub world: MotionScene,
    /// The lens: the command line's, else the file's, else a pinhole.
    pub lens: Lens,
    /// The filter and the pixel sampler: the command line's, else the file's.
    pub film: FilmSetup,
    /// How the shutter times of a pixel's samples are drawn.
    pub time_sampling: TimeSampling,
    /// The pixel sampler, drawing the shutter time as `time_sampling` says.
    pub sampler: StratifiedTime<PixelSampler>,
}

impl Shot {
    /// The shot of `world` for `job`: the lens `lens` asks for (from the file's `side`, or a
    /// pinhole), the film side `anti_aliasing` asks for, and the times drawn by
    /// `time_sampling` (the command line's choice), else [`TimeSampling::by_default`].
    pub fn new(
        world: MotionScene,
        side: Option<CameraSide>,
        anti_aliasing: &AntiAliasingArgs,
        lens: &LensArgs,
        time_sampling: Option<TimeSampling>,
        job: &RenderJob,
    ) -> anyhow::Result<Shot> {
        let (film, scene_lens) = match side {
            Some(side) => (Some(side.film), side.lens),
            None => (None, Lens::PINHOLE),
        };
        let lens = lens.lens_or_pinhole(scene_lens)?;
        let budget = &job.settings.budget;
        let film = anti_aliasing.film_setup(film.as_ref(), budget, job.seed)?;
        // The default is stratified only for a sample count, so only a choice can fail.
        let time_sampling =
            time_sampling.unwrap_or_else(|| TimeSampling::by_default(world.moves(), budget));
        let sampler = time_sampling
            .sampler(film.pixel_sampler.clone(), budget, job.seed)
            .map_err(|e| anyhow::anyhow!("--time-sampling {}: {e}", time_sampling.name()))?;
        Ok(Shot {
            world,
            lens,
            film,
            time_sampling,
            sampler,
        })
    }

    /// Adds the shot to a render's statistics (a JSON object): the lens, the shutter, the
    /// filter and the pixel sampler.
    pub fn record_stats(&self, stats: &mut serde_json::Value) {
        let shutter = self.world.shutter;
        stats["aperture_radius"] = self.lens.aperture_radius.into();
        stats["focus_distance"] = self.lens.focus_distance.into();
        stats["shutter_open"] = shutter.open.into();
        stats["shutter_close"] = shutter.close.into();
        self.film.record_stats(stats);
    }
}
