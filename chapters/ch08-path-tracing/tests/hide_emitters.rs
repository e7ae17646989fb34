//! Mitsuba's `hide_emitters`: the camera stops seeing the light source and the environment,
//! and nothing else changes. The same samples are drawn either way, so every pixel that does
//! not look straight at something glowing must come out bit for bit the same.

mod support;
use support::render_text;

/// A floor under a square light, seen from the side, with a grey sky around.
fn scene(hide: bool) -> String {
    format!(
        r#"<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value="4"/>
        <boolean name="hide_emitters" value="{hide}"/></integrator>
    <sensor type="perspective"><float name="fov" value="60"/>
        <transform name="to_world"><lookat origin="0, 1, 4" target="0, 0.8, 0" up="0, 1, 0"/></transform>
        <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
        <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="16"/>
            <rfilter type="box"/></film></sensor>
    <emitter type="constant"><rgb name="radiance" value="0.5"/></emitter>
    <shape type="rectangle"><transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/></transform></shape>
    <shape type="rectangle">
        <transform name="to_world"><scale value="0.5"/><rotate x="1" angle="90"/><translate y="1.5"/></transform>
        <emitter type="area"><rgb name="radiance" value="8"/></emitter></shape>
</scene>"#
    )
}

#[test]
fn hidden_emitters_darken_only_what_the_camera_sees_glowing() {
    let shown = render_text(&scene(false));
    let hidden = render_text(&scene(true));
    let (mut same, mut darker) = (0, 0);
    for y in 0..shown.height {
        for x in 0..shown.width {
            let (a, b) = (shown.get(x, y), hidden.get(x, y));
            if a == b {
                same += 1;
            } else {
                // Only light seen directly goes: a hidden pixel is never brighter.
                assert!(b.cmple(a).all(), "pixel ({x}, {y}): {b} brighter than {a}");
                darker += 1;
            }
        }
    }
    // The sky above the horizon and the light's underside are hidden; the lit floor is not.
    assert!(darker > 0, "hide_emitters changed nothing");
    assert!(same > 0, "hide_emitters changed every pixel");
    // The top row looks at the sky only: black when hidden.
    assert_eq!(hidden.get(0, 0), glam::Vec3::ZERO);
    assert!(shown.get(0, 0).x > 0.4);
    // The bottom row looks at the floor, lit by the light and the sky: unchanged.
    let bottom = shown.height - 1;
    assert_eq!(hidden.get(12, bottom), shown.get(12, bottom));
    assert!(shown.get(12, bottom).x > 0.0);
}

#[test]
fn chapters_before_08_refuse_hidden_emitters() {
    let folder = tempfile::tempdir().unwrap();
    let file = folder.path().join("hidden.xml");
    std::fs::write(&file, scene(true)).unwrap();
    let scene = workbench::scene_file::load_scene_file(&file, &[])
        .unwrap()
        .scene;
    let refusal = ch07_soft_shadows::lab::CAPABILITIES
        .check(&scene)
        .unwrap_err();
    assert!(refusal.contains("hide_emitters"), "{refusal}");
    assert!(refusal.contains("chapter 08"), "{refusal}");
    assert!(ch08_path_tracing::lab::CAPABILITIES.check(&scene).is_ok());
}

/// A lamp facing the camera in front of a wall lit by a point light, with `hide`.
fn lamp_before_a_wall(hide: bool) -> String {
    format!(
        r#"<scene version="3.0.0">
    <integrator type="path"><integer name="max_depth" value="3"/>
        <boolean name="hide_emitters" value="{hide}"/></integrator>
    <sensor type="perspective"><float name="fov" value="30"/>
        <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
        <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/>
            <rfilter type="box"/></film></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="3"/></transform>
        <bsdf type="diffuse"><rgb name="reflectance" value="0.5"/></bsdf></shape>
    <shape type="rectangle">
        <transform name="to_world"><scale value="0.4"/><translate z="1"/></transform>
        <emitter type="area"><rgb name="radiance" value="8"/></emitter></shape>
    <emitter type="point"><point name="position" x="2" y="2" z="3"/>
        <rgb name="intensity" value="20"/></emitter>
</scene>"#
    )
}

#[test]
fn a_hidden_lamp_shows_what_is_behind_it() {
    let shown = render_text(&lamp_before_a_wall(false));
    let hidden = render_text(&lamp_before_a_wall(true));
    let centre = (shown.width / 2, shown.height / 2);
    assert_eq!(
        shown.get(centre.0, centre.1),
        glam::Vec3::splat(8.0),
        "the camera sees the lamp's face"
    );
    let behind = hidden.get(centre.0, centre.1);
    // The wall, lit by the point light: neither black nor the lamp.
    assert!(
        behind.x > 0.05 && behind.x < 1.0,
        "a hidden lamp must let the camera ray through to the lit wall behind it (Mitsuba's \
         hide_emitters skips emitting shapes along camera rays), found {behind}: black means \
         the lamp still stops the ray"
    );
}
