//! What the chapter's integration tests share: a scene from its text, and means over images
//! and over seeds.

use ch05_motion_blur::MotionScene;
use common::image::Image;
use workbench::scene_file::parse_scene;

/// The scene `text` (as if read from `name`), ready to trace.
pub fn world(text: &str, name: &str) -> MotionScene {
    let loaded = parse_scene(text, std::path::Path::new(name), &[]).expect("the scene loads");
    MotionScene::new(loaded.scene).expect("no motion to refuse")
}

/// The mean of `image`'s green channel.
pub fn mean(image: &Image) -> f64 {
    image.pixels.iter().map(|p| f64::from(p.y)).sum::<f64>() / image.pixels.len() as f64
}

/// The mean of `values` and its standard error.
pub fn mean_and_error(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (variance / n).sqrt())
}
