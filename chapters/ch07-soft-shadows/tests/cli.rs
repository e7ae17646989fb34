//! The `render` command line: good input renders, bad input is refused before any work, with
//! a message naming the problem, and nothing is written.

use workbench::test_support::{assert_refused, run_binary};

const BINARY: &str = env!("CARGO_BIN_EXE_ch07-soft-shadows");

fn scene(name: &str) -> String {
    format!("{}/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn a_small_render_writes_its_image_and_stats() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("shapes.png");
    let stats = dir.path().join("stats.json");
    let run = run_binary(
        BINARY,
        &[
            "render",
            "--builtin",
            "shapes",
            "--spp",
            "2",
            "--width",
            "32",
            "--height",
            "24",
            "--light-samples",
            "3",
            "--light-strata",
            "independent",
            "--light-sampling",
            "area",
            "--disc-warp",
            "naive",
            "--light-scale",
            "2",
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
        "\"area_lights\": 4",
        "\"light_samples\": 3",
        "\"light_strata\": \"independent\"",
        "\"light_sampling\": \"area\"",
        "\"disc_warp\": \"naive\"",
        "\"light_scale\": 2.0",
    ] {
        assert!(stats.contains(fragment), "{fragment} in {stats}");
    }
}

#[test]
fn a_scene_file_renders_with_its_lights() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("quad.exr");
    let file = scene("rectangle-light.xml");
    let run = run_binary(
        BINARY,
        &[
            "render",
            "--scene",
            &file,
            "-D",
            "spp=2",
            "-D",
            "size=0.2",
            "--out",
            out.to_str().unwrap(),
        ],
    );
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(out.exists());
}

#[test]
fn bad_input_is_refused_and_nothing_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("never.png");
    let out_arg = out.to_str().unwrap();
    let quad = scene("rectangle-light.xml");
    let cases: &[(&[&str], &str)] = &[
        (&["--light-samples", "0"], "--light-samples"),
        (&["--light-samples", "5000"], "--light-samples"),
        (&["--light-samples", "-3"], "--light-samples"),
        (&["--light-scale", "0"], "--light-scale"),
        (&["--light-scale", "-2"], "--light-scale"),
        (&["--light-scale", "nan"], "--light-scale"),
        (&["--light-scale", "inf"], "--light-scale"),
        (&["--light-scale", "big"], "is not a number"),
        (&["--light-sampling", "cone"], "--light-sampling"),
        (&["--disc-warp", "square"], "--disc-warp"),
        (&["--light-strata", "halton"], "--light-strata"),
        (&["--builtin", "sun"], "--builtin"),
        (&["--scene", &quad, "--light-scale", "2"], "--light-scale"),
        (&["--exponent", "-1"], "--exponent"),
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
fn a_moving_light_in_a_scene_file_is_refused_with_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("moving.xml");
    std::fs::write(&file, MOVING_LIGHT).unwrap();
    let out = dir.path().join("never.png");
    assert_refused(
        BINARY,
        &[
            "render",
            "--scene",
            file.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ],
        "area light that moves",
    );
    assert!(!out.exists());
}

const MOVING_LIGHT: &str = r#"<scene version="3.0.0">
    <sensor type="perspective"><float name="fov" value="40"/>
        <transform name="to_world"><lookat origin="0, 1, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>
    </sensor>
    <shape type="sphere">
        <animation name="to_world">
            <transform time="0"><translate x="0"/></transform>
            <transform time="1"><translate x="1"/></transform>
        </animation>
        <emitter type="area"><rgb name="radiance" value="1, 1, 1"/></emitter>
    </shape>
</scene>
"#;

#[test]
fn the_figures_command_needs_an_output_directory() {
    let run = run_binary(BINARY, &["figures"]);
    assert!(!run.status.success());
}
