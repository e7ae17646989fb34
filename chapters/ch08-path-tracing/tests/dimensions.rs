//! How many dimensions a path draws, and that counting them leaves the image alone.
//!
//! The scenes look at one big matte plane that fills the view, so every camera ray hits it
//! and every bounce off it leaves the scene: each path's count is then known exactly.
//!
//! At `max_depth` 2 a path is the camera ray and next-event estimation at the plane. Point
//! lights draw nothing there, however many (each gets its shadow ray, with no pick and no
//! point on it to choose), and the BSDF direction that would extend the path is not drawn
//! either: its segment would be the last, and could only find emission, which a scene of
//! point lights has none of. So a static pinhole path draws exactly the 2 numbers of its
//! pixel position. The lights a ray can find (the sky, a lamp) are sampled: a point on them
//! (2), a pick among them when there are several (1), and then the BSDF direction (2), since
//! the last segment may find them.

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{MotionScene, Shutter};
use ch08_path_tracing::LectureMaterials;
use ch08_path_tracing::dimensions::{DimensionStats, render_counted};
use ch08_path_tracing::{Method, PathOptions};
use common::film::PixelBoxFilter;
use common::geometry::{Parallelogram, Shape, Sphere};
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use common::scene::{
    AreaEmitter, Camera, CameraFrame, FilmSettings, Material, PointLight, SceneBuilder,
};
use glam::{Mat4, Vec3};

/// The plane, seen by a camera 5 units in front of it, lit by `lights` point lights.
fn plane(lights: usize) -> SceneBuilder {
    let mut builder = SceneBuilder::new().shape(
        // X x Y = +Z: the plane faces the camera.
        Shape::Parallelogram(Parallelogram::new(
            Vec3::new(-10.0, -10.0, 0.0),
            20.0 * Vec3::X,
            20.0 * Vec3::Y,
        )),
        Material::diffuse(Vec3::splat(0.7)),
    );
    for i in 0..lights {
        builder = builder.light(PointLight {
            position: Vec3::new(i as f32, 0.5, 3.0),
            intensity: Vec3::splat(10.0),
        });
    }
    builder
}

/// `builder`'s scene as chapter 08 renders it, seen over `shutter`.
fn scene(builder: SceneBuilder, shutter: Shutter) -> MotionScene {
    let frame = CameraFrame::look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y)
        .expect("a valid camera direction");
    let mut camera = Camera::pinhole(frame, 40.0);
    camera.shutter_open = shutter.open;
    camera.shutter_close = shutter.close;
    MotionScene::new(builder.build(camera, FilmSettings::new(8, 8), 2)).expect("valid motion")
}

/// `world` with shape number `shape` glowing with `radiance`.
fn with_lamp(mut world: MotionScene, shape: usize, radiance: Vec3) -> MotionScene {
    world.scene.surfaces[shape].emitter = Some(AreaEmitter::uniform(radiance));
    world
}

fn static_scene(lights: usize) -> MotionScene {
    scene(plane(lights), Shutter::INSTANT)
}

/// The plane under a sky of radiance 0.5, with (`lamp`) or without a small area light above
/// it, out of the camera's view.
fn sky_scene(lamp: bool) -> MotionScene {
    let mut builder = plane(0).environment(Vec3::splat(0.5));
    if lamp {
        // X x Z = -Y: the lamp faces down, towards the plane's lower edge.
        builder = builder.shape(
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(-0.5, 2.5, 0.5),
                Vec3::X,
                Vec3::Z,
            )),
            Material::diffuse(Vec3::ZERO),
        );
    }
    let base = scene(builder, Shutter::INSTANT);
    if lamp {
        with_lamp(base, 1, Vec3::splat(4.0))
    } else {
        base
    }
}

/// `builder` with a small matte sphere in front of the plane, sliding sideways over the
/// shutter.
fn with_sliding_sphere(builder: SceneBuilder) -> SceneBuilder {
    let keyframes = vec![
        (0.0, Mat4::IDENTITY),
        (1.0, Mat4::from_translation(0.5 * Vec3::X)),
    ];
    let sphere = Shape::Sphere(Sphere::new(Vec3::new(0.0, 0.0, 1.0), 0.3));
    builder.moving(sphere, keyframes, Material::diffuse(Vec3::splat(0.5)))
}

/// Renders 8 x 8 pixels at 2 samples and returns the dimensions per path.
fn dimensions(scene: &MotionScene, lens: &Lens, max_depth: u32) -> DimensionStats {
    let (_, stats) = render_counted(
        true,
        scene,
        Method::new(PathOptions::with_depth(max_depth)),
        LectureMaterials::default(),
        lens,
        &RenderSettings::new(8, 8, 2),
        &IndependentSampler::new(1),
        &PixelBoxFilter,
    );
    let stats = stats.expect("counted");
    assert_eq!(stats.paths, 8 * 8 * 2);
    stats
}

/// Asserts that every path drew exactly `n` dimensions.
fn assert_exactly(stats: DimensionStats, n: u64) {
    assert_eq!((stats.mean, stats.max), (n as f64, n), "{stats:?}");
}

fn thin_lens() -> Lens {
    Lens::new(0.1, 5.0).expect("a valid lens")
}

#[test]
fn a_static_pinhole_path_to_point_lights_draws_only_its_pixel() {
    // Pixel 2; the point lights 0 (no pick, no point on a point), no BSDF numbers.
    assert_exactly(dimensions(&static_scene(1), &Lens::PINHOLE, 2), 2);
    assert_exactly(dimensions(&static_scene(3), &Lens::PINHOLE, 2), 2);
}

#[test]
fn a_lens_adds_exactly_two() {
    assert_exactly(dimensions(&static_scene(1), &thin_lens(), 2), 4);
}

#[test]
fn motion_adds_exactly_one() {
    let shutter = Shutter::new(0.0, 1.0).expect("a valid shutter");
    let moving = scene(with_sliding_sphere(plane(1)), shutter);
    assert_exactly(dimensions(&moving, &Lens::PINHOLE, 2), 3);
    assert_exactly(dimensions(&moving, &thin_lens(), 2), 5);
}

#[test]
fn the_pick_among_several_lights_draws_no_number_of_its_own() {
    // The sky alone: pixel 2, a direction to the sky 2, the BSDF's 2 (the last segment may
    // find the sky). With a lamp as well, the same: the pick between the two reads the first
    // number of the light sample's pair and leaves the rest of it to the point.
    assert_exactly(dimensions(&sky_scene(false), &Lens::PINHOLE, 2), 6);
    assert_exactly(dimensions(&sky_scene(true), &Lens::PINHOLE, 2), 6);
}

#[test]
fn a_scene_without_lights_draws_no_light_numbers() {
    assert_exactly(dimensions(&static_scene(0), &Lens::PINHOLE, 2), 2);
    // One bounce more: pixel 2, then the BSDF's 2 at the plane; the bounce leaves the scene.
    // Point lights add nothing to it.
    assert_exactly(dimensions(&static_scene(0), &Lens::PINHOLE, 3), 4);
    assert_exactly(dimensions(&static_scene(2), &Lens::PINHOLE, 3), 4);
}

#[test]
fn counting_leaves_the_image_bit_identical() {
    // Everything that draws: a lens, motion, two point lights and an area light, glass.
    let shutter = Shutter::new(0.0, 1.0).expect("a valid shutter");
    let builder = plane(2)
        .shape(
            Shape::Sphere(Sphere::new(Vec3::new(-0.6, 0.3, 1.0), 0.4)),
            Material::glass(1.5),
        )
        .shape(
            Shape::Parallelogram(Parallelogram::new(
                Vec3::new(0.5, 1.0, 2.0),
                Vec3::X,
                -Vec3::Z,
            )),
            Material::diffuse(Vec3::ZERO),
        );
    let base = scene(with_sliding_sphere(builder), shutter);
    let lamp = 2; // the third still shape
    let scene = with_lamp(base, lamp, Vec3::splat(4.0));
    let render = |count| {
        render_counted(
            count,
            &scene,
            Method::new(PathOptions::with_depth(6)),
            LectureMaterials::default(),
            &thin_lens(),
            &RenderSettings::new(16, 16, 4),
            &IndependentSampler::new(3),
            &PixelBoxFilter,
        )
    };
    let (plain, none) = render(false);
    let (counted, stats) = render(true);
    assert!(none.is_none());
    assert_eq!(plain.image, counted.image);
    assert_eq!(plain.stats.rays, counted.stats.rays);
    let stats = stats.expect("counted");
    // Pixel, time and lens (5), then at least the plane's light sample and BSDF numbers.
    assert!(stats.mean > 5.0 && stats.max > 10, "{stats:?}");
}
