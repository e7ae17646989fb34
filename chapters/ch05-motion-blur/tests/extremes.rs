//! What must hold at the edges: no motion means no time drawn and the static image, bit for
//! bit; motion across the whole frame and spins past a full turn stay finite; the ray's time
//! reaches reflections and shadow rays.

mod support;

use ch04_depth_of_field::scenes::{Builtin as DofBuiltin, DEFAULT_MAX_DEPTH as DOF_DEPTH};
use ch04_depth_of_field::{Lens, render_with as dof_render_with};
use ch05_motion_blur::scenes::{Builtin, DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER};
use ch05_motion_blur::world::MotionScene;
use ch05_motion_blur::{AnimatedTransform, Shutter, StratifiedTime, render_with};
use common::film::PixelBoxFilter;
use common::geometry::{Shape, Sphere};
use common::image::Image;
use common::metrics::rmse;
use common::render::RenderSettings;
use common::sampler::IndependentSampler;
use glam::{Mat4, Vec3};
use support::{Counting, frozen_at, keyframes_of, mirror_only_scene, with_moving, with_shutter};

fn assert_all_finite(image: &Image) {
    assert!(
        image.pixels.iter().all(|p| p.is_finite()),
        "a pixel is not finite"
    );
}

#[test]
fn a_scene_without_motion_is_chapter_04s_image_bit_for_bit_and_draws_no_time() {
    let settings = RenderSettings::new(40, 24, 4);
    for lens in [Lens::PINHOLE, Lens::new(0.2, 5.0).unwrap()] {
        let ours = MotionScene::new(with_shutter(
            DofBuiltin::Bokeh.build(DOF_DEPTH),
            Shutter::new(0.0, 1.0).unwrap(),
        ))
        .unwrap();
        let sampler = Counting::new(5);
        let image = render_with(&ours, &lens, &settings, &sampler, &PixelBoxFilter).image;
        assert_eq!(sampler.times(), 0, "a still scene draws no time");
        let theirs = dof_render_with(
            &DofBuiltin::Bokeh.build(DOF_DEPTH),
            &lens,
            &settings,
            &IndependentSampler::new(5),
            &PixelBoxFilter,
        )
        .image;
        assert_eq!(image, theirs);
    }
}

#[test]
fn a_zero_length_shutter_draws_no_time_and_shows_the_still_image() {
    let settings = RenderSettings::new(48, 30, 2);
    for time in [0.0, 0.37, 1.0] {
        let instant = Shutter::new(time, time).unwrap();
        let world = Builtin::Street.build(DEFAULT_MAX_DEPTH, instant);
        let sampler = Counting::new(1);
        let moving =
            render_with(&world, &Lens::PINHOLE, &settings, &sampler, &PixelBoxFilter).image;
        assert_eq!(sampler.times(), 0, "shutter [{time}, {time}] drew a time");
        // The same objects placed in world space where they are at `time`.
        let still = MotionScene::still(frozen_at(&world, time));
        let expected = render_with(
            &still,
            &Lens::PINHOLE,
            &settings,
            &IndependentSampler::new(1),
            &PixelBoxFilter,
        )
        .image;
        // Object space and world space round differently, by a few ulps: an edge pixel may
        // flip, nothing more.
        let differing = moving
            .pixels
            .iter()
            .zip(&expected.pixels)
            .filter(|(a, b)| (**a - **b).abs().max_element() > 1e-3)
            .count();
        assert!(differing <= 2, "time {time}: {differing} pixels differ");
        assert!(rmse(&moving, &expected) < 1e-2, "time {time}");
    }
}

#[test]
fn an_open_shutter_on_a_moving_scene_draws_one_time_per_sample() {
    let settings = RenderSettings::new(16, 10, 3);
    let world = Builtin::Street.build(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
    let sampler = Counting::new(2);
    render_with(&world, &Lens::PINHOLE, &settings, &sampler, &PixelBoxFilter);
    assert_eq!(sampler.times(), 16 * 10 * 3);
    // A still camera and no aperture: nothing else is drawn.
    assert_eq!(
        sampler
            .other_draws
            .load(std::sync::atomic::Ordering::Relaxed),
        0
    );
}

#[test]
fn motion_across_the_frame_and_spins_past_a_full_turn_stay_finite() {
    let settings = RenderSettings::new(40, 25, 8);
    for builtin in Builtin::ALL {
        for shutter in [(0.0, 1.0), (0.0, 1e-6), (0.25, 0.5), (-3.0, 4.0)] {
            let shutter = Shutter::new(shutter.0, shutter.1).unwrap();
            let world = builtin.build(DEFAULT_MAX_DEPTH, shutter);
            let sampler = StratifiedTime::new(IndependentSampler::new(3), 8, 3);
            let out = render_with(&world, &Lens::PINHOLE, &settings, &sampler, &PixelBoxFilter);
            assert_eq!(out.stats.nonfinite_samples, 0, "{builtin:?} {shutter:?}");
            assert_all_finite(&out.image);
        }
    }
}

#[test]
fn absurdly_fast_and_far_motion_stays_finite() {
    // A sphere crossing 2e6 units within the shutter, and one spinning 1000 turns.
    // The spinner's lights, environment and camera, without its cube: only the two shapes
    // below move, and the centre of the image shows the spinning sphere's ring alone.
    let mut base = Builtin::Spinner.scene(DEFAULT_MAX_DEPTH, DEFAULT_SHUTTER);
    base.moving.clear();
    base.surface_of_shape.truncate(base.geometry.shapes().len());
    let material = common::scene::Material::diffuse(Vec3::splat(0.7));
    let streak = vec![
        (0.0, Mat4::from_translation(Vec3::new(-1e6, 0.0, 0.0))),
        (1.0, Mat4::from_translation(Vec3::new(1e6, 0.0, 0.0))),
    ];
    let spin = keyframes_of(&AnimatedTransform::spin(
        Vec3::Z,
        1000.0,
        0.0,
        1.0,
        Mat4::IDENTITY,
    ));
    let scene = with_moving(
        base,
        Shape::Sphere(Sphere::new(Vec3::ZERO, 0.5)),
        streak,
        material.clone(),
    );
    let scene = with_moving(
        scene,
        Shape::Sphere(Sphere::new(Vec3::new(0.8, 0.0, 0.0), 0.3)),
        spin,
        material,
    );
    let world = MotionScene::new(with_shutter(scene, Shutter::new(0.0, 1.0).unwrap())).unwrap();
    let out = render_with(
        &world,
        &Lens::PINHOLE,
        &RenderSettings::new(24, 24, 8),
        &IndependentSampler::new(9),
        &PixelBoxFilter,
    );
    assert_eq!(out.stats.nonfinite_samples, 0);
    assert_all_finite(&out.image);
    // The spin is fast enough to be a ring of uniform grey around the centre: not black.
    assert!(out.image.get(12, 12).max_element() > 0.0 || out.image.get(18, 12).max_element() > 0.0);
}

#[test]
fn a_moving_object_seen_only_in_a_mirror_is_blurred_there() {
    let world = mirror_only_scene();
    let settings = RenderSettings::new(32, 16, 64);
    let still_at = |time: f32| {
        let instant = MotionScene::still(frozen_at(&world, time));
        render_with(
            &instant,
            &Lens::PINHOLE,
            &settings,
            &IndependentSampler::new(4),
            &PixelBoxFilter,
        )
        .image
    };
    let (start, end) = (still_at(0.0), still_at(1.0));
    let blurred = render_with(
        &world,
        &Lens::PINHOLE,
        &settings,
        &StratifiedTime::new(IndependentSampler::new(4), 64, 4),
        &PixelBoxFilter,
    )
    .image;
    // In the mirror, the sphere at time 0 and at time 1 are in different places ...
    assert!(
        rmse(&start, &end) > 0.05,
        "the sphere must show in the mirror: {}",
        rmse(&start, &end)
    );
    // ... and the blurred image is neither: the reflection is smeared between them.
    assert!(rmse(&blurred, &start) > 0.02 && rmse(&blurred, &end) > 0.02);
    // A pixel that the reflection covers at neither end but in the middle of the shutter.
    let middle = still_at(0.5);
    let (x, y) = (16, 8);
    let (background, covered) = (start.get(x, y), middle.get(x, y));
    assert!(
        (covered - background).length() > 0.1,
        "{covered} vs {background}"
    );
    let seen = blurred.get(x, y);
    assert!(
        seen.max_element() > background.max_element() + 0.02
            && seen.max_element() < covered.max_element() - 0.02,
        "blurred {seen}, background {background}, covered {covered}"
    );
}

#[test]
fn the_rays_time_reaches_the_shadow_test() {
    use ch01_whitted::tracer::trace;
    use common::Ray;
    use common::geometry::Parallelogram;
    use common::scene::{Camera, CameraFrame, FilmSettings, Material, PointLight, SceneBuilder};
    // A floor lit from straight above; a sphere passes between during the first half of the
    // shutter only, out of the camera ray's way.
    let floor = Shape::Parallelogram(Parallelogram::new(
        Vec3::new(-5.0, 0.0, -5.0),
        10.0 * Vec3::Z,
        10.0 * Vec3::X,
    ));
    let scene = SceneBuilder::new()
        .shape(floor, Material::diffuse(Vec3::splat(0.5)))
        .light(PointLight {
            position: Vec3::new(0.0, 4.0, 0.0),
            intensity: Vec3::splat(10.0),
        })
        .moving(
            Shape::Sphere(Sphere::new(Vec3::ZERO, 0.3)),
            vec![
                (0.0, Mat4::from_translation(Vec3::new(0.0, 2.0, 0.0))),
                (0.5, Mat4::from_translation(Vec3::new(0.0, 2.0, 0.0))),
                (0.6, Mat4::from_translation(Vec3::new(-3.0, 2.0, 0.0))),
                (1.0, Mat4::from_translation(Vec3::new(-3.0, 2.0, 0.0))),
            ],
            Material::diffuse(Vec3::ONE),
        );
    let frame = CameraFrame::look_at(Vec3::new(0.0, 3.0, 3.0), Vec3::ZERO, Vec3::Y).unwrap();
    let scene = scene.build(Camera::pinhole(frame, 40.0), FilmSettings::new(8, 8), 4);
    let world = MotionScene::new(with_shutter(scene, Shutter::new(0.0, 1.0).unwrap())).unwrap();
    // A camera ray to the floor's centre, which misses the sphere at every time.
    let ray = Ray::new(
        Vec3::new(0.0, 3.0, 3.0),
        Vec3::new(0.0, -3.0, -3.0).normalize(),
    );
    let at = |time: f32| trace(&world, &ray.with_time(time), 1);
    assert_eq!(at(0.25), Vec3::ZERO, "in the sphere's shadow at time 0.25");
    assert!(at(0.75).min_element() > 0.0, "lit at time 0.75");
}
