//! Textures on other parameters than a diffuse reflectance: plastic's base and coat, a metal's
//! reflection, an area light's radiance. Each multiplies its colour and is read at a hit by
//! `Scene::material_at` or `Scene::emitted_at`; an image named by several parameters is one
//! bitmap; what is still not read is refused in words.

use std::path::Path;

use glam::{Vec2, Vec3};
use image::{ImageFormat, Rgb, RgbImage};

use super::super::parse_scene;
use super::scene_with;
use crate::capabilities::{Capabilities, Chapter};
use common::scene::{Conductor, Material, Plastic, Scene, TintedGlass};

/// A red and blue checkerboard of one square per half of `uv` along `u`: red where
/// `u < 0.5` (and `v < 0.5`), blue to its right.
const BOARD: &str = r#"<rgb name="color0" value="1, 0, 0"/><rgb name="color1" value="0, 0, 1"/>"#;

/// A 2 x 1 PNG: white on the left, black on the right.
fn write_png(path: &Path) {
    let image = RgbImage::from_fn(2, 1, |x, _| Rgb([if x == 0 { 255 } else { 0 }; 3]));
    image.save_with_format(path, ImageFormat::Png).unwrap();
}

fn scene_in(dir: &Path, body: &str) -> Result<Scene, String> {
    parse_scene(&scene_with(body), &dir.join("scene.xml"), &[])
        .map(|loaded| loaded.scene)
        .map_err(|e| e.to_string())
}

fn one_shape(bsdf: &str) -> Scene {
    let dir = tempfile::tempdir().unwrap();
    scene_in(
        dir.path(),
        &format!(r#"<shape type="rectangle">{bsdf}</shape>"#),
    )
    .unwrap()
}

const LEFT: Vec2 = Vec2::new(0.2, 0.2);
const RIGHT: Vec2 = Vec2::new(0.7, 0.2);

#[test]
fn plastic_takes_textures_for_its_base_and_its_coat() {
    for type_name in ["plastic", "roughplastic"] {
        let scene = one_shape(&format!(
            r#"<bsdf type="{type_name}">
                 <texture type="checkerboard" name="diffuse_reflectance">{BOARD}</texture>
                 <texture type="checkerboard" name="specular_reflectance">
                   <rgb name="color0" value="0.5"/><rgb name="color1" value="1"/></texture>
               </bsdf>"#
        ));
        let Material::Plastic(plastic) = scene.surfaces[0].material else {
            panic!("{:?}", scene.surfaces[0].material)
        };
        assert_eq!(plastic.roughness.is_some(), type_name == "roughplastic");
        // The colours are 1, the textures' factors everything.
        assert_eq!(plastic.diffuse_reflectance, Vec3::ONE);
        assert!(plastic.diffuse_texture.is_some() && plastic.specular_texture.is_some());
        let at = |uv| match scene.material_at(0, uv).into_owned() {
            Material::Plastic(p) => p,
            other => panic!("{other:?}"),
        };
        let (left, right) = (at(LEFT), at(RIGHT));
        assert_eq!(
            (left.diffuse_reflectance, left.specular_reflectance),
            (Vec3::X, Vec3::splat(0.5))
        );
        assert_eq!(
            (right.diffuse_reflectance, right.specular_reflectance),
            (Vec3::Z, Vec3::ONE)
        );
        // What a BSDF is made from has no texture left to read.
        assert_eq!(
            (right.diffuse_texture, right.specular_texture),
            (None, None)
        );
        assert_eq!(
            Material::Plastic(right),
            Material::Plastic(Plastic {
                diffuse_texture: None,
                specular_texture: None,
                diffuse_reflectance: Vec3::Z,
                ..plastic
            })
        );
    }
}

#[test]
fn a_metals_reflection_may_be_a_texture_and_then_is_no_plain_mirror() {
    for (bsdf, eta) in [
        (r#"<bsdf type="conductor">"#, Vec3::ZERO),
        (
            r#"<bsdf type="roughconductor"><float name="alpha" value="0.3"/>"#,
            Vec3::ZERO,
        ),
        (
            r#"<bsdf type="conductor"><string name="material" value="Au"/>"#,
            Vec3::new(0.143, 0.375, 1.442),
        ),
    ] {
        let scene = one_shape(&format!(
            r#"{bsdf}<texture type="checkerboard" name="specular_reflectance">{BOARD}</texture></bsdf>"#
        ));
        // Without eta and k, Mitsuba's default metal reflects everything: a mirror, but one
        // whose reflection varies, so a conductor of eta 0 and k 1 that keeps its texture.
        let Material::Conductor(metal) = scene.surfaces[0].material else {
            panic!("{:?}", scene.surfaces[0].material)
        };
        assert!(
            (metal.eta - eta).abs().max_element() < 2e-3,
            "{}",
            metal.eta
        );
        assert!(metal.specular_texture.is_some());
        let Material::Conductor(left) = scene.material_at(0, LEFT).into_owned() else {
            panic!()
        };
        assert_eq!(
            left,
            Conductor {
                specular_reflectance: Vec3::X,
                specular_texture: None,
                ..metal
            }
        );
    }
}

#[test]
fn an_area_lights_radiance_may_be_a_texture_read_at_the_point() {
    let scene = one_shape(&format!(
        r#"<emitter type="area"><texture type="checkerboard" name="radiance">{BOARD}</texture>
           </emitter>"#
    ));
    let emitter = scene.surfaces[0].emitter.unwrap();
    assert_eq!(emitter.radiance, Vec3::ONE);
    assert!(emitter.texture.is_some());
    assert_eq!(scene.emitted_at(0, LEFT), Vec3::X);
    assert_eq!(scene.emitted_at(0, RIGHT), Vec3::Z);
    // A plain light is the same everywhere.
    let plain = one_shape(r#"<emitter type="area"><rgb name="radiance" value="3"/></emitter>"#);
    assert_eq!(plain.emitted_at(0, LEFT), Vec3::splat(3.0));
    assert_eq!(plain.emitted_at(0, RIGHT), Vec3::splat(3.0));
}

#[test]
fn one_image_named_by_several_parameters_is_one_bitmap() {
    let dir = tempfile::tempdir().unwrap();
    write_png(&dir.path().join("two.png"));
    let scene = scene_in(
        dir.path(),
        r#"<texture type="bitmap" id="stripes"><string name="filename" value="two.png"/>
             <string name="filter_type" value="nearest"/></texture>
           <shape type="rectangle"><bsdf type="plastic">
             <ref name="diffuse_reflectance" id="stripes"/>
             <ref name="specular_reflectance" id="stripes"/></bsdf></shape>
           <shape type="rectangle"><bsdf type="conductor">
             <ref name="specular_reflectance" id="stripes"/></bsdf>
             <emitter type="area"><ref name="radiance" id="stripes"/></emitter></shape>"#,
    )
    .unwrap();
    assert_eq!(scene.bitmaps.len(), 1);
    let Material::Plastic(left) = scene.material_at(0, LEFT).into_owned() else {
        panic!()
    };
    assert_eq!(left.diffuse_reflectance, Vec3::ONE);
    assert_eq!(scene.emitted_at(1, LEFT), Vec3::ONE);
    assert_eq!(scene.emitted_at(1, RIGHT), Vec3::ZERO);
}

#[test]
fn what_cannot_be_a_texture_or_is_given_twice_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let board = r#"<texture type="checkerboard" name="NAME"/>"#;
    let cases = [
        (
            r#"<bsdf type="plastic"><rgb name="diffuse_reflectance" value="0.5"/>TEXTURE</bsdf>"#,
            "diffuse_reflectance",
            "plastic bsdf's diffuse_reflectance is given twice",
        ),
        (
            r#"<bsdf type="roughconductor"><rgb name="specular_reflectance" value="0.5"/>TEXTURE</bsdf>"#,
            "specular_reflectance",
            "roughconductor bsdf's specular_reflectance is given twice",
        ),
        (
            r#"<bsdf type="roughplastic">TEXTURE</bsdf>"#,
            "alpha",
            "roughplastic bsdf's `alpha` cannot be a texture yet",
        ),
        (
            r#"<bsdf type="dielectric"><rgb name="specular_transmittance" value="0.5"/>TEXTURE</bsdf>"#,
            "specular_transmittance",
            "dielectric bsdf's specular_transmittance is given twice",
        ),
        (
            r#"<bsdf type="roughplastic">TEXTURE</bsdf>"#,
            "alpha",
            "roughplastic bsdf's `alpha` cannot be a texture yet",
        ),
        (
            r#"<emitter type="area"><rgb name="radiance" value="2"/>TEXTURE</emitter>"#,
            "radiance",
            "area emitter's radiance is given twice",
        ),
        (
            r#"<emitter type="area">TEXTURE</emitter>"#,
            "irradiance",
            "area emitter's `irradiance` cannot be a texture yet",
        ),
    ];
    for (element, name, expected) in cases {
        let element = element.replace("TEXTURE", &board.replace("NAME", name));
        let message = scene_in(
            dir.path(),
            &format!(r#"<shape type="rectangle">{element}</shape>"#),
        )
        .unwrap_err();
        assert!(
            message.contains(expected) && message.contains("scene.xml:"),
            "{message}\n  should say: {expected}"
        );
    }
    let message = scene_in(
        dir.path(),
        &format!(
            r#"<emitter type="point">{}</emitter>"#,
            board.replace("NAME", "intensity")
        ),
    )
    .unwrap_err();
    assert!(
        message.contains("point emitter's `intensity` cannot be a texture yet"),
        "{message}"
    );
}

#[test]
fn the_lecture_refuses_these_textures_naming_the_chapter_that_reads_them() {
    let soft_shadows = Capabilities {
        chapter: Chapter::SOFT_SHADOWS,
        approximates: &[],
    };
    let path_tracing = Capabilities {
        chapter: Chapter::PATH_TRACING,
        approximates: &[],
    };
    let materials = Capabilities {
        chapter: Chapter::MATERIALS,
        approximates: &[],
    };
    for (shape, words, brought_by, by_08) in [
        (
            r#"<bsdf type="conductor"><texture type="checkerboard" name="specular_reflectance"/></bsdf>"#,
            "a texture (shape 1: a metal's specular_reflectance); textures on other parameters",
            "chapter 09 (ch09-materials)",
            false,
        ),
        (
            r#"<emitter type="area"><texture type="checkerboard" name="radiance"/></emitter>"#,
            "an area light whose radiance is a texture (shape 1); lights that vary",
            "chapter 08 (ch08-path-tracing)",
            true,
        ),
        (
            r#"<bsdf type="dielectric"><rgb name="specular_transmittance" value="0.5"/></bsdf>"#,
            "glass with a specular_reflectance or specular_transmittance (shape 1)",
            "chapter 09 (ch09-materials)",
            false,
        ),
    ] {
        let scene = one_shape(shape);
        let refusal = soft_shadows.check(&scene).unwrap_err();
        assert!(
            refusal.contains(words) && refusal.contains(brought_by),
            "{refusal}"
        );
        assert_eq!(path_tracing.check(&scene).is_ok(), by_08, "{words}");
        assert!(materials.check(&scene).is_ok());
    }
}

#[test]
fn glass_with_factors_or_textures_on_its_lobes_is_tinted_glass() {
    // Plain glass stays the lecture's glass, or a lobe standing in for its roughness.
    assert!(matches!(
        one_shape(r#"<bsdf type="dielectric"><rgb name="specular_reflectance" value="1"/></bsdf>"#)
            .surfaces[0]
            .material,
        Material::Dielectric { .. }
    ));
    assert!(matches!(
        one_shape(r#"<bsdf type="roughdielectric"/>"#).surfaces[0].material,
        Material::RoughGlass(_)
    ));
    let scene = one_shape(
        r#"<bsdf type="dielectric"><float name="int_ior" value="1.33"/>
             <rgb name="specular_reflectance" value="0.5"/></bsdf>"#,
    );
    assert_eq!(
        scene.surfaces[0].material,
        Material::TintedGlass(TintedGlass {
            int_ior: 1.33,
            ext_ior: 1.000277,
            specular_reflectance: Vec3::splat(0.5),
            specular_transmittance: Vec3::ONE,
            reflectance_texture: None,
            transmittance_texture: None,
            roughness: None,
        })
    );
    let scene = one_shape(&format!(
        r#"<bsdf type="roughdielectric"><float name="alpha" value="0.2"/>
             <texture type="checkerboard" name="specular_transmittance">{BOARD}</texture></bsdf>"#
    ));
    let Material::TintedGlass(glass) = scene.surfaces[0].material else {
        panic!("{:?}", scene.surfaces[0].material)
    };
    assert_eq!(glass.roughness.map(|r| r.alpha()), Some(0.2));
    let Material::TintedGlass(right) = scene.material_at(0, RIGHT).into_owned() else {
        panic!()
    };
    assert_eq!(
        (right.specular_reflectance, right.specular_transmittance),
        (Vec3::ONE, Vec3::Z)
    );
    assert_eq!(right.transmittance_texture, None);
}

/// The microfacet roughness of the first shape's material at `uv`, as `ch09-materials` reads
/// it.
fn roughness_at(scene: &Scene, uv: Vec2) -> common::scene::Microfacet {
    match scene.material_at(0, uv).into_owned() {
        Material::Conductor(Conductor {
            roughness: Some(m), ..
        }) => m,
        Material::RoughGlass(g) => g.stands_in_for.unwrap(),
        other => panic!("{other:?}"),
    }
}

#[test]
fn rough_metals_and_glass_take_their_widths_from_textures() {
    // A checkerboard read for one number swaps its colours, as Mitsuba's does: color1 where
    // the fractional parts of u and v are on the same side of 1/2.
    let board = r#"<float name="color0" value="0.05"/><float name="color1" value="0.3"/>"#;
    for type_name in ["roughconductor", "roughdielectric"] {
        let scene = one_shape(&format!(
            r#"<bsdf type="{type_name}"><texture type="checkerboard" name="alpha">{board}</texture></bsdf>"#
        ));
        let (same_side, other_side) = (roughness_at(&scene, LEFT), roughness_at(&scene, RIGHT));
        assert!(
            (same_side.alpha_u - 0.3).abs() < 1e-6,
            "{type_name}: {same_side:?}"
        );
        assert!(
            (other_side.alpha_u - 0.05).abs() < 1e-6,
            "{type_name}: {other_side:?}"
        );
        assert_eq!(
            same_side.alpha_u, same_side.alpha_v,
            "alpha sets both widths"
        );
        assert!(
            same_side.alpha_texture.is_none(),
            "read at the hit, none is left"
        );
        // The lecture's lobes cannot vary over a surface: refused, naming chapter 09.
        let refusal = Capabilities {
            chapter: Chapter::SOFT_SHADOWS,
            approximates: &[],
        }
        .check(&scene)
        .unwrap_err();
        assert!(
            refusal.contains("alpha") && refusal.contains("chapter 09"),
            "{refusal}"
        );
    }
    // One width a texture, the other a number; a width of 0 rises to Mitsuba's 1e-4.
    let scene = one_shape(
        r#"<bsdf type="roughconductor"><float name="alpha_u" value="0.2"/>
             <texture type="checkerboard" name="alpha_v"><float name="color0" value="0"/>
               <float name="color1" value="0"/></texture></bsdf>"#,
    );
    let m = roughness_at(&scene, LEFT);
    assert_eq!((m.alpha_u, m.alpha_v), (0.2, 1e-4));
    // What Mitsuba refuses, or what the workbook does not read, in words.
    for (bsdf, says) in [
        (
            r#"<bsdf type="roughconductor"><float name="alpha" value="0.2"/>
                 <texture type="checkerboard" name="alpha"/></bsdf>"#,
            "alpha is given twice: as a number and as a texture",
        ),
        (
            r#"<bsdf type="roughplastic"><texture type="checkerboard" name="alpha"/></bsdf>"#,
            "alpha",
        ),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let error = scene_in(
            dir.path(),
            &format!(r#"<shape type="rectangle">{bsdf}</shape>"#),
        )
        .unwrap_err();
        assert!(error.contains(says), "{bsdf}: {error}");
    }
}

#[test]
fn an_anisotropic_roughness_runs_along_the_shapes_dp_du() {
    // The rectangle's dp/du is its first edge, to_world's x scaled by 2.
    let stretched = one_shape(
        r#"<bsdf type="roughconductor"><float name="alpha_u" value="0.05"/>
             <float name="alpha_v" value="0.3"/></bsdf>"#,
    );
    assert_eq!(
        roughness_at(&stretched, LEFT).dp_du,
        Vec3::new(2.0, 0.0, 0.0)
    );
    // A round roughness needs no tangent, and gets none.
    let round =
        one_shape(r#"<bsdf type="roughdielectric"><float name="alpha" value="0.2"/></bsdf>"#);
    assert_eq!(roughness_at(&round, LEFT).dp_du, Vec3::ZERO);
    // Textured widths that differ at a hit get it there, and not where they agree.
    let scene = one_shape(
        r#"<bsdf type="roughconductor"><float name="alpha_u" value="0.3"/>
             <texture type="checkerboard" name="alpha_v"><float name="color0" value="0.1"/>
               <float name="color1" value="0.3"/></texture></bsdf>"#,
    );
    assert_eq!(roughness_at(&scene, LEFT).dp_du, Vec3::ZERO, "0.3 and 0.3");
    assert_eq!(
        roughness_at(&scene, RIGHT).dp_du,
        Vec3::new(2.0, 0.0, 0.0),
        "0.3 and 0.1"
    );
}
