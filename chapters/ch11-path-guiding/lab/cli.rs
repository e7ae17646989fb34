//! `render`: a scene file path traced as chapter 08 does, every material chapter 09 knows,
//! guided as `--guiding` says. With guiding, the budget (`--spp` or `--time`) pays for the
//! training and the final pass together, and `--stats` writes what each training iteration
//! learnt and cost.

use crate::training::GuidingOptions;
use crate::{GuidingTarget, PassWeighting, render_guided};
use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch05_motion_blur::lab::scene_file::motion_for_render;
use ch05_motion_blur::lab::shot::Shot;
use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::PathOptions;
use ch08_path_tracing::lab::scene_file::PathSide;
use ch09_materials::SceneMaterials;
use common::scene::Scene;
use workbench::capabilities::Capabilities;
use workbench::driver::{ChapterRender, RenderCommand, RenderJob, Rendered, drive};

/// `--guiding`: what, if anything, guides the directions.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum GuidingArg {
    /// Chapter 08's path tracer: every direction from the BSDF.
    Off,
    /// Guides learnt from the light arriving (Müller et al. 2017).
    Radiance,
    /// Guides learnt from the second moment of the pixel's estimate (Rath et al. 2020).
    Variance,
}

impl GuidingArg {
    /// The lecture's target this option names (`None` for off).
    pub fn target(self) -> Option<GuidingTarget> {
        match self {
            GuidingArg::Off => None,
            GuidingArg::Radiance => Some(GuidingTarget::Radiance),
            GuidingArg::Variance => Some(GuidingTarget::Variance),
        }
    }

    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        self.target().map_or("off", GuidingTarget::name)
    }
}

/// `--combine-passes`: how the training's images join the final pass's.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CombineArg {
    /// The final pass alone makes the image; the training's images are thrown away.
    Final,
    /// Every pass weighed by its samples: all the budget in the image, still unbiased.
    Samples,
    /// Every pass weighed by its samples times the square root of the samples its guides
    /// learnt from: the better guided passes count for more, still unbiased.
    Learning,
    /// Every pass weighed by its measured noise (Müller et al. 2019): less noise where the
    /// early passes are poor, but the image is consistent rather than unbiased.
    Noise,
}

impl CombineArg {
    /// The weighting this option names.
    pub fn weighting(self) -> PassWeighting {
        match self {
            CombineArg::Final => PassWeighting::FinalOnly,
            CombineArg::Samples => PassWeighting::BySamples,
            CombineArg::Learning => PassWeighting::ByLearning,
            CombineArg::Noise => PassWeighting::ByMeasuredNoise,
        }
    }

    /// Its name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            CombineArg::Final => "final",
            CombineArg::Samples => "samples",
            CombineArg::Learning => "learning",
            CombineArg::Noise => "noise",
        }
    }
}

/// The options of `render`.
// Its flattened fields are chapters 03 and 04's option groups, documented where defined.
#[allow(missing_docs)]
#[derive(clap::Args, Debug)]
pub struct RenderOptions {
    /// What guides the directions.
    #[arg(long, value_enum, default_value_t = GuidingArg::Variance)]
    pub guiding: GuidingArg,
    /// The probability of drawing a direction from the BSDF rather than the guide (0 to 1),
    /// the same everywhere; without it each region of the scene learns its own.
    #[arg(long, value_parser = fraction, allow_hyphen_values = true)]
    pub bsdf_fraction: Option<f32>,
    /// How the training's images join the final pass's in the image.
    #[arg(long, value_enum, default_value_t = CombineArg::Learning)]
    pub combine_passes: CombineArg,
    #[command(flatten)]
    pub anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    pub lens: LensArgs,
}

/// A probability that leaves both techniques a chance: strictly between 0 and 1.
fn fraction(s: &str) -> Result<f32, String> {
    let value: f32 = s.parse().map_err(|_| format!("`{s}` is not a number"))?;
    if value > 0.0 && value < 1.0 {
        Ok(value)
    } else {
        Err(format!(
            "{s} is not strictly between 0 and 1: with 0 the guide alone draws, and misses \
             what it has not learnt; with 1 nothing is guided (use --guiding off)"
        ))
    }
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
        let world = motion_for_render(scene, &job.name)?;
        let shot = Shot::new(
            world,
            Some(side.camera),
            &self.anti_aliasing,
            &self.lens,
            None,
            job,
        )?;
        Ok((shot, side.options))
    }

    fn render(
        &self,
        (shot, options): (Shot, PathOptions),
        job: &RenderJob,
    ) -> anyhow::Result<Rendered> {
        let world = &shot.world;
        let pixels = u64::from(job.settings.width) * u64::from(job.settings.height);
        let guiding = self.guiding.target().map(|target| GuidingOptions {
            bsdf_fraction: self.bsdf_fraction,
            passes: self.combine_passes.weighting(),
            ..GuidingOptions::for_image(target, pixels)
        });
        let rendered = render_guided(
            world,
            SceneMaterials::of(&world.scene, FuzzMethod::Lobe),
            options,
            guiding,
            &shot.lens,
            &job.settings,
            &shot.sampler,
            &shot.film.filter,
        );
        let mut stats = serde_json::json!({
            "guiding": self.guiding.name(),
            "bsdf_fraction": guiding.map(|g| match g.bsdf_fraction {
                Some(f) => serde_json::json!(f),
                None => serde_json::json!("learnt"),
            }),
        });
        if let Some(trained) = &rendered.training {
            stats["training"] = serde_json::json!({
                "spp": trained.spp,
                "combine_passes": self.combine_passes.name(),
                "pass_weights": rendered.pass_weights,
                "learnt_fractions": learnt_fractions(&trained.guides),
                "seconds": trained.iterations.iter().map(|i| i.seconds).sum::<f64>(),
                "iterations": trained.iterations.iter().map(|i| serde_json::json!({
                    "spp": i.spp,
                    "seconds": i.seconds,
                    "rays": i.rays,
                    "spatial_leaves": i.leaves,
                    "quadtree_nodes": i.quadtree_nodes,
                    "memory_bytes": i.memory_bytes,
                    "learnt_fraction": i.learnt_fraction,
                })).collect::<Vec<_>>(),
            });
        }
        shot.record_stats(&mut stats);
        Ok(Rendered {
            output: rendered.output,
            stats,
            detail: format!(", --guiding {}", self.guiding.name()),
        })
    }
}

/// The learnt BSDF fractions over the spatial leaves that learnt one: the least, the mean
/// weighted by the samples each learnt from, the most, and how many leaves.
pub fn learnt_fractions(guides: &crate::spatial::SpatialTree) -> serde_json::Value {
    let learnt: Vec<(f64, f64)> = guides
        .guides
        .iter()
        .filter(|g| g.fraction.steps() > 0)
        .map(|g| {
            (
                f64::from(g.fraction.fraction()),
                f64::from(g.fraction.steps()),
            )
        })
        .collect();
    let steps: f64 = learnt.iter().map(|l| l.1).sum();
    if learnt.is_empty() || steps <= 0.0 {
        return serde_json::Value::Null;
    }
    serde_json::json!({
        "leaves": learnt.len(),
        "min": learnt.iter().map(|l| l.0).fold(f64::INFINITY, f64::min),
        "mean": learnt.iter().map(|l| l.0 * l.1).sum::<f64>() / steps,
        "max": learnt.iter().map(|l| l.0).fold(f64::NEG_INFINITY, f64::max),
    })
}
