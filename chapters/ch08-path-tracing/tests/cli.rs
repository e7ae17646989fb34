//! The binary: bad input gives a clear message, a non-zero exit and no file.

use workbench::test_support::assert_refused;

const BIN: &str = env!("CARGO_BIN_EXE_ch08-path-tracing");

#[test]
fn bad_input_is_refused_with_a_message() {
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cornell-box.xml");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("never.png");
    let out = path.to_str().unwrap();
    assert_refused(BIN, &["render", "--out", out], "needs a scene");
    for (args, expected) in [
        (&["--rr-depth", "0"][..], "neither a depth"),
        (&["--mis", "sometimes"], "sometimes"),
        (&["--glass", "both"], "--glass both"),
        (&["--light-samples", "4"], "one light sample"),
    ] {
        let mut all = vec!["render", "--scene", scene, "--out", out];
        all.extend_from_slice(args);
        assert_refused(BIN, &all, expected);
    }
    assert!(!path.exists(), "nothing is written");
}

#[test]
fn a_render_writes_its_image() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("box.png");
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/cornell-box.xml");
    let output = workbench::test_support::run_binary(
        BIN,
        &[
            "render",
            "--scene",
            scene,
            "--spp",
            "2",
            "--width",
            "16",
            "--height",
            "16",
            "--mis",
            "balance",
            "--rr-depth",
            "off",
            "--out",
            out.to_str().unwrap(),
        ],
    );
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(out.exists());
}
