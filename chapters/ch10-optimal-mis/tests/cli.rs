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
