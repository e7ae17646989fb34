//! Shared helpers: the mean radiance of many paths through fixed film positions, with its
//! standard error, the crate's scene files, and the binary's `render` at a tiny size or
//! on a scene written in the test.
#![allow(dead_code)]

use ch04_depth_of_field::Lens;
use ch05_motion_blur::CameraRays;
use ch05_motion_blur::MotionScene;
use ch07_soft_shadows::AreaLights;
use ch08_path_tracing::{Method, PathOptions, PathTracer, SceneLights};
use ch09_materials::SceneMaterials;
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2};
use std::path::Path;

/// A scene file of the crate, made ready for tracing, with its path options.
pub struct SceneFile {
    /// The scene with its motion.
    pub world: MotionScene,
    /// The path tracer's options from the file's integrator.
    pub options: PathOptions,
}

/// The crate's scene file `name`.
pub fn scene_file(name: &str) -> SceneFile {
    let path = ch09_materials::lab::agreement::AGREEMENT
        .scenes_dir()
        .join(name);
    let loaded = workbench::scene_file::load_scene_file(&path, &[]).expect("the scene loads");
    ch09_materials::lab::CAPABILITIES
        .check(&loaded.scene)
        .expect("the crate renders it");
    SceneFile {
        options: ch08_path_tracing::lab::scene_file::path_options(&loaded.scene),
        world: MotionScene::new(loaded.scene).expect("its motion is valid"),
    }
}

/// The mean luminance-free green channel of `n` paths through each film position of
/// `pixels` (or, for `direct` sample counts in `method`, of Mitsuba's direct estimate), and
/// the standard error of that mean. Panics on a non-finite sample.
pub fn estimate(
    scene: &MotionScene,
    method: Method,
    pixels: &[Vec2],
    n: u64,
    seed: u64,
) -> (f64, f64) {
    let world = scene;
    let film = world.scene.film;
    let rays = CameraRays::new(world, &Lens::PINHOLE, film.width, film.height);
    let area_lights = AreaLights::of(&world.scene);
    let tracer = PathTracer {
        world,
        lights: SceneLights::of(world, &area_lights, method.light_sampling),
        options: method.options,
        materials: SceneMaterials::of(&world.scene, method.fuzz),
    };
    let mut sampler = IndependentSampler::new(seed);
    let (mut sum, mut sum2, mut count) = (0.0f64, 0.0f64, 0u64);
    for (p, &p_film) in pixels.iter().enumerate() {
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::new(p as u32, 0), i);
            let ray = rays.generate(world, p_film, &mut sampler);
            let l = match method.options.direct {
                Some(samples) => tracer.direct(&ray, samples, &mut sampler),
                None => tracer.radiance(&ray, &mut sampler),
            };
            assert!(l.is_finite(), "radiance {l} at {p_film}");
            let x = f64::from(l.y);
            sum += x;
            sum2 += x * x;
            count += 1;
        }
    }
    let mean = sum / count as f64;
    let variance = (sum2 / count as f64 - mean * mean).max(0.0);
    (mean, (variance / count as f64).sqrt())
}

/// A `k x k` grid of film positions over a `width x height` image (pixel centres).
pub fn grid(width: u32, height: u32, k: u32) -> Vec<Vec2> {
    let mut points = Vec::new();
    for j in 0..k {
        for i in 0..k {
            points.push(Vec2::new(
                ((i * width / k) as f32 + 0.5).min(width as f32 - 0.5),
                ((j * height / k) as f32 + 0.5).min(height as f32 - 0.5),
            ));
        }
    }
    points
}

/// Renders `scene` at 16 x 12 pixels and 2 samples per pixel; `Err` with the message if
/// `render` refuses it. A panic or a non-finite sample fails the test.
pub fn render_tiny(scene: &Path, out: &Path) -> Result<common::image::Image, String> {
    let image = out.join("image.pfm");
    let stats = out.join("stats.json");
    let output = workbench::test_support::run_binary(
        env!("CARGO_BIN_EXE_ch09-materials"),
        &[
            "render",
            "--scene",
            scene.to_str().unwrap(),
            "--width",
            "16",
            "--height",
            "12",
            "--spp",
            "2",
            "--threads",
            "1",
            "--out",
            image.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ],
    );
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert!(
        !stderr.contains("panicked"),
        "{}: {stderr}",
        scene.display()
    );
    if !output.status.success() {
        return Err(stderr);
    }
    let stats: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    assert_eq!(
        stats["nonfinite_samples"],
        0,
        "{}: {stderr}",
        scene.display()
    );
    Ok(workbench::output::read_image(&image).unwrap())
}

/// The image the binary's `render` makes of the scene file `text` (written to a temporary
/// folder), at the file's own size and sample count. A refusal fails the test with its
/// message.
pub fn render_text(text: &str) -> common::image::Image {
    let folder = tempfile::tempdir().unwrap();
    let file = folder.path().join("scene.xml");
    std::fs::write(&file, text).unwrap();
    let image = folder.path().join("image.pfm");
    let output = workbench::test_support::run_binary(
        env!("CARGO_BIN_EXE_ch09-materials"),
        &[
            "render",
            "--scene",
            file.to_str().unwrap(),
            "--out",
            image.to_str().unwrap(),
        ],
    );
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    workbench::output::read_image(&image).unwrap()
}
