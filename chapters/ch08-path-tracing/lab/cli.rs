//! The path tracer's `render`, shared by the binaries that path-trace a scene file: its
//! options (`--no-nee`, `--mis`, `--rr-depth`, with those of chapters 03 to 07 that mean
//! something for a path), and the render through the workbench's driver with the materials a
//! binary knows ([`PathMaterials`]): chapter 08's the lecture's, `ch09-materials` every one.

use crate::Method;
use crate::bsdf::Materials;
use crate::dimensions::render_counted;
use crate::lab::scene_file::PathSide;
use crate::mis::MisHeuristic;
use crate::options::PathOptions;
use ch03_anti_aliasing::lab::cli::AntiAliasingArgs;
use ch04_depth_of_field::lab::cli::LensArgs;
use ch05_motion_blur::lab::scene_file::motion_for_render;
use ch05_motion_blur::lab::shot::Shot;
use ch06_fuzzy_reflections::lab::cli::FuzzyArgs;
use ch06_fuzzy_reflections::{BelowSurface, FuzzMethod, GlassStrategy};
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::lab::cli::LightArgs;
use common::scene::Scene;
use std::fmt::Debug;
use std::marker::PhantomData;
use workbench::capabilities::Capabilities;
use workbench::driver::{ChapterRender, RenderCommand, RenderJob, Rendered, drive};

/// How paths are traced.
#[derive(clap::Args, Clone, Debug)]
pub struct PathArgs {
    /// Switch next-event estimation off: light is found only by paths that hit it (point
    /// lights, which no path can hit, then go dark).
    #[arg(long)]
    pub no_nee: bool,
    /// How light samples and BSDF samples are combined. Without next-event estimation there
    /// are no light samples to combine, so it cannot be given with `--no-nee`.
    #[arg(long, value_enum, default_value_t = MisHeuristic::Power, conflicts_with = "no_nee")]
    pub mis: MisHeuristic,
    /// The segment from which Russian roulette may end a path, or `off`
    /// [default: the scene file's, or 5].
    #[arg(long, value_name = "N|off", value_parser = parse_rr_depth, allow_hyphen_values = true)]
    pub rr_depth: Option<RrDepth>,
}

/// `--rr-depth`: a depth, or off.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RrDepth(pub Option<u32>);

/// A depth from 1 to 1000, or `off`.
pub fn parse_rr_depth(text: &str) -> Result<RrDepth, String> {
    if text.trim() == "off" {
        return Ok(RrDepth(None));
    }
    match text.trim().parse::<u32>() {
        Ok(depth) if (1..=1000).contains(&depth) => Ok(RrDepth(Some(depth))),
        _ => Err(format!(
            "`{text}` is neither a depth from 1 to 1000 nor `off`"
        )),
    }
}

impl PathArgs {
    /// `file` (the scene's options) with these arguments applied.
    pub fn options(&self, file: PathOptions) -> PathOptions {
        PathOptions {
            nee: !self.no_nee,
            mis: self.mis,
            rr_depth: self.rr_depth.map_or(file.rr_depth, |d| d.0),
            ..file
        }
    }
}

/// What a path-tracing binary renders with: what it renders of a scene file, and the
/// materials it gives chapter 08's path loop.
pub trait PathMaterials: Debug + 'static {
    /// What the binary renders of a scene file (the rest refused or stood in for).
    const CAPABILITIES: Capabilities;
    /// The materials the path loop is given.
    type Materials: Materials;
    /// The materials of `scene` (their tables made now, before the render), lobes spread as
    /// `fuzz` says.
    fn of(scene: &Scene, fuzz: FuzzMethod) -> Self::Materials;
}

/// The options of `render`: the path's own, and those of chapters 03 to 07 that mean
/// something for a path; `K` says which materials the binary knows.
// Its fields are chapters 03 to 08's option groups, documented where they are defined.
#[allow(missing_docs)]
#[derive(clap::Args, Debug)]
pub struct RenderOptions<K: PathMaterials> {
    #[command(flatten)]
    pub path: PathArgs,
    #[command(flatten)]
    pub lights: LightArgs,
    #[command(flatten)]
    pub fuzzy: FuzzyArgs,
    #[command(flatten)]
    pub anti_aliasing: AntiAliasingArgs,
    #[command(flatten)]
    pub lens: LensArgs,
    #[arg(skip)]
    pub materials: PhantomData<K>,
}

/// The options of chapters 06 and 07 that mean something for a path: a path follows one ray
/// at glass, chosen by Fresnel, drops lobe directions below the surface, and sends one light
/// sample per bounce.
fn check_path_options<K: PathMaterials>(options: &RenderOptions<K>) -> anyhow::Result<()> {
    if options.fuzzy.glass != GlassStrategy::Fresnel {
        anyhow::bail!(
            "--glass {}: a path follows one ray per bounce, chosen at glass by the Fresnel term; only --glass fresnel applies",
            options.fuzzy.glass.name()
        );
    }
    if options.fuzzy.below_surface != BelowSurface::Drop {
        anyhow::bail!(
            "--below-surface {}: the path tracer's BSDFs drop lobe directions below the surface; only --below-surface drop applies",
            options.fuzzy.below_surface.name()
        );
    }
    if options.lights.light_samples != 1 {
        anyhow::bail!(
            "--light-samples {}: the path tracer sends one light sample per bounce, to one light picked uniformly",
            options.lights.light_samples
        );
    }
    Ok(())
}

/// `render`: the path's options checked, then the workbench's driver with the materials `K`.
pub fn run_render<K: PathMaterials>(
    command: RenderCommand<RenderOptions<K>>,
) -> anyhow::Result<()> {
    check_path_options(&command.chapter)?;
    drive(command)
}

impl<K: PathMaterials> ChapterRender for RenderOptions<K> {
    type FromFile = PathSide;
    type Prepared = (Shot, PathOptions);
    const CAPABILITIES: Capabilities = K::CAPABILITIES;
    // Never used: a path-tracing binary renders scene files only.
    const BUILTIN_SPP: u64 = 16;

    fn builtin(&self) -> anyhow::Result<(Scene, String)> {
        anyhow::bail!(
            "render needs a scene: --scene FILE.xml (see chapters/{}/scenes/)",
            K::CAPABILITIES.chapter.package
        )
    }

    fn prepare(
        &self,
        scene: Scene,
        from_file: Option<PathSide>,
        job: &RenderJob,
    ) -> anyhow::Result<(Shot, PathOptions)> {
        let side = from_file.expect("the scene was read from a file");
        let world = motion_for_render(self.fuzzy.apply(scene)?, &job.name)?;
        let options = PathOptions {
            max_depth: world.scene.max_depth,
            ..self.path.options(side.options)
        };
        let shot = Shot::new(
            world,
            Some(side.camera),
            &self.anti_aliasing,
            &self.lens,
            None,
            job,
        )?;
        Ok((shot, options))
    }

    fn render(
        &self,
        (shot, options): (Shot, PathOptions),
        job: &RenderJob,
    ) -> anyhow::Result<Rendered> {
        let method = Method {
            options,
            light_sampling: self.lights.options().sampling,
            fuzz: self.fuzzy.fuzz,
        };
        let world = &shot.world;
        // Dimensions are counted only for --stats, where they are written.
        let (output, dimensions) = render_counted(
            job.writes_stats,
            world,
            method,
            K::of(&world.scene, method.fuzz),
            &shot.lens,
            &job.settings,
            &shot.sampler,
            &shot.film.filter,
        );
        let mut stats = serde_json::json!({
            "nee": options.nee,
            "mis": options.mis.name(),
            "rr_depth": options.rr_depth,
            "area_lights": AreaLights::of(&world.scene).lights.len(),
            "point_lights": world.scene.point_lights.len(),
        });
        shot.record_stats(&mut stats);
        self.fuzzy.record_stats(&mut stats);
        if let Some(dimensions) = dimensions {
            // What `--stats` writes of them: `{"mean": .., "max": .., "paths": ..}`.
            stats["dimensions_per_path"] = serde_json::json!({
                "mean": dimensions.mean,
                "max": dimensions.max,
                "paths": dimensions.paths,
            });
        }
        Ok(Rendered {
            output,
            stats,
            detail: String::new(),
        })
    }
}
