//! The chapter's scene files: a `thinlens` sensor with an aperture renders here (chapter 01
//! refuses it), and its lens is the file's.

use ch03_anti_aliasing::lab::scene_file::filter_of;
use ch03_anti_aliasing::{PixelSampler, PixelSamplerKind};
use ch04_depth_of_field::lab::CAPABILITIES;
use ch04_depth_of_field::lab::scene_file::lens_of;
use ch04_depth_of_field::render_with;
use common::render::RenderSettings;
use std::path::{Path, PathBuf};
use workbench::scene_file::load_scene_file;

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

fn define(pairs: &[(&str, &str)]) -> Vec<(String, String)> {
    pairs
        .iter()
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

#[test]
fn every_chapter_scene_renders_with_finite_pixels() {
    let dir = std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes")).unwrap();
    let mut rendered = 0;
    for entry in dir {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("xml") {
            continue;
        }
        let tiny = define(&[("width", "16"), ("height", "10"), ("spp", "4")]);
        let loaded = load_scene_file(&path, &tiny).unwrap();
        let scene = loaded.scene;
        CAPABILITIES.check(&scene).unwrap();
        let spp = u64::from(scene.sampler.sample_count);
        let settings = RenderSettings::new(16, 10, spp);
        let sampler = PixelSampler::new(PixelSamplerKind::Random, spp, 0).unwrap();
        let lens = lens_of(&scene.camera).unwrap();
        let filter = filter_of(scene.film.filter).unwrap();
        let out = render_with(&scene, &lens, &settings, &sampler, &filter);
        assert_eq!(out.stats.nonfinite_samples, 0, "{}", path.display());
        assert!(out.image.pixels.iter().all(|p| p.is_finite()));
        assert!(out.image.pixels.iter().any(|p| p.max_element() > 0.0));
        rendered += 1;
    }
    assert!(rendered >= 1, "no scene files found");
}

#[test]
fn the_thin_lens_comes_from_the_file() {
    let path = scene_path("thinlens-spheres.xml");
    let loaded =
        load_scene_file(&path, &define(&[("aperture", "0.25"), ("focus", "3.3")])).unwrap();
    // Chapter 01 refuses the aperture and names this chapter.
    let refusal = ch01_whitted::lab::CAPABILITIES
        .check(&loaded.scene)
        .expect_err("chapter 01 refuses a lens");
    assert!(refusal.contains("chapter 04"), "{refusal}");
    CAPABILITIES.check(&loaded.scene).unwrap();
    let lens = lens_of(&loaded.scene.camera).unwrap();
    assert_eq!(lens.aperture_radius, 0.25);
    assert_eq!(lens.focus_distance, 3.3);
    assert_eq!(loaded.scene.sampler.sample_count, 64);
}

#[test]
fn a_bad_lens_in_a_file_is_refused_with_the_reason() {
    let path = scene_path("thinlens-spheres.xml");
    for (name, value, expected) in [
        ("focus", "0", "focus_distance"),
        ("focus", "-2", "focus_distance"),
        ("aperture", "-0.1", "aperture_radius"),
    ] {
        let error = load_scene_file(&path, &define(&[(name, value)]))
            .expect_err("refused")
            .to_string();
        assert!(error.contains(expected), "{name}={value}: {error}");
    }
}
