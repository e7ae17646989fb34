//! What real scene files use to be spread over several files and to name objects: `<include>`,
//! `<path>`, `<ref>` to objects declared before or after, `$name` anywhere; and the sensor
//! settings of files written by other people (`focal_length`, no `fov`, a principal point).

use std::fs;
use std::path::{Path, PathBuf};

use glam::{Vec2, Vec3};

use super::super::*;
use super::{parse, scene_with};
use common::scene::Material;

/// Writes `files` (relative path, text) into a new temporary folder and returns it.
fn folder_with(files: &[(&str, &str)]) -> tempfile::TempDir {
    let folder = tempfile::tempdir().expect("temporary folder");
    for (name, text) in files {
        let path = folder.path().join(name);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, text).unwrap();
    }
    folder
}

const SENSOR: &str = "<sensor type=\"perspective\"><float name=\"fov\" value=\"40\"/></sensor>";

fn load_from(folder: &Path, name: &str) -> Result<LoadedDescription, SceneError> {
    let path: PathBuf = folder.join(name);
    parse_description(&fs::read_to_string(&path).unwrap(), &path, &[])
}

#[test]
fn an_include_puts_the_other_files_objects_where_it_stands() {
    let folder = folder_with(&[
        (
            "main.xml",
            &format!(
                "<scene version=\"3.0.0\">{SENSOR}<shape type=\"sphere\"/>\
                 <include filename=\"parts/more.xml\"/><shape type=\"cube\"/></scene>"
            ),
        ),
        (
            "parts/more.xml",
            "<scene version=\"3.0.0\"><shape type=\"disk\"/>\
             <include filename=\"deeper.xml\"/></scene>",
        ),
        // Nested: looked up next to the file that includes it.
        (
            "parts/deeper.xml",
            "<scene version=\"3.0.0\"><shape type=\"rectangle\"/></scene>",
        ),
    ]);
    let loaded = load_from(folder.path(), "main.xml").expect("loads");
    let kinds: Vec<_> = loaded
        .scene
        .shapes
        .iter()
        .map(|shape| shape.geometry.clone())
        .collect();
    assert_eq!(
        kinds,
        vec![
            ShapeGeometry::Sphere {
                center: Vec3::ZERO,
                radius: 1.0
            },
            ShapeGeometry::Disc,
            ShapeGeometry::Rectangle,
            ShapeGeometry::Cube,
        ]
    );
}

#[test]
fn an_error_in_an_included_file_names_that_file_and_its_line() {
    let folder = folder_with(&[
        (
            "main.xml",
            &format!("<scene version=\"3.0.0\">{SENSOR}\n<include filename=\"bad.xml\"/></scene>"),
        ),
        (
            "bad.xml",
            "<scene version=\"3.0.0\">\n\n<shape type=\"torus\"/></scene>",
        ),
    ]);
    let error = load_from(folder.path(), "main.xml").expect_err("the torus is unknown");
    assert_eq!(error.file, folder.path().join("bad.xml"));
    assert_eq!(error.line, 3);
    assert!(error.message.contains("unknown shape type"), "{error}");
}

#[test]
fn a_file_that_includes_itself_is_refused_not_followed_forever() {
    let folder = folder_with(&[
        (
            "main.xml",
            &format!("<scene version=\"3.0.0\">{SENSOR}<include filename=\"a.xml\"/></scene>"),
        ),
        (
            "a.xml",
            "<scene version=\"3.0.0\"><include filename=\"b.xml\"/></scene>",
        ),
        (
            "b.xml",
            "<scene version=\"3.0.0\"><include filename=\"a.xml\"/></scene>",
        ),
    ]);
    let error = load_from(folder.path(), "main.xml").expect_err("a loop");
    assert!(error.message.contains("makes a loop"), "{error}");
    assert_eq!(error.file, folder.path().join("b.xml"));
}

#[test]
fn a_missing_include_is_an_error_at_the_include() {
    let error = parse(&scene_with("\n<include filename=\"nowhere.xml\"/>")).expect_err("missing");
    assert_eq!(
        (error.line, error.file.as_path()),
        (3, Path::new("test.xml"))
    );
    assert!(
        error.message.contains("cannot read the included file"),
        "{error}"
    );
    assert!(error.message.contains("nowhere.xml"), "{error}");
}

#[test]
fn a_path_element_adds_a_folder_where_meshes_and_includes_are_found() {
    let triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    let folder = folder_with(&[
        (
            "scenes/main.xml",
            &format!(
                "<scene version=\"3.0.0\"><path value=\"../shared\"/>{SENSOR}\
                 <include filename=\"parts.xml\"/>\
                 <shape type=\"obj\"><string name=\"filename\" value=\"meshes/tri.obj\"/></shape>\
                 </scene>"
            ),
        ),
        (
            "shared/parts.xml",
            "<scene version=\"3.0.0\"><shape type=\"disk\"/></scene>",
        ),
        ("shared/meshes/tri.obj", triangle),
    ]);
    let loaded = load_from(folder.path(), "scenes/main.xml").expect("loads");
    assert_eq!(loaded.scene.shapes.len(), 2);
    let ShapeGeometry::Obj { filename, .. } = &loaded.scene.shapes[1].geometry else {
        panic!("an obj");
    };
    assert!(filename.exists(), "{}", filename.display());
    assert!(filename.ends_with("shared/meshes/tri.obj"));
}

#[test]
fn a_bsdf_and_an_area_emitter_may_be_referenced_before_they_are_declared() {
    let loaded = parse(&scene_with(
        "<shape type=\"sphere\"><ref id=\"gold\"/><ref id=\"lamp\"/></shape>\
         <bsdf type=\"diffuse\" id=\"gold\"><rgb name=\"reflectance\" value=\"0.8, 0.6, 0.2\"/>\
         </bsdf>\
         <emitter type=\"area\" id=\"lamp\"><rgb name=\"radiance\" value=\"4\"/></emitter>",
    ))
    .expect("loads");
    assert_eq!(loaded.warnings, vec![]);
    let shape = &loaded.scene.shapes[0];
    assert_eq!(shape.material, Material::diffuse(Vec3::new(0.8, 0.6, 0.2)));
    assert_eq!(shape.emitter.unwrap().radiance, Vec3::splat(4.0));
}

#[test]
fn a_twosided_may_wrap_a_reference_and_a_reference_to_itself_is_refused() {
    let loaded = parse(&scene_with(
        "<bsdf type=\"twosided\" id=\"both\"><ref id=\"grey\"/></bsdf>\
         <bsdf type=\"diffuse\" id=\"grey\"/>\
         <shape type=\"sphere\"><ref id=\"both\"/></shape>",
    ))
    .expect("loads");
    assert_eq!(
        loaded.scene.shapes[0].material,
        Material::two_sided_diffuse(Vec3::splat(0.5))
    );
    let error = parse(&scene_with(
        "<bsdf type=\"twosided\" id=\"loop\">\n<ref id=\"loop\"/></bsdf>",
    ))
    .expect_err("a loop");
    assert!(error.message.contains("refers to itself"), "{error}");
}

#[test]
fn an_id_given_twice_is_refused_with_both_places() {
    let error = parse(&scene_with(
        "<bsdf type=\"diffuse\" id=\"a\"/>\n<bsdf type=\"diffuse\" id=\"a\"/>",
    ))
    .expect_err("twice");
    assert_eq!(error.line, 3);
    assert!(error.message.contains("line 2, column"), "{error}");
}

#[test]
fn a_sampler_film_and_filter_may_be_declared_apart_and_referenced() {
    let text = "<scene version=\"3.0.0\">\
        <default name=\"integrator\" value=\"path\"/>\
        <integrator type=\"$integrator\"><integer name=\"max_depth\" value=\"3\"/></integrator>\
        <sampler type=\"independent\" id=\"spp\"><integer name=\"sample_count\" value=\"9\"/>\
        </sampler>\
        <rfilter type=\"tent\" id=\"tent\"/>\
        <sensor type=\"perspective\"><float name=\"fov\" value=\"30\"/><ref id=\"spp\"/>\
        <ref id=\"film\"/></sensor>\
        <film type=\"hdrfilm\" id=\"film\"><integer name=\"width\" value=\"64\"/>\
        <ref id=\"tent\"/></film></scene>";
    let loaded = parse(text).expect("loads");
    assert_eq!(loaded.warnings, vec![]);
    let sensor = &loaded.scene.sensor;
    assert_eq!(sensor.sampler.sample_count, 9);
    assert_eq!(sensor.film.width, 64);
    assert_eq!(
        sensor.film.filter,
        common::scene::FilmFilter::Tent { radius: 1.0 }
    );
    assert_eq!(
        loaded.scene.integrator,
        Integrator::Path {
            max_depth: 3,
            rr_depth: 5
        }
    );
}

#[test]
fn an_object_declared_apart_and_never_used_is_a_warning() {
    let loaded =
        parse(&scene_with("<sampler type=\"independent\" id=\"unused\"/>")).expect("loads");
    assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
    assert!(loaded.warnings[0].message.contains("never referenced"));
}

#[test]
fn a_parameter_may_name_a_plugin_type_and_defaults_in_includes_count() {
    let folder = folder_with(&[
        (
            "main.xml",
            &format!(
                "<scene version=\"3.0.0\"><include filename=\"defaults.xml\"/>{SENSOR}\
                 <shape type=\"$kind\"/></scene>"
            ),
        ),
        (
            "defaults.xml",
            "<scene version=\"3.0.0\"><default name=\"kind\" value=\"cube\"/></scene>",
        ),
    ]);
    let loaded = load_from(folder.path(), "main.xml").expect("loads");
    assert_eq!(loaded.scene.shapes[0].geometry, ShapeGeometry::Cube);
}

/// A sensor with `properties` on a 300 x 200 film.
fn sensor_with(properties: &str) -> Result<LoadedDescription, SceneError> {
    parse(&format!(
        "<scene version=\"3.0.0\"><sensor type=\"perspective\">{properties}\
         <film type=\"hdrfilm\"><integer name=\"width\" value=\"300\"/>\
         <integer name=\"height\" value=\"200\"/></film></sensor></scene>"
    ))
}

#[test]
fn without_a_fov_the_focal_length_sets_it_as_on_a_35mm_film() {
    // The horizontal fields of view Mitsuba 3 computes for a 300 x 200 film.
    let fov = |properties: &str| {
        sensor_with(properties)
            .expect("loads")
            .scene
            .sensor
            .fov_x_degrees
    };
    approx::assert_relative_eq!(fov(""), 39.597_75, max_relative = 1e-4);
    approx::assert_relative_eq!(
        fov("<string name=\"focal_length\" value=\"35mm\"/>"),
        54.432_22,
        max_relative = 1e-4
    );
    approx::assert_relative_eq!(
        fov("<float name=\"focal_length\" value=\"20\"/>"),
        83.974_43,
        max_relative = 1e-4
    );
    for bad in ["-5mm", "fifty", "0mm"] {
        let error = sensor_with(&format!("<string name=\"focal_length\" value=\"{bad}\"/>"))
            .expect_err(bad);
        assert!(error.message.contains("focal_length must be"), "{error}");
    }
    let both = sensor_with(
        "<float name=\"fov\" value=\"30\"/><string name=\"focal_length\" value=\"35mm\"/>",
    )
    .expect_err("both");
    assert!(both.message.contains("both fov and focal_length"), "{both}");
}

#[test]
fn the_principal_point_offset_is_read() {
    let sensor = sensor_with(
        "<float name=\"fov\" value=\"40\"/>\
         <float name=\"principal_point_offset_x\" value=\"0.1\"/>\
         <float name=\"principal_point_offset_y\" value=\"0.2\"/>",
    )
    .expect("loads")
    .scene
    .sensor;
    assert_eq!(sensor.principal_point_offset, Vec2::new(0.1, 0.2));
}

#[test]
fn wrappers_that_do_not_write_radiance_are_refused_with_what_they_write() {
    for (wrapper, says) in [
        ("aov", "extra channels"),
        ("moment", "moments"),
        ("stokes", "polarisation"),
    ] {
        let error = parse(&scene_with(&format!(
            "<integrator type=\"{wrapper}\">\n<integrator type=\"path\"/></integrator>"
        )))
        .expect_err(wrapper);
        assert_eq!(error.line, 2, "{error}");
        assert!(error.message.contains(says), "{error}");
        assert!(
            error.message.contains("not an image of radiance"),
            "{error}"
        );
    }
}

#[test]
fn direct_reads_its_sample_counts_and_hide_emitters() {
    use common::scene::DirectSamples;
    let direct = |body: &str| {
        parse(&scene_with(&format!(
            "<integrator type=\"direct\">{body}</integrator>"
        )))
        .map(|loaded| {
            (
                loaded.scene.integrator,
                loaded.scene.hide_emitters,
                loaded.warnings,
            )
        })
    };
    let (integrator, hide, warnings) = direct(
        "<integer name=\"emitter_samples\" value=\"4\"/><integer name=\"bsdf_samples\" \
         value=\"0\"/><boolean name=\"hide_emitters\" value=\"true\"/>",
    )
    .expect("loads");
    let counts = |emitter, bsdf| Integrator::Direct(DirectSamples { emitter, bsdf });
    assert_eq!(integrator, counts(4, 0));
    assert!(hide);
    assert!(
        warnings.is_empty(),
        "the counts are rendered as given: {warnings:?}"
    );
    // Defaults, shading_samples for both, one count given alone.
    assert_eq!(direct("").unwrap().0, counts(1, 1));
    assert_eq!(
        direct("<integer name=\"shading_samples\" value=\"3\"/>")
            .unwrap()
            .0,
        counts(3, 3)
    );
    assert_eq!(
        direct("<integer name=\"bsdf_samples\" value=\"2\"/>")
            .unwrap()
            .0,
        counts(1, 2)
    );
    // What Mitsuba refuses, refused where it is written.
    for (body, says) in [
        (
            "<integer name=\"shading_samples\" value=\"2\"/>\
             <integer name=\"emitter_samples\" value=\"2\"/>",
            "emitter_samples cannot be given beside shading_samples",
        ),
        (
            "<integer name=\"emitter_samples\" value=\"0\"/>\
             <integer name=\"bsdf_samples\" value=\"0\"/>",
            "needs at least one emitter or BSDF sample",
        ),
        (
            "<integer name=\"bsdf_samples\" value=\"-1\"/>",
            "bsdf_samples must be a whole number from 0 to 4096, found -1",
        ),
        (
            "<integer name=\"emitter_samples\" value=\"100000\"/>",
            "emitter_samples must be a whole number from 0 to 4096, found 100000",
        ),
    ] {
        let error = direct(body).expect_err(body);
        assert_eq!(error.line, 2, "{error}");
        assert!(error.message.contains(says), "{body}: {error}");
    }
}

#[test]
fn a_shape_without_a_bsdf_is_grey_unless_it_glows_then_black_as_in_mitsuba() {
    let loaded = parse(&scene_with(
        "<shape type=\"sphere\"/>\
         <shape type=\"rectangle\"><emitter type=\"area\"/></shape>",
    ))
    .expect("loads");
    assert_eq!(
        loaded.scene.shapes[0].material,
        Material::diffuse(Vec3::splat(0.5))
    );
    assert_eq!(
        loaded.scene.shapes[1].material,
        Material::diffuse(Vec3::ZERO)
    );
}
