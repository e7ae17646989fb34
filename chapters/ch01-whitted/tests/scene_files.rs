//! Rendering Mitsuba 3 XML scene files, and refusing what chapter 01 cannot render.

use ch01_whitted::lab::CAPABILITIES;
use ch01_whitted::scenes::Builtin;
use ch01_whitted::{PixelPattern, render};
use common::render::RenderSettings;
use common::scene::Scene;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use workbench::scene_file::{load_scene_file, parse_scene};

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

/// The notes chapter 01 prints for `scene`, or its refusal.
fn convert(scene: &Scene) -> Result<Vec<String>, String> {
    CAPABILITIES.check(scene)
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ch01-whitted"))
        .args(args)
        .output()
        .expect("the binary runs")
}

#[test]
fn the_cornell_file_renders_like_the_builtin_cornell_box() {
    let loaded = load_scene_file(&scene_path("cornell-point.xml"), &[]).unwrap();
    assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    convert(&loaded.scene).unwrap();
    let settings = RenderSettings::new(64, 64, 1);
    let from_file = render(&loaded.scene, &settings, PixelPattern::Centre, 0)
        .unwrap()
        .image;
    let builtin = render(
        &Builtin::Cornell.build(12),
        &settings,
        PixelPattern::Centre,
        0,
    )
    .unwrap()
    .image;
    // The box is symmetric and the camera on its axis, so the pixel centres on the image's
    // diagonals look exactly into the room's creases, where two walls tie for the nearest hit
    // and the last bits of the camera frame decide which wall (and whether the shadow ray
    // starts a rounding error outside the room). About 31 such pixels differ; everything else
    // must agree.
    let differing = from_file
        .pixels
        .iter()
        .zip(&builtin.pixels)
        .filter(|(a, b)| (**a - **b).abs().max_element() > 1e-3)
        .count();
    assert!(differing <= 40, "{differing} of 4096 pixels differ");
    let mean = |image: &common::image::Image| {
        image
            .pixels
            .iter()
            .map(|p| f64::from(p.element_sum()))
            .sum::<f64>()
    };
    let relative = (mean(&from_file) - mean(&builtin)).abs() / mean(&builtin);
    assert!(relative < 2e-3, "the images' means differ by {relative}");
}

#[test]
fn scene_defaults_and_overrides_reach_the_render() {
    let dir = tempfile::tempdir().unwrap();
    let stats = dir.path().join("stats.json");
    let image = dir.path().join("img.pfm");
    let scene = scene_path("matte-spheres.xml");
    let out = run(&[
        "render",
        "--scene",
        scene.to_str().unwrap(),
        "-D",
        "spp=4",
        "-D",
        "width=20",
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
    assert_eq!(json["spp"], 4);
    assert_eq!(json["width"], 20);
    assert_eq!(json["height"], 96);
    assert_eq!(json["max_depth"], 2);
    assert_eq!(
        json["pixel"], "grid",
        "a scene file's 4 samples spread over the pixel"
    );
    // `max_depth` 2 asks for direct light only, which Whitted's method computes exactly: no
    // light is left out, so there is nothing to note.
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        !stderr.contains("leaves out indirect light"),
        "a note about light that is not missing: {stderr}"
    );
    // A file that asks for indirect light (the Cornell box's `max_depth` 12) gets the note.
    let cornell = scene_path("cornell-point.xml");
    let out = run(&[
        "render",
        "--scene",
        cornell.to_str().unwrap(),
        "-D",
        "width=8",
        "-D",
        "height=8",
        "--out",
        image.to_str().unwrap(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("leaves out indirect light"),
        "the note about missing light: {stderr}"
    );
}

/// A minimal scene around one shape, bsdf, emitter or sensor fragment.
fn scene_with(sensor_extra: &str, body: &str) -> String {
    format!(
        r#"<scene version="3.0.0">
    <sensor type="{sensor_type}">
        <float name="fov" value="45"/>{sensor_inner}
        <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>
    </sensor>
    {body}
</scene>"#,
        sensor_type = if sensor_extra.is_empty() {
            "perspective"
        } else {
            "thinlens"
        },
        sensor_inner = sensor_extra,
    )
}

#[test]
fn features_of_later_chapters_are_refused_with_their_chapter() {
    let cases = [
        (
            scene_with(
                "",
                r#"<shape type="sphere"><emitter type="area"><rgb name="radiance" value="1"/></emitter></shape>"#,
            ),
            // The refusal points at the shape in the file (line 7 of `scene_with`'s text).
            "line 7, column 5: an area light (shape 1); soft shadows from lights with an area come in chapter 07 (ch07-soft-shadows)",
        ),
        (
            scene_with(
                r#"<float name="aperture_radius" value="0.1"/><float name="focus_distance" value="5"/>"#,
                r#"<shape type="sphere"/>"#,
            ),
            "chapter 04",
        ),
        (
            scene_with("", r#"<shape type="sphere"><bsdf type="phong"/></shape>"#),
            "chapter 06",
        ),
    ];
    for (text, expected) in cases {
        let loaded =
            parse_scene(&text, Path::new("test.xml"), &[]).expect("the file itself is valid");
        let error = convert(&loaded.scene)
            .err()
            .unwrap_or_else(|| panic!("accepted: {text}"));
        assert!(
            error.contains(expected),
            "expected `{expected}` in: {error}"
        );
    }
    // A lens of aperture 0 is a pinhole, and renders.
    let pinhole = scene_with(
        r#"<float name="aperture_radius" value="0"/><float name="focus_distance" value="5"/>"#,
        r#"<shape type="sphere"/>"#,
    );
    assert!(
        convert(
            &parse_scene(&pinhole, Path::new("test.xml"), &[])
                .unwrap()
                .scene
        )
        .is_ok()
    );
}

/// Motion (the workbook's `<animation>` extension) is chapter 05's.
#[test]
fn moving_shapes_and_cameras_are_refused_with_chapter_05() {
    let keyframes = r#"<animation name="to_world">
            <transform time="0"><translate x="-1"/></transform>
            <transform time="1"><translate x="1"/></transform>
        </animation>"#;
    let moving_shape = scene_with("", &format!(r#"<shape type="sphere">{keyframes}</shape>"#));
    let moving_sensor = format!(
        r#"<scene version="3.0.0">
    <sensor type="perspective"><float name="fov" value="45"/>{keyframes}</sensor>
    <shape type="sphere"/>
</scene>"#
    );
    for (text, expected) in [
        (
            moving_shape,
            "line 7, column 5: a shape that moves (shape 1)",
        ),
        (moving_sensor, "line 2, column 5: a camera that moves"),
    ] {
        let loaded =
            parse_scene(&text, Path::new("test.xml"), &[]).expect("the file itself is valid");
        let error = convert(&loaded.scene)
            .err()
            .unwrap_or_else(|| panic!("accepted: {text}"));
        assert!(
            error.contains(expected),
            "expected `{expected}` in: {error}"
        );
        assert!(error.contains("chapter 05 (ch05-motion-blur)"), "{error}");
    }
}

/// What no chapter renders is refused by the loader itself, before any chapter's check.
#[test]
fn what_no_chapter_renders_is_refused_while_loading() {
    for (body, expected) in [
        (
            r#"<shape type="sphere"><bsdf type="conductor"><string name="material" value="Unobtainium"/></bsdf></shape>"#,
            "unknown material \"Unobtainium\"",
        ),
        (
            r#"<shape type="obj"><string name="filename" value="bunny.obj"/></shape>"#,
            "cannot read the mesh bunny.obj",
        ),
    ] {
        let error = parse_scene(&scene_with("", body), Path::new("test.xml"), &[])
            .err()
            .unwrap_or_else(|| panic!("accepted: {body}"))
            .to_string();
        assert!(
            error.contains(expected),
            "expected `{expected}` in: {error}"
        );
    }
}

#[test]
fn broken_scene_files_are_refused_by_the_binary() {
    let dir = tempfile::tempdir().unwrap();
    let image = dir.path().join("img.png");
    let broken = dir.path().join("broken.xml");
    std::fs::write(&broken, "<scene version=\"3.0.0\">\n  <shape type=\"sphere\">\n    <float name=\"radius\" value=\"1.0x\"/>\n  </shape>\n</scene>\n").unwrap();
    let area =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../workbench/tests/scenes/cornell.xml");
    let missing = dir.path().join("missing.xml");
    for (scene, expected) in [
        (broken.to_str().unwrap(), "broken.xml:3:"),
        (area.to_str().unwrap(), "chapter 07"),
        (missing.to_str().unwrap(), "missing.xml"),
    ] {
        let out = run(&["render", "--scene", scene, "--out", image.to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{scene} rendered");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(
            stderr.contains(expected),
            "expected `{expected}` in: {stderr}"
        );
    }
    let out = run(&[
        "render",
        "--builtin",
        "cornell",
        "-D",
        "spp=3",
        "--out",
        image.to_str().unwrap(),
    ]);
    assert!(!out.status.success(), "-D without --scene was accepted");
    assert!(!image.exists());
}

#[test]
fn a_gold_sphere_renders_as_the_mirror_of_its_colour_square_on_with_a_note() {
    let light = r#"<emitter type="point"><point name="position" x="0" y="3" z="3"/><rgb name="intensity" value="20"/></emitter>
        <shape type="rectangle"><transform name="to_world"><scale value="3"/><translate z="-2"/></transform>
          <bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.5, 0.8"/></bsdf></shape>"#;
    let gold = scene_with(
        "",
        &format!(
            r#"{light}<shape type="sphere"><bsdf type="conductor"><string name="material" value="Au"/></bsdf></shape>"#
        ),
    );
    let mut scene = parse_scene(&gold, Path::new("gold.xml"), &[])
        .unwrap()
        .scene;
    let notes = convert(&scene).unwrap();
    assert!(
        notes.iter().any(
            |n| n.contains("a metal (shape 2: rendered as a mirror of reflectance")
                && n.contains("chapter 09")
        ),
        "{notes:?}"
    );
    CAPABILITIES.put_in_stand_ins(&mut scene);
    let common::scene::Material::Mirror { reflectance } = scene.surfaces[1].material else {
        panic!("{:?}", scene.surfaces[1]);
    };
    // The same scene written with that mirror renders the same image, bit for bit.
    let mirror = scene_with(
        "",
        &format!(
            r#"{light}<shape type="sphere"><bsdf type="conductor"><rgb name="specular_reflectance" value="{}, {}, {}"/></bsdf></shape>"#,
            reflectance.x, reflectance.y, reflectance.z
        ),
    );
    let mirror = parse_scene(&mirror, Path::new("mirror.xml"), &[])
        .unwrap()
        .scene;
    let settings = RenderSettings::new(8, 8, 1);
    let image = |scene: &Scene| {
        render(scene, &settings, PixelPattern::Centre, 0)
            .unwrap()
            .image
    };
    assert_eq!(image(&scene).pixels, image(&mirror).pixels);
    // And gold is not white: the blue wall in it is darkened more than the rest.
    assert!(reflectance.x > 0.9 && reflectance.z < 0.5, "{reflectance}");
}

#[test]
fn a_textured_diffuse_surface_shows_its_texture_at_each_hit() {
    // A rectangle filling the view, red where u and v are on the same side of 1/2, blue
    // elsewhere. Looking down -z with +y up, the image's left is world -x: the top-left
    // quarter has u < 1/2 < v, blue. Mitsuba 3 renders this scene blue at pixel (1, 1) and
    // red at (6, 1) and (1, 6).
    let text = scene_with(
        "",
        r#"<shape type="rectangle">
             <transform name="to_world"><scale x="3" y="3"/></transform>
             <bsdf type="diffuse"><texture type="checkerboard" name="reflectance">
               <rgb name="color0" value="0.9, 0, 0"/><rgb name="color1" value="0, 0, 0.9"/>
             </texture></bsdf>
           </shape>
           <emitter type="point"><point name="position" x="0" y="0" z="3"/>
             <rgb name="intensity" value="10"/></emitter>"#,
    );
    let loaded = parse_scene(&text, Path::new("test.xml"), &[]).unwrap();
    let notes = convert(&loaded.scene).expect("chapter 01 renders textures");
    assert!(
        !notes.iter().any(|note| note.contains("texture")),
        "{notes:?}"
    );
    let settings = RenderSettings::new(8, 8, 1);
    let image = render(&loaded.scene, &settings, PixelPattern::Centre, 0)
        .unwrap()
        .image;
    let (top_left, top_right) = (image.get(1, 1), image.get(6, 1));
    let (bottom_left, bottom_right) = (image.get(1, 6), image.get(6, 6));
    for red in [top_right, bottom_left] {
        assert!(red.x > 0.0 && red.z == 0.0, "{red}");
    }
    for blue in [top_left, bottom_right] {
        assert!(blue.z > 0.0 && blue.x == 0.0, "{blue}");
    }
}
