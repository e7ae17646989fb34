//! Shared helpers: the mean radiance of many paths through fixed film positions, with its
//! standard error, the chapter's scene files, and the binary's `render` at a tiny size or
//! on a scene written in the test.
#![allow(dead_code)]

use ch03_anti_aliasing::{FilterKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch08_path_tracing::{Method, PathOptions, render_with};
use common::render::{RenderOutput, RenderSettings};
use common::sampler::IndependentSampler;
use glam::Vec2;
use std::path::Path;

/// A scene file of the chapter, made ready for tracing, with its path options.
pub struct SceneFile {
    /// The scene with its motion.
    pub world: MotionScene,
    /// The path tracer's options from the file's integrator.
    pub options: PathOptions,
}

/// The chapter's scene file `name`.
pub fn scene_file(name: &str) -> SceneFile {
    let path = ch08_path_tracing::lab::agreement::AGREEMENT
        .scenes_dir()
        .join(name);
    let loaded = workbench::scene_file::load_scene_file(&path, &[]).expect("the scene loads");
    ch08_path_tracing::lab::CAPABILITIES
        .check(&loaded.scene)
        .expect("the chapter renders it");
    SceneFile {
        options: ch08_path_tracing::lab::scene_file::path_options(&loaded.scene),
        world: MotionScene::new(loaded.scene).expect("its motion is valid"),
    }
}

/// `scene` path-traced through a pinhole at `width` x `height` with `spp` samples per pixel
/// (box filter, independent samples from `seed`), with `options` and the default method.
pub fn render_pinhole(
    scene: &MotionScene,
    options: PathOptions,
    (width, height, spp): (u32, u32, u64),
    seed: u64,
) -> RenderOutput {
    let filter = ReconstructionFilter::new(FilterKind::Box, None).unwrap();
    render_with(
        scene,
        Method::new(options),
        &Lens::PINHOLE,
        &RenderSettings::new(width, height, spp),
        &IndependentSampler::new(seed),
        &filter,
    )
}

/// The mean green channel of `n` paths through each film position of `pixels` (or, for
/// `direct` sample counts in `method`, of Mitsuba's direct estimate), and the standard error
/// of that mean ([`ch08_path_tracing::lab::estimate`]).
pub fn estimate(
    scene: &MotionScene,
    method: Method,
    pixels: &[Vec2],
    n: u64,
    seed: u64,
) -> (f64, f64) {
    let materials = ch08_path_tracing::LectureMaterials { fuzz: method.fuzz };
    ch08_path_tracing::lab::estimate::estimate(scene, method, materials, pixels, n, seed)
}

/// The binary's `render` of `scene` at 16 x 12 pixels and 2 samples per pixel
/// ([`workbench::test_support::render_tiny`]).
pub fn render_tiny(scene: &Path, out: &Path) -> Result<common::image::Image, String> {
    workbench::test_support::render_tiny(env!("CARGO_BIN_EXE_ch08-path-tracing"), scene, out)
}

/// The image the binary's `render` makes of the scene file `text`
/// ([`workbench::test_support::render_text`]).
pub fn render_text(text: &str) -> common::image::Image {
    workbench::test_support::render_text(env!("CARGO_BIN_EXE_ch08-path-tracing"), text)
}
