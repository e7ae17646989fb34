//! The tracer against answers known in closed form.

use ch01_whitted::camera::PinholeCamera;
use ch01_whitted::scenes::Builtin;
use ch01_whitted::tracer::trace;
use ch01_whitted::{PixelPattern, render};
use common::Ray;
use common::geometry::{Parallelogram, Shape, Sphere};
use common::image::Image;
use common::render::RenderSettings;
use common::scene::{Camera, CameraFrame, FilmSettings, Material, PointLight, Scene, SceneBuilder};
use glam::{Vec2, Vec3};

/// A pinhole at `origin` looking at `target` on a square film of `size` pixels.
fn camera_at(origin: Vec3, target: Vec3, fov: f32, size: u32) -> (Camera, FilmSettings) {
    let frame = CameraFrame::look_at(origin, target, Vec3::Y).expect("a valid frame");
    (Camera::pinhole(frame, fov), FilmSettings::new(size, size))
}

/// The scene of `builder` seen by `camera`, limited to `max_depth` segments.
fn build(builder: SceneBuilder, (camera, film): (Camera, FilmSettings), max_depth: u32) -> Scene {
    builder.build(camera, film, max_depth)
}

fn render_image(scene: &Scene, size: u32) -> Image {
    let out = render(
        scene,
        &RenderSettings::new(size, size, 1),
        PixelPattern::Centre,
        0,
    )
    .unwrap();
    assert_eq!(
        out.stats.nonfinite_samples, 0,
        "no sample may be NaN or infinite"
    );
    assert!(out.image.pixels.iter().all(|p| p.is_finite()));
    out.image
}

fn max_difference(a: &Image, b: &Image) -> f32 {
    a.pixels
        .iter()
        .zip(&b.pixels)
        .map(|(p, q)| (*p - *q).abs().max_element())
        .fold(0.0, f32::max)
}

#[test]
fn a_matte_floor_under_a_point_light_has_the_analytic_radiance() {
    let albedo = Vec3::new(0.8, 0.5, 0.2);
    let intensity = Vec3::splat(10.0);
    let light = Vec3::new(1.0, 2.0, 0.5);
    let floor = Parallelogram::new(Vec3::new(-5.0, 0.0, 5.0), 10.0 * Vec3::X, -10.0 * Vec3::Z);
    let scene = build(
        SceneBuilder::new()
            .shape(Shape::Parallelogram(floor), Material::diffuse(albedo))
            .light(PointLight {
                position: light,
                intensity,
            }),
        camera_at(Vec3::new(0.0, 3.0, 3.0), Vec3::ZERO, 40.0, 9),
        2,
    );
    // Trace straight at the origin and compare with albedo / pi * I cos(theta) / r^2.
    let origin = Vec3::new(0.0, 3.0, 3.0);
    let ray = Ray::new(origin, (-origin).normalize());
    let radiance = trace(&scene, &ray, 1);
    let r2 = light.length_squared();
    let cos_theta = light.y / r2.sqrt();
    let expected = albedo / std::f32::consts::PI * intensity * cos_theta / r2;
    approx::assert_relative_eq!(radiance, expected, max_relative = 1e-5);
}

#[test]
fn max_depth_one_shows_only_the_background() {
    let scene = Builtin::Spheres.build(1);
    let image = render_image(&scene, 24);
    for p in &image.pixels {
        assert!(*p == scene.environment || *p == Vec3::ZERO, "{p}");
    }
}

#[test]
fn glass_of_index_one_is_invisible() {
    // Without an interface there is no reflection (F = 0) and no bending (eta = 1): the
    // sphere disappears. (It would still cast a hard shadow, as every Whitted surface does,
    // so the scene has no lights.)
    let background = Vec3::new(0.3, 0.5, 0.9);
    let camera = camera_at(Vec3::new(0.0, 1.0, 4.0), Vec3::new(0.0, 0.5, 0.0), 45.0, 32);
    let plain = build(
        SceneBuilder::new().environment(background),
        camera.clone(),
        10,
    );
    let ghost = build(
        SceneBuilder::new().environment(background).shape(
            Shape::Sphere(Sphere::new(Vec3::new(0.0, 0.5, 0.0), 0.8)),
            Material::Dielectric {
                int_ior: 1.0,
                ext_ior: 1.0,
            },
        ),
        camera,
        10,
    );
    let difference = max_difference(&render_image(&plain, 32), &render_image(&ghost, 32));
    assert!(
        difference < 1e-6,
        "an index-matched sphere changed a pixel by {difference}"
    );
}

#[test]
fn a_perfect_mirror_in_a_uniform_world_reflects_the_world() {
    let background = Vec3::new(0.2, 0.4, 0.6);
    let scene = build(
        SceneBuilder::new().environment(background).shape(
            Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0)),
            Material::mirror(),
        ),
        camera_at(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, 50.0, 32),
        3,
    );
    let image = render_image(&scene, 32);
    assert!(image.pixels.iter().all(|p| *p == background));
}

#[test]
fn glass_in_a_uniform_world_neither_creates_nor_loses_much_light() {
    // Radiance divided by the squared index is conserved along a path through smooth glass,
    // so a glass sphere in a uniform world looks uniform too, up to the light carried by
    // paths cut off by the depth limit. Near the silhouette the internal reflectance is high
    // and the series converges slowly: depth 40 still misses 0.6%, depth 200 nothing visible.
    let background = Vec3::ONE;
    let scene = build(
        SceneBuilder::new().environment(background).shape(
            Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0)),
            Material::glass(1.5),
        ),
        camera_at(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, 45.0, 32),
        200,
    );
    let image = render_image(&scene, 32);
    let worst = image
        .pixels
        .iter()
        .map(|p| (p.x - 1.0).abs())
        .fold(0.0, f32::max);
    assert!(
        worst < 1e-5,
        "a pixel differs from the background by {worst}"
    );
}

#[test]
fn a_camera_inside_a_glass_sphere_sees_a_finite_world() {
    let scene = build(
        SceneBuilder::new().environment(Vec3::splat(0.5)).shape(
            Shape::Sphere(Sphere::new(Vec3::ZERO, 2.0)),
            Material::glass(1.5),
        ),
        camera_at(Vec3::ZERO, Vec3::Z, 90.0, 24),
        12,
    );
    let image = render_image(&scene, 24);
    // From inside, rays beyond the critical angle bounce until the depth limit; the rest leave.
    assert!(image.pixels.iter().any(|p| p.x > 0.0));
}

#[test]
fn grazing_views_of_glass_and_floors_stay_finite() {
    // The camera sits exactly in the plane of the floor and looks along it, through a glass
    // sphere resting on it.
    let scene = build(
        SceneBuilder::new()
            .environment(Vec3::splat(0.5))
            .shape(
                Shape::Parallelogram(Parallelogram::new(
                    Vec3::new(-50.0, 0.0, 50.0),
                    100.0 * Vec3::X,
                    -100.0 * Vec3::Z,
                )),
                Material::two_sided_diffuse(Vec3::splat(0.5)),
            )
            .shape(
                Shape::Sphere(Sphere::new(Vec3::new(0.0, 1.0, -3.0), 1.0)),
                Material::glass(1.5),
            )
            .light(PointLight {
                position: Vec3::new(0.0, 1e-3, 0.0),
                intensity: Vec3::ONE,
            }),
        camera_at(
            Vec3::new(0.0, 0.0, 2.0),
            Vec3::new(0.0, 0.0, -3.0),
            60.0,
            32,
        ),
        12,
    );
    render_image(&scene, 32);
}

#[test]
fn images_do_not_depend_on_the_thread_count() {
    let scene = Builtin::Spheres.build(12);
    let image_with = |threads| {
        let settings = RenderSettings {
            threads: Some(threads),
            ..RenderSettings::new(40, 30, 4)
        };
        render(&scene, &settings, PixelPattern::Grid, 3)
            .unwrap()
            .image
    };
    assert_eq!(image_with(1), image_with(2));
}

#[test]
fn film_positions_map_to_camera_rays_as_in_mitsuba() {
    // The top-left pixel looks up and to the left.
    let (camera, _) = camera_at(Vec3::ZERO, Vec3::NEG_Z, 90.0, 10);
    let ray = PinholeCamera::of(&camera, 10, 10).generate_ray(Vec2::new(0.5, 0.5));
    assert!(ray.dir.x < 0.0 && ray.dir.y > 0.0 && ray.dir.z < 0.0);
}
