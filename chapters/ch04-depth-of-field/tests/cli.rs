//! The binary refuses bad input with a message and a non-zero exit, never a panic, and
//! writes nothing then; good input writes the image.

use std::path::Path;
use std::process::Output;
use workbench::test_support::run_binary;

const BINARY: &str = env!("CARGO_BIN_EXE_ch04-depth-of-field");

fn run(args: &[&str]) -> Output {
    run_binary(BINARY, args)
}

fn assert_refused(args: &[&str], expected: &str) {
    workbench::test_support::assert_refused(BINARY, args, expected);
}

#[test]
fn bad_lens_options_are_refused_with_a_clear_message() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("out.png");
    let png = png.to_str().unwrap();
    let small = ["--width", "8", "--height", "6", "--spp", "1"];
    let cases: &[(&[&str], &str)] = &[
        (&["--f-number", "0", "--focal-length", "0.05"], "f-number"),
        (&["--f-number", "-2", "--focal-length", "0.05"], "f-number"),
        (&["--f-number", "nan", "--focal-length", "0.05"], "f-number"),
        (&["--f-number", "2", "--focal-length", "0"], "focal length"),
        (&["--f-number", "2", "--focal-length", "-1"], "focal length"),
        (&["--f-number", "2"], "--focal-length"),
        (&["--focal-length", "0.05"], "--f-number"),
        (
            &[
                "--aperture-radius",
                "0.1",
                "--f-number",
                "2",
                "--focal-length",
                "0.05",
            ],
            "cannot be used with",
        ),
        (&["--aperture-radius", "-0.1"], "aperture radius"),
        (&["--aperture-radius", "inf"], "aperture radius"),
        (&["--aperture-radius", "wide"], "not a number"),
        (&["--focus-distance", "0"], "focus distance"),
        (&["--focus-distance", "-3"], "focus distance"),
        (&["--focus-distance", "nan"], "focus distance"),
        (&["--blades", "2"], "3 and 64 blades"),
        (&["--blades", "-6"], "3 and 64 blades"),
        (&["--blades", "65"], "3 and 64 blades"),
        (
            &["--aperture", "disc", "--blades", "5"],
            "--aperture polygon",
        ),
        (
            &["--aperture", "polygon", "--lens-warp", "naive"],
            "--lens-warp",
        ),
        (&["--aperture-rotation", "inf", "--blades", "5"], "rotation"),
        (&["--aperture", "heart"], "heart"),
        (&["--lens-warp", "wobbly"], "wobbly"),
        (&["--builtin", "teapot"], "teapot"),
        (&["--sampler", "stratified", "--time", "1"], "--spp"),
        (&["--filter-radius", "0"], "filter radius"),
        (&["--max-depth", "0"], "--max-depth"),
        (&["-D", "spp=4"], "--scene"),
    ];
    for (extra, expected) in cases {
        let mut args = vec!["render", "--out", png];
        // The flags under test come first, so a conflict with --spp is theirs to report.
        args.extend_from_slice(extra);
        if !extra.contains(&"--time") {
            args.extend_from_slice(&small);
        }
        assert_refused(&args, expected);
    }
    assert!(
        !Path::new(png).exists(),
        "a refused render wrote its output"
    );
}

#[test]
fn a_scene_file_with_a_bad_lens_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("out.png");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/thinlens-spheres.xml");
    assert_refused(
        &[
            "render",
            "--scene",
            scene.to_str().unwrap(),
            "-D",
            "focus=-1",
            "--out",
            png.to_str().unwrap(),
        ],
        // The loader refuses it, naming the sensor's parameter.
        "focus_distance must be a finite positive distance",
    );
    assert!(!png.exists());
}

#[test]
fn good_runs_write_the_image_and_the_statistics() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("bokeh.png");
    let stats = dir.path().join("bokeh.json");
    let out = run(&[
        "render",
        "--out",
        png.to_str().unwrap(),
        "--stats",
        stats.to_str().unwrap(),
        "--width",
        "12",
        "--height",
        "8",
        "--spp",
        "4",
        "--f-number",
        "1.4",
        "--focal-length",
        "0.3",
        "--focus-distance",
        "3.5",
        "--blades",
        "5",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(png.exists());
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&stats).unwrap()).unwrap();
    let radius = json["aperture_radius"].as_f64().unwrap();
    assert!((radius - 0.3 / 2.8).abs() < 1e-6, "{json}");
    assert_eq!(json["aperture"]["polygon"]["blades"], 5);
    assert_eq!(json["nonfinite_samples"], 0);

    let exr = dir.path().join("file.exr");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/thinlens-spheres.xml");
    let out = run(&[
        "render",
        "--scene",
        scene.to_str().unwrap(),
        "-D",
        "spp=2",
        "--width",
        "16",
        "--height",
        "10",
        "--lens-warp",
        "polar",
        "--out",
        exr.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(exr.exists());
}

#[test]
fn quick_figures_are_written() {
    let dir = tempfile::tempdir().unwrap();
    let out = run(&["figures", "--out", dir.path().to_str().unwrap(), "--quick"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for name in [
        "apertures.png",
        "focus.png",
        "naive_vs_correct.png",
        "naive_vs_correct_crops.png",
        "bokeh_shapes.png",
        "bokeh_shapes_crops.png",
        "lens_samples.png",
        "circle_of_confusion.png",
        "convergence.csv",
        "convergence.png",
        "diagrams/thin-lens.svg",
        "diagrams/focal-plane.svg",
    ] {
        assert!(dir.path().join(name).exists(), "{name} is missing");
    }
}
