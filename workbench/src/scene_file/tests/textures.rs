//! `<texture>` in scene files: checkerboards and bitmaps inline or referenced, their options as
//! Mitsuba reads them, each image decoded once, and refusals that say what is wrong.

use std::path::Path;

use glam::{Vec2, Vec3};
use image::{ImageFormat, Rgb, RgbImage};

use super::{error_in, parse, scene_in, scene_with};
use common::scene::{BitmapFilter, Material, Texture, WrapMode};

/// A 2 x 1 PNG: red on the left, blue on the right.
fn write_png(path: &Path) {
    let image = RgbImage::from_fn(2, 1, |x, _| {
        if x == 0 {
            Rgb([255, 0, 0])
        } else {
            Rgb([0, 0, 255])
        }
    });
    image.save_with_format(path, ImageFormat::Png).unwrap();
}

/// A rectangle made of `bsdf`.
fn rectangle(bsdf: &str) -> String {
    format!(r#"<shape type="rectangle">{bsdf}</shape>"#)
}

#[test]
fn an_inline_checkerboard_is_a_textured_diffuse_reflectance() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(
        dir.path(),
        &rectangle(
            r#"<bsdf type="diffuse"><texture type="checkerboard" name="reflectance">
                 <rgb name="color0" value="1, 0, 0"/><rgb name="color1" value="0, 0, 1"/>
                 <transform name="to_uv"><scale x="4" y="2"/></transform>
               </texture></bsdf>"#,
        ),
    );
    let Material::TexturedDiffuse {
        texture: Texture::Checkerboard(board),
        two_sided: false,
    } = scene.surfaces[0].material
    else {
        panic!("{:?}", scene.surfaces[0].material)
    };
    assert_eq!(board.colour0, Vec3::X);
    assert_eq!(board.to_uv.transform_point2(Vec2::ONE), Vec2::new(4.0, 2.0));
    // Through the one function every chapter uses: uv (0.2, 0.1) -> (0.8, 0.2): colour 1.
    assert_eq!(
        scene.material_at(0, Vec2::new(0.2, 0.1)).into_owned(),
        Material::diffuse(Vec3::Z)
    );
}

#[test]
fn a_checkerboard_has_mitsubas_default_colours() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(
        dir.path(),
        &rectangle(
            r#"<bsdf type="diffuse"><texture type="checkerboard" name="reflectance"/></bsdf>"#,
        ),
    );
    // Mitsuba 3.9.1: 0.4 at uv (0.1, 0.1), 0.2 at (0.6, 0.1).
    let at = |u, v| scene.material_at(0, Vec2::new(u, v)).into_owned();
    assert_eq!(at(0.1, 0.1), Material::diffuse(Vec3::splat(0.4)));
    assert_eq!(at(0.6, 0.1), Material::diffuse(Vec3::splat(0.2)));
}

#[test]
fn a_bitmap_declared_apart_is_read_once_per_file_and_shared() {
    let dir = tempfile::tempdir().unwrap();
    write_png(&dir.path().join("two.png"));
    let body = format!(
        r#"<texture type="bitmap" id="wood"><string name="filename" value="two.png"/>
             <string name="filter_type" value="nearest"/><string name="wrap_mode" value="clamp"/>
           </texture>
           <bsdf type="twosided" id="shared"><bsdf type="diffuse">
             <ref name="reflectance" id="wood"/></bsdf></bsdf>
           {}
           {}
           {}"#,
        rectangle(r#"<ref id="shared"/>"#),
        rectangle(r#"<bsdf type="diffuse"><ref name="reflectance" id="wood"/></bsdf>"#),
        rectangle(
            r#"<bsdf type="diffuse"><texture type="bitmap" name="reflectance">
                 <string name="filename" value="two.png"/><boolean name="raw" value="true"/>
               </texture></bsdf>"#
        ),
    );
    let scene = scene_in(dir.path(), &body);
    // One texture with an id, read once; the inline one is a second bitmap of another `raw`.
    assert_eq!(scene.bitmaps.len(), 2);
    assert_eq!(scene.bitmaps[0].filter, BitmapFilter::Nearest);
    assert_eq!(scene.bitmaps[0].wrap, WrapMode::Clamp);
    assert_eq!(scene.bitmaps[1].filter, BitmapFilter::Bilinear);
    assert!(matches!(
        scene.surfaces[0].material,
        Material::TexturedDiffuse {
            two_sided: true,
            ..
        }
    ));
    assert_eq!(scene.surfaces[0].material, {
        let Material::TexturedDiffuse { texture, .. } = scene.surfaces[1].material else {
            panic!()
        };
        Material::TexturedDiffuse {
            texture,
            two_sided: true,
        }
    });
    // uv (0, 0) is the image's top-left: red; the right half is blue (clamped beyond).
    assert_eq!(
        scene.material_at(1, Vec2::new(0.2, 0.5)).into_owned(),
        Material::diffuse(Vec3::X)
    );
    assert_eq!(
        scene.material_at(1, Vec2::new(1.7, 0.5)).into_owned(),
        Material::diffuse(Vec3::Z)
    );
}

#[test]
fn textures_are_refused_where_they_cannot_be_rendered_yet() {
    let cases = [
        (
            r#"<bsdf type="conductor"><texture type="checkerboard" name="eta"/></bsdf>"#,
            "conductor bsdf's `eta` cannot be a texture yet",
        ),
        (
            r#"<bsdf type="diffuse"><texture type="checkerboard" name="alpha"/></bsdf>"#,
            "diffuse bsdf's `alpha` cannot be a texture yet",
        ),
        (
            r#"<bsdf type="diffuse"><rgb name="reflectance" value="0.5"/>
                 <texture type="checkerboard" name="reflectance"/></bsdf>"#,
            "reflectance is given twice",
        ),
        (
            r#"<bsdf type="diffuse"><texture type="checkerboard"/></bsdf>"#,
            "needs the name of the parameter",
        ),
        (
            r#"<bsdf type="bumpmap"><texture type="checkerboard" name="map"/></bsdf>"#,
            "unknown bsdf type \"bumpmap\"",
        ),
        (
            r#"<bsdf type="diffuse"><texture type="mesh_attribute" name="reflectance"/></bsdf>"#,
            "texture type \"mesh_attribute\" is not one the workbook renders",
        ),
        (
            r#"<bsdf type="diffuse"><texture type="checkerboard" name="reflectance">
                 <float name="colour0" value="1"/></texture></bsdf>"#,
            "has no property `colour0`",
        ),
        (
            r#"<bsdf type="diffuse"><texture type="bitmap" name="reflectance"/></bsdf>"#,
            "needs its image",
        ),
        (
            r#"<bsdf type="diffuse"><texture type="bitmap" name="reflectance">
                 <string name="filename" value="missing.png"/></texture></bsdf>"#,
            "missing.png",
        ),
        (
            r#"<bsdf type="diffuse"><texture type="bitmap" name="reflectance">
                 <string name="filename" value="garbage.png"/></texture></bsdf>"#,
            "garbage.png: not a PNG, JPEG, BMP, EXR or HDR",
        ),
        (
            r#"<bsdf type="diffuse"><texture type="bitmap" name="reflectance">
                 <string name="filename" value="two.png"/>
                 <string name="wrap_mode" value="tile"/></texture></bsdf>"#,
            "wrap_mode \"tile\" is not one Mitsuba knows",
        ),
        (
            r#"<bsdf type="diffuse"><texture type="bitmap" name="reflectance">
                 <string name="filename" value="two.png"/>
                 <string name="filter_type" value="trilinear"/></texture></bsdf>"#,
            "filter_type \"trilinear\" is not one Mitsuba knows",
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    write_png(&dir.path().join("two.png"));
    std::fs::write(dir.path().join("garbage.png"), b"no picture here").unwrap();
    for (bsdf, expected) in cases {
        let message = error_in(dir.path(), &rectangle(bsdf));
        assert!(
            message.contains(expected),
            "{message}\n  should say: {expected}"
        );
        assert!(message.contains("scene.xml:"), "{message}");
    }
}

#[test]
fn a_texture_declared_apart_and_never_used_is_a_warning() {
    let loaded = parse(&scene_with(r#"<texture type="checkerboard" id="unused"/>"#)).unwrap();
    let warnings: Vec<String> = loaded.warnings.iter().map(|w| w.to_string()).collect();
    assert!(
        warnings.iter().any(|w| w.contains("never referenced")),
        "{warnings:?}"
    );
}
