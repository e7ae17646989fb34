//! Transforms compose as in Mitsuba 3, and the camera's field of view is converted to x.

use glam::{Mat4, Vec3, Vec4};

use super::super::*;
use super::{parse, scene_with};

/// The `to_world` of the only shape in `body`.
fn shape_to_world(body: &str) -> Mat4 {
    let loaded = parse(&scene_with(body)).expect("scene loads");
    loaded.scene.shapes[0].to_world
}

#[test]
fn lookat_puts_plus_x_on_the_images_left() {
    let text = r#"<scene version="3.0.0"><sensor type="perspective">
        <float name="fov" value="40"/>
        <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
    </sensor></scene>"#;
    let to_world = parse(text).expect("loads").scene.sensor.to_world;
    // Looking down -z with +y up, the image's left is world -x.
    let expected = Mat4::from_cols(
        Vec4::new(-1.0, 0.0, 0.0, 0.0),
        Vec4::new(0.0, 1.0, 0.0, 0.0),
        Vec4::new(0.0, 0.0, -1.0, 0.0),
        Vec4::new(0.0, 0.0, 5.0, 1.0),
    );
    assert!(to_world.abs_diff_eq(expected, 1e-6), "{to_world}");
}

#[test]
fn rotate_then_translate_puts_the_cornell_floor_at_y_minus_1_facing_up() {
    let to_world = shape_to_world(
        r#"<shape type="rectangle"><transform name="to_world">
            <rotate x="1" angle="-90"/><translate y="-1"/>
        </transform></shape>"#,
    );
    let normal = to_world.inverse().transpose().transform_vector3(Vec3::Z);
    assert!(normal.normalize().abs_diff_eq(Vec3::Y, 1e-6), "{normal}");
    let corner = to_world.transform_point3(Vec3::new(1.0, 1.0, 0.0));
    assert!(
        corner.abs_diff_eq(Vec3::new(1.0, -1.0, -1.0), 1e-6),
        "{corner}"
    );
}

#[test]
fn later_elements_apply_after_earlier_ones() {
    // Scale then translate: the translation is not scaled.
    let scale_first = shape_to_world(
        r#"<shape type="cube"><transform name="to_world"><scale value="2"/><translate x="1"/></transform></shape>"#,
    );
    assert!(
        scale_first
            .transform_point3(Vec3::ZERO)
            .abs_diff_eq(Vec3::X, 1e-6)
    );
    // Translate then scale: the translation is scaled.
    let translate_first = shape_to_world(
        r#"<shape type="cube"><transform name="to_world"><translate x="1"/><scale value="2"/></transform></shape>"#,
    );
    assert!(
        translate_first
            .transform_point3(Vec3::ZERO)
            .abs_diff_eq(2.0 * Vec3::X, 1e-6)
    );
}

#[test]
fn matrix_is_read_row_by_row() {
    let to_world = shape_to_world(
        r#"<shape type="cube"><transform name="to_world">
            <matrix value="1 0 0 3  0 1 0 4  0 0 1 5  0 0 0 1"/>
        </transform></shape>"#,
    );
    assert_eq!(
        to_world.transform_point3(Vec3::ZERO),
        Vec3::new(3.0, 4.0, 5.0)
    );
}

#[test]
fn fov_axes_are_converted_to_horizontal_for_a_wide_film() {
    let aspect = 2.0_f32;
    let horizontal = |axis| horizontal_fov(60.0, axis, aspect).expect("known axis");
    let from_vertical = 2.0 * ((30.0_f32).to_radians().tan() * 2.0).atan().to_degrees();
    assert_eq!(horizontal("x"), 60.0);
    assert!((horizontal("y") - from_vertical).abs() < 1e-4);
    // On a wide film the smaller axis is y and the larger is x.
    assert_eq!(horizontal("smaller"), horizontal("y"));
    assert_eq!(horizontal("larger"), 60.0);
    // The diagonal's half-width is tan(30°) · 2 / sqrt(5).
    let from_diagonal = 2.0 * ((30.0_f32).to_radians().tan() * 2.0 / 5.0_f32.sqrt()).atan();
    assert!((horizontal("diagonal") - from_diagonal.to_degrees()).abs() < 1e-4);
    assert_eq!(horizontal_fov(60.0, "z", aspect), None);
}

#[test]
fn fov_axis_y_in_a_file_uses_the_films_aspect() {
    let text = r#"<scene version="3.0.0"><sensor type="perspective">
        <float name="fov" value="60"/><string name="fov_axis" value="y"/>
        <film type="hdrfilm"><integer name="width" value="200"/><integer name="height" value="100"/></film>
    </sensor></scene>"#;
    let fov_x = parse(text).expect("loads").scene.sensor.fov_x_degrees;
    let expected = horizontal_fov(60.0, "y", 2.0).expect("known axis");
    assert!((fov_x - expected).abs() < 1e-4, "{fov_x} vs {expected}");
    assert!(fov_x > 90.0);
}
