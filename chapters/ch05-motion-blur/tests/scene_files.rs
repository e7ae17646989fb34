//! Scene files with the `<animation>` extension: they render, and what is wrong is refused.

use ch05_motion_blur::lab::CAPABILITIES;
use ch05_motion_blur::lab::scene_file::motion_of;
use ch05_motion_blur::world::MotionScene;
use common::scene::Scene;
use std::path::{Path, PathBuf};
use workbench::scene_file::{load_scene_file, parse_scene};
use workbench::test_support::run_binary;

const BINARY: &str = env!("CARGO_BIN_EXE_ch05-motion-blur");

/// What the chapter's binary does with a loaded scene: checks that the chapter renders it,
/// then makes its motion ready; the scene in motion and every note, or the refusal.
fn convert(scene: &Scene) -> Result<(MotionScene, Vec<String>), String> {
    let mut notes = CAPABILITIES.check(scene)?;
    let (world, note) = motion_of(scene.clone())?;
    notes.extend(note);
    Ok((world, notes))
}

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

#[test]
fn the_chapters_scene_files_render_with_their_motion() {
    for (name, shapes_moving, camera_moving) in [
        ("rolling-ball.xml", 7, false),
        ("panning-camera.xml", 0, true),
    ] {
        let loaded = load_scene_file(&scene_path(name), &[]).expect(name);
        assert!(loaded.warnings.is_empty(), "{name}: {:?}", loaded.warnings);
        let (world, _notes) = convert(&loaded.scene).expect(name);
        assert!(world.moves(), "{name}");
        // A sphere is one shape, a cube six faces.
        assert_eq!(world.moving.shapes().len(), shapes_moving, "{name}");
        assert_eq!(world.camera_motion.is_some(), camera_moving, "{name}");
        assert_eq!((world.shutter.open, world.shutter.close), (0.0, 1.0));

        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out.png");
        let path = scene_path(name);
        let args = [
            "render",
            "--scene",
            path.to_str().unwrap(),
            "--spp",
            "2",
            "--width",
            "24",
            "--height",
            "16",
            "--out",
            out.to_str().unwrap(),
        ];
        let run = run_binary(BINARY, &args);
        assert!(
            run.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&run.stderr)
        );
        assert!(out.exists());
    }
}

fn scene_with(shutter: &str, body: &str) -> String {
    format!(
        r#"<scene version="3.0.0">
    <sensor type="perspective">
        <float name="fov" value="45"/>{shutter}
        <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>
    </sensor>
    {body}
</scene>"#
    )
}

const MOVING_SPHERE: &str = r#"<shape type="sphere"><animation name="to_world">
    <transform time="0"><translate x="-1"/></transform>
    <transform time="1"><translate x="1"/></transform></animation></shape>"#;

#[test]
fn what_the_chapter_cannot_render_is_refused_with_the_reason() {
    // The refusals point at the shape in the file (line 7 of `scene_with`'s text).
    let cases = [
        (
            scene_with(
                "",
                r#"<shape type="sphere"><animation name="to_world">
                <transform time="0"/><transform time="1"><rotate y="1" angle="180"/></transform>
                </animation></shape>"#,
            ),
            "line 7, column 5: shape 1: the keyframe at time 1 is turned half a turn",
        ),
        (
            scene_with(
                "",
                r#"<shape type="sphere"><animation name="to_world">
                <transform time="0"/><transform time="1"><translate x="1"/></transform>
                </animation><emitter type="area"><rgb name="radiance" value="1"/></emitter></shape>"#,
            ),
            "line 7, column 5: an area light that moves (shape 1)",
        ),
        (
            scene_with(
                "",
                r#"<shape type="sphere"><animation name="to_world">
                <transform time="0"/><transform time="1"><translate x="1"/></transform>
                </animation><bsdf type="roughconductor"/></shape>"#,
            ),
            "chapter 06",
        ),
    ];
    for (text, expected) in cases {
        let loaded = parse_scene(&text, Path::new("test.xml"), &[]).expect("valid file");
        let error = convert(&loaded.scene)
            .err()
            .unwrap_or_else(|| panic!("accepted: {text}"));
        assert!(
            error.contains(expected),
            "expected `{expected}` in: {error}"
        );
    }
    // A shutter that closes before it opens makes no sense to any chapter: the loader itself
    // refuses it, pointing at the sensor.
    let text = scene_with(
        r#"<float name="shutter_open" value="1"/><float name="shutter_close" value="0.5"/>"#,
        MOVING_SPHERE,
    );
    let error = parse_scene(&text, Path::new("test.xml"), &[])
        .err()
        .unwrap_or_else(|| panic!("accepted: {text}"))
        .to_string();
    let expected = "the shutter must open before it closes";
    assert!(
        error.contains(expected),
        "expected `{expected}` in: {error}"
    );
}

#[test]
fn a_moving_scene_with_a_closed_shutter_renders_an_instant_and_says_so() {
    let loaded = parse_scene(&scene_with("", MOVING_SPHERE), Path::new("test.xml"), &[]).unwrap();
    let (world, notes) = convert(&loaded.scene).unwrap();
    assert!(world.shutter.is_instant());
    assert!(
        notes.iter().any(|n| n.contains("without blur")),
        "{notes:?}"
    );
}
