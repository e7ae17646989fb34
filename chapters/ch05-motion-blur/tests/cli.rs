//! The `render` command line: good input renders, bad input is refused before any work, with
//! a message naming the problem, and nothing is written.

use workbench::test_support::{assert_refused, run_binary};

const BINARY: &str = env!("CARGO_BIN_EXE_ch05-motion-blur");

#[test]
fn a_small_render_writes_its_image_and_stats() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("street.png");
    let stats = dir.path().join("stats.json");
    let run = run_binary(
        BINARY,
        &[
            "render",
            "--spp",
            "4",
            "--width",
            "32",
            "--height",
            "20",
            "--shutter-open",
            "0.2",
            "--shutter-close",
            "0.6",
            "--time-sampling",
            "independent",
            "--stretches",
            "3",
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
    assert!(out.exists());
    let stats = std::fs::read_to_string(stats).unwrap();
    for fragment in [
        "\"shutter_open\": 0.2",
        "\"shutter_close\": 0.6",
        "\"time_sampling\": \"independent\"",
        "\"stretches\": 3",
    ] {
        assert!(stats.contains(fragment), "{fragment} in {stats}");
    }
}

#[test]
fn bad_input_is_refused_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("never.png");
    let out_arg = out.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (
            &["--shutter-open", "1", "--shutter-close", "0.5"],
            "must close at or after",
        ),
        (&["--shutter-open", "nan"], "must be finite"),
        (&["--shutter-close", "inf"], "must be finite"),
        (&["--shutter-close", "-inf"], "must be finite"),
        (&["--shutter-open", "soon"], "is not a number"),
        (
            &["--time", "1", "--sampler", "random"],
            "--time-sampling stratified",
        ),
        (&["--stretches", "0"], "--stretches"),
        (&["--aperture-radius", "-1"], "--aperture-radius"),
        (&["--time-sampling", "halton"], "--time-sampling"),
        (&["-D", "spp=4"], "--scene"),
        (&["--spp", "0"], "spp"),
    ];
    for (extra, expected) in cases {
        let mut args = vec!["render", "--width", "8", "--height", "8", "--out", out_arg];
        args.extend_from_slice(extra);
        assert_refused(BINARY, &args, expected);
        assert!(!out.exists(), "{extra:?} wrote an image");
    }
}

#[test]
fn the_figures_command_needs_an_output_directory() {
    let run = run_binary(BINARY, &["figures"]);
    assert!(!run.status.success());
}
