//! The meshes scene with its OBJ meshes rewritten as PLY (ASCII and both binary byte orders)
//! and as Mitsuba `.serialized` files (versions 3 and 4, single and double precision) renders
//! the same image, bit for bit: every reader gives the renderer the same triangles.

use std::path::Path;

use ch01_whitted::{PixelPattern, render};
use common::image::Image;
use common::render::RenderSettings;
use workbench::scene_file::{load_obj, load_scene_file};
use workbench::test_support::mesh_files::{
    PlyEncoding, PlyStyle, SerializedStyle, write_ply, write_serialized,
};

/// The meshes scene's file, and the OBJ meshes it names (relative to it).
const MESHES: [&str; 2] = ["meshes/icosphere.obj", "meshes/pyramid.obj"];

fn scenes_dir() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes"))
}

fn render_file(path: &Path) -> Image {
    let loaded = load_scene_file(path, &[]).unwrap_or_else(|e| panic!("{e}"));
    let settings = RenderSettings::new(64, 48, 1);
    render(&loaded.scene, &settings, PixelPattern::Centre, 0)
        .expect("one centre sample per pixel")
        .image
}

/// The meshes scene with each OBJ shape replaced by `type_name` reading the file that `write`
/// makes of the OBJ's mesh, in a fresh directory.
fn rewritten(
    dir: &Path,
    type_name: &str,
    extension: &str,
    write: impl Fn(&common::geometry::TriangleMesh) -> Vec<u8>,
) -> std::path::PathBuf {
    let mut text = std::fs::read_to_string(scenes_dir().join("meshes.xml")).unwrap();
    for obj in MESHES {
        let mesh = load_obj(&scenes_dir().join(obj)).unwrap();
        let name = Path::new(obj).with_extension(extension);
        let name = name.file_name().unwrap().to_str().unwrap();
        std::fs::write(dir.join(name), write(&mesh)).unwrap();
        text = text.replace(&format!("value=\"{obj}\""), &format!("value=\"{name}\""));
    }
    text = text.replace(
        "<shape type=\"obj\">",
        &format!("<shape type=\"{type_name}\">"),
    );
    assert!(!text.contains("\"obj\""), "every OBJ shape is replaced");
    let path = dir.join("meshes.xml");
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn ply_and_serialized_copies_of_the_obj_meshes_render_the_same_image() {
    let from_obj = render_file(&scenes_dir().join("meshes.xml"));
    let lit = from_obj.pixels.iter().filter(|p| p.max_element() > 0.0);
    assert!(lit.count() > 1000, "the scene is not black");
    for encoding in [
        PlyEncoding::Ascii,
        PlyEncoding::LittleEndian,
        PlyEncoding::BigEndian,
    ] {
        let dir = tempfile::tempdir().unwrap();
        let style = PlyStyle::plain(encoding);
        let scene = rewritten(dir.path(), "ply", "ply", |mesh| {
            write_ply(mesh, None, &style)
        });
        assert!(
            render_file(&scene).pixels == from_obj.pixels,
            "PLY {encoding:?} renders another image"
        );
    }
    for (version, double_precision) in [(3, false), (4, true)] {
        let dir = tempfile::tempdir().unwrap();
        let style = SerializedStyle {
            version,
            double_precision,
            colours: false,
        };
        let scene = rewritten(dir.path(), "serialized", "serialized", |mesh| {
            write_serialized(std::slice::from_ref(mesh), style)
        });
        assert!(
            render_file(&scene).pixels == from_obj.pixels,
            "serialized {style:?} renders another image"
        );
    }
}
