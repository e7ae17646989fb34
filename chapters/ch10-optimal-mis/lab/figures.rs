//! The chapter's figures: the three combinations side by side on the zero-variance plane and
//! on the glossy floor, with their errors, and their error against time on three scenes.

use crate::pixel::Combination;
use crate::{render_direct_with, render_path_with};
use ch04_depth_of_field::Lens;
use ch08_path_tracing::{MisHeuristic, PathOptions};
use ch09_materials::lab::figure_scene::FigureScene;
use common::image::Image;
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
    let mut figures = FigureSet::start("ch10", out, quick)?;
    let level = figures.level();
    figures.make("the diagrams", |out| {
        crate::lab::diagrams::write_all(&out.join("diagrams"))
    })?;
    figures.make("the zero-variance plane", |out| {
        side_by_side(out, "plane-under-sky", 4, 4, level, Reference::Exact)
    })?;
    figures.make("the glossy floor", |out| {
        side_by_side(
            out,
            "glossy-floor",
            16,
            level.pick(256, 4096),
            level,
            Reference::Power,
        )
    })?;
    for (scene_name, file, what) in EQUAL_TIME_SCENES {
        figures.make(what, |out| {
            error_against_time(out, scene_name, file, Light::Direct, level)
        })?;
    }
    figures.make("the error against time: the Cornell box's paths", |out| {
        error_against_time(
            out,
            "cornell-box-paths",
            "../ch08-path-tracing/scenes/cornell-box.xml",
            Light::Paths,
            level,
        )
    })?;
    figures.agreement(&crate::lab::agreement::AGREEMENT)?;
    figures.finish()
}

/// The scenes whose error is measured against time: chapter 09's Veach plates and chapter
/// 08's Cornell box, lit directly, and the chapter's glossy floor.
const EQUAL_TIME_SCENES: [(&str, &str, &str); 3] = [
    (
        "veach-plates",
        "../ch09-materials/scenes/veach-plates.xml",
        "the error against time: Veach's plates",
    ),
    (
        "cornell-box",
        "../ch08-path-tracing/scenes/cornell-box.xml",
        "the error against time: the Cornell box",
    ),
    (
        "glossy-floor",
        "scenes/glossy-floor.xml",
        "the error against time: the glossy floor",
    ),
];

/// What the figures render of a scene file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Light {
    /// The light straight from the lights at the surface the camera sees.
    Direct,
    /// Whole paths, as the file's `path` integrator asks, combined at every vertex per depth.
    Paths,
}

/// The combinations on the scene file `file` (relative to the crate) at growing sample
/// counts, timed, against a long render with the power heuristic, the lights the camera sees
/// left out: `NAME-error-time.csv`, its
/// log-log plot `NAME-error-time.png`, and the table `NAME-error-time.md`.
fn error_against_time(
    out: &Path,
    name: &str,
    file: &str,
    light: Light,
    level: Level,
) -> anyhow::Result<()> {
    // The lights the camera sees are left out (Mitsuba's `hide_emitters`): the noise of their
    // edges is the same for every combination and would drown the difference.
    let renders = Renders::of(file, level, light, |file_options| PathOptions {
        hide_emitters: true,
        ..match light {
            Light::Direct => PathOptions::default(),
            Light::Paths => file_options,
        }
    })?;
    let render = |spp, seed, combination| renders.render(spp, seed, combination);
    let reference_spp = match light {
        Light::Direct => level.pick(1024, 4096),
        Light::Paths => level.pick(256, 4096),
    };
    let reference = render(reference_spp, 1_000, POWER);
    let techniques: Vec<Technique> = Combination::ALL
        .into_iter()
        .map(|combination| {
            Technique::new(combination.name(), move |spp| render(spp, 1, combination))
        })
        .collect();
    let budgets: &[u64] = level.pick(&[1, 4, 16], &[1, 4, 16, 64, 256]);
    let records = run_convergence(&techniques, budgets, &reference);
    write_convergence_csv(&out.join(format!("{name}-error-time.csv")), &records)?;
    plot_error_vs_time(
        &out.join(format!("{name}-error-time.png")),
        &format!(
            "{name}: error against time, {}",
            match light {
                Light::Direct => "direct light",
                Light::Paths => "whole paths, combined per depth",
            }
        ),
        &records,
    )?;
    write_text(
        &out.join(format!("{name}-error-time.md")),
        &convergence_markdown(&records, "samples per pixel"),
    )?;
    Ok(())
}

/// What a figure's errors are measured against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Reference {
    /// The value every pixel of the plane has: `ρ L` (1, 0.5, 0.25).
    Exact,
    /// A long render with the power heuristic, at the reference sample count.
    Power,
}

/// The power heuristic, what the references are rendered with.
const POWER: Combination = Combination::Heuristic(MisHeuristic::Power);

/// A scene file rendered again and again, as the figures render it ([`FigureScene`]): its
/// direct light or its paths, with `options`.
struct Renders {
    scene: FigureScene,
    options: PathOptions,
    light: Light,
}

impl Renders {
    /// The scene file `file` (relative to the crate), ready to render `light` with the
    /// options `options` makes of the file's.
    fn of(
        file: &str,
        level: Level,
        light: Light,
        options: impl FnOnce(PathOptions) -> PathOptions,
    ) -> anyhow::Result<Self> {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(file);
        let scene = FigureScene::load(&path, level)?;
        let options = options(scene.options);
        Ok(Self {
            scene,
            options,
            light,
        })
    }

    /// The image at `spp` samples per pixel with `seed`, combined as `combination` says.
    fn render(&self, spp: u64, seed: u64, combination: Combination) -> Image {
        let settings = RenderSettings::new(self.scene.width, self.scene.height, spp);
        let sampler = IndependentSampler::new(seed);
        let render = match self.light {
            Light::Direct => render_direct_with,
            Light::Paths => render_path_with,
        };
        render(
            &self.scene.world,
            self.scene.materials.clone(),
            self.options,
            &Lens::PINHOLE,
            &settings,
            &sampler,
            combination,
        )
        .image
    }
}

/// The scene `name` rendered with each combination at `spp` samples per pixel (half size at
/// the quick level), each image written as `NAME-COMBINATION.png`, and a table of their RMSE
/// against `reference` (rendered with `reference_spp` where it is a render) as `NAME.md`.
fn side_by_side(
    out: &Path,
    name: &str,
    spp: u64,
    reference_spp: u64,
    level: Level,
    reference: Reference,
) -> anyhow::Result<()> {
    let renders = Renders::of(&format!("scenes/{name}.xml"), level, Light::Direct, |_| {
        PathOptions::default()
    })?;
    let (width, height) = (renders.scene.width, renders.scene.height);
    let render = |spp, seed, combination| renders.render(spp, seed, combination);
    let expected = match reference {
        Reference::Exact => Image {
            width,
            height,
            pixels: vec![glam::Vec3::new(1.0, 0.5, 0.25); (width * height) as usize],
        },
        Reference::Power => render(reference_spp, 1_000, POWER),
    };
    let mut table = String::from("| combination | RMSE |\n|---|---:|\n");
    for combination in Combination::ALL {
        let image = render(spp, 1, combination);
        write_image(
            &out.join(format!("{name}-{}.png", combination.name())),
            &image,
        )?;
        let rmse = common::metrics::rmse(&image, &expected);
        table += &format!("| {} | {rmse:.3e} |\n", combination.name());
    }
    write_text(&out.join(format!("{name}.md")), &table)?;
    Ok(())
}
