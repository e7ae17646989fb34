//! What a scene file asks of the path tracer: the integrator's depth and roulette.
//!
//! Everything else of the file (materials, lens, filter, motion, point and area lights, the
//! `constant` environment and the `envmap`) is in the scene itself; the earlier chapters'
//! notes about light they leave out do not apply here, as the chapter's capabilities say.

use crate::options::PathOptions;
use ch05_motion_blur::lab::scene_file::CameraSide;
use common::scene::{DirectSamples, Integrator, Scene};
use std::path::Path;
use workbench::capabilities::Capabilities;
use workbench::cli::CliError;
use workbench::driver::FromSceneFile;

/// What chapter 08's `render` reads from a scene file: chapter 04's camera side, and the
/// integrator's options, read before `--max-depth` changes the scene.
pub struct PathSide {
    /// The lens, the film's filter and the pixel sampler.
    pub camera: CameraSide,
    /// The file's integrator as the path tracer's options.
    pub options: PathOptions,
}

impl FromSceneFile for PathSide {
    fn read(
        path: &Path,
        defines: &[(String, String)],
        capabilities: &Capabilities,
    ) -> Result<(Scene, PathSide), CliError> {
        let (scene, camera) = CameraSide::read(path, defines, capabilities)?;
        let options = path_options(&scene);
        Ok((scene, PathSide { camera, options }))
    }
}

/// NEE and the power heuristic as Mitsuba's `path` does them, with the scene's depth limit and,
/// for a `path` integrator, its `rr_depth`; Mitsuba's `direct` with one light and one BSDF
/// sample is the path cut after one bounce (the scene's depth 2), with other counts
/// [`PathTracer::direct`](crate::PathTracer::direct).
pub fn path_options(scene: &Scene) -> PathOptions {
    match scene.integrator {
        Integrator::Path { rr_depth } => PathOptions {
            max_depth: scene.max_depth,
            rr_depth: Some(rr_depth),
            hide_emitters: scene.hide_emitters,
            ..PathOptions::default()
        },
        Integrator::Direct(samples) => PathOptions {
            max_depth: scene.max_depth,
            hide_emitters: scene.hide_emitters,
            direct: (samples != DirectSamples::ONE_EACH).then_some(samples),
            ..PathOptions::default()
        },
    }
}
