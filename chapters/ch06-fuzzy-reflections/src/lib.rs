//! # Chapter 06: fuzzy reflections and refractions
//!
//! Chapter 01's mirror and glass are perfectly smooth: one reflected ray, one refracted ray,
//! every reflection sharp. Real surfaces are rough at a scale too small to see, and the light
//! they reflect comes from a spread of directions around the mirror direction. This chapter
//! samples that spread, one random direction per bounce, and asks at glass which of the two
//! rays to follow.
//!
//! - [`glass_choice`]: following both rays at glass, or one chosen at random with its weight.
//! - [`fuzz`]: spreading a direction: the empirical disc, and the `cos^n` lobe.
//! - [`below_surface`]: what to do with a spread ray that points into the surface.
//! - [`highlights`]: the point lights seen in a fuzzy mirror.
//! - [`lighting`]: the hook through which chapter 07 adds lights with an area.
//! - [`tracer`]: the recursive tracer with random choices.
//! - [`scenes`]: what to look at.
//!
//! The chapter's workbench (its binary and options, the book's figures, agreement with
//! Mitsuba 3) is `lab`, in the folder `lab/` beside `src/`, built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod below_surface;
pub mod furnace;
pub mod fuzz;
pub mod glass_choice;
pub mod highlights;
pub mod lighting;
pub mod scenes;
pub mod tracer;

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;

pub use below_surface::BelowSurface;
pub use fuzz::FuzzMethod;
pub use glass_choice::GlassStrategy;
pub use lighting::{Lighting, PointLights};
pub use tracer::{TraceOptions, Tracer};

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene, TimeSampler};
use common::film::Filter;
use common::render::{self, RenderOutput, RenderSettings};

// ANCHOR: render_with
/// Renders `world`, lit by `lighting`, through `lens`. Each sample draws, in order: the pixel
/// position (in the render loop), the time and the lens point (chapter 05's camera rays, each
/// only when the scene needs it), then the numbers of each bounce. A scene of smooth
/// materials traced with [`GlassStrategy::Both`] is chapter 05's render, bit for bit.
pub fn render_with<L: Lighting, S: TimeSampler>(
    world: &MotionScene,
    lighting: &L,
    options: TraceOptions,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let camera_rays = CameraRays::new(world, lens, settings.width, settings.height);
    let tracer = Tracer {
        world,
        lighting,
        options,
    };
    render::render(settings, sampler, filter, |p_film, sampler| {
        let ray = camera_rays.generate(world, p_film, sampler);
        tracer.trace(&ray, 1, sampler)
    })
}
// ANCHOR_END: render_with
