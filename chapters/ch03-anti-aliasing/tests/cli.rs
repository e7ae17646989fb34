//! The binary refuses bad input with a message and a non-zero exit, never a panic, and
//! writes nothing then; good input writes the image.

use std::path::{Path, PathBuf};
use std::process::Output;
use workbench::test_support::run_binary;

const BINARY: &str = env!("CARGO_BIN_EXE_ch03-anti-aliasing");

fn run(args: &[&str]) -> Output {
    run_binary(BINARY, args)
}

fn assert_refused(args: &[&str], expected: &str) {
    workbench::test_support::assert_refused(BINARY, args, expected);
}

fn scene_file(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

#[test]
fn bad_input_is_refused_with_a_clear_message() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("out.png");
    let png = png.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (&["render", "--out", png, "--spp", "0"], "--spp"),
        (&["render", "--out", png, "--width", "0"], "--width"),
        (&["render", "--out", png, "--time", "nan"], "time budget"),
        (
            &["render", "--out", png, "--sampler", "blue-noise"],
            "blue-noise",
        ),
        (&["render", "--out", png, "--filter", "lanczos"], "lanczos"),
        (&["render", "--out", png, "--filter-radius", "0"], "radius"),
        (&["render", "--out", png, "--filter-radius", "-1"], "radius"),
        (
            &["render", "--out", png, "--filter-radius", "nan"],
            "radius",
        ),
        (&["render", "--out", png, "--filter-radius", "17"], "radius"),
        (&["render", "--out", png, "--filter-radius", "wide"], "wide"),
        (
            &[
                "render",
                "--out",
                png,
                "--sampler",
                "stratified",
                "--time",
                "1",
            ],
            "--spp",
        ),
        (
            &[
                "render",
                "--out",
                png,
                "--sampler",
                "multijitter",
                "--time",
                "1",
            ],
            "--spp",
        ),
        (&["render", "--out", png, "--builtin", "teapot"], "teapot"),
        (&["render", "--out", png, "--max-depth", "0"], "--max-depth"),
        (&["render", "--out", png, "-D", "spp=4"], "--scene"),
        (
            &["render", "--out", png, "--scene", "no/such/scene.xml"],
            "no/such/scene.xml",
        ),
        (&["render", "--no-such-flag"], "--no-such-flag"),
        (&["render"], "--out"),
        (&["figures"], "--out"),
    ];
    for (args, expected) in cases {
        assert_refused(args, expected);
    }
    assert!(
        !Path::new(png).exists(),
        "a refused render wrote its output"
    );
    let jpg = dir.path().join("out.jpg");
    assert_refused(
        &["render", "--out", jpg.to_str().unwrap()],
        ".png, .exr or .pfm",
    );
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        0,
        "files left behind"
    );
}

#[test]
fn a_small_render_writes_the_image_and_its_statistics() {
    let dir = tempfile::tempdir().unwrap();
    let image = dir.path().join("img.pfm");
    let stats = dir.path().join("stats.json");
    let out = run(&[
        "render",
        "--builtin",
        "checkerboard",
        "--sampler",
        "halton",
        "--filter",
        "mitchell",
        "--spp",
        "4",
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
    assert!(decoded.pixels.iter().all(|p| p.is_finite()));
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    assert_eq!(json["nonfinite_samples"], 0);
    assert_eq!(json["spp"], 4);
    assert_eq!(json["sampler"], "halton");
    assert_eq!(json["filter"], "mitchell");
    assert_eq!(json["filter_radius"], 2.0);
}

#[test]
fn a_timed_render_works_with_samplers_that_need_no_count() {
    let dir = tempfile::tempdir().unwrap();
    for sampler in [
        "random",
        "halton",
        "centre",
        "sobol",
        "independent",
        "ldsampler",
    ] {
        let image = dir.path().join(format!("{sampler}.png"));
        let out = run(&[
            "render",
            "--sampler",
            sampler,
            "--time",
            "0.01",
            "--width",
            "8",
            "--height",
            "6",
            "--out",
            image.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "{sampler}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(image.exists());
    }
}

#[test]
fn the_chapter_scene_files_render_with_their_own_filter() {
    let dir = tempfile::tempdir().unwrap();
    for (name, filter, radius) in [
        ("tent-spheres.xml", "tent", 1.5),
        ("gaussian-bars.xml", "gaussian", 1.0),
    ] {
        let image = dir.path().join("scene.png");
        let stats = dir.path().join("scene.json");
        let out = run(&[
            "render",
            "--scene",
            scene_file(name).to_str().unwrap(),
            "-D",
            "spp=4",
            "--width",
            "24",
            "--height",
            "16",
            "--out",
            image.to_str().unwrap(),
            "--stats",
            stats.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
        assert_eq!(json["filter"], filter, "{name}");
        assert_eq!(json["filter_radius"], radius, "{name}");
        assert_eq!(json["spp"], 4, "{name}");
        assert_eq!(json["nonfinite_samples"], 0, "{name}");
        let decoded = workbench::output::read_image(&image).unwrap();
        let mean = decoded.pixels.iter().map(|p| p.x + p.y + p.z).sum::<f32>();
        assert!(mean > 0.0, "{name} rendered black");
    }
    // The command line overrides the file's filter.
    let image = dir.path().join("box.png");
    let stats = dir.path().join("box.json");
    let out = run(&[
        "render",
        "--scene",
        scene_file("tent-spheres.xml").to_str().unwrap(),
        "--filter",
        "box",
        "--spp",
        "1",
        "--width",
        "8",
        "--height",
        "6",
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
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    assert_eq!(json["filter"], "box");
}
