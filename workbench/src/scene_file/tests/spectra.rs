//! `<spectrum>` properties in scene files: a BSDF's reflectance and an emitter's radiance read
//! from spectra as Mitsuba 3's RGB variants read them, `.spd` files found like other files,
//! and the errors and warnings placed at the element.

// Mitsuba's colours are written to nine digits, as its Python bindings print them.
#![allow(clippy::excessive_precision)]

use std::fs;

use glam::Vec3;

use super::super::*;
use super::{parse, scene_with};
use common::scene::Material;

/// A diffuse sphere with a reflectance `spectrum`, lit by an area emitter with a radiance
/// `spectrum` on a rectangle.
fn two_spectra(reflectance: &str, radiance: &str) -> String {
    scene_with(&format!(
        "<shape type=\"sphere\"><bsdf type=\"diffuse\">\
         <spectrum name=\"reflectance\" value=\"{reflectance}\"/></bsdf></shape>\
         <shape type=\"rectangle\"><emitter type=\"area\">\
         <spectrum name=\"radiance\" value=\"{radiance}\"/></emitter></shape>"
    ))
}

#[test]
fn the_same_spectrum_is_white_as_a_reflectance_and_purple_as_a_light() {
    let loaded = parse(&two_spectra("360:1, 830:1", "360:1, 830:1")).expect("loads");
    assert_eq!(loaded.warnings, vec![]);
    let Material::Diffuse { albedo, .. } = loaded.scene.shapes[0].material else {
        panic!("{:?}", loaded.scene.shapes[0].material)
    };
    // Mitsuba 3.9.1 (scalar_rgb) gives these, as the spectrum module's tests check in detail.
    assert!(albedo.abs_diff_eq(Vec3::new(0.998985291, 0.998873711, 0.998801589), 1e-6));
    let radiance = loaded.scene.shapes[1].emitter.unwrap().radiance;
    assert!(radiance.abs_diff_eq(Vec3::new(1.20488369, 0.94822818, 0.909266829), 1e-6));
}

#[test]
fn a_single_number_is_grey_for_a_bsdf_and_purple_for_a_light() {
    let loaded = parse(&two_spectra("0.25", "2")).expect("loads");
    assert_eq!(
        loaded.scene.shapes[0].material,
        Material::diffuse(Vec3::splat(0.25))
    );
    let radiance = loaded.scene.shapes[1].emitter.unwrap().radiance;
    assert!(radiance.abs_diff_eq(Vec3::new(2.40958786, 1.89658201, 1.81783211), 1e-6));
}

#[test]
fn point_and_constant_emitters_convert_as_lights() {
    let text = scene_with(
        "<emitter type=\"point\"><spectrum name=\"intensity\" value=\"3\"/></emitter>\
         <emitter type=\"constant\"><spectrum name=\"radiance\" value=\"1\"/></emitter>",
    );
    let emitters = parse(&text).expect("loads").scene.emitters;
    let purple = Vec3::new(1.20479393, 0.948291004, 0.908916056);
    match &emitters[..] {
        [
            EmitterDescription::Point { intensity, .. },
            EmitterDescription::Constant { radiance, .. },
        ] => {
            assert!(intensity.abs_diff_eq(purple * 3.0, 1e-5), "{intensity}");
            assert!(radiance.abs_diff_eq(purple, 1e-6), "{radiance}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn an_out_of_gamut_reflectance_is_clamped_with_a_warning_at_its_line() {
    let loaded = parse(&two_spectra("500:1, 510:1", "400:1, 700:1")).expect("loads");
    let Material::Diffuse { albedo, .. } = loaded.scene.shapes[0].material else {
        panic!("{:?}", loaded.scene.shapes[0].material)
    };
    assert_eq!(albedo.x, 0.0);
    assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
    let warning = &loaded.warnings[0];
    assert_eq!(warning.line, 2);
    assert!(
        warning.message.contains("\"reflectance\""),
        "{}",
        warning.message
    );
    assert!(
        warning.message.contains("[0, 1]: clamped"),
        "{}",
        warning.message
    );
}

#[test]
fn a_light_with_a_negative_channel_is_clamped_with_a_warning() {
    let loaded = parse(&two_spectra("0.5", "500:1, 510:1")).expect("loads");
    let radiance = loaded.scene.shapes[1].emitter.unwrap().radiance;
    assert_eq!(radiance.x, 0.0);
    assert!(radiance.y > 0.0);
    assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
    let message = &loaded.warnings[0].message;
    assert!(
        message.contains("\"radiance\" of the area emitter"),
        "{message}"
    );
    assert!(message.contains("not negative: clamped"), "{message}");
}

#[test]
fn a_spd_file_is_found_next_to_the_scene() {
    let folder = tempfile::tempdir().expect("temporary folder");
    let spd = "# wavelength value\n400 0.2\n500 0.6\n600 0.9\n700 0.4\n";
    fs::write(folder.path().join("paint.spd"), spd).unwrap();
    let text = scene_with(
        "<shape type=\"sphere\"><bsdf type=\"diffuse\">\
         <spectrum name=\"reflectance\" filename=\"paint.spd\"/></bsdf></shape>",
    );
    let path = folder.path().join("scene.xml");
    let loaded = parse_description(&text, &path, &[]).expect("loads");
    let Material::Diffuse { albedo, .. } = loaded.scene.shapes[0].material else {
        panic!("{:?}", loaded.scene.shapes[0].material)
    };
    let mitsuba = Vec3::new(0.85172081, 0.745245039, 0.371197373);
    assert!(albedo.abs_diff_eq(mitsuba, 1e-6), "{albedo}");
}

/// The error `body` (in a scene, starting on line 2) gives.
fn error_of(body: &str) -> SceneError {
    parse(&scene_with(body)).expect_err("the scene is refused")
}

#[test]
fn broken_spectra_are_errors_at_their_element() {
    let cases = [
        ("400:0.5, 300:1", "300 nm comes after 400 nm"),
        ("400:0.5 700", "no colon"),
        ("red", "found \"red\""),
        ("400:0.5", "at least two"),
    ];
    for (value, fragment) in cases {
        let error = error_of(&format!(
            "<bsdf type=\"diffuse\"><spectrum name=\"reflectance\" value=\"{value}\"/></bsdf>"
        ));
        assert_eq!((error.line, error.column), (2, 22), "{value}: {error}");
        assert!(error.message.starts_with("<spectrum>: "), "{error}");
        assert!(error.message.contains(fragment), "{value}: {error}");
    }
}

#[test]
fn a_spectrum_needs_exactly_one_of_value_and_filename() {
    for attributes in ["", " value=\"0.5\" filename=\"a.spd\""] {
        let error = error_of(&format!(
            "<bsdf type=\"diffuse\"><spectrum name=\"reflectance\"{attributes}/></bsdf>"
        ));
        assert!(
            error
                .message
                .contains("either a \"value\" or a \"filename\""),
            "{error}"
        );
    }
}

#[test]
fn a_missing_spd_file_is_an_error_naming_it() {
    let error = error_of(
        "<bsdf type=\"diffuse\"><spectrum name=\"reflectance\" filename=\"nowhere.spd\"/></bsdf>",
    );
    assert_eq!(error.line, 2);
    assert!(error.message.contains("nowhere.spd"), "{error}");
}

#[test]
fn spectrum_plugins_are_refused_by_name() {
    let error = error_of(
        "<bsdf type=\"diffuse\"><spectrum name=\"reflectance\" type=\"blackbody\"/></bsdf>",
    );
    assert!(error.message.contains("type=\"blackbody\""), "{error}");
}

#[test]
fn a_spectrum_where_a_number_is_expected_is_refused() {
    let error = error_of("<shape type=\"sphere\"><spectrum name=\"radius\" value=\"1\"/></shape>");
    assert!(error.message.contains("found a <spectrum>"), "{error}");
}
