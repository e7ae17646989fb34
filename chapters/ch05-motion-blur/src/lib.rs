//! # Chapter 05: motion blur
//!
//! A real shutter stays open for a while, and whatever moves meanwhile is smeared along its
//! path. This chapter gives every camera ray a time, uniform over the shutter interval, and
//! follows its path through a world that answers each ray at its time, so the image becomes
//! the average of the world over the interval.
//!
//! - [`shutter`]: the interval and the time a uniform number picks; [`shutter_opening`]: a
//!   shutter that opens and closes over a fraction of the exposure.
//! - [`animated_transform`]: transforms between keyframes (translation, rotation and scale,
//!   each interpolated in its own way).
//! - [`object_space`]: intersecting a moving object by taking the ray into its own space.
//! - [`motion_bounds`]: boxes that hold a moving object over an interval.
//! - [`moving`]: moving shapes and the BVH over their motion bounds, per stretch of the
//!   shutter.
//! - [`world`]: the scene in motion, answering chapter 01's `World` questions at a ray's time.
//! - [`path`]: the tracer of the chapter's images, chapter 01's recursion through the world in
//!   motion, with one time for a whole path.
//! - [`time_sampling`]: independent and stratified time samples.
//! - [`scenes`]: what to look at.
//!
//! The chapter's workbench (its binary, a scene file's motion made ready, the setup every
//! `render` from this chapter on shares, the book's figures) is `lab`, in the folder `lab/`
//! beside `src/`, built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod animated_transform;
pub mod motion_bounds;
pub mod moving;
pub mod object_space;
pub mod path;
pub mod scenes;
pub mod shutter;
pub mod shutter_opening;
pub mod time_sampling;
pub mod world;

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;

pub use animated_transform::AnimatedTransform;
pub use moving::{MovingObjects, MovingShape};
pub use shutter::Shutter;
pub use time_sampling::{StratifiedTime, TimeSampler, TimeSampling};
pub use world::MotionScene;

use ch04_depth_of_field::{Lens, ThinLensCamera};
use common::film::Filter;
use common::render::{self, RenderOutput, RenderSettings};
use common::{Ray, Vec2};

// ANCHOR: render_with
/// Camera rays over a shutter interval: the time a sample draws, the camera where it is at
/// that time, the lens in front. Built once per render; chapter 06 builds its camera rays
/// with it too, so both chapters draw the same numbers in the same order.
#[derive(Clone, Copy, Debug)]
pub struct CameraRays {
    shutter: Shutter,
    draws_time: bool,
    camera_moves: bool,
    camera_at_open: ThinLensCamera,
    lens: Lens,
    width: u32,
    height: u32,
}

impl CameraRays {
    /// Camera rays of `world` through `lens` for an image of `width` by `height` pixels.
    pub fn new(world: &MotionScene, lens: &Lens, width: u32, height: u32) -> Self {
        let shutter = world.shutter;
        CameraRays {
            shutter,
            draws_time: !shutter.is_instant() && world.moves(),
            camera_moves: world.camera_motion.is_some(),
            camera_at_open: ThinLensCamera::new(
                world.camera_at(shutter.open, width, height),
                *lens,
            ),
            lens: *lens,
            width,
            height,
        }
    }

    /// The camera ray through film point `p_film`. Draws, in order: the time (only if the
    /// shutter is open for a while and something moves), then the lens point (only for an
    /// aperture). The ray carries its time.
    pub fn generate<S: TimeSampler>(
        &self,
        world: &MotionScene,
        p_film: Vec2,
        sampler: &mut S,
    ) -> Ray {
        let time = if self.draws_time {
            self.shutter.time_at(sampler.get_time_1d())
        } else {
            self.shutter.open
        };
        let moved;
        let camera = if self.camera_moves {
            moved = ThinLensCamera::new(world.camera_at(time, self.width, self.height), self.lens);
            &moved
        } else {
            &self.camera_at_open // borrowed, not copied: a still camera costs nothing here
        };
        camera.generate_ray(p_film, sampler).with_time(time)
    }
}

/// Renders `world` through `lens` over its shutter interval. Each sample draws, in order: the
/// pixel position (in the render loop), the time (only if the shutter is open for a while and
/// something moves), the lens point (only for an aperture). The path goes on through
/// [`path::trace_in_motion`]. Without motion this is chapter 04's render, bit for bit.
pub fn render_with<S: TimeSampler>(
    world: &MotionScene,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let camera_rays = CameraRays::new(world, lens, settings.width, settings.height);
    render::render(settings, sampler, filter, |p_film, sampler| {
        let ray = camera_rays.generate(world, p_film, sampler);
        path::trace_in_motion(world, &ray, 1)
    })
}
// ANCHOR_END: render_with
