//! Scene files: the chapter's own render, rough materials converted (with the note that says
//! how), and broken or unknown materials refused with the shape they belong to.

use ch06_fuzzy_reflections::lab::CAPABILITIES;
use ch06_fuzzy_reflections::lab::agreement::AGREEMENT;
use common::scene::Material;
use common::scene::Scene;
use workbench::scene_file::{load_scene_file, parse_scene};
use workbench::test_support::{assert_refused, run_binary};

const BINARY: &str = env!("CARGO_BIN_EXE_ch06-fuzzy-reflections");

#[test]
fn every_shipped_scene_renders() {
    let dir = tempfile::tempdir().unwrap();
    for name in [
        "rough-metal",
        "frosted-glass",
        "phong-plates",
        "glass-panes",
    ] {
        let scene = AGREEMENT.scenes_dir().join(format!("{name}.xml"));
        let out = dir.path().join(format!("{name}.exr"));
        let run = run_binary(
            BINARY,
            &[
                "render",
                "--scene",
                scene.to_str().unwrap(),
                "-D",
                "spp=2",
                "--width",
                "24",
                "--height",
                "18",
                "--out",
                out.to_str().unwrap(),
            ],
        );
        assert!(
            run.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&run.stderr)
        );
        assert!(out.exists(), "{name}");
    }
}

#[test]
fn rough_materials_become_lobes_with_a_note() {
    let mut loaded = load_scene_file(&AGREEMENT.scenes_dir().join("rough-metal.xml"), &[]).unwrap();
    let notes = CAPABILITIES.check(&loaded.scene).unwrap();
    CAPABILITIES.put_in_stand_ins(&mut loaded.scene);
    let Material::Glossy(floor) = loaded.scene.surfaces[0].material else {
        panic!("the floor is glossy: {:?}", loaded.scene.surfaces[0]);
    };
    approx::assert_relative_eq!(floor.exponent, 198.0, max_relative = 1e-4);
    assert!(
        notes.iter().any(|n| n.contains("n = 2/alpha^2 - 2")),
        "{notes:?}"
    );
    // The frosted pane is a cube: six faces, each frosted glass, sharing the cube's surface.
    let loaded = load_scene_file(&AGREEMENT.scenes_dir().join("frosted-glass.xml"), &[]).unwrap();
    let scene = &loaded.scene;
    let frosted: Vec<u32> = (0..scene.shape_count() as u32)
        .filter(|&shape| matches!(scene.surface(shape).material, Material::RoughGlass(_)))
        .collect();
    assert_eq!(frosted.len(), 6);
    let cube = scene.surface_of_shape[frosted[0] as usize];
    assert!(
        frosted
            .iter()
            .all(|&shape| scene.surface_of_shape[shape as usize] == cube)
    );
}

/// The scene file with `bsdf` as the material of its only shape, loaded and checked against
/// this chapter, with the lecture's stand-ins in place as the chapter renders it.
fn convert_with(bsdf: &str) -> Result<Scene, String> {
    let xml = format!(
        r#"<scene version="3.0.0">
             <sensor type="perspective"><float name="fov" value="40"/><film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film></sensor>
             <shape type="sphere">{bsdf}</shape>
           </scene>"#
    );
    let mut loaded =
        parse_scene(&xml, std::path::Path::new("test.xml"), &[]).map_err(|e| e.to_string())?;
    CAPABILITIES.check(&loaded.scene)?;
    CAPABILITIES.put_in_stand_ins(&mut loaded.scene);
    Ok(loaded.scene)
}

#[test]
fn every_rough_material_is_read_and_wrong_ones_are_refused() {
    let material = |bsdf: &str| convert_with(bsdf).unwrap().surfaces[0].material.clone();
    let glossy = material(r#"<bsdf type="phong"><float name="exponent" value="50"/></bsdf>"#);
    assert!(matches!(glossy, Material::Glossy(g) if g.exponent == 50.0));
    let two_sided = material(
        r#"<bsdf type="twosided"><bsdf type="roughconductor"><float name="alpha" value="0.2"/></bsdf></bsdf>"#,
    );
    assert!(matches!(two_sided, Material::Glossy(g) if g.two_sided));
    let glass = material(
        r#"<bsdf type="roughdielectric"><string name="int_ior" value="water"/><float name="alpha" value="0.05"/></bsdf>"#,
    );
    assert!(matches!(glass, Material::RoughGlass(g) if g.int_ior == 1.333));
    // A rough gold: the lobe of gold's colour square on.
    let gold = material(
        r#"<bsdf type="roughconductor"><string name="material" value="Au"/><float name="alpha" value="0.2"/></bsdf>"#,
    );
    assert!(matches!(gold, Material::Glossy(g) if g.reflectance.x > 0.9 && g.reflectance.z < 0.5));
    // Plastic waits for the materials beyond the lecture.
    let plastic = convert_with(r#"<bsdf type="plastic"/>"#).unwrap_err();
    assert!(plastic.contains("chapter 09 (ch09-materials)"), "{plastic}");
    // So do cut-outs, named where the file writes them.
    let mask = convert_with(r#"<bsdf type="mask"><bsdf type="diffuse"/></bsdf>"#).unwrap_err();
    assert!(
        mask.starts_with("line 3, column 14: a cut-out (mask) (shape 1);")
            && mask.contains("in chapter 09 (ch09-materials)"),
        "{mask}"
    );
    for (bsdf, expected) in [
        (
            r#"<bsdf type="measured"/>"#,
            "unknown bsdf type \"measured\"",
        ),
        (
            r#"<bsdf type="roughconductor"><string name="material" value="gold"/></bsdf>"#,
            "unknown material \"gold\"",
        ),
        (
            r#"<bsdf type="roughconductor"><float name="alpha" value="-0.1"/></bsdf>"#,
            "alpha must be a positive number",
        ),
        (
            r#"<bsdf type="roughconductor"><float name="alpah" value="0.1"/></bsdf>"#,
            "has no property `alpah`",
        ),
        (
            r#"<bsdf type="roughconductor"><string name="distribution" value="phong"/></bsdf>"#,
            "unknown microfacet distribution",
        ),
        (
            r#"<bsdf type="roughdielectric"><string name="int_ior" value="glassy"/></bsdf>"#,
            "unknown material \"glassy\"",
        ),
        (
            r#"<bsdf type="phong"><float name="exponent" value="-3"/></bsdf>"#,
            "lobe exponent",
        ),
    ] {
        let message = convert_with(bsdf)
            .err()
            .unwrap_or_else(|| panic!("{bsdf} was accepted"));
        assert!(message.contains(expected), "{bsdf}: {message}");
        // The refusal points at the element in the file, on the shape's line.
        assert!(message.contains("test.xml:3:"), "{bsdf}: {message}");
    }
}

#[test]
fn a_broken_scene_file_is_refused_by_the_binary() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("broken.xml");
    std::fs::write(&scene, "<scene version=\"3.0.0\"><shape type=\"sphere\">").unwrap();
    let out = dir.path().join("never.png");
    assert_refused(
        BINARY,
        &[
            "render",
            "--scene",
            scene.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ],
        "broken.xml",
    );
    assert!(!out.exists());
}
