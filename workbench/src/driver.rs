//! The render driver: what every chapter's `render` does around its tracer, written once.
//!
//! A chapter states its own options and what its tracer does with them ([`ChapterRender`]);
//! [`drive`] does the rest, in one order for every chapter: it reads the options every render
//! shares ([`RenderArgs`]: the scene, `-D`, the budget, the seed, the threads, the outputs,
//! `--max-depth`), reads the scene file as the chapter does ([`FromSceneFile`]) or builds its
//! built-in scene, settles the render's settings (the sample count is read here and nowhere
//! else), lets the chapter settle the rest, checks the outputs can be written, has the chapter
//! trace, and writes the image and the statistics whole, then says what it wrote. Progress
//! and Ctrl-C come with the settings.
//!
//! Everything that can refuse the command line is settled before the first pixel, so that a
//! mistake costs a millisecond, not a render.

use crate::capabilities::Capabilities;
use crate::cli::{CliError, RenderArgs, read_scene_file};
use common::render::{RenderOutput, RenderSettings};
use common::scene::Scene;
use std::path::Path;

/// A chapter's `render` command: the chapter's own options `C`, then the options every render
/// shares, which the driver reads.
#[derive(clap::Args, Debug)]
pub struct RenderCommand<C: clap::Args> {
    // A doc comment on a flattened group would become clap's help text, so this says it:
    // the chapter's options, then the scene, budget and outputs.
    #[allow(missing_docs)]
    #[command(flatten)]
    pub chapter: C,
    #[allow(missing_docs)]
    #[command(flatten)]
    pub args: RenderArgs,
}

/// What a chapter's `render` adds to the driver: its options (the type implementing this,
/// flattened into [`RenderCommand`]) and what its tracer does with them, in the steps
/// [`drive`] calls.
pub trait ChapterRender: clap::Args {
    /// What the chapter reads from a scene file besides the scene: chapter 03's film side,
    /// chapter 04's lens with it, ...; `()` for nothing.
    type FromFile: FromSceneFile;
    /// What the chapter settles before it traces: its scene made ready, its lens, its
    /// sampler. Every refusal of the chapter's options comes while preparing it.
    type Prepared;

    /// What the chapter renders of a scene file.
    const CAPABILITIES: Capabilities;
    /// Samples per pixel of a built-in scene when neither `--spp` nor `--time` is given (a
    /// scene file's are its `sample_count`).
    const BUILTIN_SPP: u64;

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

/// What a chapter reads from a scene file besides the scene, in its own terms.
pub trait FromSceneFile: Sized {
    /// The scene file at `path` read with the `-D` `defines` ([`read_scene_file`]: checked
    /// against what the chapter renders, its notes printed), with what the chapter takes from
    /// it; a refusal names the file.
    fn read(
        path: &Path,
        defines: &[(String, String)],
        capabilities: &Capabilities,
    ) -> Result<(Scene, Self), CliError>;
}

/// Nothing beyond the scene.
impl FromSceneFile for () {
    fn read(
        path: &Path,
        defines: &[(String, String)],
        capabilities: &Capabilities,
    ) -> Result<(Scene, ()), CliError> {
        Ok((read_scene_file(path, defines, capabilities)?, ()))
    }
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
pub fn drive<C: ChapterRender>(command: RenderCommand<C>) -> anyhow::Result<()> {
    let RenderCommand { chapter, args } = command;
    let (mut scene, from_file, name) = match args.scene_file()? {
        Some(path) => {
            let (scene, from_file) = C::FromFile::read(path, &args.define, &C::CAPABILITIES)?;
            (scene, Some(from_file), path.display().to_string())
        }
        None => {
            let (scene, name) = chapter.builtin()?;
            (scene, None, name)
        }
    };
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
    let prepared = chapter.prepare(scene, from_file, &job)?;
    args.check_outputs()?;
    let Rendered {
        output,
        mut stats,
        detail,
    } = chapter.render(prepared, &job)?;
    stats["scene"] = job.name.into();
    stats["max_depth"] = max_depth.into();
    stats["seed"] = job.seed.into();
    args.write_outputs(&output, stats)?;
    args.report_written(&output, &detail);
    Ok(())
}
