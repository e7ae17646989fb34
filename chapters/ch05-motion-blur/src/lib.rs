//! # Chapter 05: motion blur
//!
//! A real shutter stays open for a while, and whatever moves meanwhile is smeared along its
//! path. This chapter gives every camera ray a time, uniform over the shutter interval, and
//! keeps that time for every ray of its path, so the image becomes the average of the world
//! over the interval.
//!
//! - [`shutter`]: the interval and the time a uniform number picks.
//! - [`animated_transform`]: transforms between keyframes (translation, slerped rotation,
//!   scale).
//! - [`object_space`]: intersecting a moving object by taking the ray into its own space.
//! - [`motion_bounds`]: boxes that hold a moving object over an interval.
//! - [`moving`]: moving shapes and the BVH over their motion bounds, per stretch of the
//!   shutter.
//! - [`world`]: the scene in motion, traced by chapter 01's tracer through its `World` trait.
//! - [`time_sampling`]: independent and stratified time samples.
//! - [`scenes`], [`scene_file`]: what to look at; [`figures`]: the chapter's figures.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod animated_transform;
pub mod figures;
pub mod motion_bounds;
pub mod moving;
pub mod object_space;
pub mod scene_file;
pub mod scenes;
pub mod shutter;
pub mod time_sampling;
pub mod world;

pub use animated_transform::AnimatedTransform;
pub use moving::{MovingObjects, MovingShape};
pub use shutter::Shutter;
pub use time_sampling::{StratifiedTime, TimeSampler, TimeSampling};
pub use world::MotionScene;

use ch01_whitted::tracer;
use ch04_depth_of_field::{Lens, ThinLensCamera};
use common::film::Filter;
use common::render::{self, RenderOutput, RenderSettings};

// ANCHOR: render_with
/// Renders `world` through `lens` over its shutter interval. Each sample draws, in order: the
/// pixel position (in the render loop), the time (only if the shutter is open for a while and
/// something moves), the lens point (only for an aperture). Every ray of the path keeps the
/// camera ray's time. Without motion this is chapter 04's render, bit for bit.
pub fn render_with<S: TimeSampler>(
    world: &MotionScene,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let (width, height) = (settings.width, settings.height);
    let shutter = world.shutter;
    let draws_time = !shutter.is_instant() && world.moves();
    let camera_at_open = ThinLensCamera::new(world.camera_at(shutter.open, width, height), *lens);
    render::render(settings, sampler, filter, |p_film, sampler, counters| {
        let time = if draws_time {
            shutter.time_at(sampler.get_time_1d())
        } else {
            shutter.open
        };
        let camera = if world.camera_motion.is_some() {
            ThinLensCamera::new(world.camera_at(time, width, height), *lens)
        } else {
            camera_at_open
        };
        let ray = camera.generate_ray(p_film, sampler).with_time(time);
        tracer::trace(world, &ray, 1, counters)
    })
}
// ANCHOR_END: render_with
