//! A scene in motion: chapter 01's static scene, moving shapes, a camera that may move, and
//! the shutter interval the motion is seen through.
//!
//! It implements chapter 01's [`World`], so chapter 01's tracer traces it unchanged: the
//! nearest hit is the nearer of the static BVH's and the moving objects', and a shadow ray is
//! blocked by either, each at the ray's time. A scene with no moving shapes asks the static
//! BVH only, at chapter 01's cost.

use crate::animated_transform::AnimatedTransform;
use crate::moving::{MovingObjects, MovingShape};
use crate::shutter::Shutter;
use ch01_whitted::camera::{CameraFrame, PinholeCamera};
use ch01_whitted::material::Material;
use ch01_whitted::scene::{Scene, World};
use common::Ray;
use common::geometry::SurfaceHit;
use glam::Mat4;

/// How many stretches of the shutter get their own BVH over the moving shapes by default.
pub const DEFAULT_STRETCHES: usize = 8;

/// Everything a motion-blurred render needs to know about the world.
pub struct MotionScene {
    /// The static shapes, the lights, the background, the camera at rest (or at the shutter's
    /// opening) and the materials: static shapes' first, then one per moving shape.
    pub scene: Scene,
    /// The moving shapes, bounded for [`shutter`](Self::shutter).
    pub moving: MovingObjects,
    /// The camera's motion (camera to world, Mitsuba's columns: left, up, forward, origin);
    /// `None` for a camera that stays where `scene.camera` is.
    pub camera_motion: Option<AnimatedTransform>,
    /// The shutter interval.
    pub shutter: Shutter,
}

impl MotionScene {
    /// `scene` with `moving` shapes (each with its material) added, seen through `shutter`.
    pub fn new(
        mut scene: Scene,
        moving: Vec<(MovingShape, Material)>,
        camera_motion: Option<AnimatedTransform>,
        shutter: Shutter,
    ) -> Self {
        let first_index = scene.materials.len() as u32;
        let (shapes, materials): (Vec<MovingShape>, Vec<Material>) = moving.into_iter().unzip();
        scene.materials.extend(materials);
        Self {
            scene,
            moving: MovingObjects::new(shapes, first_index, shutter, DEFAULT_STRETCHES),
            camera_motion,
            shutter,
        }
    }

    /// A scene without motion.
    pub fn still(scene: Scene) -> Self {
        Self::new(scene, Vec::new(), None, Shutter::INSTANT)
    }

    /// The same scene seen through another shutter, its motion bounds cut into `stretches`.
    pub fn with_shutter(mut self, shutter: Shutter, stretches: usize) -> Self {
        self.moving = self.moving.rebuilt(shutter, stretches);
        self.shutter = shutter;
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
        let camera = self.scene.camera.with_size(width, height);
        match &self.camera_motion {
            None => camera,
            Some(motion) => PinholeCamera {
                frame: frame_of(&motion.at(time)),
                ..camera
            },
        }
    }
}

/// The camera frame of a camera-to-world matrix (columns left, up, forward, origin).
pub fn frame_of(m: &Mat4) -> CameraFrame {
    CameraFrame {
        origin: m.w_axis.truncate(),
        left: m.x_axis.truncate().normalize(),
        up: m.y_axis.truncate().normalize(),
        forward: m.z_axis.truncate().normalize(),
    }
}

/// The camera-to-world matrix of a frame: the inverse of [`frame_of`].
pub fn matrix_of(frame: &CameraFrame) -> Mat4 {
    Mat4::from_cols(
        frame.left.extend(0.0),
        frame.up.extend(0.0),
        frame.forward.extend(0.0),
        frame.origin.extend(1.0),
    )
}

// ANCHOR: world
impl World for MotionScene {
    fn scene(&self) -> &Scene {
        &self.scene
    }

    #[inline]
    fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        let still = self.scene.geometry.intersect(ray);
        if self.moving.is_empty() {
            return still;
        }
        // Only a moving shape nearer than the static hit matters.
        let t_max = still.map_or(ray.t_max, |hit| hit.t);
        self.moving.intersect(&Ray { t_max, ..*ray }).or(still)
    }

    #[inline]
    fn occluded(&self, ray: &Ray) -> bool {
        self.scene.geometry.occluded(ray) || (!self.moving.is_empty() && self.moving.occluded(ray))
    }
}
// ANCHOR_END: world
