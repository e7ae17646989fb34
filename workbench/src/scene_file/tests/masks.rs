//! `mask` (Mitsuba 3's cut-out) as the loader reads it: its opacity a value, a colour or a
//! texture, its one nested material inline or referenced, and the refusals.

use std::path::Path;

use glam::{Vec2, Vec3};
use image::{ImageFormat, Luma, Rgb, RgbImage};

use super::super::parse_scene;
use super::scene_with;
use common::scene::{Mask, Material, Opacity, Scene, Texture};

/// The scene whose body is `body`, read as `test.xml` in `dir`.
fn scene_in(dir: &Path, body: &str) -> Result<Scene, String> {
    parse_scene(&scene_with(body), &dir.join("test.xml"), &[])
        .map(|loaded| loaded.scene)
        .map_err(|e| e.to_string())
}

/// The mask of the only shape of a scene whose body is a rectangle with `bsdf`.
fn mask(bsdf: &str) -> Mask {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(
        dir.path(),
        &format!(r#"<shape type="rectangle">{bsdf}</shape>"#),
    );
    match scene.map(|scene| scene.surfaces[0].material.clone()) {
        Ok(Material::Mask(mask)) => mask,
        other => panic!("{bsdf}: {other:?}"),
    }
}

/// The error reading a scene whose body is `body`.
fn error(body: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    scene_in(dir.path(), body).map(|_| ()).unwrap_err()
}

#[test]
fn a_uniform_opacity_is_a_number_a_colours_mean_or_mitsubas_half() {
    let white = Box::new(Material::diffuse(Vec3::ONE));
    let number = mask(
        r#"<bsdf type="mask"><float name="opacity" value="0.3"/>
           <bsdf type="diffuse"><rgb name="reflectance" value="1"/></bsdf></bsdf>"#,
    );
    assert_eq!(
        number,
        Mask {
            opacity: Opacity::Uniform(0.3),
            nested: white.clone()
        }
    );
    let colour = mask(
        r#"<bsdf type="mask"><rgb name="opacity" value="0.2, 0.4, 0.9"/>
           <bsdf type="diffuse"/></bsdf>"#,
    );
    assert_eq!(colour.opacity, Opacity::Uniform(0.5));
    assert_eq!(*colour.nested, Material::diffuse(Vec3::splat(0.5)));
    let default = mask(r#"<bsdf type="mask"><bsdf type="diffuse"/></bsdf>"#);
    assert_eq!(default.opacity, Opacity::Uniform(0.5));
    // A mask around a twosided material keeps the two sides.
    let two_sided =
        mask(r#"<bsdf type="mask"><bsdf type="twosided"><bsdf type="diffuse"/></bsdf></bsdf>"#);
    assert_eq!(
        *two_sided.nested,
        Material::two_sided_diffuse(Vec3::splat(0.5))
    );
}

#[test]
fn a_textured_opacity_is_read_as_mitsuba_reads_one_value() {
    let dir = tempfile::tempdir().unwrap();
    // A checkerboard's colours by their mean: (0.1 + 0.2 + 0.6) / 3 and (1 + 1 + 1) / 3, each
    // where Mitsuba's `eval_1` puts it: color0 where u and v are on different sides of 1/2.
    let scene = scene_in(
        dir.path(),
        r#"<shape type="rectangle"><bsdf type="mask">
             <texture type="checkerboard" name="opacity">
               <rgb name="color0" value="0.1, 0.2, 0.6"/><rgb name="color1" value="1"/>
             </texture>
             <bsdf type="diffuse"/></bsdf></shape>"#,
    )
    .unwrap();
    let Material::Mask(mask) = &scene.surfaces[0].material else {
        panic!("{:?}", scene.surfaces[0].material);
    };
    assert!(matches!(
        mask.opacity,
        Opacity::Texture(Texture::Checkerboard(_))
    ));
    let at = |u, v| scene.opacity(mask.opacity, Vec2::new(u, v));
    approx::assert_relative_eq!(at(0.75, 0.25), 0.3, max_relative = 1e-6);
    assert_eq!(at(0.25, 0.25), 1.0);
    assert_eq!(at(0.75, 0.75), 1.0);
    // An image by its luminance: a grey image by its grey, a colour by Mitsuba's weights.
    let grey = image::GrayImage::from_pixel(1, 1, Luma([255]));
    grey.save_with_format(dir.path().join("grey.png"), ImageFormat::Png)
        .unwrap();
    RgbImage::from_pixel(1, 1, Rgb([0, 255, 0]))
        .save_with_format(dir.path().join("green.png"), ImageFormat::Png)
        .unwrap();
    for (file, expected) in [("grey.png", 1.0), ("green.png", 0.715160)] {
        let scene = scene_in(
            dir.path(),
            &format!(
                r#"<shape type="rectangle"><bsdf type="mask">
                     <texture type="bitmap" name="opacity"><string name="filename" value="{file}"/></texture>
                     <bsdf type="diffuse"/></bsdf></shape>"#
            ),
        )
        .unwrap();
        let Material::Mask(mask) = &scene.surfaces[0].material else {
            panic!("{file}");
        };
        let opacity = scene.opacity(mask.opacity, Vec2::splat(0.5));
        approx::assert_relative_eq!(opacity, expected, max_relative = 1e-5);
    }
}

#[test]
fn a_scene_hands_chapter_08_the_mask_read_at_the_hit() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(
        dir.path(),
        r#"<shape type="rectangle"><bsdf type="mask">
             <texture type="checkerboard" name="opacity">
               <rgb name="color0" value="0"/><rgb name="color1" value="2"/>
             </texture>
             <bsdf type="diffuse"><texture type="checkerboard" name="reflectance"/></bsdf>
           </bsdf></shape>"#,
    )
    .unwrap();
    // Opacity clamped to [0, 1] as Mitsuba clamps it (color1 where u and v are on one side
    // of 1/2), and the nested texture read too (as a colour: color0 there, Mitsuba's 0.4).
    assert_eq!(
        scene.material_at(0, Vec2::new(0.25, 0.25)).into_owned(),
        Material::Mask(Mask {
            opacity: Opacity::Uniform(1.0),
            nested: Box::new(Material::diffuse(Vec3::splat(0.4))),
        })
    );
    let Material::Mask(clear) = scene.material_at(0, Vec2::new(0.75, 0.25)).into_owned() else {
        panic!("not a mask");
    };
    assert_eq!(clear.opacity, Opacity::Uniform(0.0));
}

#[test]
fn the_nested_material_and_the_mask_itself_may_be_referenced() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_in(
        dir.path(),
        r#"<bsdf type="mask" id="leaf"><float name="opacity" value="0.25"/><ref id="green"/></bsdf>
           <bsdf type="diffuse" id="green"><rgb name="reflectance" value="0.1, 0.6, 0.1"/></bsdf>
           <shape type="rectangle"><ref id="leaf"/></shape>
           <shape type="sphere"><bsdf type="mask"><ref name="inner" id="green"/></bsdf></shape>"#,
    )
    .unwrap();
    let green = Material::diffuse(Vec3::new(0.1, 0.6, 0.1));
    for (surface, opacity) in scene.surfaces.iter().zip([0.25, 0.5]) {
        assert_eq!(
            surface.material,
            Material::Mask(Mask {
                opacity: Opacity::Uniform(opacity),
                nested: Box::new(green.clone()),
            })
        );
    }
}

#[test]
fn what_a_mask_cannot_be_is_refused_where_it_is_written() {
    for (body, expected) in [
        (
            r#"<shape type="sphere"><bsdf type="mask"/></shape>"#,
            "test.xml:2:22: a mask bsdf wraps exactly one nested <bsdf> or <ref>, found 0",
        ),
        (
            r#"<shape type="sphere"><bsdf type="mask"><bsdf type="diffuse"/><bsdf type="diffuse"/></bsdf></shape>"#,
            "test.xml:2:22: a mask bsdf wraps exactly one nested <bsdf> or <ref>, found 2",
        ),
        (
            r#"<shape type="sphere"><bsdf type="mask"><bsdf type="leafy"/></bsdf></shape>"#,
            "test.xml:2:40: unknown bsdf type \"leafy\": the workbook renders",
        ),
        (
            r#"<shape type="sphere"><bsdf type="bumpmap"><bsdf type="diffuse"/></bsdf></shape>"#,
            "test.xml:2:22: unknown bsdf type \"bumpmap\"",
        ),
        (
            r#"<shape type="sphere"><bsdf type="twosided"><bsdf type="mask"><bsdf type="diffuse"/></bsdf></bsdf></shape>"#,
            "test.xml:2:22: a twosided bsdf cannot wrap a mask",
        ),
        (
            r#"<shape type="sphere"><bsdf type="mask"><float name="opacity" value="0.5"/>
               <texture type="checkerboard" name="opacity"/><bsdf type="diffuse"/></bsdf></shape>"#,
            "test.xml:3:16: the mask's opacity is given twice",
        ),
        (
            r#"<shape type="sphere"><bsdf type="mask"><float name="opasity" value="0.5"/><bsdf type="diffuse"/></bsdf></shape>"#,
            "opasity",
        ),
        (
            r#"<shape type="sphere"><bsdf type="mask"><texture type="checkerboard" name="reflectance"/><bsdf type="diffuse"/></bsdf></shape>"#,
            "test.xml:2:40:",
        ),
    ] {
        let message = error(body);
        assert!(message.contains(expected), "{body}\n{message}");
    }
}
