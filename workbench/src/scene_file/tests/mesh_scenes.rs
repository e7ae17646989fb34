//! PLY and `.serialized` meshes named by a scene file: found beside it, placed by their
//! `to_world`, with their normals and texture coordinates, `face_normals`, `flip_normals` and
//! `shape_index` as Mitsuba reads them, and errors that name the mesh file.

use std::path::Path;

use glam::{Vec2, Vec3};

use super::super::parse_scene;
use super::scene_with;
use crate::test_support::mesh_files::{
    PlyEncoding, PlyStyle, SerializedStyle, write_ply, write_serialized,
};
use common::Ray;
use common::geometry::{SurfaceHit, TriangleMesh};
use common::scene::Scene;

/// The unit square `[0, 1]^2` in z = 0, its texture coordinates equal to x and y, its normals
/// all tilted towards +y (so that a shading normal taken from the file is told apart from the
/// geometric normal +z).
fn square(normals: bool, uvs: bool) -> TriangleMesh {
    let positions = vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
    let uv = positions.iter().map(|p| p.truncate()).collect();
    let normals = normals.then(|| vec![Vec3::new(0.0, 0.6, 0.8); 4]);
    TriangleMesh::new(positions, normals, vec![[0, 1, 2], [0, 2, 3]])
        .and_then(|mesh| mesh.with_uvs(uvs.then_some(uv)))
        .unwrap()
}

/// The nearest hit of a ray straight down (-z) onto the point `(x, y)`.
fn hit_below(scene: &Scene, x: f32, y: f32) -> SurfaceHit {
    scene
        .geometry
        .intersect(&Ray::new(Vec3::new(x, y, 5.0), -Vec3::Z))
        .unwrap_or_else(|| panic!("nothing below ({x}, {y})"))
}

/// A shape of `type_name` reading `file` (with more properties), moved by `(x, y)`.
fn mesh_shape(type_name: &str, file: &str, x: f32, y: f32, more: &str) -> String {
    format!(
        r#"<shape type="{type_name}"><string name="filename" value="{file}"/>{more}
           <transform name="to_world"><translate x="{x}" y="{y}"/></transform></shape>"#
    )
}

#[test]
fn ply_and_serialized_meshes_are_placed_with_their_normals_and_texture_coordinates() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, bytes: Vec<u8>| std::fs::write(dir.path().join(name), bytes).unwrap();
    let ply = |encoding| PlyStyle::plain(encoding);
    write(
        "ascii.ply",
        write_ply(&square(true, true), None, &ply(PlyEncoding::Ascii)),
    );
    write(
        "little.ply",
        write_ply(&square(false, true), None, &ply(PlyEncoding::LittleEndian)),
    );
    write(
        "big.ply",
        write_ply(&square(true, false), None, &ply(PlyEncoding::BigEndian)),
    );
    let style = SerializedStyle {
        version: 4,
        double_precision: false,
        colours: false,
    };
    write(
        "two.serialized",
        write_serialized(&[square(false, false), square(true, true)], style),
    );
    let shapes = [
        mesh_shape("ply", "ascii.ply", 0.0, 0.0, ""),
        mesh_shape("ply", "little.ply", 2.0, 0.0, ""),
        mesh_shape(
            "ply",
            "little.ply",
            2.0,
            4.0,
            r#"<boolean name="flip_tex_coords" value="true"/>"#,
        ),
        mesh_shape(
            "ply",
            "big.ply",
            4.0,
            0.0,
            r#"<boolean name="face_normals" value="true"/>"#,
        ),
        mesh_shape(
            "ply",
            "big.ply",
            6.0,
            0.0,
            r#"<boolean name="flip_normals" value="true"/>"#,
        ),
        mesh_shape(
            "serialized",
            "two.serialized",
            0.0,
            2.0,
            r#"<integer name="shape_index" value="1"/>"#,
        ),
        mesh_shape("serialized", "two.serialized", 2.0, 2.0, ""),
    ];
    let text = scene_with(&shapes.join("\n"));
    let scene = parse_scene(&text, &dir.path().join("scene.xml"), &[])
        .unwrap_or_else(|e| panic!("{e}"))
        .scene;
    assert_eq!(scene.geometry.shapes().len(), 14);
    let tilted = Vec3::new(0.0, 0.6, 0.8);
    let close = |a: Vec3, b: Vec3| (a - b).length() < 1e-5;

    // ASCII, normals and texture coordinates from the file.
    let hit = hit_below(&scene, 0.25, 0.5);
    assert!(close(hit.p, Vec3::new(0.25, 0.5, 0.0)), "{hit:?}");
    assert!((hit.uv - Vec2::new(0.25, 0.5)).length() < 1e-6, "{hit:?}");
    assert!(
        close(hit.n, Vec3::Z) && close(hit.shading_n, tilted),
        "{hit:?}"
    );
    // Binary little-endian, texture coordinates but no normals: smooth normals computed from
    // the flat square are its face normal.
    let hit = hit_below(&scene, 2.25, 0.5);
    assert!((hit.uv - Vec2::new(0.25, 0.5)).length() < 1e-6, "{hit:?}");
    assert!(close(hit.shading_n, Vec3::Z), "{hit:?}");
    // The same with flip_tex_coords: v becomes 1 - v.
    let hit = hit_below(&scene, 2.25, 4.75);
    assert!((hit.uv - Vec2::new(0.25, 0.25)).length() < 1e-6, "{hit:?}");
    // Binary big-endian, normals but no texture coordinates: uv is the barycentric (b1, b2)
    // of the triangle (0, 0), (1, 1), (0, 1) at (0.25, 0.5), which is (0.25, 0.25).
    // `face_normals` drops the file's normals.
    let hit = hit_below(&scene, 4.25, 0.5);
    assert!((hit.uv - Vec2::new(0.25, 0.25)).length() < 1e-6, "{hit:?}");
    assert!(close(hit.shading_n, Vec3::Z), "{hit:?}");
    // The same file flipped: both normals turn over, and the barycentric uv is the same as
    // unflipped, as in Mitsuba: (0.25, 0.5) at (0.25, 0.75), not (0.5, 0.25).
    let hit = hit_below(&scene, 6.25, 0.5);
    assert!(
        close(hit.n, -Vec3::Z) && close(hit.shading_n, -tilted),
        "{hit:?}"
    );
    let hit = hit_below(&scene, 6.25, 0.75);
    assert!((hit.uv - Vec2::new(0.25, 0.5)).length() < 1e-6, "{hit:?}");
    // The second mesh of the serialized file, then the first (no normals, no uvs).
    let hit = hit_below(&scene, 0.25, 2.5);
    assert!((hit.uv - Vec2::new(0.25, 0.5)).length() < 1e-6, "{hit:?}");
    assert!(close(hit.shading_n, tilted), "{hit:?}");
    let hit = hit_below(&scene, 2.25, 2.5);
    assert!((hit.uv - Vec2::new(0.25, 0.25)).length() < 1e-6, "{hit:?}");
    assert!(close(hit.shading_n, Vec3::Z), "{hit:?}");
}

#[test]
fn mesh_files_that_cannot_be_read_are_named_in_the_error() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("broken.ply"),
        b"ply\nformat ascii 1.0\nend_header\n",
    )
    .unwrap();
    let style = SerializedStyle {
        version: 3,
        double_precision: false,
        colours: false,
    };
    std::fs::write(
        dir.path().join("one.serialized"),
        write_serialized(&[square(false, false)], style),
    )
    .unwrap();
    let cases = [
        (
            mesh_shape("ply", "missing.ply", 0.0, 0.0, ""),
            "missing.ply",
        ),
        (
            mesh_shape("ply", "broken.ply", 0.0, 0.0, ""),
            "broken.ply: the file has no `vertex` element",
        ),
        (
            mesh_shape(
                "serialized",
                "one.serialized",
                0.0,
                0.0,
                r#"<integer name="shape_index" value="3"/>"#,
            ),
            "one.serialized (shape 3): shape_index 3 is out of range: the file holds 1 meshes",
        ),
        (
            mesh_shape(
                "serialized",
                "one.serialized",
                0.0,
                0.0,
                r#"<integer name="shape_index" value="-1"/>"#,
            ),
            "shape_index -1 must be a non-negative integer",
        ),
        (
            r#"<shape type="ply"/>"#.to_string(),
            "a ply shape needs <string name=\"filename\"",
        ),
    ];
    for (shape, expected) in cases {
        let error = parse_scene(&scene_with(&shape), &dir.path().join("scene.xml"), &[])
            .map(|_| ())
            .unwrap_err()
            .to_string();
        assert!(
            error.contains(expected),
            "expected `{expected}` in `{error}`"
        );
        assert!(error.contains("scene.xml:2:"), "{error}");
    }
    // Relative paths are resolved against the scene file's directory, not the working one.
    let elsewhere = parse_scene(
        &scene_with(&mesh_shape("serialized", "one.serialized", 0.0, 0.0, "")),
        Path::new("scene.xml"),
        &[],
    );
    assert!(elsewhere.is_err());
}
