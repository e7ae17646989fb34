//! # Chapter 08: combined effects and the path tracer
//!
//! Chapters 03 to 07 each added one dimension to the distribution: the pixel, the time, the
//! lens, the glossy lobe, the point on the light. Here they are combined into one estimator of
//! the rendering equation, the *path tracer*: a camera ray, then at every surface one
//! direction drawn from its BSDF, with the light sampled at every bounce and the two combined
//! by multiple importance sampling. Indirect diffuse light, which chapters 01 to 07 leave out,
//! is now simply one more bounce.
//!
//! - [`bsdf`]: every lecture material's sample, `f cos θ` and density, one module each, and
//!   the two traits through which the path loop takes its materials from outside.
//! - [`lights`]: area lights, point lights and the environment; every point light is
//!   connected, one of the others picked uniformly; [`environment`]: the constant environment
//!   and the environment map as one light.
//! - [`mis`]: the balance and the power heuristic; [`nee`]: the light sample, its MIS-weighted
//!   contribution, and the point and directional lights' shadow rays.
//! - [`roulette`]: Russian roulette; [`options`]: what is switched on.
//! - [`path`]: the path loop, generic over the materials it knows; [`render_with`].
//! - [`direct`]: Mitsuba's `direct` integrator (light and BSDF samples in other numbers than
//!   one of each), from the same light sample and BSDF step.
//! - [`dimensions`]: a sampler that counts the numbers each path draws, so that a scene is
//!   seen to pay only for what it uses.
//! - [`distribution_tracer`]: Cook's branching tracer with every effect, for comparison;
//!   [`render_distribution`].
//! - [`furnace`]: the white furnace.
//!
//! The chapter's workbench (its binary and options, a scene file's path options, the book's
//! figures, agreement with Mitsuba 3's `path`) is `lab`, in the folder `lab/` beside `src/`,
//! built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bsdf;
pub mod dimensions;
pub mod direct;
pub mod distribution_tracer;
pub mod environment;
pub mod furnace;
pub mod lights;
pub mod mis;
pub mod nee;
pub mod options;
pub mod path;
pub mod roulette;

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;

pub use bsdf::{Bsdf, BsdfSample, LectureMaterials, Materials, SurfaceBsdf};
pub use distribution_tracer::{DistributionOptions, DistributionTracer, render_distribution};
pub use lights::SceneLights;
pub use mis::MisHeuristic;
pub use options::PathOptions;
pub use path::PathTracer;

use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch05_motion_blur::{CameraRays, TimeSampler};
use ch06_fuzzy_reflections::FuzzMethod;
use ch07_soft_shadows::{AreaLights, LightSampling};
use common::film::Filter;
use common::render::{self, RenderOutput, RenderSettings};

/// Everything about a path-traced render besides the scene and the image settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Method {
    /// NEE, MIS, roulette, depth.
    pub options: PathOptions,
    /// How area lights are sampled (chapter 07).
    pub light_sampling: LightSampling,
    /// How fuzzy lobes spread (chapter 06).
    pub fuzz: FuzzMethod,
}

impl Method {
    /// `options` with Mitsuba's light sampling (spheres by solid angle) and the `cos^n` lobe.
    pub fn new(options: PathOptions) -> Self {
        Self {
            options,
            light_sampling: LightSampling::solid_angle(),
            fuzz: FuzzMethod::Lobe,
        }
    }
}

// ANCHOR: render_with
/// Path-traces `world` through `lens` with the lecture's materials. Each sample draws, in
/// order: the pixel position, the time and the lens point (chapter 05's camera rays, each only
/// when needed), then the numbers of each bounce (see [`path`]). The same seed gives the same
/// image on any number of threads.
pub fn render_with<S: TimeSampler>(
    world: &MotionScene,
    method: Method,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let materials = LectureMaterials { fuzz: method.fuzz };
    render_with_materials(world, method, materials, lens, settings, sampler, filter)
}
// ANCHOR_END: render_with

/// [`render_with`] with the materials given: the same loop over another set of materials
/// (their tables, if any, made before the threads start).
pub fn render_with_materials<S: TimeSampler, M: Materials>(
    world: &MotionScene,
    method: Method,
    materials: M,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let camera_rays = CameraRays::new(world, lens, settings.width, settings.height);
    let area_lights = AreaLights::of(&world.scene);
    let tracer = PathTracer {
        world,
        lights: SceneLights::of(world, &area_lights, method.light_sampling),
        options: method.options,
        materials,
    };
    render::render(settings, sampler, filter, |p_film, sampler| {
        let ray = camera_rays.generate(world, p_film, sampler);
        match method.options.direct {
            // Mitsuba's `direct` with other sample counts than one of each (beyond the lecture).
            Some(samples) => tracer.direct(&ray, samples, sampler),
            None => tracer.radiance(&ray, sampler),
        }
    })
}
