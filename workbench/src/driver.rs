//! The render driver: what every chapter's `render` does around its tracer, written once.
//!
//! A chapter states its own options and what its tracer does with them ([`ChapterRender`]);
//! [`drive`] does the rest, in one order for every chapter: it reads the options every render
//! shares ([`RenderArgs`]: the scene, `-D`, the budget, the seed, the threads, the outputs,
//! `--max-depth`), loads the scene file through the chapter or builds its built-in scene,
//! settles the render's settings (the sample count is read here and nowhere else), lets the
//! chapter settle the rest, checks the outputs can be written, has the chapter trace, and
//! writes the image and the statistics whole, then says what it wrote. Progress and Ctrl-C
//! come with the settings.
//!
//! Everything that can refuse the command line is settled before the first pixel, so that a
//! mistake costs a millisecond, not a render.

use crate::cli::{CliError, RenderArgs};
use common::render::{RenderOutput, RenderSettings};
use common::scene::Scene;
use std::path::Path;

/// A chapter's `render` command: its own options (with [`RenderArgs`] flattened into them) and
/// what its tracer does with them, in the steps [`drive`] calls.
pub trait ChapterRender {
    /// What the chapter reads from a scene file besides the scene: chapter 03's film side,
    /// chapter 04's lens with it, ...; `()` for nothing.
    type FromFile;
    /// What the chapter settles before it traces: its scene made ready, its lens, its
    /// sampler. Every refusal of the chapter's options comes while preparing it.
    type Prepared;

    /// Samples per pixel of a built-in scene when neither `--spp` nor `--time` is given (a
    /// scene file's are its `sample_count`).
    const BUILTIN_SPP: u64;

    /// The options every render shares.
    fn args(&self) -> &RenderArgs;

    /// The scene file at `path` read for this chapter with the `-D` `defines`: checked against
    /// what the chapter renders, its notes printed, with what the chapter takes from it.
    fn read_scene_file(
        &self,
        path: &Path,
        defines: &[(String, String)],
    ) -> Result<(Scene, Self::FromFile), CliError>;

    /// The built-in scene the chapter's options name, and its name (when no `--scene` is
    /// given); or why there is none.
    fn builtin(&self) -> anyhow::Result<(Scene, String)>;

    /// The chapter's options applied to `scene` (with `--max-depth` applied) and checked, and
    /// what the tracer needs made ready.
    fn prepare(
        &self,
        scene: Scene,
        from_file: Option<Self::FromFile>,
        job: &RenderJob,
    ) -> anyhow::Result<Self::Prepared>;

    /// Traces the prepared render.
    fn render(&self, prepared: Self::Prepared, job: &RenderJob) -> anyhow::Result<Rendered>;
}

/// What the driver settled of a render before the chapter's part.
#[derive(Clone, Debug)]
pub struct RenderJob {
    /// The scene file's path, or the built-in scene's name.
    pub name: String,
    /// Size, budget, threads, progress and the Ctrl-C flag.
    pub settings: RenderSettings,
    /// The seed of every random number of the render.
    pub seed: u64,
    /// Whether the statistics are written (`--stats`): what only they report need not be
    /// counted otherwise.
    pub writes_stats: bool,
}

/// What a chapter's render hands back to the driver.
pub struct Rendered {
    /// The image and the statistics every render keeps.
    pub output: RenderOutput,
    /// The chapter's entries of the statistics (a JSON object): its options and what they
    /// settled. The driver adds the scene, the depth limit and the seed.
    pub stats: serde_json::Value,
    /// What the chapter's options chose, for the line that reports the image, such as
    /// ", glass fresnel"; empty for nothing.
    pub detail: String,
}

/// Runs a chapter's `render` command: the steps of the module's documentation, in order.
pub fn drive<C: ChapterRender>(command: C) -> anyhow::Result<()> {
    let args = command.args();
    let (scene, from_file, name) = match args.scene_file()? {
        Some(path) => {
            let (scene, from_file) = command.read_scene_file(path, &args.define)?;
            (scene, Some(from_file), path.display().to_string())
        }
        None => {
            let (scene, name) = command.builtin()?;
            (scene, None, name)
        }
    };
    let mut scene = scene;
    if let Some(max_depth) = args.max_depth {
        scene.max_depth = max_depth;
    }
    let default_spp = match from_file {
        Some(_) => u64::from(scene.sampler.sample_count.max(1)),
        None => C::BUILTIN_SPP,
    };
    let job = RenderJob {
        name,
        settings: args.settings((scene.film.width, scene.film.height), default_spp)?,
        seed: args.seed,
        writes_stats: args.stats.is_some(),
    };
    let max_depth = scene.max_depth;
    let prepared = command.prepare(scene, from_file, &job)?;
    args.check_outputs()?;
    let Rendered {
        output,
        mut stats,
        detail,
    } = command.render(prepared, &job)?;
    stats["scene"] = job.name.into();
    stats["max_depth"] = max_depth.into();
    stats["seed"] = job.seed.into();
    args.write_outputs(&output, stats)?;
    args.report_written(&output, &detail);
    Ok(())
}
