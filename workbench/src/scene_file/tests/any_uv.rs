//! Surface parameters a wrong answer computed (NaN, infinite, huge) read a colour like any
//! other: every texture lookup of the scene model answers with finite numbers, never a panic,
//! so that a chapter's check can name the wrong `uv` instead of crashing inside `common`.

use std::sync::LazyLock;

use glam::{Vec2, Vec3};
use image::{Rgb, RgbImage};
use proptest::prelude::*;

use common::geometry::awkward::{self, vec2};
use common::scene::{Material, Scene, Texture};

/// An image, and every way to read it: each filter, each wrap mode, the scale of `to_uv`.
fn bitmap(filter: &str, wrap: &str) -> String {
    format!(
        r#"<texture type="bitmap"><string name="filename" value="image.png"/>
             <string name="filter_type" value="{filter}"/><string name="wrap_mode" value="{wrap}"/>
             <transform name="to_uv"><scale x="1e20" y="3"/></transform></texture>"#
    )
}

/// A scene with a texture on everything that takes one: diffuse colours (bitmaps read every
/// way, a checkerboard), an area light's radiance, plastic's base and coat, a metal's widths
/// along and across (so that `material_at` also asks the shape for `dp/du`), a mask's opacity.
static SCENE: LazyLock<Scene> = LazyLock::new(|| {
    let dir = tempfile::tempdir().unwrap();
    RgbImage::from_fn(3, 2, |x, y| Rgb([40 * x as u8, 90 * y as u8, 200]))
        .save(dir.path().join("image.png"))
        .unwrap();
    let mut shapes = String::new();
    for filter in ["nearest", "bilinear"] {
        for wrap in ["repeat", "mirror", "clamp"] {
            let texture =
                bitmap(filter, wrap).replace("<texture", r#"<texture name="reflectance""#);
            shapes +=
                &format!(r#"<shape type="sphere"><bsdf type="diffuse">{texture}</bsdf></shape>"#);
        }
    }
    let named = |name: &str| {
        bitmap("bilinear", "repeat").replace("<texture", &format!(r#"<texture name="{name}""#))
    };
    shapes += &format!(
        r#"<shape type="rectangle"><emitter type="area">{}</emitter></shape>
           <shape type="disk"><bsdf type="plastic">{}
             <texture type="checkerboard" name="specular_reflectance"/></bsdf></shape>
           <shape type="sphere"><bsdf type="roughconductor">{}<float name="alpha_v" value="0.3"/></bsdf></shape>
           <shape type="rectangle"><bsdf type="mask">{}<bsdf type="diffuse"/></bsdf></shape>
           <shape type="rectangle"><bsdf type="diffuse"><texture type="checkerboard" name="reflectance"/></bsdf></shape>"#,
        named("radiance"),
        named("diffuse_reflectance"),
        named("alpha_u"),
        named("opacity"),
    );
    let file = format!(
        r#"<scene version="3.0.0">{shapes}<sensor type="perspective"><float name="fov" value="40"/></sensor></scene>"#
    );
    crate::scene_file::parse_scene(&file, &dir.path().join("scene.xml"), &[])
        .unwrap_or_else(|e| panic!("{e}"))
        .scene
});

/// Every texture the scene's surfaces hold.
fn textures(scene: &Scene) -> Vec<Texture> {
    let mut textures = Vec::new();
    for surface in &scene.surfaces {
        if let Material::TexturedDiffuse { texture, .. } = surface.material {
            textures.push(texture);
        }
        if let Some(texture) = surface.emitter.and_then(|e| e.texture) {
            textures.push(texture);
        }
    }
    textures
}

proptest! {
    #![proptest_config(awkward::config(256))]

    #[test]
    fn every_lookup_at_any_uv_is_finite(uv in vec2(), u in vec2()) {
        let scene = &*SCENE;
        let textures = textures(scene);
        prop_assert!(textures.len() >= 8);
        for texture in textures {
            let albedo = scene.albedo(texture, uv);
            let value = scene.texture_value(texture, uv);
            prop_assert!(albedo.is_finite() && value.is_finite(), "{texture:?}: {albedo}, {value}");
        }
        for shape in 0..scene.shape_count() as u32 {
            let emitted = scene.emitted_at(shape, uv);
            prop_assert!(emitted.is_finite(), "shape {shape}: {emitted}");
            let _ = scene.material_at(shape, uv);
            let _ = scene.dp_du(shape, uv);
            if let Some(grid) = scene.emission_grid(shape) {
                let (p, density) = grid.sample(u);
                prop_assert!(p.cmpge(Vec2::ZERO).all() && p.cmple(Vec2::ONE).all(), "{p}");
                prop_assert!(density > 0.0 && density.is_finite(), "{density} at {p} for {u}");
                prop_assert!(grid.density(uv).is_finite());
            }
        }
        prop_assert!(scene.background(Vec3::new(uv.x, uv.y, u.x)).is_finite());
    }
}
