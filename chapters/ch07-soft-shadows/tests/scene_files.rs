//! The chapter's scene files load with their lights where the file puts them: one light per
//! piece of a shape (six for a cube, one per triangle of a mesh), each with the file's
//! radiance; what the chapter cannot render is refused with the shape's position.

use ch07_soft_shadows::area_lights::LightShape;
use ch07_soft_shadows::lab::CAPABILITIES;
use ch07_soft_shadows::{AreaLights, DiscWarp, LightSampling};
use common::scene::Scene;
use glam::{Vec2, Vec3};
use std::path::Path;
use workbench::scene_file::{load_scene_file, parse_scene};

/// A scene file as this chapter sees it: the scene, its area lights, the notes of the check.
struct Converted {
    scene: Scene,
    lights: AreaLights,
    notes: Vec<String>,
}

/// `scene` checked against this chapter, with its lights.
fn convert(scene: Scene) -> Result<Converted, String> {
    let notes = CAPABILITIES.check(&scene)?;
    Ok(Converted {
        lights: AreaLights::of(&scene),
        scene,
        notes,
    })
}

fn converted(name: &str) -> Converted {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name);
    let loaded = load_scene_file(&path, &[]).unwrap();
    convert(loaded.scene).unwrap_or_else(|e| panic!("{name}: {e}"))
}

#[test]
fn every_shipped_scene_converts_with_its_lights() {
    let cases = [
        ("rectangle-light.xml", 1),
        ("disc-light.xml", 1),
        ("sphere-light.xml", 1),
        ("several-lights.xml", 6 + 2),
    ];
    for (name, lights) in cases {
        let file = converted(name);
        assert_eq!(file.lights.lights.len(), lights, "{name}");
        // Every light is a shape of the world, and the table points back at it.
        let shapes = file.scene.geometry.shapes();
        for (shape, entry) in shapes.iter().zip(&file.lights.light_of_shape) {
            if let Some(index) = entry {
                let light = file.lights.lights[*index as usize];
                assert_eq!(
                    light.shape,
                    ch07_soft_shadows::area_lights::light_shape(shape),
                    "{name}"
                );
            }
        }
        assert!(
            converted(name)
                .notes
                .iter()
                .all(|n| !n.contains("indirect")),
            "{name}: direct light only"
        );
    }
}

#[test]
fn a_cube_light_is_six_parallelograms_and_a_mesh_one_triangle_per_face() {
    let file = converted("several-lights.xml");
    let scene = &file.lights;
    let kinds: Vec<_> = scene
        .lights
        .iter()
        .map(|light| match light.shape {
            LightShape::Parallelogram(_) => "parallelogram",
            LightShape::Triangle(_) => "triangle",
            LightShape::Disc(_) => "disc",
            LightShape::Sphere(_) => "sphere",
        })
        .collect();
    assert_eq!(
        kinds,
        [["parallelogram"; 6].as_slice(), &["triangle"; 2]].concat()
    );
    for light in &scene.lights[..6] {
        assert_eq!(light.radiance, Vec3::new(14.0, 4.5, 2.2));
    }
    for light in &scene.lights[6..] {
        assert_eq!(light.radiance, Vec3::new(2.0, 4.0, 9.0));
        // The diamond faces down.
        let LightShape::Triangle(t) = light.shape else {
            unreachable!()
        };
        assert!((t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]).y < 0.0);
    }
    assert_eq!(file.scene.point_lights.len(), 1, "the point light");
}

fn convert_text(text: &str) -> Result<Converted, String> {
    let loaded = parse_scene(text, Path::new("test.xml"), &[]).map_err(|e| e.to_string())?;
    convert(loaded.scene)
}

const SENSOR: &str = r#"<sensor type="perspective"><float name="fov" value="40"/>
        <transform name="to_world"><lookat origin="0, 1, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>
    </sensor>"#;

#[test]
fn a_scene_without_lights_is_chapter_06s_and_the_integrator_notes_follow_the_depth() {
    let text = |integrator: &str, emitter: &str| {
        format!(
            r#"<scene version="3.0.0">{integrator}{SENSOR}
            <shape type="rectangle"/>
            <shape type="sphere">{emitter}</shape>
            <emitter type="point"><point name="position" x="0" y="3" z="0"/></emitter></scene>"#
        )
    };
    let dark = convert_text(&text("", "")).unwrap();
    assert!(dark.lights.lights.is_empty());
    assert_eq!(dark.lights.light_of_shape, vec![None, None]);
    let lit = convert_text(&text(
        r#"<integrator type="path"><integer name="max_depth" value="8"/></integrator>"#,
        r#"<emitter type="area"><rgb name="radiance" value="2, 2, 2"/></emitter>"#,
    ))
    .unwrap();
    assert_eq!(lit.lights.light_of_shape, vec![None, Some(0)]);
    assert!(
        lit.notes.iter().any(|n| n.contains("indirect")),
        "{:?}",
        lit.notes
    );
    let direct = convert_text(&text(
        r#"<integrator type="path"><integer name="max_depth" value="2"/></integrator>"#,
        r#"<emitter type="area"><rgb name="radiance" value="2, 2, 2"/></emitter>"#,
    ))
    .unwrap();
    assert!(
        direct.notes.iter().all(|n| !n.contains("indirect")),
        "{:?}",
        direct.notes
    );
}

#[test]
fn a_sphere_light_turned_inside_out_faces_inwards() {
    let text = format!(
        r#"<scene version="3.0.0">{SENSOR}<shape type="sphere"><boolean name="flip_normals" value="true"/>
        <float name="radius" value="2"/>
        <emitter type="area"><rgb name="radiance" value="1, 1, 1"/></emitter></shape></scene>"#
    );
    let file = convert_text(&text).unwrap();
    let light = file.lights.lights[0];
    let LightShape::Sphere(sphere) = light.shape else {
        panic!("{:?}", light.shape);
    };
    assert!(sphere.inward, "flip_normals reaches the light's sphere");
    // From inside (no cone there, so by area with either strategy), every light sample faces
    // the receiver: the light shines inwards.
    let receiver = Vec3::new(0.3, -0.2, 0.5);
    for sampling in [
        LightSampling::solid_angle(),
        LightSampling::area(DiscWarp::Concentric),
    ] {
        for i in 0..64 {
            let u = Vec2::new((i % 8) as f32 + 0.5, (i / 8) as f32 + 0.5) / 8.0;
            let sample = light.sample(receiver, u, sampling).unwrap();
            assert!(
                sample.n.dot(receiver - sample.p) > 0.0,
                "a sample of a flipped sphere must carry the inward normal, got {} at {}",
                sample.n,
                sample.p
            );
        }
    }
}
