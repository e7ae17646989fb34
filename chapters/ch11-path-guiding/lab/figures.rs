//! The chapter's figures: chapter 08's path tracer and the two guided ones side by side on the
//! door-gap room, with their errors; their error against time there and on chapter 08's
//! Cornell box, where there is little to guide; what the training learnt and cost.

use crate::guided_bsdf::BSDF_FRACTION;
use crate::render_guided;
use crate::training::GuidingOptions;
use crate::{GuidedRender, GuidingTarget, PassWeighting};
use ch04_depth_of_field::Lens;
use ch09_materials::lab::figure_scene::FigureScene;
use common::film::PixelBoxFilter;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use std::path::Path;
use workbench::convergence::{
    Technique, convergence_markdown, plot_error_vs_time, run_convergence, write_convergence_csv,
};
use workbench::figure_set::{FigureSet, Level};
use workbench::output::{write_image, write_text};

/// Writes every figure of the chapter to `out` (small and fast with `quick`).
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch11", out, quick)?;
    let level = figures.level();
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.agreement(&crate::lab::agreement::AGREEMENT)?;
    figures.make("the door-gap room side by side", |out| {
        side_by_side(out, "door-gap", level)
    })?;
    for (name, file, what) in EQUAL_TIME_SCENES {
        figures.make(what, |out| error_against_time(out, name, file, level))?;
    }
    figures.finish()
}

/// The scenes whose error is measured against time: the door-gap room and the glossy floor lit
/// from a bright patch of ceiling, where guiding should pay, and chapter 08's Cornell box, lit
/// from a panel every point sees, where it has little to learn and its cost shows.
const EQUAL_TIME_SCENES: [(&str, &str, &str); 3] = [
    (
        "door-gap",
        "scenes/door-gap.xml",
        "the error against time: the door-gap room",
    ),
    (
        "glossy-indirect",
        "scenes/glossy-indirect.xml",
        "the error against time: a glossy floor in indirect light",
    ),
    (
        "cornell-box",
        "../ch08-path-tracing/scenes/cornell-box.xml",
        "the error against time: the Cornell box",
    ),
];

/// The three ways of choosing directions, by their names in the figures.
const METHODS: [(&str, Option<GuidingTarget>); 3] = [
    ("off", None),
    ("radiance", Some(GuidingTarget::Radiance)),
    ("variance", Some(GuidingTarget::Variance)),
];

/// A scene file rendered again and again, as the figures render it ([`FigureScene`]), with the
/// file's path options.
struct Renders {
    scene: FigureScene,
}

impl Renders {
    /// The scene file `file` (relative to the crate), ready to render.
    fn of(file: &str, level: Level) -> anyhow::Result<Self> {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
        Ok(Self {
            scene: FigureScene::load(&path, level)?,
        })
    }

    /// The render of a budget of `spp` samples per pixel with `seed`, guided towards `target`
    /// (not at all with `None`): with guiding, the budget pays for training and final pass.
    fn render(&self, spp: u64, seed: u64, target: Option<GuidingTarget>) -> GuidedRender {
        self.render_with(spp, seed, target, None, PassWeighting::ByLearning)
    }

    /// [`render`](Self::render) with the BSDF fraction fixed at `bsdf_fraction` everywhere, if
    /// given, rather than learnt, and the passes averaged as `passes` says.
    fn render_with(
        &self,
        spp: u64,
        seed: u64,
        target: Option<GuidingTarget>,
        bsdf_fraction: Option<f32>,
        passes: PassWeighting,
    ) -> GuidedRender {
        let scene = &self.scene;
        let settings = RenderSettings::new(scene.width, scene.height, spp);
        let pixels = u64::from(scene.width) * u64::from(scene.height);
        render_guided(
            &scene.world,
            scene.materials.clone(),
            scene.options,
            target.map(|t| GuidingOptions {
                bsdf_fraction,
                passes,
                ..GuidingOptions::for_image(t, pixels)
            }),
            &Lens::PINHOLE,
            &settings,
            &IndependentSampler::new(seed),
            &PixelBoxFilter,
        )
    }
}

/// The scene `name` with each method at one budget, each image written as `NAME-METHOD.png`,
/// with a table of their RMSE against a long unguided render and their times (`NAME.md`), and
/// the training of the variance-aware guide iteration by iteration (`NAME-training.md`).
fn side_by_side(out: &Path, name: &str, level: Level) -> anyhow::Result<()> {
    let renders = Renders::of(&format!("scenes/{name}.xml"), level)?;
    let reference = renders
        .render(level.pick(256, 4096), 1_000, None)
        .output
        .image;
    let spp = level.pick(16, 256);
    // The room is dark (its light comes through a gap): the images are shown brighter, by the
    // whole stops that bring the reference's mean to a mid grey.
    let stops = exposure_stops(&reference);
    let mut table = String::from(
        "| guiding | samples per pixel in the image | seconds | RMSE |\n|---|---:|---:|---:|\n",
    );
    let mut training = String::new();
    for (method, target) in METHODS {
        let rendered = renders.render(spp, 1, target);
        let image = &rendered.output.image;
        let mut shown = image.clone();
        for pixel in &mut shown.pixels {
            *pixel *= 2f32.powi(stops);
        }
        write_image(&out.join(format!("{name}-{method}.png")), &shown)?;
        let rmse = common::metrics::rmse(image, &reference);
        table += &format!(
            "| {method} | {} | {:.2} | {rmse:.3e} |\n",
            rendered.output.stats.spp, rendered.output.stats.seconds
        );
        if target == Some(GuidingTarget::Variance)
            && let Some(trained) = &rendered.training
        {
            training = String::from(
                "| iteration | samples per pixel | seconds | spatial leaves | quadtree nodes | memory (kB) | BSDF fraction learnt | weight in the image |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n",
            );
            for (k, i) in trained.iterations.iter().enumerate() {
                training += &format!(
                    "| {} | {} | {:.3} | {} | {} | {:.0} | {} | {} |\n",
                    k + 1,
                    i.spp,
                    i.seconds,
                    i.leaves,
                    i.quadtree_nodes,
                    i.memory_bytes as f64 / 1024.0,
                    i.learnt_fraction
                        .map_or_else(|| "-".to_string(), |f| format!("{f:.3}")),
                    weight_of(&rendered.pass_weights, k),
                );
            }
            let last = trained.iterations.len();
            let training_seconds: f64 = trained.iterations.iter().map(|i| i.seconds).sum();
            training += &format!(
                "| final pass | {} | {:.3} | | | | | {} |\n",
                if rendered.pass_weights.is_empty() {
                    rendered.output.stats.spp
                } else {
                    rendered.output.stats.spp.saturating_sub(trained.spp)
                },
                (rendered.output.stats.seconds - training_seconds).max(0.0),
                weight_of(&rendered.pass_weights, last),
            );
        }
    }
    table += &format!(
        "\nThe images are shown {stops} stops ({}x) brighter than rendered; the RMSE is the \
         rendered images'.\n",
        1u32 << stops.clamp(0, 31)
    );
    write_text(&out.join(format!("{name}.md")), &table)?;
    write_text(&out.join(format!("{name}-training.md")), &training)?;
    Ok(())
}

/// The three methods on the scene file `file` (relative to the crate) at growing budgets,
/// timed (training included), against a long unguided render: `NAME-error-time.csv`, its
/// log-log plot `NAME-error-time.png`, and the table `NAME-error-time.md`.
fn error_against_time(out: &Path, name: &str, file: &str, level: Level) -> anyhow::Result<()> {
    let renders = Renders::of(file, level)?;
    let reference = renders
        .render(level.pick(256, 4096), 1_000, None)
        .output
        .image;
    let renders = &renders;
    let techniques: Vec<Technique> = METHODS
        .into_iter()
        .map(|(method, target)| {
            Technique::new(method, move |spp| {
                renders.render(spp, 1, target).output.image
            })
        })
        .collect();
    let budgets: &[u64] = level.pick(&[4, 16], &[4, 16, 64, 256, 1024]);
    let records = run_convergence(&techniques, budgets, &reference);
    write_convergence_csv(&out.join(format!("{name}-error-time.csv")), &records)?;
    plot_error_vs_time(
        &out.join(format!("{name}-error-time.png")),
        &format!("{name}: error against time, path guiding"),
        &records,
    )?;
    write_text(
        &out.join(format!("{name}-error-time.md")),
        &convergence_markdown(&records, "samples per pixel (the budget)"),
    )?;
    let top = budgets.last().copied().unwrap_or(1);
    write_text(
        &out.join(format!("{name}-equal-time.md")),
        &equal_time_table(renders, top),
    )?;
    Ok(())
}

/// Each method at a budget of `spp`, its error measured without a reference: an unbiased
/// image's mean squared error is its variance, and two renders with different seeds differ by
/// twice that. Variance falls as one over the time spent, so variance times seconds is the
/// same at any budget, and divided by the unguided method's it is the ratio of their errors
/// at equal time (below 1, guiding wins), free of the long reference's own noise, which the
/// error-against-time table adds to every method alike.
///
/// The guided methods appear three times: with the render's defaults (the BSDF fraction
/// learnt, the passes averaged by their samples and what their guides learnt from), with the
/// fraction pinned at a half (Müller et al. 2017), and pinned with the passes averaged by their
/// measured noise (Müller et al. 2019: consistent rather than unbiased).
fn equal_time_table(renders: &Renders, spp: u64) -> String {
    let (radiance, variance) = (Some(GuidingTarget::Radiance), Some(GuidingTarget::Variance));
    let half = Some(BSDF_FRACTION);
    let (by_learning, by_noise) = (PassWeighting::ByLearning, PassWeighting::ByMeasuredNoise);
    let variants = [
        ("radiance, BSDF fraction 0.5", radiance, half, by_learning),
        ("variance, BSDF fraction 0.5", variance, half, by_learning),
        (
            "radiance, fraction 0.5, passes by noise",
            radiance,
            half,
            by_noise,
        ),
        (
            "variance, fraction 0.5, passes by noise",
            variance,
            half,
            by_noise,
        ),
    ];
    let rows: Vec<(&str, f64, f64)> = METHODS
        .into_iter()
        .map(|(method, target)| (method, target, None, by_learning))
        .chain(variants)
        .map(|(method, target, fraction, passes)| {
            let render = |seed| renders.render_with(spp, seed, target, fraction, passes);
            let (a, b) = (render(11), render(12));
            let variance = common::metrics::rmse(&a.output.image, &b.output.image).powi(2) / 2.0;
            let seconds = 0.5 * (a.output.stats.seconds + b.output.stats.seconds);
            (method, seconds, variance)
        })
        .collect();
    let off = rows[0].1 * rows[0].2;
    let mut table = format!(
        "| guiding (budget {spp} samples per pixel) | seconds | variance | variance × seconds | \
         MSE at equal time, over guiding off's |\n|---|---:|---:|---:|---:|\n"
    );
    for (method, seconds, variance) in rows {
        let product = variance * seconds;
        table += &format!(
            "| {method} | {seconds:.2} | {variance:.3e} | {product:.3e} | {:.2} |\n",
            product / off
        );
    }
    table
}

/// Pass `k`'s weight in the image, or a dash when the final pass alone makes it.
fn weight_of(weights: &[f64], k: usize) -> String {
    weights
        .get(k)
        .map_or_else(|| "-".to_string(), |w| format!("{w:.3}"))
}

/// The whole stops (at least 0) by which `reference` must be brightened for its mean to be a
/// mid grey (0.18).
fn exposure_stops(reference: &common::image::Image) -> i32 {
    let mean = reference.pixels.iter().map(|p| f64::from(p.y)).sum::<f64>()
        / reference.pixels.len().max(1) as f64;
    if mean.is_nan() || mean <= 0.0 {
        return 0;
    }
    (0.18 / mean).log2().round().clamp(0.0, 20.0) as i32
}
