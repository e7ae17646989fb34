//! The chapter's figures, a first set: NEE off and on, MIS off and on, Russian roulette on
//! and off, each as an image and as error against time on the Cornell box.

use crate::agreement::scenes_dir;
use crate::mis::MisHeuristic;
use crate::options::PathOptions;
use crate::scene_file::convert;
use crate::{Method, render_with};
use anyhow::Context;
use ch03_anti_aliasing::{FilterKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch07_soft_shadows::SoftShadowScene;
use common::image::Image;
use common::metrics::{Technique, plot_error_vs_time, run_convergence, write_convergence_csv};
use common::output::write_image;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use std::path::Path;

/// The techniques compared, by name.
pub fn techniques(file: PathOptions) -> Vec<(&'static str, PathOptions)> {
    let mitsuba = PathOptions {
        nee: true,
        mis: MisHeuristic::Power,
        ..file
    };
    vec![
        (
            "bsdf-only",
            PathOptions {
                nee: false,
                ..mitsuba
            },
        ),
        (
            "nee",
            PathOptions {
                mis: MisHeuristic::None,
                ..mitsuba
            },
        ),
        (
            "nee-mis-balance",
            PathOptions {
                mis: MisHeuristic::Balance,
                ..mitsuba
            },
        ),
        ("nee-mis-power", mitsuba),
        (
            "nee-mis-power-no-rr",
            PathOptions {
                rr_depth: None,
                ..mitsuba
            },
        ),
    ]
}

/// Renders `scene` with `options` at `spp`, independent samples, box filter.
pub fn render(
    scene: &SoftShadowScene,
    options: PathOptions,
    size: (u32, u32),
    spp: u64,
    seed: u64,
) -> Image {
    let settings = RenderSettings::new(size.0, size.1, spp);
    render_with(
        scene,
        Method::new(options),
        &Lens::PINHOLE,
        &settings,
        &IndependentSampler::new(seed),
        &ReconstructionFilter::new(FilterKind::Box, None).expect("the box filter"),
    )
    .image
}

/// Writes every figure into `out`.
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let file = scenes_dir().join("cornell-box.xml");
    let loaded = common::scene::load_scene_file(&file, &[])?;
    let scene = convert(&loaded.scene).map_err(anyhow::Error::msg)?;
    let camera = scene.converted.scene.scene.world.scene.camera;
    let size = if quick {
        (32, 32)
    } else {
        (camera.width, camera.height)
    };
    let (reference_spp, budgets): (u64, &[u64]) = if quick {
        (64, &[1, 4])
    } else {
        (2048, &[1, 4, 16, 64])
    };
    let scene_ref = &scene.converted.scene;
    let reference = render(scene_ref, scene.options, size, reference_spp, 99);
    let techniques = techniques(scene.options);
    for &(name, options) in &techniques {
        let image = render(scene_ref, options, size, 16, 1);
        write_image(&out.join(format!("ch08-{name}-16spp.png")), &image)?;
    }
    let runs: Vec<Technique> = techniques
        .iter()
        .map(|&(name, options)| {
            Technique::new(name, move |spp| render(scene_ref, options, size, spp, 1))
        })
        .collect();
    let records = run_convergence(&runs, budgets, &reference);
    write_convergence_csv(&out.join("ch08-convergence.csv"), &records)?;
    plot_error_vs_time(
        &out.join("ch08-convergence.png"),
        "Cornell box: error against time",
        &records,
    )?;
    eprintln!("ch08 figures written to {}", out.display());
    Ok(())
}
