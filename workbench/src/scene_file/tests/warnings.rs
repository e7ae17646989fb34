//! Harmless oddities give warnings, and the scene still loads.

use super::{parse, scene_with};

#[test]
fn unknown_property_is_a_warning_with_its_line() {
    let text =
        scene_with("<shape type=\"sphere\">\n  <float name=\"radios\" value=\"2\"/>\n</shape>");
    let loaded = parse(&text).expect("an unknown property does not stop loading");
    assert_eq!(loaded.scene.shapes.len(), 1);
    assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
    let warning = &loaded.warnings[0];
    assert!(
        warning.message.contains("\"radios\""),
        "{}",
        warning.message
    );
    assert_eq!(warning.line, 3);
}

#[test]
fn the_workbooks_phong_is_a_glossy_lobe() {
    let text = scene_with(
        "<shape type=\"cube\"><bsdf type=\"phong\"><float name=\"exponent\" value=\"20\"/></bsdf></shape>",
    );
    let loaded = parse(&text).expect("loads");
    assert_eq!(
        loaded.scene.shapes[0].material,
        common::scene::Material::glossy(glam::Vec3::ONE, 20.0)
    );
    assert_eq!(loaded.warnings, vec![]);
}
