//! A scene in motion: the scene model's moving shapes and moving camera, made ready to be
//! traced at any time of the shutter interval.
//!
//! The scene says how things move (keyframes); this chapter says how to find them at a
//! time: transforms interpolated between keyframes, moving shapes behind a BVH per stretch of
//! the shutter. [`MotionScene`] implements chapter 01's [`World`], so chapter 01's recursion
//! (here [`trace_in_motion`](crate::path::trace_in_motion)) traces it: the nearest hit is the
//! nearer of the still BVH's and the moving objects', and a shadow ray is blocked by either,
//! each at the ray's time. A scene with no moving shapes asks the still BVH only, at chapter
//! 01's cost.

use crate::animated_transform::AnimatedTransform;
use crate::moving::{MovingObjects, MovingShape};
use crate::shutter::Shutter;
use ch01_whitted::camera::PinholeCamera;
use ch01_whitted::world::World;
use common::Ray;
use common::geometry::SurfaceHit;
use common::render::count_ray;
use common::scene::{CameraFrame, Material, Scene};
use glam::Vec3;
use std::borrow::Cow;

/// How many stretches of the shutter get their own BVH over the moving shapes by default.
pub const DEFAULT_STRETCHES: usize = 8;

/// A scene with its motion made ready for tracing.
pub struct MotionScene {
    /// The scene: shapes (still and moving), surfaces, lights, camera, shutter.
    pub scene: Scene,
    /// The moving shapes, bounded for [`shutter`](Self::shutter).
    pub moving: MovingObjects,
    /// The camera's motion (camera to world, Mitsuba's columns: left, up, forward, origin);
    /// `None` for a camera that stays where the scene's camera is.
    pub camera_motion: Option<AnimatedTransform>,
    /// The shutter interval.
    pub shutter: Shutter,
}

impl MotionScene {
    /// `scene` made ready for tracing over its shutter interval, or why its motion cannot be
    /// followed (keyframes half a turn apart, a shutter that closes before it opens), naming
    /// the shape.
    pub fn new(scene: Scene) -> Result<Self, String> {
        let camera = &scene.camera;
        let shutter = Shutter::new(camera.shutter_open, camera.shutter_close).map_err(|e| {
            format!(
                "the camera's shutter from {} to {}: {e}",
                camera.shutter_open, camera.shutter_close
            )
        })?;
        let first_index = scene.geometry.shapes().len();
        let mut moving = Vec::with_capacity(scene.moving.len());
        for (j, animated) in scene.moving.iter().enumerate() {
            let surface = scene.surface((first_index + j) as u32);
            let motion = AnimatedTransform::new(&animated.keyframes).map_err(|e| {
                let at = surface
                    .origin
                    .as_ref()
                    .map(|p| format!("{p}: "))
                    .unwrap_or_default();
                format!("{at}shape {}: {e}", first_index + j + 1)
            })?;
            moving.push(MovingShape::new(animated.shape, motion));
        }
        let camera_motion = if camera.keyframes.is_empty() {
            None
        } else {
            Some(
                AnimatedTransform::new(&camera.keyframes)
                    .map_err(|e| format!("the camera's motion: {e}"))?,
            )
        };
        Ok(Self {
            moving: MovingObjects::new(moving, first_index as u32, shutter, DEFAULT_STRETCHES),
            camera_motion,
            shutter,
            scene,
        })
    }

    /// A scene built in code, whose motions are valid by construction (a scene without any
    /// motion, say).
    pub fn still(scene: Scene) -> Self {
        Self::new(scene).expect("a scene built in code has valid motions")
    }

    /// The same scene seen through another shutter, its motion bounds cut into `stretches`.
    pub fn with_shutter(mut self, shutter: Shutter, stretches: usize) -> Self {
        self.moving = self.moving.rebuilt(shutter, stretches);
        self.shutter = shutter;
        self.scene.camera.shutter_open = shutter.open;
        self.scene.camera.shutter_close = shutter.close;
        self
    }

    /// Whether anything moves: a moving shape or the camera. A render of a scene that does
    /// not move draws no time.
    pub fn moves(&self) -> bool {
        self.moving.any_moving()
            || self
                .camera_motion
                .as_ref()
                .is_some_and(AnimatedTransform::is_moving)
    }

    /// The pinhole camera at `time`, on a film of `width x height`.
    pub fn camera_at(&self, time: f32, width: u32, height: u32) -> PinholeCamera {
        let camera = PinholeCamera::of(&self.scene.camera, width, height);
        match &self.camera_motion {
            None => camera,
            Some(motion) => PinholeCamera {
                frame: CameraFrame::from_matrix(&motion.at(time)),
                ..camera
            },
        }
    }

    /// What the surface `hit` found is made of, its textures read at the hit point: the one
    /// way a tracer reads a surface, so that none reaches through the world into the scene.
    pub fn material_at(&self, hit: &SurfaceHit) -> Cow<'_, Material> {
        self.scene.material_at(hit.shape, hit.uv)
    }

    /// The radiance arriving along a ray that leaves the scene in direction `dir`.
    pub fn background(&self, dir: Vec3) -> Vec3 {
        self.scene.background(dir)
    }
}

// ANCHOR: world
impl World for MotionScene {
    fn scene(&self) -> &Scene {
        &self.scene
    }

    fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        count_ray();
        let still = self.scene.geometry.intersect(ray);
        if self.moving.is_empty() {
            return still;
        }
        // Only a moving shape nearer than the static hit matters.
        let t_max = still.map_or(ray.t_max, |hit| hit.t);
        self.moving.intersect(&Ray { t_max, ..*ray }).or(still)
    }

    fn occluded(&self, ray: &Ray) -> bool {
        count_ray();
        self.scene.geometry.occluded(ray) || (!self.moving.is_empty() && self.moving.occluded(ray))
    }
}
// ANCHOR_END: world
