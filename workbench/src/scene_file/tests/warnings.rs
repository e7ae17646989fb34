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

#[test]
fn an_area_emitters_sampling_weight_is_read_and_must_be_positive() {
    let text = scene_with(
        "<shape type=\"sphere\"><emitter type=\"area\"><rgb name=\"radiance\" value=\"1\"/>\
         <float name=\"sampling_weight\" value=\"3\"/></emitter></shape>",
    );
    let loaded = parse(&text).expect("loads");
    assert_eq!(loaded.warnings, vec![]);
    let emitter = loaded.scene.shapes[0].emitter.expect("an area light");
    assert_eq!(emitter.sampling_weight, 3.0);
    let text = scene_with(
        "<shape type=\"sphere\"><emitter type=\"area\"><rgb name=\"radiance\" value=\"1\"/>\
         <float name=\"sampling_weight\" value=\"-1\"/></emitter></shape>",
    );
    let error = parse(&text).expect_err("a negative weight is refused");
    assert!(error.to_string().contains("sampling_weight"), "{error}");
}
