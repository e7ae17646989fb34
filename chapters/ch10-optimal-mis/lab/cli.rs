//! `render`: a scene file, the two techniques combined as `--mis` says.
//!
//! A file's `direct` integrator is rendered with one light sample and one BSDF sample (the
//! chapter's subject is the combination of those two; the binary says so when the file asks
//! for other counts); its `path` integrator as chapter 08 renders it, the two techniques
//! combined at every vertex, per pixel and per depth. Each pixel is estimated from its own
//! samples, as under a box filter, for every `--mis`, so that the three are compared on the
//! same footing; a file's wider filter is left aside with a note.

use crate::pixel::Combination;
use crate::{render_direct_with, render_path_with};
use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch05_motion_blur::lab::scene_file::motion_for_render;
use ch05_motion_blur::lab::shot::Shot;
use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::lab::scene_file::PathSide;
use ch08_path_tracing::{MisHeuristic, PathOptions};
use ch09_materials::SceneMaterials;
use common::scene::Scene;
use workbench::capabilities::Capabilities;
use workbench::driver::{ChapterRender, RenderCommand, RenderJob, Rendered, drive};

/// `--mis`: how the light sample and the BSDF sample are combined.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum MisArg {
    /// The weights that minimise the variance, solved per pixel from its samples.
    Optimal,
    /// The same, unbiased: each iteration of a pixel's samples (4, 8, 16, ...) weighted with
    /// those solved from the iterations before it.
    Progressive,
    /// Veach's power heuristic (exponent 2), chapter 08's default.
    Power,
    /// The balance heuristic.
    Balance,
}

impl MisArg {
    /// The lecture's combination this option names.
    pub fn combination(self) -> Combination {
        match self {
            MisArg::Optimal => Combination::Optimal,
            MisArg::Progressive => Combination::Progressive,
            MisArg::Power => Combination::Heuristic(MisHeuristic::Power),
            MisArg::Balance => Combination::Heuristic(MisHeuristic::Balance),
        }
    }
}

/// The options of `render`.
// Its flattened fields are chapters 03 and 04's option groups, documented where defined.
#[allow(missing_docs)]
#[derive(clap::Args, Debug)]
pub struct RenderOptions {
    /// How the light sample and the BSDF sample are combined.
    #[arg(long, value_enum, default_value_t = MisArg::Optimal)]
    pub mis: MisArg,
    #[command(flatten)]
    pub anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    pub lens: LensArgs,
}

/// `render`, through the workbench's driver.
pub fn run_render(command: RenderCommand<RenderOptions>) -> anyhow::Result<()> {
    drive(command)
}

impl ChapterRender for RenderOptions {
    type FromFile = PathSide;
    type Prepared = (Shot, PathOptions);
    const CAPABILITIES: Capabilities = super::CAPABILITIES;
    // Never used: the binary renders scene files only.
    const BUILTIN_SPP: u64 = 16;

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        anyhow::bail!("render needs a scene: --scene FILE.xml")
    }

    fn prepare(
        &self,
        scene: Scene,
        from_file: Option<PathSide>,
        job: &RenderJob,
    ) -> anyhow::Result<(Shot, PathOptions)> {
        let side = from_file.expect("the scene was read from a file");
        let other_counts = side
            .options
            .direct
            .is_some_and(|samples| samples != common::scene::DirectSamples::ONE_EACH);
        if other_counts {
            eprintln!(
                "note: {}: rendered as Mitsuba's `direct` with one light sample and one BSDF \
                 sample, not the counts the file asks for",
                job.name
            );
        }
        let world = motion_for_render(scene, &job.name)?;
        let shot = Shot::new(
            world,
            Some(side.camera),
            &self.anti_aliasing,
            &self.lens,
            None,
            job,
        )?;
        if common::film::Filter::radius(&shot.film.filter) != glam::Vec2::splat(0.5) {
            eprintln!(
                "note: {}: each pixel is estimated from its own samples (a box filter), so \
                 that the optimal weights can be solved per pixel; the file's wider filter is \
                 not used",
                job.name
            );
        }
        Ok((shot, side.options))
    }

    fn render(
        &self,
        (shot, options): (Shot, PathOptions),
        job: &RenderJob,
    ) -> anyhow::Result<Rendered> {
        let combination = self.mis.combination();
        let materials = SceneMaterials::of(&shot.world.scene, FuzzMethod::Lobe);
        // A `direct` integrator, or a path cut after its first bounce, is the direct light.
        let paths = options.direct.is_none() && options.max_depth > 2;
        let render = if paths {
            render_path_with
        } else {
            render_direct_with
        };
        let output = render(
            &shot.world,
            materials,
            options,
            &shot.lens,
            &job.settings,
            &shot.sampler,
            combination,
        );
        let light = if paths { "paths" } else { "direct" };
        let mut stats = serde_json::json!({ "mis": combination.name(), "light": light });
        shot.record_stats(&mut stats);
        Ok(Rendered {
            output,
            stats,
            detail: format!(", --mis {}", combination.name()),
        })
    }
}
