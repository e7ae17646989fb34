//! The binary's `render`: each `--mis` on a scene file, end to end, and its refusals.

use std::path::Path;
use workbench::output::read_image;
use workbench::test_support::{assert_refused, run_binary};

const BINARY: &str = env!("CARGO_BIN_EXE_ch10-optimal-mis");

/// The chapter's scene file `name`.
fn scene(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
        .display()
        .to_string()
}

/// Through the binary, the plane under the sky is exactly `ρ L` in every pixel with
/// `--mis optimal` (the default), and noisy with the heuristics; `--stats` names the choice.
#[test]
fn render_combines_as_mis_says() {
    let dir = tempfile::tempdir().unwrap();
    for (mis, exact) in [("optimal", true), ("power", false), ("balance", false)] {
        let out = dir.path().join(format!("{mis}.exr"));
        let stats = dir.path().join(format!("{mis}.json"));
        let run = run_binary(
            BINARY,
            &[
                "render",
                "--scene",
                &scene("plane-under-sky.xml"),
                "--mis",
                mis,
                "--spp",
                "4",
                "--out",
                out.to_str().unwrap(),
                "--stats",
                stats.to_str().unwrap(),
            ],
        );
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        let image = read_image(&out).unwrap();
        let largest = image
            .pixels
            .iter()
            .map(|p| (*p - glam::Vec3::new(1.0, 0.5, 0.25)).abs().max_element())
            .fold(0.0, f32::max);
        assert_eq!(
            largest < 1e-4,
            exact,
            "--mis {mis}: largest error {largest}"
        );
        let written = std::fs::read_to_string(&stats).unwrap();
        assert!(
            written.contains(&format!("\"mis\": \"{mis}\"")),
            "{written}"
        );
    }
}

#[test]
fn render_refuses_an_unknown_combination_and_a_missing_scene() {
    assert_refused(
        BINARY,
        &[
            "render",
            "--scene",
            &scene("plane-under-sky.xml"),
            "--mis",
            "best",
            "--out",
            "x.png",
        ],
        "invalid value 'best'",
    );
    assert_refused(
        BINARY,
        &["render", "--out", "x.png"],
        "render needs a scene",
    );
}

/// A file's `path` integrator renders whole paths, combined per depth (`"light": "paths"` in
/// the stats, and brighter than the same file's direct light alone); a `direct` one renders the
/// direct light.
#[test]
fn render_follows_the_files_integrator() {
    let dir = tempfile::tempdir().unwrap();
    let cornell = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../ch08-path-tracing/scenes/cornell-box.xml")
        .display()
        .to_string();
    let render = |scene: &str, name: &str| {
        let out = dir.path().join(format!("{name}.exr"));
        let stats = dir.path().join(format!("{name}.json"));
        let run = run_binary(
            BINARY,
            &[
                "render",
                "--scene",
                scene,
                "--width",
                "16",
                "--height",
                "12",
                "--spp",
                "16",
                "--out",
                out.to_str().unwrap(),
                "--stats",
                stats.to_str().unwrap(),
            ],
        );
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        let image = read_image(&out).unwrap();
        let mean = image.pixels.iter().map(|p| p.y).sum::<f32>() / image.pixels.len() as f32;
        (mean, std::fs::read_to_string(&stats).unwrap())
    };
    let (paths, written) = render(&cornell, "paths");
    assert!(written.contains("\"light\": \"paths\""), "{written}");
    let (_, written) = render(&scene("glossy-floor.xml"), "direct");
    assert!(written.contains("\"light\": \"direct\""), "{written}");
    let two_segments = std::fs::read_to_string(&cornell).unwrap().replace(
        r#"name="max_depth" value="8""#,
        r#"name="max_depth" value="2""#,
    );
    let cut = dir.path().join("cut.xml");
    std::fs::write(&cut, two_segments).unwrap();
    let (direct, written) = render(cut.to_str().unwrap(), "cut");
    assert!(written.contains("\"light\": \"direct\""), "{written}");
    assert!(
        paths > 1.2 * direct,
        "the Cornell box's paths ({paths}) should be brighter than its direct light ({direct})"
    );
}
