//! The `render` command line: good input renders, bad input is refused before any work, with
//! a message naming the problem, and nothing is written.

use workbench::test_support::{assert_refused, run_binary};

const BINARY: &str = env!("CARGO_BIN_EXE_ch06-fuzzy-reflections");

#[test]
fn a_small_render_writes_its_image_and_stats() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("floor.png");
    let stats = dir.path().join("stats.json");
    let run = run_binary(
        BINARY,
        &[
            "render",
            "--builtin",
            "frosted",
            "--spp",
            "4",
            "--width",
            "32",
            "--height",
            "24",
            "--exponent",
            "30",
            "--glass",
            "half",
            "--fuzz",
            "disc",
            "--below-surface",
            "resample",
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
        "\"glass\": \"half\"",
        "\"fuzz\": \"disc\"",
        "\"below_surface\": \"resample\"",
        "\"exponent\": 30.0",
        "\"nonfinite_samples\": 0",
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
        (&["--exponent", "-1"], "lobe exponent"),
        (&["--exponent", "nan"], "lobe exponent"),
        (&["--exponent", "inf"], "lobe exponent"),
        (&["--exponent", "rough"], "is not a number"),
        (&["--glass", "both-ways"], "--glass"),
        (&["--fuzz", "gauss"], "--fuzz"),
        (&["--below-surface", "clamp"], "--below-surface"),
        (&["--max-depth", "0"], "--max-depth"),
        (&["--builtin", "mirror"], "--builtin"),
        (&["--aperture-radius", "-1"], "--aperture-radius"),
        (&["-D", "spp=4"], "--scene"),
        (&["--spp", "0"], "spp"),
        (&["--scene", "no/such/file.xml"], "no/such/file.xml"),
    ];
    for (extra, expected) in cases {
        let mut args = vec!["render", "--width", "8", "--height", "8", "--out", out_arg];
        args.extend_from_slice(extra);
        assert_refused(BINARY, &args, expected);
        assert!(!out.exists(), "{extra:?} wrote {}", out.display());
    }
}

#[test]
fn render_without_a_subcommand_explains_itself() {
    let run = run_binary(BINARY, &[]);
    assert!(!run.status.success());
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(
        stderr.contains("render") && stderr.contains("figures"),
        "{stderr}"
    );
}
