//! The surface parameters `uv` each shape of a scene file gives a hit, checked against
//! Mitsuba 3.9.1 (`scalar_rgb`): the numbers below are `si.uv` of `scene.ray_intersect` for
//! the same shape and ray, so that a texture lands where Mitsuba puts it.

use glam::{Vec2, Vec3};

use super::super::parse_scene;
use super::scene_with;
use common::Ray;

/// The uv of each ray's nearest hit on the scene made of `shape`.
fn uvs(shape: &str, rays: &[([f32; 3], [f32; 3])]) -> Vec<Vec2> {
    let scene = parse_scene(&scene_with(shape), std::path::Path::new("test.xml"), &[])
        .unwrap_or_else(|e| panic!("{e}"))
        .scene;
    rays.iter()
        .map(|&(origin, dir)| {
            let ray = Ray::new(Vec3::from(origin), Vec3::from(dir));
            scene
                .geometry
                .intersect(&ray)
                .unwrap_or_else(|| panic!("{shape}: the ray from {origin:?} misses"))
                .uv
        })
        .collect()
}

fn agrees(shape: &str, rays: &[([f32; 3], [f32; 3])], mitsuba: &[[f32; 2]]) {
    for ((uv, expected), ray) in uvs(shape, rays).into_iter().zip(mitsuba).zip(rays) {
        assert!(
            uv.abs_diff_eq(Vec2::from(*expected), 1e-4),
            "{shape}\nthe ray {ray:?} hits at uv {uv}; Mitsuba says {expected:?}"
        );
    }
}

const DOWN: [f32; 3] = [0.0, -1.0, 0.0];

#[test]
fn rectangles_as_mitsuba() {
    agrees(
        r#"<shape type="rectangle"/>"#,
        &[
            ([0.5, 0.25, 3.0], [0.0, 0.0, -1.0]),
            ([-0.9, -0.7, 3.0], [0.0, 0.0, -1.0]),
        ],
        &[[0.75, 0.625], [0.05, 0.15]],
    );
    agrees(
        r#"<shape type="rectangle"><transform name="to_world"><scale x="2" y="3"/>
             <rotate x="1" angle="-90"/><translate y="1"/></transform></shape>"#,
        &[([0.5, 3.0, 0.3], DOWN), ([-1.2, 3.0, -2.0], DOWN)],
        &[[0.625, 0.45], [0.2, 0.83333]],
    );
}

#[test]
fn discs_as_mitsuba() {
    agrees(
        r#"<shape type="disk"/>"#,
        &[
            ([0.5, 0.0, 3.0], [0.0, 0.0, -1.0]),
            ([0.0, -0.7, 3.0], [0.0, 0.0, -1.0]),
            ([0.3, 0.4, 3.0], [0.0, 0.0, -1.0]),
        ],
        &[[0.5, 0.0], [0.7, 0.75], [0.5, 0.147584]],
    );
    agrees(
        r#"<shape type="disk"><transform name="to_world"><scale value="2"/>
             <rotate x="1" angle="-90"/><translate y="1"/></transform></shape>"#,
        &[([0.5, 3.0, 0.3], DOWN), ([-1.2, 3.0, -1.0], DOWN)],
        &[[0.29155, 0.91399], [0.78102, 0.38943]],
    );
}

#[test]
fn spheres_as_mitsuba() {
    let rays = [
        ([1.0, 2.0, 10.0], [0.0, 0.0, -1.0]),
        ([1.0, 10.0, 3.5], DOWN),
        ([-5.0, 2.3, 3.4], [1.0, 0.0, 0.0]),
    ];
    agrees(
        r#"<shape type="sphere"><point name="center" x="1" y="2" z="3"/>
             <float name="radius" value="2"/></shape>"#,
        &rays,
        &[[0.0, 0.0], [0.25, 0.41957], [0.47554, 0.43591]],
    );
    // The same sphere made by to_world.
    agrees(
        r#"<shape type="sphere"><transform name="to_world"><scale value="2"/>
             <translate x="1" y="2" z="3"/></transform></shape>"#,
        &rays,
        &[[0.0, 0.0], [0.25, 0.41957], [0.47554, 0.43591]],
    );
    // Not yet: a rotation in to_world turns Mitsuba's sphere's own frame, and its uv with it
    // (Mitsuba gives [0.75, 0.5], [0.75, 0.08043], [0.53242, 0.45207] for the rays above under
    // a rotation of -90 degrees about x); the workbook's spheres have no frame of their own.
}

#[test]
fn cubes_as_mitsuba() {
    let z = |sign: f32| ([0.5, 0.25, 3.0 * sign], [0.0, 0.0, -sign]);
    let x = |sign: f32| ([3.0 * sign, 0.5, 0.25], [-sign, 0.0, 0.0]);
    let y = |sign: f32| ([0.5, 3.0 * sign, 0.25], [0.0, -sign, 0.0]);
    agrees(
        r#"<shape type="cube"/>"#,
        &[z(1.0), z(-1.0), x(1.0), x(-1.0), y(1.0), y(-1.0)],
        &[
            [0.625, 0.75],
            [0.375, 0.75],
            [0.75, 0.375],
            [0.75, 0.625],
            [0.25, 0.375],
            [0.625, 0.75],
        ],
    );
}
