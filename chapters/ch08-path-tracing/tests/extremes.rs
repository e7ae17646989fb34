//! Extremes: no NaN, no infinity, at any depth limit, with roulette or without, through glass.

mod support;

use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::furnace::scene_of;
use ch08_path_tracing::PathOptions;
use ch08_path_tracing::furnace::spheres;
use common::geometry::{Parallelogram, Shape, Sphere};
use common::scene::AreaEmitter;
use common::scene::Material as Smooth;
use common::scene::Material;
use glam::Vec3;

fn render_finite(scene: &ch05_motion_blur::MotionScene, options: PathOptions, what: &str) -> f64 {
    let out = support::render_pinhole(scene, options, (16, 16, 4), 5);
    assert_eq!(out.stats.nonfinite_samples, 0, "{what}");
    assert!(out.image.pixels.iter().all(|p| p.is_finite()), "{what}");
    common::metrics::mean(&out.image).y
}

#[test]
fn the_cornell_box_is_finite_at_depth_1_and_1000_with_and_without_roulette() {
    let scene = support::scene_file("cornell-box.xml");
    let s = &scene.world;
    let one = render_finite(
        s,
        PathOptions {
            max_depth: 1,
            ..scene.options
        },
        "depth 1",
    );
    let deep = render_finite(
        s,
        PathOptions {
            max_depth: 1000,
            rr_depth: None,
            ..scene.options
        },
        "depth 1000, no roulette",
    );
    let rr = render_finite(
        s,
        PathOptions {
            max_depth: 1000,
            rr_depth: Some(1),
            ..scene.options
        },
        "depth 1000, roulette from 1",
    );
    // Depth 1 sees the light only; more depth adds light, never removes it.
    assert!(one > 0.0 && deep > one && rr > one, "{one} {deep} {rr}");
}

#[test]
fn an_all_glass_world_and_a_light_through_glass_stay_finite() {
    let glass = Smooth::glass(1.5);
    let rough = Material::rough_glass(1.5, 5.0);
    render_finite(
        &spheres(&[glass.clone(), rough, glass], 1000),
        PathOptions {
            rr_depth: None,
            ..PathOptions::with_depth(1000)
        },
        "all glass",
    );
    let scene = support::scene_file("point-and-sky.xml");
    render_finite(
        &scene.world,
        PathOptions {
            max_depth: 1000,
            ..scene.options
        },
        "lights through glass",
    );
}

#[test]
fn a_black_world_stays_black() {
    let black = Smooth::diffuse(Vec3::ZERO);
    let mut scene = spheres(&[black], 8);
    scene.scene.environment = Vec3::ZERO;
    assert_eq!(
        render_finite(&scene, PathOptions::with_depth(8), "black"),
        0.0
    );
}

/// A glass ball on a matte floor, and behind it a light a hundredth wide and 10⁴ bright,
/// in a black world: the camera sees the light only through the glass, and the floor
/// gets its focused light (a caustic) only from paths that bounce through the glass to it,
/// since every light sample from behind the ball is blocked.
fn a_small_light_behind_glass() -> MotionScene {
    let floor = Parallelogram::new(
        Vec3::new(-50.0, -1.0, -50.0),
        100.0 * Vec3::Z,
        100.0 * Vec3::X,
    );
    let shapes = vec![
        (
            Shape::Parallelogram(floor),
            Smooth::diffuse(Vec3::splat(0.5)),
        ),
        (
            Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0)),
            Smooth::glass(1.5),
        ),
        (
            Shape::Sphere(Sphere::new(Vec3::new(0.0, 0.0, -3.0), 0.01)),
            Smooth::diffuse(Vec3::ZERO),
        ),
    ];
    let mut world = scene_of(shapes, Vec3::ZERO, Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, 12);
    world.scene.surfaces[2].emitter = Some(AreaEmitter::uniform(Vec3::splat(1e4)));
    world
}

#[test]
fn a_tiny_bright_light_seen_through_glass_stays_finite_at_every_depth() {
    let scene = a_small_light_behind_glass();
    let direct = render_finite(&scene, PathOptions::with_depth(2), "depth 2");
    for rr_depth in [Some(1), Some(5), None] {
        let deep = render_finite(
            &scene,
            PathOptions {
                rr_depth,
                ..PathOptions::with_depth(1000)
            },
            "depth 1000",
        );
        // Through the glass there is more light to find, never less.
        assert!(deep > direct, "roulette {rr_depth:?}: {deep} vs {direct}");
    }
}
