//! The path tracer's `render`: its options (`--no-nee`, `--mis`, `--rr-depth`, with chapters
//! 05 to 07's), and the render of a scene file with the materials a binary knows.

use crate::Method;
use crate::bsdf::Materials;
use crate::dimensions::render_counted;
use crate::lab::scene_file::path_options;
use crate::mis::MisHeuristic;
use crate::options::PathOptions;
use ch05_motion_blur::lab::render_setup::CameraArgs;
use ch06_fuzzy_reflections::lab::cli::FuzzyArgs;
use ch06_fuzzy_reflections::{BelowSurface, FuzzMethod, GlassStrategy};
use ch07_soft_shadows::AreaLights;
use ch07_soft_shadows::lab::cli::LightArgs;
use common::scene::Scene;
use workbench::capabilities::Capabilities;

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

/// The options of `render`: the path's own, and those of chapters 05 to 07 that mean
/// something for a path.
// Its fields are chapters 05 to 08's option groups, documented where they are defined.
#[allow(missing_docs)]
#[derive(clap::Args, Debug)]
pub struct RenderCommand {
    #[command(flatten)]
    pub path: PathArgs,
    #[command(flatten)]
    pub lights: LightArgs,
    #[command(flatten)]
    pub fuzzy: FuzzyArgs,
    #[command(flatten)]
    pub camera: CameraArgs,
}

/// The options of chapters 06 and 07 that mean something for a path: a path follows one ray
/// at glass, chosen by Fresnel, drops lobe directions below the surface, and sends one light
/// sample per bounce.
fn check_path_options(command: &RenderCommand) -> anyhow::Result<()> {
    if command.fuzzy.glass != GlassStrategy::Fresnel {
        anyhow::bail!(
            "--glass {}: a path follows one ray per bounce, chosen at glass by the Fresnel term; only --glass fresnel applies",
            command.fuzzy.glass.name()
        );
    }
    if command.fuzzy.below_surface != BelowSurface::Drop {
        anyhow::bail!(
            "--below-surface {}: the path tracer's BSDFs drop lobe directions below the surface; only --below-surface drop applies",
            command.fuzzy.below_surface.name()
        );
    }
    if command.lights.light_samples != 1 {
        anyhow::bail!(
            "--light-samples {}: the path tracer sends one light sample per bounce, to one light picked uniformly",
            command.lights.light_samples
        );
    }
    Ok(())
}

/// `render`: path-traces the scene file with the materials `materials_of` makes of it (after
/// the chapter's `capabilities` have checked it and put their stand-ins in), and writes the
/// outputs and `--stats`.
pub fn run_render<M: Materials>(
    command: RenderCommand,
    capabilities: &Capabilities,
    materials_of: impl FnOnce(&Scene, FuzzMethod) -> M,
) -> anyhow::Result<()> {
    check_path_options(&command)?;
    let builtin = || {
        anyhow::bail!(
            "render needs a scene: --scene FILE.xml (see chapters/{}/scenes/)",
            capabilities.chapter.package
        )
    };
    // The file's integrator, before --max-depth changes the scene.
    let mut file_options = None;
    let adjust = |scene: Scene| {
        file_options = Some(path_options(&scene));
        command.fuzzy.apply(scene)
    };
    let setup = command.camera.setup(capabilities, builtin, adjust, Ok)?;
    let world = &setup.world;
    let options = crate::PathOptions {
        max_depth: world.scene.max_depth,
        ..command
            .path
            .options(file_options.expect("the scene was read"))
    };
    let args = &command.camera.args;
    args.check_outputs()?;
    let method = Method {
        options,
        light_sampling: command.lights.options().sampling,
        fuzz: command.fuzzy.fuzz,
    };
    // Dimensions are counted only for --stats, where they are written.
    let count = args.stats.is_some();
    let (rendered, dimensions) = render_counted(
        count,
        world,
        method,
        materials_of(&world.scene, method.fuzz),
        &setup.lens,
        &setup.film.settings,
        &setup
            .sampler(setup.default_time_sampling())
            .map_err(anyhow::Error::msg)?,
        &setup.film.filter,
    );
    let mut extra = setup.stats();
    extra["nee"] = options.nee.into();
    extra["mis"] = options.mis.name().into();
    extra["rr_depth"] = serde_json::json!(options.rr_depth);
    extra["area_lights"] = AreaLights::of(&world.scene).lights.len().into();
    extra["point_lights"] = world.scene.point_lights.len().into();
    command.fuzzy.record_stats(&mut extra);
    if let Some(dimensions) = dimensions {
        // What `--stats` writes of them: `{"mean": .., "max": .., "paths": ..}`.
        extra["dimensions_per_path"] = serde_json::json!({
            "mean": dimensions.mean,
            "max": dimensions.max,
            "paths": dimensions.paths,
        });
    }
    args.write_outputs(&rendered, extra)?;
    args.report_written(&rendered, "");
    Ok(())
}
