//! `<emitter type="envmap">`: the image, `scale` and `to_world` as Mitsuba reads them, every
//! image format Mitsuba's envmaps use, and refusals that point at the line and column.

use std::path::Path;

use glam::Vec3;
use image::{ImageFormat, Rgb, Rgb32FImage, RgbImage};

use super::super::parse_scene;
use super::{error_in, scene_in, scene_with};
use crate::capabilities::{Capabilities, Chapter};

/// The 4 x 3 map of the scene model's tests: pixel (x, y) holds
/// `(1 + x, 10 (1 + y), (x + 1)(y + 1) / 2)`, with `bad` NaN at one pixel.
fn write_exr(path: &Path, bad: bool) {
    let image = Rgb32FImage::from_fn(4, 3, |x, y| {
        let (x, y) = (x as f32, y as f32);
        let green = if bad && (x, y) == (2.0, 1.0) {
            f32::NAN
        } else {
            10.0 * (1.0 + y)
        };
        Rgb([1.0 + x, green, 0.5 * (x + 1.0) * (y + 1.0)])
    });
    image.save_with_format(path, ImageFormat::OpenExr).unwrap();
}

#[test]
fn an_exr_envmap_is_read_with_its_scale_and_rotation() {
    let dir = tempfile::tempdir().unwrap();
    write_exr(&dir.path().join("sky.exr"), false);
    let scene = scene_in(
        dir.path(),
        r#"<emitter type="envmap"><string name="filename" value="sky.exr"/>
             <float name="scale" value="2"/>
             <transform name="to_world"><rotate y="1" angle="90"/></transform></emitter>"#,
    );
    let map = scene.environment_map.as_ref().expect("an environment map");
    assert_eq!(map.size(), (4, 3));
    // Mitsuba 3.9.1's radiance for these directions (see the scene model's tests).
    assert!(
        map.radiance(Vec3::NEG_Z)
            .abs_diff_eq(Vec3::new(3.0, 40.0, 3.0), 1e-4)
    );
    assert!(
        map.radiance(Vec3::X)
            .abs_diff_eq(Vec3::new(5.0, 40.0, 5.0), 1e-4)
    );
    assert_eq!(scene.background(Vec3::X), map.radiance(Vec3::X));
    assert_eq!(scene.environment, Vec3::ZERO);
    assert_eq!(scene.origins.environment_map.as_ref().unwrap().line, 2);
}

#[test]
fn a_constant_emitter_adds_to_the_map() {
    let dir = tempfile::tempdir().unwrap();
    write_exr(&dir.path().join("sky.exr"), false);
    let scene = scene_in(
        dir.path(),
        r#"<emitter type="envmap"><string name="filename" value="sky.exr"/></emitter>
           <emitter type="constant"><rgb name="radiance" value="1, 2, 3"/></emitter>"#,
    );
    let expected = Vec3::new(2.5, 20.0, 2.5) + Vec3::new(1.0, 2.0, 3.0);
    assert!(scene.background(Vec3::NEG_Z).abs_diff_eq(expected, 1e-4));
}

#[test]
fn radiance_hdr_and_srgb_png_maps_are_read_as_mitsuba_reads_them() {
    let dir = tempfile::tempdir().unwrap();
    // Radiance RGBE keeps 8 bits of mantissa per channel: 5.5 and 0.25 are exact.
    Rgb32FImage::from_pixel(2, 2, Rgb([5.5, 0.25, 1.0]))
        .save_with_format(dir.path().join("sky.hdr"), ImageFormat::Hdr)
        .unwrap();
    let scene = scene_in(
        dir.path(),
        r#"<emitter type="envmap"><string name="filename" value="sky.hdr"/></emitter>"#,
    );
    let hdr = scene.environment_map.unwrap().radiance(Vec3::Y);
    assert!(hdr.abs_diff_eq(Vec3::new(5.5, 0.25, 1.0), 1e-6), "{hdr}");
    // An 8-bit image holds sRGB-encoded values: Mitsuba 3.9.1 reads (187, 123, 243) as
    // (0.496933, 0.198069, 0.896269).
    RgbImage::from_pixel(1, 1, Rgb([187, 123, 243]))
        .save_with_format(dir.path().join("sky.png"), ImageFormat::Png)
        .unwrap();
    let scene = scene_in(
        dir.path(),
        r#"<emitter type="envmap"><string name="filename" value="sky.png"/>
             <float name="scale" value="10"/></emitter>"#,
    );
    let png = scene.environment_map.unwrap().radiance(Vec3::X);
    assert!(
        png.abs_diff_eq(Vec3::new(4.96933, 1.98069, 8.96269), 1e-4),
        "{png}"
    );
}

#[test]
fn bad_envmaps_are_refused_with_line_and_column() {
    let dir = tempfile::tempdir().unwrap();
    write_exr(&dir.path().join("sky.exr"), false);
    write_exr(&dir.path().join("nan.exr"), true);
    let cases = [
        (
            r#"<emitter type="envmap"/>"#,
            "scene.xml:2:1: an envmap emitter needs its image",
        ),
        (
            r#"<emitter type="envmap"><string name="filename" value="nowhere.exr"/></emitter>"#,
            "scene.xml:2:24: cannot read the image",
        ),
        (
            r#"<emitter type="envmap"><string name="filename" value="nan.exr"/></emitter>"#,
            "scene.xml:2:24: the envmap image's pixel (2, 1) times the scale is not a finite",
        ),
        (
            r#"<emitter type="envmap"><string name="filename" value="sky.exr"/>
<float name="scale" value="-1"/></emitter>"#,
            "scene.xml:3:1: an envmap's scale must be finite and not negative",
        ),
        (
            r#"<emitter type="envmap"><string name="filename" value="sky.exr"/>
<float name="scale" value="1e38"/></emitter>"#,
            "is not a finite number",
        ),
        (
            r#"<emitter type="envmap"><string name="filename" value="sky.exr"/>
<transform name="to_world"><scale x="2"/></transform></emitter>"#,
            "scene.xml:3:1: the envmap's to_world must be a rotation",
        ),
        (
            r#"<emitter type="envmap"><string name="filename" value="sky.exr"/></emitter>
<emitter type="envmap"><string name="filename" value="sky.exr"/></emitter>"#,
            "scene.xml:3:1: a second envmap emitter",
        ),
        (
            r#"<emitter type="envmap"><string name="filename" value="sky.exr"/>
<rgb name="radiance" value="1"/></emitter>"#,
            "",
        ),
    ];
    for (body, expected) in cases {
        if expected.is_empty() {
            // An unknown property is a warning, as for every plugin, not an error.
            let loaded = parse_scene(&scene_with(body), &dir.path().join("scene.xml"), &[]);
            let warnings = loaded.unwrap().warnings;
            assert!(
                warnings.iter().any(|w| w.to_string().contains("radiance")),
                "{warnings:?}"
            );
            continue;
        }
        let error = error_in(dir.path(), body);
        assert!(
            error.contains(expected),
            "{body}\ngave: {error}\nexpected: {expected}"
        );
    }
}

#[test]
fn chapters_before_08_refuse_an_envmap_and_name_chapter_08() {
    let dir = tempfile::tempdir().unwrap();
    write_exr(&dir.path().join("sky.exr"), false);
    let scene = scene_in(
        dir.path(),
        r#"<emitter type="envmap"><string name="filename" value="sky.exr"/></emitter>"#,
    );
    for chapter in [
        Chapter::WHITTED,
        Chapter::MOTION_BLUR,
        Chapter::SOFT_SHADOWS,
    ] {
        let capabilities = Capabilities {
            chapter,
            approximates: &[],
        };
        let refusal = capabilities.check(&scene).unwrap_err();
        assert!(
            refusal.starts_with("line 2, column 1: an environment map (envmap)")
                && refusal.contains("in chapter 08 (ch08-path-tracing)"),
            "{refusal}"
        );
    }
    let path_tracing = Capabilities {
        chapter: Chapter::PATH_TRACING,
        approximates: &[],
    };
    assert_eq!(path_tracing.check(&scene), Ok(vec![]));
}
