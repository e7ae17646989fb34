//! Agreement with an independent renderer: is our image what Mitsuba 3 computes?
//!
//! One render of each renderer is not enough to tell: both are noisy. The check therefore
//! uses three images of the other renderer, made once and stored next to the scene:
//!
//! - a **reference** at many samples per pixel, close to converged;
//! - a **second render at the sample count we compare**, with another seed.
//!
//! Our render at that sample count is then measured against the reference exactly as the other
//! renderer's own second render is. If ours is unbiased, its [`bias_blocks`] score is as low
//! as the second render's, and if its noise is no worse, so is its RMSE. The stored images make
//! the check repeatable without the other renderer installed: tests and the book use them.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};

use glam::{DVec3, Vec3};
use serde::{Deserialize, Serialize};

use crate::output::figures::comparison_grid;
use crate::output::{OutputError, read_image, write_image, write_text};
use common::image::Image;
use common::metrics::{bias_blocks, mean, rmse};

/// How the stored renders were made, kept in `<name>.json` beside them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RenderProvenance {
    /// The renderer and its variant, e.g. `Mitsuba 3.9.1 (scalar_rgb)`.
    pub renderer: String,
    /// Samples per pixel of the reference.
    pub reference_spp: u64,
    /// Samples per pixel of the second render, the count that is compared.
    pub spp: u64,
    /// Seeds of the reference and of the second render.
    pub seeds: [u64; 2],
}

/// The stored images of one scene by the other renderer.
#[derive(Clone, Debug)]
pub struct ReferenceRenders {
    /// How they were made.
    pub provenance: RenderProvenance,
    /// The near-converged reference.
    pub reference: Image,
    /// A render at [`RenderProvenance::spp`] samples with another seed.
    pub equal_spp: Image,
}

impl ReferenceRenders {
    /// The files of scene `name` in `dir`: `<name>.json`, `<name>.reference.exr` and
    /// `<name>.spp.exr`.
    pub fn paths(dir: &Path, name: &str) -> [PathBuf; 3] {
        [
            dir.join(format!("{name}.json")),
            dir.join(format!("{name}.reference.exr")),
            dir.join(format!("{name}.spp.exr")),
        ]
    }

    /// Reads the stored renders of scene `name` from `dir`.
    pub fn load(dir: &Path, name: &str) -> Result<Self, OutputError> {
        let [json, reference, equal_spp] = Self::paths(dir, name);
        let text = std::fs::read_to_string(&json).map_err(|source| OutputError::Read {
            path: json.clone(),
            source,
        })?;
        let provenance = serde_json::from_str(&text).map_err(|e| OutputError::Malformed {
            path: json.clone(),
            expected: format!("the JSON of a reference render ({e})"),
        })?;
        let renders = Self {
            provenance,
            reference: read_image(&reference)?,
            equal_spp: read_image(&equal_spp)?,
        };
        let size = |image: &Image| (image.width, image.height);
        if size(&renders.reference) != size(&renders.equal_spp) {
            return Err(OutputError::Malformed {
                path: equal_spp,
                expected: "an image of the reference's size".to_string(),
            });
        }
        Ok(renders)
    }

    /// Writes the three files of scene `name` into `dir`, made if missing (each file whole or
    /// not at all).
    pub fn save(&self, dir: &Path, name: &str) -> Result<(), OutputError> {
        let [json, reference, equal_spp] = Self::paths(dir, name);
        std::fs::create_dir_all(dir).map_err(|source| OutputError::Write {
            path: dir.to_owned(),
            source,
        })?;
        let text =
            serde_json::to_string_pretty(&self.provenance).expect("provenance always serialises");
        write_text(&json, &(text + "\n"))?;
        write_image(&reference, &self.reference)?;
        write_image(&equal_spp, &self.equal_spp)
    }

    /// Compares `ours` (at the same sample count) and the stored second render with the
    /// reference.
    pub fn agreement(&self, ours: &Image) -> Agreement {
        Agreement {
            ours: Comparison::new(ours, &self.reference),
            other: Comparison::new(&self.equal_spp, &self.reference),
        }
    }
}

/// One image measured against the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// Root-mean-square error: noise and bias together.
    pub rmse: f64,
    /// The share of 8x8 blocks off by more than 3 standard errors: bias.
    pub bias_blocks: f64,
    /// The image's mean colour.
    pub mean: DVec3,
}

impl Comparison {
    /// Measures `image` against `reference`.
    pub fn new(image: &Image, reference: &Image) -> Self {
        Self {
            rmse: rmse(image, reference),
            bias_blocks: bias_blocks(image, reference),
            mean: mean(image),
        }
    }
}

/// Our render and the other renderer's second render, each against the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Agreement {
    /// Ours.
    pub ours: Comparison,
    /// The other renderer's render at the same sample count.
    pub other: Comparison,
}

impl Agreement {
    /// Whether ours is as unbiased as the other renderer's own second render: its
    /// `bias_blocks` score at most `slack` above the other's (or above 1 %, whichever is
    /// larger, since a handful of 3-sigma blocks in a few hundred happen by chance).
    pub fn unbiased(&self, slack: f64) -> bool {
        self.ours.bias_blocks <= self.other.bias_blocks.max(0.01) + slack
    }

    /// Whether our noise is no worse: our RMSE at most `factor` times the other's.
    pub fn noise_no_worse(&self, factor: f64) -> bool {
        self.ours.rmse <= factor * self.other.rmse
    }

    /// Both, with the workbook's tolerances [`BIAS_SLACK`] and [`NOISE_TOLERANCE`].
    pub fn holds(&self) -> bool {
        self.unbiased(BIAS_SLACK) && self.noise_no_worse(NOISE_TOLERANCE)
    }
}

/// The rows of a Markdown table for the book, one per scene: name, sample count, our RMSE and
/// bias score, the other renderer's, and both mean brightnesses against the reference's.
pub fn agreement_table(rows: &[(String, &ReferenceRenders, Agreement)]) -> String {
    let mut table = String::from(
        "| scene | spp | RMSE ours | RMSE Mitsuba | bias_blocks ours | bias_blocks Mitsuba | mean ours | mean Mitsuba | mean reference |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for (name, renders, agreement) in rows {
        let brightness = |m: DVec3| (m.x + m.y + m.z) / 3.0;
        table.push_str(&format!(
            "| {name} | {} | {:.2e} | {:.2e} | {:.3} | {:.3} | {:.5} | {:.5} | {:.5} |\n",
            renders.provenance.spp,
            agreement.ours.rmse,
            agreement.other.rmse,
            agreement.ours.bias_blocks,
            agreement.other.bias_blocks,
            brightness(agreement.ours.mean),
            brightness(agreement.other.mean),
            brightness(mean(&renders.reference)),
        ));
    }
    table
}

/// Saves the side-by-side figure: ours, the other renderer at the same sample count, its
/// reference, and each difference from the reference magnified `difference_gain` times (so
/// that noise shows; bias would show as a region of one colour).
pub fn write_agreement_figure(
    path: &Path,
    ours_label: &str,
    ours: &Image,
    renders: &ReferenceRenders,
    difference_gain: f32,
    scale: u32,
) -> Result<(), OutputError> {
    let spp = renders.provenance.spp;
    let difference = |image: &Image| Image {
        width: image.width,
        height: image.height,
        pixels: image
            .pixels
            .iter()
            .zip(&renders.reference.pixels)
            .map(|(a, b)| ((*a - *b).abs() * difference_gain).min(Vec3::ONE))
            .collect(),
    };
    let cells = vec![
        (format!("{ours_label}, {spp} spp"), ours.clone()),
        (format!("Mitsuba 3, {spp} spp"), renders.equal_spp.clone()),
        (
            format!("Mitsuba 3, {} spp", renders.provenance.reference_spp),
            renders.reference.clone(),
        ),
        (
            format!("|ours - ref| x {difference_gain}"),
            difference(ours),
        ),
        (
            format!("|Mitsuba - ref| x {difference_gain}"),
            difference(&renders.equal_spp),
        ),
    ];
    comparison_grid(path, &cells, 5, scale)
}

/// How much higher our RMSE may be than the other renderer's second render and still count as
/// "no noisier": the RMSE of a single 64-spp image of the same estimator varies by about 5 %
/// from seed to seed (measured on chapter 03's tent scene over five seeds: 2.59e-4 to
/// 2.81e-4), so two equally noisy renders differ by up to 10-15 %.
pub const NOISE_TOLERANCE: f64 = 1.15;

/// How much higher our `bias_blocks` score may be than the other renderer's (or than 1 %,
/// whichever is larger): a few blocks in a few hundred pass 3 standard errors by chance.
pub const BIAS_SLACK: f64 = 0.005;

/// Samples per pixel of the renders compared: ours and the other renderer's second render.
pub const AGREEMENT_SPP: u64 = 64;

/// Samples per pixel of the other renderer's reference.
pub const REFERENCE_SPP: u64 = 4096;

/// One scene file of a chapter that is checked against Mitsuba 3.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AgreementScene {
    /// The file's stem in the chapter's `scenes/` folder; the stored renders are in
    /// `scenes/mitsuba/` under the same name.
    pub name: &'static str,
    /// What the scene checks, for messages and the book.
    pub checks: &'static str,
    /// The Mitsuba variant that renders it (see [`MITSUBA_VARIANT`](super::MITSUBA_VARIANT)).
    pub variant: &'static str,
}

impl AgreementScene {
    /// The scene file in `scenes_dir`.
    pub fn file(&self, scenes_dir: &Path) -> PathBuf {
        scenes_dir.join(format!("{}.xml", self.name))
    }
}

/// A chapter's render of one scene file at [`AGREEMENT_SPP`] samples per pixel.
pub type RenderSceneFile = fn(&Path) -> Result<Image, String>;

/// `render` of `file`, made once per process: a chapter's render of a file draws the same
/// numbers every time, so a test run that both checks the chapter's agreement and writes its
/// figures, which show the same renders, waits for one render of each scene instead of making
/// two.
fn rendered_once(file: &Path, render: RenderSceneFile) -> Result<Image, String> {
    type Slot = Arc<OnceLock<Result<Image, String>>>;
    static RENDERS: Mutex<BTreeMap<(PathBuf, usize), Slot>> = Mutex::new(BTreeMap::new());
    let slot = RENDERS
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
        .entry((file.to_path_buf(), render as usize))
        .or_default()
        .clone();
    slot.get_or_init(|| render(file)).clone()
}

/// A chapter's agreement set: the scene files it checks against Mitsuba 3, where they are, and
/// the chapter's render of one of them. The tests, the book's figures and the refresh with
/// Mitsuba all start from it.
#[derive(Clone, Copy, Debug)]
pub struct AgreementSet {
    /// What the figures call our render: `"chapter 07"`, say.
    pub label: &'static str,
    /// The chapter's scene folder; the stored renders are in its `mitsuba/` folder.
    pub scenes_dir: &'static str,
    /// The scenes compared, with what each one checks.
    pub scenes: &'static [AgreementScene],
    /// The chapter's render of a scene file.
    pub render: RenderSceneFile,
}

impl AgreementSet {
    /// The chapter's scene folder.
    pub fn scenes_dir(&self) -> &Path {
        Path::new(self.scenes_dir)
    }

    /// Where the stored renders of the scenes are: `scenes/mitsuba/`.
    pub fn stored_renders_dir(&self) -> PathBuf {
        self.scenes_dir().join("mitsuba")
    }

    /// The file of `scene`.
    pub fn file(&self, scene: &AgreementScene) -> PathBuf {
        scene.file(self.scenes_dir())
    }

    /// Our render of `scene` measured against its stored renders.
    pub fn stored(
        &self,
        scene: &AgreementScene,
    ) -> Result<(Image, ReferenceRenders, Agreement), String> {
        let renders = ReferenceRenders::load(&self.stored_renders_dir(), scene.name)
            .map_err(|e| e.to_string())?;
        let ours = rendered_once(&self.file(scene), self.render)?;
        let agreement = renders.agreement(&ours);
        Ok((ours, renders, agreement))
    }

    /// Checks every scene against its stored renders: ours must be as unbiased as the other
    /// renderer's second render ([`BIAS_SLACK`]) and no noisier ([`NOISE_TOLERANCE`]). Returns
    /// a message naming each scene that fails.
    pub fn check_stored(&self) -> Result<(), String> {
        let mut failures = Vec::new();
        for scene in self.scenes {
            let (_, _, agreement) = self.stored(scene)?;
            if !agreement.holds() {
                failures.push(format!("{} ({}): {agreement:?}", scene.name, scene.checks));
            }
        }
        if failures.is_empty() {
            Ok(())
        } else {
            Err(format!(
                "disagreement with Mitsuba on {}",
                failures.join("; ")
            ))
        }
    }

    /// Writes the book's comparison figures `mitsuba-<name>.png` and the table `mitsuba.md`.
    pub fn write_figures(&self, out: &Path) -> Result<(), String> {
        let mut rows = Vec::new();
        for scene in self.scenes {
            let (ours, renders, agreement) = self.stored(scene)?;
            write_agreement_figure(
                &out.join(format!("mitsuba-{}.png", scene.name)),
                self.label,
                &ours,
                &renders,
                10.0,
                2,
            )
            .map_err(|e| e.to_string())?;
            rows.push((scene.name.to_string(), renders, agreement));
        }
        let table: Vec<_> = rows
            .iter()
            .map(|(name, renders, agreement)| (name.clone(), renders, *agreement))
            .collect();
        write_text(&out.join("mitsuba.md"), &agreement_table(&table)).map_err(|e| e.to_string())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn renders() -> ReferenceRenders {
        let reference = Image::filled(16, 16, Vec3::splat(0.5));
        let mut equal_spp = reference.clone();
        for (i, p) in equal_spp.pixels.iter_mut().enumerate() {
            *p += Vec3::splat(if i % 2 == 0 { 0.05 } else { -0.05 });
        }
        ReferenceRenders {
            provenance: RenderProvenance {
                renderer: "test".to_string(),
                reference_spp: 1024,
                spp: 16,
                seeds: [1, 2],
            },
            reference,
            equal_spp,
        }
    }

    #[test]
    fn renders_survive_a_round_trip_through_their_files() {
        let dir = tempfile::tempdir().unwrap();
        let stored = renders();
        stored.save(dir.path(), "scene").unwrap();
        let loaded = ReferenceRenders::load(dir.path(), "scene").unwrap();
        assert_eq!(loaded.provenance, stored.provenance);
        assert_eq!(loaded.reference.pixels, stored.reference.pixels);
        assert_eq!(loaded.equal_spp.pixels, stored.equal_spp.pixels);
        let missing = ReferenceRenders::load(dir.path(), "other").unwrap_err();
        assert!(missing.to_string().contains("other.json"), "{missing}");
    }

    #[test]
    fn a_biased_render_fails_and_a_noisy_unbiased_one_passes() {
        let stored = renders();
        // The same noise pattern, shifted in phase: unbiased, equally noisy.
        let mut fair = stored.reference.clone();
        for (i, p) in fair.pixels.iter_mut().enumerate() {
            *p += Vec3::splat(if i % 2 == 1 { 0.05 } else { -0.05 });
        }
        let agreement = stored.agreement(&fair);
        assert!(agreement.unbiased(0.0) && agreement.noise_no_worse(1.0));
        // The same noise, 4 % brighter overall: every block is off.
        let biased = Image {
            pixels: fair.pixels.iter().map(|p| *p * 1.04).collect(),
            ..fair
        };
        let agreement = stored.agreement(&biased);
        assert_eq!(agreement.ours.bias_blocks, 1.0);
        assert!(!agreement.unbiased(0.1));
        let table = agreement_table(&[("scene".to_string(), &stored, agreement)]);
        assert!(table.lines().nth(2).unwrap().starts_with("| scene | 16 |"));
    }
}
