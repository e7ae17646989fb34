//! Agreement with Mitsuba 3 on a scene both render exactly: direct light from a point light on
//! matte surfaces (Mitsuba's `path` with `max_depth` 2 computes nothing more).
//!
//! Needs a Python with the `mitsuba` package (`pip install mitsuba`), so it is ignored by
//! default. Run it with
//! `MITSUBA_PYTHON=/path/to/python cargo test --release -p ch01-whitted --test mitsuba -- --ignored`.

use ch01_whitted::scene_file::convert;
use ch01_whitted::{PixelPattern, render};
use common::render::RenderSettings;
use common::scene::load_scene_file;
use std::path::Path;
use std::process::Command;

/// Renders `scene` with Mitsuba's `scalar_rgb` variant and writes a PFM to `out`.
const RENDER_WITH_MITSUBA: &str = r#"
import sys, numpy as np, mitsuba as mi
mi.set_variant("scalar_rgb")
scene = mi.load_file(sys.argv[1], spp=int(sys.argv[3]))
img = np.array(mi.render(scene, seed=1), dtype=np.float32)[:, :, :3]
h, w, _ = img.shape
with open(sys.argv[2], "wb") as f:
    f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
    f.write(np.ascontiguousarray(img[::-1]).astype("<f4").tobytes())
"#;

#[test]
#[ignore = "needs Mitsuba 3 (set MITSUBA_PYTHON)"]
fn direct_light_agrees_with_mitsuba() {
    let python = std::env::var("MITSUBA_PYTHON").unwrap_or_else(|_| "python3".to_string());
    let scene_file = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/matte-spheres.xml");
    let dir = tempfile::tempdir().unwrap();
    let reference_path = dir.path().join("mitsuba.pfm");
    let spp = 1024;
    let status = Command::new(&python)
        .args([
            "-c",
            RENDER_WITH_MITSUBA,
            scene_file.to_str().unwrap(),
            reference_path.to_str().unwrap(),
            &spp.to_string(),
        ])
        .status()
        .expect("MITSUBA_PYTHON runs");
    assert!(status.success(), "Mitsuba failed to render");
    let reference = common::output::read_image(&reference_path).unwrap();

    let loaded = load_scene_file(&scene_file, &[]).unwrap();
    let converted = convert(&loaded.scene).unwrap();
    let settings = RenderSettings::new(reference.width, reference.height, spp);
    // Mitsuba spreads its samples randomly over each pixel; a fine regular grid integrates the
    // same pixel area.
    let ours = render(&converted.scene, &settings, PixelPattern::Grid, 0)
        .unwrap()
        .image;

    let mean = |image: &common::image::Image| common::metrics::mean(image);
    let (m_ours, m_ref) = (mean(&ours), mean(&reference));
    let relative = ((m_ours - m_ref).length() / m_ref.length()).abs();
    let rmse = common::metrics::rmse(&ours, &reference);
    eprintln!(
        "mean ours {m_ours}, Mitsuba {m_ref}; relative difference {relative:.2e}; RMSE {rmse:.2e}"
    );
    assert!(relative < 2e-3, "the means differ by {relative}");
    assert!(rmse < 2e-3, "RMSE {rmse}");
}
