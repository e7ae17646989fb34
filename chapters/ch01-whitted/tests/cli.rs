//! The binary refuses bad input with a message and a non-zero exit, never a panic, and
//! writes nothing then.

use std::path::Path;
use std::process::Output;
use workbench::test_support::run_binary;

const BINARY: &str = env!("CARGO_BIN_EXE_ch01-whitted");

fn run(args: &[&str]) -> Output {
    run_binary(BINARY, args)
}

fn assert_refused(args: &[&str], expected: &str) {
    workbench::test_support::assert_refused(BINARY, args, expected);
}

#[test]
fn bad_input_is_refused_with_a_clear_message() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("out.png");
    let png = png.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (&["render", "--out", png, "--spp", "0"], "--spp"),
        (&["render", "--out", png, "--spp", "-3"], "-3"),
        (&["render", "--out", png, "--width", "0"], "--width"),
        (&["render", "--out", png, "--width", "-5"], "-5"),
        (&["render", "--out", png, "--time", "0"], "time budget"),
        (&["render", "--out", png, "--time", "nan"], "time budget"),
        (
            &["render", "--out", png, "--spp", "2", "--time", "1"],
            "cannot be used with",
        ),
        (&["render", "--out", png, "--builtin", "teapot"], "teapot"),
        (&["render", "--out", png, "--max-depth", "0"], "--max-depth"),
        (&["render", "--out", png, "--threads", "0"], "--threads"),
        (
            &["render", "--out", png, "--pixel", "grid", "--spp", "8"],
            "square",
        ),
        (
            &[
                "render", "--out", png, "--width", "65536", "--height", "65536",
            ],
            "MiB",
        ),
        (&["render", "--no-such-flag"], "--no-such-flag"),
        (&["render"], "--out"),
    ];
    for (args, expected) in cases {
        assert_refused(args, expected);
    }
    assert!(
        !Path::new(png).exists(),
        "a refused render wrote its output"
    );
}

#[test]
fn unwritable_outputs_are_refused_before_rendering() {
    let dir = tempfile::tempdir().unwrap();
    let jpg = dir.path().join("out.jpg");
    assert_refused(
        &["render", "--out", jpg.to_str().unwrap()],
        ".png, .exr or .pfm",
    );
    assert!(!jpg.exists());
    // A file where a directory should be.
    let blocker = dir.path().join("file");
    std::fs::write(&blocker, b"x").unwrap();
    let inside = blocker.join("out.png");
    assert_refused(
        &["render", "--out", inside.to_str().unwrap()],
        "cannot create the directory",
    );
    let stats = dir.path().join("stats.txt");
    let png = dir.path().join("ok.png");
    assert_refused(
        &[
            "render",
            "--out",
            png.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ],
        ".json",
    );
    assert!(!png.exists());
}

#[test]
fn a_small_render_writes_the_image_and_its_statistics() {
    let dir = tempfile::tempdir().unwrap();
    for ext in ["png", "exr", "pfm"] {
        let image = dir.path().join(format!("img.{ext}"));
        let stats = dir.path().join("stats.json");
        let out = run(&[
            "render",
            "--width",
            "16",
            "--height",
            "12",
            "--out",
            image.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let decoded = workbench::output::read_image(&image).unwrap();
        assert_eq!((decoded.width, decoded.height), (16, 12));
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
        for key in [
            "seconds",
            "spp",
            "width",
            "height",
            "rays",
            "samples_per_second",
            "nonfinite_samples",
        ] {
            assert!(json.get(key).is_some(), "stats lack {key}: {json}");
        }
        assert_eq!(json["nonfinite_samples"], 0);
        assert_eq!(json["width"], 16);
    }
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|name| !["img.png", "img.exr", "img.pfm", "stats.json"].contains(&name.as_str()))
        .collect();
    assert!(
        leftovers.is_empty(),
        "temporary files left behind: {leftovers:?}"
    );
}
