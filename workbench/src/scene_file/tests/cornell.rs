//! The Cornell box example that Mitsuba 3 renders: every value the chapters rely on.

use std::path::Path;

use glam::Vec3;

use super::super::*;

/// The example scene, kept as a fixture file.
const CORNELL: &str = include_str!("../../../tests/scenes/cornell.xml");

fn load(overrides: &[(String, String)]) -> LoadedDescription {
    parse_description(CORNELL, Path::new("cornell.xml"), overrides).expect("cornell.xml loads")
}

#[test]
fn loads_eight_shapes_without_warnings() {
    let loaded = load(&[]);
    assert_eq!(loaded.warnings, vec![]);
    // Five walls, the ceiling light and two spheres.
    assert_eq!(loaded.scene.shapes.len(), 8);
    assert!(loaded.scene.emitters.is_empty());
}

#[test]
fn integrator_is_path_with_max_depth_8_and_no_roulette() {
    let expected = Integrator::Path {
        max_depth: 8,
        rr_depth: 1000,
    };
    assert_eq!(load(&[]).scene.integrator, expected);
}

#[test]
fn sensor_has_the_files_film_sampler_and_fov() {
    let sensor = load(&[]).scene.sensor;
    assert_eq!(sensor.model, common::scene::CameraModel::Pinhole);
    assert_eq!(sensor.fov_x_degrees, 40.0);
    assert_eq!((sensor.film.width, sensor.film.height), (256, 256));
    assert_eq!(sensor.film.filter, common::scene::FilmFilter::Box);
    assert_eq!(sensor.film.component_format, "float32");
    assert_eq!(sensor.sampler.type_name, "independent");
    assert_eq!(sensor.sampler.sample_count, 64);
    assert_eq!(sensor.near_clip, 0.01);
    let camera_position = sensor.to_world.transform_point3(Vec3::ZERO);
    assert!(camera_position.abs_diff_eq(Vec3::new(0.0, 0.0, 3.9), 1e-6));
}

#[test]
fn override_changes_the_sample_count() {
    let overrides = [("spp".to_string(), "16".to_string())];
    assert_eq!(load(&overrides).scene.sensor.sampler.sample_count, 16);
}

#[test]
fn ceiling_light_has_the_files_radiance_and_a_black_bsdf() {
    let shapes = load(&[]).scene.shapes;
    let lights: Vec<_> = shapes.iter().filter(|s| s.emitter.is_some()).collect();
    assert_eq!(lights.len(), 1);
    let light = lights[0];
    assert_eq!(light.emitter.unwrap().radiance, Vec3::new(17.0, 12.0, 4.0));
    assert_eq!(light.material, common::scene::Material::diffuse(Vec3::ZERO));
    assert_eq!(light.geometry, ShapeGeometry::Rectangle);
}

#[test]
fn spheres_are_a_mirror_and_glass_with_the_files_iors() {
    let shapes = load(&[]).scene.shapes;
    let spheres: Vec<_> = shapes
        .iter()
        .filter(|s| matches!(s.geometry, ShapeGeometry::Sphere { .. }))
        .collect();
    assert_eq!(spheres.len(), 2);
    assert_eq!(
        spheres[0].geometry,
        ShapeGeometry::Sphere {
            center: Vec3::new(-0.45, -0.65, -0.3),
            radius: 0.35
        }
    );
    assert_eq!(
        spheres[0].material,
        common::scene::Material::Mirror {
            reflectance: Vec3::ONE
        }
    );
    assert_eq!(
        spheres[1].material,
        common::scene::Material::Dielectric {
            int_ior: 1.5,
            ext_ior: 1.0
        }
    );
}

#[test]
fn walls_use_the_referenced_colours() {
    let shapes = load(&[]).scene.shapes;
    let red = common::scene::Material::diffuse(Vec3::new(0.65, 0.05, 0.05));
    assert_eq!(shapes[3].material, red);
}

#[test]
fn loading_from_a_file_reads_the_same_scene() {
    let directory = tempfile::tempdir().expect("temporary directory");
    let path = directory.path().join("cornell.xml");
    std::fs::write(&path, CORNELL).expect("write fixture");
    let from_file = load_scene_file(&path, &[]).expect("loads from disk");
    let from_text = parse_scene(CORNELL, Path::new("cornell.xml"), &[]).expect("loads");
    assert_eq!(from_file.warnings, from_text.warnings);
    assert_eq!(from_file.scene.surfaces, from_text.scene.surfaces);
    assert_eq!(
        from_file.scene.geometry.shapes(),
        from_text.scene.geometry.shapes()
    );
    assert_eq!(from_file.scene.camera, from_text.scene.camera);
}
