//! Rendering a scene file with Mitsuba 3, to check our renders against an established renderer.
//!
//! Mitsuba 3 is a Python package (`pip install mitsuba`); nothing here needs it except the
//! functions that call it, which only the ignored agreement tests and the reference-refreshing
//! runs use. The environment variable [`MITSUBA_PYTHON`] names the Python that has it.

use std::path::Path;
use std::process::Command;

use super::comparison::{
    AGREEMENT_SPP, AgreementSet, REFERENCE_SPP, ReferenceRenders, RenderProvenance,
};
use crate::output::read_image;
use common::image::Image;

/// The environment variable naming a Python interpreter with the `mitsuba` package.
pub const MITSUBA_PYTHON: &str = "MITSUBA_PYTHON";

/// The Mitsuba variant used by default: RGB rendering on the CPU, like ours (spectral variants
/// turn RGB into spectra and differ slightly).
pub const MITSUBA_VARIANT: &str = "scalar_rgb";

/// The just-in-time compiled RGB variant. Its film evaluates the reconstruction filter
/// exactly, where the scalar variant looks it up in a table of 31 steps per radius, each step
/// holding the value at its inner end, so a tent of radius 1.5 weighs a sample 1 pixel away
/// with 0.355 instead of 1/3: a slightly wider filter, which shows as a bias along edges.
/// Scenes with a tent or Gaussian filter are compared with this variant. It needs a working
/// LLVM library.
pub const MITSUBA_JIT_VARIANT: &str = "llvm_ad_rgb";

/// Loads the scene (argv 1) in the variant (argv 5) with the sample count (argv 3) and `-D`
/// parameters (argv 6...), renders it with the seed (argv 4) and writes a linear PFM (argv 2).
/// Prints Mitsuba's version.
const RENDER_SCRIPT: &str = r#"
import sys, numpy as np, mitsuba as mi
mi.set_variant(sys.argv[5])
params = dict(kv.split("=", 1) for kv in sys.argv[6:])
scene = mi.load_file(sys.argv[1], spp=int(sys.argv[3]), **params)
img = np.array(mi.render(scene, seed=int(sys.argv[4])), dtype=np.float32)[:, :, :3]
h, w, _ = img.shape
with open(sys.argv[2], "wb") as f:
    f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
    f.write(np.ascontiguousarray(img[::-1]).astype("<f4").tobytes())
print(mi.__version__)
"#;

/// The Python named by [`MITSUBA_PYTHON`], if the variable is set.
pub fn mitsuba_python() -> Option<String> {
    std::env::var(MITSUBA_PYTHON).ok().filter(|p| !p.is_empty())
}

/// Renders `scene` with Mitsuba 3's `variant` at `spp` samples per pixel and `seed`, with scene
/// parameters `defines` (`name=value`, as `-D` takes them). Returns the image and Mitsuba's
/// version.
///
/// The scene must declare `<default name="spp" .../>` and use `$spp` for its sample count.
pub fn render_with_mitsuba(
    python: &str,
    variant: &str,
    scene: &Path,
    spp: u64,
    seed: u64,
    defines: &[String],
) -> Result<(Image, String), String> {
    let dir = tempfile::tempdir().map_err(|e| format!("no temporary directory: {e}"))?;
    let out = dir.path().join("mitsuba.pfm");
    let output = Command::new(python)
        .arg("-c")
        .arg(RENDER_SCRIPT)
        .arg(scene)
        .arg(&out)
        .arg(spp.to_string())
        .arg(seed.to_string())
        .arg(variant)
        .args(defines)
        .output()
        .map_err(|e| format!("cannot run {python}: {e}"))?;
    if !output.status.success() {
        return Err(format!(
            "Mitsuba failed on {}: {}",
            scene.display(),
            String::from_utf8_lossy(&output.stderr)
        ));
    }
    // The version is the script's last line; Mitsuba's warnings (a bitmap brighter than 1)
    // may come before it on the same stream.
    let stdout = String::from_utf8_lossy(&output.stdout);
    let version = stdout.lines().last().unwrap_or_default().trim().to_string();
    let image = read_image(&out).map_err(|e| e.to_string())?;
    Ok((image, version))
}

/// Makes the stored renders of `scene` with Mitsuba's `variant`: a reference at
/// `reference_spp` (seed 1) and a second render at `spp` (seed 2).
pub fn make_reference_renders(
    python: &str,
    variant: &str,
    scene: &Path,
    spp: u64,
    reference_spp: u64,
    defines: &[String],
) -> Result<ReferenceRenders, String> {
    let seeds = [1, 2];
    let (reference, version) =
        render_with_mitsuba(python, variant, scene, reference_spp, seeds[0], defines)?;
    let (equal_spp, _) = render_with_mitsuba(python, variant, scene, spp, seeds[1], defines)?;
    Ok(ReferenceRenders {
        provenance: RenderProvenance {
            renderer: format!("Mitsuba {version} ({variant})"),
            reference_spp,
            spp,
            seeds,
        },
        reference,
        equal_spp,
    })
}

/// Renders every scene of `set` (or, given `only`, those whose names it lists, separated by
/// commas) afresh with Mitsuba, compares ours with the new renders (as
/// [`AgreementSet::check_stored`] does with the stored ones) and, with `update`, stores them.
/// Returns one line per scene with the numbers, and an error naming the scenes that disagree.
pub fn refresh_agreement(
    python: &str,
    set: &AgreementSet,
    update: bool,
    only: Option<&str>,
) -> Result<Vec<String>, String> {
    refresh_agreement_at(python, set, update, only, AGREEMENT_SPP, REFERENCE_SPP)
}

/// [`refresh_agreement`] with Mitsuba's second render at `spp` samples per pixel and its
/// reference at `reference_spp`, for a set whose scenes are compared at other counts than
/// [`AGREEMENT_SPP`] (noise too skewed for the block test at that count).
pub fn refresh_agreement_at(
    python: &str,
    set: &AgreementSet,
    update: bool,
    only: Option<&str>,
    spp: u64,
    reference_spp: u64,
) -> Result<Vec<String>, String> {
    let mut lines = Vec::new();
    let mut failures = Vec::new();
    let chosen = set
        .scenes
        .iter()
        .filter(|scene| only.is_none_or(|names| names.split(',').any(|n| n == scene.name)));
    for scene in chosen {
        let file = set.file(scene);
        let renders =
            make_reference_renders(python, scene.variant, &file, spp, reference_spp, &[])?;
        let agreement = renders.agreement(&(set.render)(&file)?);
        lines.push(format!(
            "{} ({}): RMSE ours {:.2e} / Mitsuba {:.2e}, bias_blocks ours {:.4} / Mitsuba {:.4}",
            scene.name,
            scene.checks,
            agreement.ours.rmse,
            agreement.other.rmse,
            agreement.ours.bias_blocks,
            agreement.other.bias_blocks
        ));
        if !agreement.holds() {
            failures.push(scene.name);
        }
        if update {
            renders
                .save(&set.stored_renders_dir(), scene.name)
                .map_err(|e| e.to_string())?;
        }
    }
    if failures.is_empty() {
        Ok(lines)
    } else {
        Err(format!(
            "{}\ndisagreement on {failures:?}",
            lines.join("\n")
        ))
    }
}

/// The environment variable that makes [`refresh_agreement_from_env`] store the new renders.
pub const UPDATE_MITSUBA_RENDERS: &str = "UPDATE_MITSUBA_RENDERS";

/// The environment variable that limits [`refresh_agreement_from_env`] to the scenes it names
/// (comma-separated), so that one new scene can be rendered without the whole set.
pub const AGREEMENT_ONLY: &str = "AGREEMENT_ONLY";

/// [`refresh_agreement`] with the Python named by [`MITSUBA_PYTHON`], storing the new renders
/// when [`UPDATE_MITSUBA_RENDERS`] is `1` and keeping to the scenes [`AGREEMENT_ONLY`] names: what each chapter's ignored `tests/mitsuba.rs` runs.
pub fn refresh_agreement_from_env(set: &AgreementSet) -> Result<Vec<String>, String> {
    refresh_agreement_from_env_at(set, AGREEMENT_SPP, REFERENCE_SPP)
}

/// [`refresh_agreement_from_env`] at the sample counts of [`refresh_agreement_at`].
pub fn refresh_agreement_from_env_at(
    set: &AgreementSet,
    spp: u64,
    reference_spp: u64,
) -> Result<Vec<String>, String> {
    let python = mitsuba_python()
        .ok_or_else(|| format!("set {MITSUBA_PYTHON} to a Python that has the mitsuba package"))?;
    let update = std::env::var(UPDATE_MITSUBA_RENDERS).is_ok_and(|v| v == "1");
    let only = std::env::var(AGREEMENT_ONLY).ok().filter(|v| !v.is_empty());
    if let Some(names) = &only {
        let unknown: Vec<&str> = names
            .split(',')
            .filter(|n| !set.scenes.iter().any(|scene| scene.name == *n))
            .collect();
        if !unknown.is_empty() {
            return Err(format!(
                "{AGREEMENT_ONLY} names {unknown:?}, which {} does not have",
                set.label
            ));
        }
    }
    refresh_agreement_at(&python, set, update, only.as_deref(), spp, reference_spp)
}
