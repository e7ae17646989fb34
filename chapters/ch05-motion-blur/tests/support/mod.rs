//! Helpers shared by the chapter's tests.
#![allow(dead_code)]

use ch05_motion_blur::world::MotionScene;
use ch05_motion_blur::{AnimatedTransform, Shutter, TimeSampler};
use common::geometry::{Parallelogram, Shape, Sphere};
use common::image::Image;
use common::sampler::{IndependentSampler, Sampler};
use common::scene::{AnimatedShape, Material, Scene, SceneBuilder, Surface};
use glam::{Mat4, UVec2, Vec2, Vec3};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

/// Counts how many time numbers and other numbers a sampler hands out after the pixel.
#[derive(Clone)]
pub struct Counting {
    inner: IndependentSampler,
    pub time_draws: Arc<AtomicU64>,
    pub other_draws: Arc<AtomicU64>,
}

impl Counting {
    pub fn new(seed: u64) -> Self {
        Self {
            inner: IndependentSampler::new(seed),
            time_draws: Arc::new(AtomicU64::new(0)),
            other_draws: Arc::new(AtomicU64::new(0)),
        }
    }

    pub fn times(&self) -> u64 {
        self.time_draws.load(Ordering::Relaxed)
    }
}

impl Sampler for Counting {
    fn start_pixel_sample(&mut self, pixel: UVec2, index: u64) {
        self.inner.start_pixel_sample(pixel, index);
    }
    fn get_pixel_2d(&mut self) -> Vec2 {
        self.inner.get_pixel_2d()
    }
    fn get_1d(&mut self) -> f32 {
        self.other_draws.fetch_add(1, Ordering::Relaxed);
        self.inner.get_1d()
    }
}

impl TimeSampler for Counting {
    fn get_time_1d(&mut self) -> f32 {
        self.time_draws.fetch_add(1, Ordering::Relaxed);
        self.inner.get_1d()
    }
}

/// The moving shapes of `world` frozen where they are at `time`, as ordinary world-space
/// shapes in a static scene: what a still photograph at `time` shows.
pub fn frozen_at(world: &MotionScene, time: f32) -> Scene {
    let still = &world.scene;
    let mut builder = SceneBuilder::new().environment(still.environment);
    for (index, shape) in still.geometry.shapes().iter().enumerate() {
        builder = builder.surface(*shape, still.surface(index as u32).clone());
    }
    let first_moving = still.geometry.shapes().len();
    for (index, moving) in world.moving.shapes().iter().enumerate() {
        let m = moving.motion.at(time);
        let placed = place(&moving.shape, &m);
        builder = builder.surface(placed, still.surface((first_moving + index) as u32).clone());
    }
    for light in &still.point_lights {
        builder = builder.light(*light);
    }
    // The camera where it is at `time`, no longer moving, with a shutter of one instant.
    let mut camera = still.camera.clone();
    if world.camera_motion.is_some() {
        camera.frame = world
            .camera_at(time, still.film.width, still.film.height)
            .frame;
    }
    camera.keyframes.clear();
    camera.shutter_open = Shutter::INSTANT.open;
    camera.shutter_close = Shutter::INSTANT.close;
    Scene {
        sampler: still.sampler.clone(),
        integrator: still.integrator,
        origins: still.origins.clone(),
        ..builder.build(camera, still.film, still.max_depth)
    }
}

/// The `(time, matrix)` keyframes of `motion`, as the scene model keeps them.
pub fn keyframes_of(motion: &AnimatedTransform) -> Vec<(f32, Mat4)> {
    motion
        .keyframes()
        .iter()
        .map(|keyframe| (keyframe.time, keyframe.matrix))
        .collect()
}

/// `scene` with one more moving shape made of `material`, numbered after all its shapes (as
/// [`SceneBuilder::moving`] numbers it, for a scene that is already built).
pub fn with_moving(
    mut scene: Scene,
    shape: Shape,
    keyframes: Vec<(f32, Mat4)>,
    material: Material,
) -> Scene {
    scene.moving.push(AnimatedShape { shape, keyframes });
    scene.surfaces.push(Surface {
        material,
        emitter: None,
        origin: None,
    });
    scene
        .surface_of_shape
        .push((scene.surfaces.len() - 1) as u32);
    scene
}

/// `scene` seen through `shutter`.
pub fn with_shutter(mut scene: Scene, shutter: Shutter) -> Scene {
    scene.camera.shutter_open = shutter.open;
    scene.camera.shutter_close = shutter.close;
    scene
}

/// A shape moved by a rigid transform (with uniform scale).
fn place(shape: &Shape, m: &Mat4) -> Shape {
    match shape {
        Shape::Sphere(s) => {
            let scale = m.transform_vector3(Vec3::X).length();
            Shape::Sphere(Sphere::new(m.transform_point3(s.center), s.radius * scale))
        }
        Shape::Parallelogram(q) => Shape::Parallelogram(Parallelogram::new(
            m.transform_point3(q.corner()),
            m.transform_vector3(q.e1()),
            m.transform_vector3(q.e2()),
        )),
        other => panic!("frozen_at does not place {other:?}"),
    }
}

/// A sphere sliding along x through a point light's view of a mirror: the camera sees only the
/// mirror, so the sphere appears in the image by reflection alone, and its shadow falls on a
/// floor that the camera sees in the mirror too.
pub fn mirror_only_scene() -> MotionScene {
    use common::scene::{Camera, CameraFrame, FilmSettings, PointLight};
    // Camera at z = 4 looking down -z at a mirror at z = 0; the sphere sits behind the camera
    // (z = 6), out of its view.
    let mirror = Shape::Parallelogram(Parallelogram::new(
        Vec3::new(-3.0, -2.0, 0.0),
        6.0 * Vec3::X,
        4.0 * Vec3::Y,
    ));
    let scene = SceneBuilder::new()
        .environment(Vec3::splat(0.1))
        .shape(mirror, Material::mirror())
        .light(PointLight {
            position: Vec3::new(0.0, 3.0, 3.0),
            intensity: Vec3::splat(80.0),
        })
        .moving(
            Shape::Sphere(Sphere::new(Vec3::ZERO, 1.2)),
            vec![
                (0.0, Mat4::from_translation(Vec3::new(-2.0, 0.0, 7.0))),
                (1.0, Mat4::from_translation(Vec3::new(2.0, 0.0, 7.0))),
            ],
            Material::diffuse(Vec3::new(0.9, 0.6, 0.2)),
        );
    let frame = CameraFrame::look_at(Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, Vec3::Y).unwrap();
    let scene = scene.build(Camera::pinhole(frame, 50.0), FilmSettings::new(32, 16), 4);
    MotionScene::new(with_shutter(scene, Shutter::new(0.0, 1.0).unwrap())).unwrap()
}

/// The per-pixel mean of images.
pub fn average(images: &[Image]) -> Image {
    let mut out = Image::new(images[0].width, images[0].height);
    for (i, pixel) in out.pixels.iter_mut().enumerate() {
        *pixel = images.iter().map(|image| image.pixels[i]).sum::<Vec3>() / images.len() as f32;
    }
    out
}
