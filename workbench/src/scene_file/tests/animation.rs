//! `<animation name="to_world">`, the workbook's extension for moving shapes and cameras.

use glam::{Mat4, Vec3};

use super::{parse, scene_with};

#[test]
fn a_moving_shape_keeps_its_keyframes_and_its_first_matrix_as_to_world() {
    let loaded = parse(&scene_with(
        r#"<shape type="sphere"><animation name="to_world">
            <transform time="0"><translate x="-1"/></transform>
            <transform time="0.5"><rotate y="1" angle="90"/><translate x="0.5"/></transform>
            <transform time="1"><scale value="2"/><translate x="1"/></transform>
        </animation></shape>"#,
    ))
    .expect("loads");
    assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    let shape = &loaded.scene.shapes[0];
    let times: Vec<f32> = shape.to_world_keyframes.iter().map(|k| k.0).collect();
    assert_eq!(times, [0.0, 0.5, 1.0]);
    assert_eq!(shape.to_world, Mat4::from_translation(-Vec3::X));
    assert_eq!(shape.to_world_keyframes[0].1, shape.to_world);
    let middle = shape.to_world_keyframes[1].1;
    assert!(
        middle
            .transform_point3(Vec3::Z)
            .abs_diff_eq(Vec3::new(1.5, 0.0, 0.0), 1e-6),
        "{middle}"
    );
    let last = shape.to_world_keyframes[2].1;
    assert_eq!(last.transform_point3(Vec3::ZERO), Vec3::X);
    assert_eq!(last.transform_vector3(Vec3::Y), 2.0 * Vec3::Y);
}

#[test]
fn a_moving_sensor_keeps_its_keyframes() {
    let text = r#"<scene version="3.0.0"><sensor type="perspective">
        <float name="fov" value="40"/>
        <float name="shutter_close" value="1"/>
        <animation name="to_world">
            <transform time="0"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
            <transform time="1"><lookat origin="1, 0, 5" target="1, 0, 0" up="0, 1, 0"/></transform>
        </animation>
    </sensor></scene>"#;
    let sensor = parse(text).expect("loads").scene.sensor;
    assert_eq!(sensor.to_world_keyframes.len(), 2);
    assert_eq!(sensor.to_world, sensor.to_world_keyframes[0].1);
    assert_eq!(
        sensor.to_world_keyframes[1].1.w_axis.truncate(),
        Vec3::new(1.0, 0.0, 5.0)
    );
    assert_eq!(sensor.shutter_close, 1.0);
}

#[test]
fn static_shapes_and_sensors_have_no_keyframes() {
    let loaded = parse(&scene_with(
        r#"<shape type="cube"><transform name="to_world"><translate y="2"/></transform></shape>"#,
    ))
    .expect("loads");
    assert!(loaded.scene.shapes[0].to_world_keyframes.is_empty());
    assert!(loaded.scene.sensor.to_world_keyframes.is_empty());
}
