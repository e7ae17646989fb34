//! The chapter's figures: the three combinations side by side on the zero-variance plane and
//! on the glossy floor, with their errors.

use crate::pixel::Combination;
use crate::render_direct;
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use common::image::Image;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use std::path::{Path, PathBuf};
use workbench::figure_set::{FigureSet, Level};
use workbench::output::{write_image, write_text};

/// Writes every figure of the chapter to `out` (small and fast with `quick`).
pub fn write_all(out: &Path, quick: bool) -> anyhow::Result<()> {
    let mut figures = FigureSet::start("ch10", out, quick)?;
    let level = figures.level();
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
    figures.finish()
}

/// What a figure's errors are measured against.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Reference {
    /// The value every pixel of the plane has: `ρ L` (1, 0.5, 0.25).
    Exact,
    /// A long render with the power heuristic, at the reference sample count.
    Power,
}

/// The chapter's scene file `name`, ready to trace.
fn scene(name: &str) -> anyhow::Result<MotionScene> {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "scenes", &format!("{name}.xml")]
        .iter()
        .collect();
    let loaded = workbench::scene_file::load_scene_file(&path, &[])?;
    MotionScene::new(loaded.scene).map_err(anyhow::Error::msg)
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
    let world = scene(name)?;
    let film = world.scene.film;
    let (width, height) = level.pick((film.width / 2, film.height / 2), (film.width, film.height));
    let render = |spp, seed, combination| -> Image {
        let settings = RenderSettings::new(width, height, spp);
        let sampler = IndependentSampler::new(seed);
        render_direct(&world, &Lens::PINHOLE, &settings, &sampler, combination).image
    };
    let expected = match reference {
        Reference::Exact => Image {
            width,
            height,
            pixels: vec![glam::Vec3::new(1.0, 0.5, 0.25); (width * height) as usize],
        },
        Reference::Power => render(reference_spp, 1_000, Combination::ALL[1]),
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
