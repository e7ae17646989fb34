//! # Beyond the lecture: path guiding
//!
//! Chapter 08's path draws each bounce's direction from the BSDF: where the light that
//! matters arrives through a small opening, a door ajar, a lamp seen through its shade, most
//! directions find nothing, and the rest of the path is spent on them. The light sample helps
//! only when the opening is the light itself. Path guiding learns, while rendering, where the
//! light arrives from at each region of the scene, and draws directions from that as well.
//!
//! Müller, Gross and Novák (*Practical Path Guiding for Efficient Light-Transport
//! Simulation*, EGSR 2017) store what they learn in a binary tree over space whose leaves hold
//! quadtrees over directions, and train it over iterations of doubling sample counts; Rath,
//! Grittmann, Herholz, Vévoda, Slusallek and Křivánek (*Variance-Aware Path Guiding*,
//! SIGGRAPH 2020) changed what it learns, from the light arriving to the square root of the
//! second moment of the pixel's estimate, the density that makes the pixel's variance
//! smallest.
//!
//! - [`directions`]: the sphere of directions as the unit square, area for area;
//! - [`quadtree`]: the directional quadtree, its sampling and its density, its rebuilding;
//! - [`spatial`]: the binary tree over space whose leaves hold the guides;
//! - [`guided_bsdf`]: the BSDF and the guide sampled as one mixture;
//! - [`selection`]: how often each region asks the BSDF rather than its guide, learnt;
//! - [`target`]: what a vertex records, towards the light or towards the pixel's variance;
//! - [`path`]: chapter 08's path with guided directions, recording while it trains;
//! - [`training`]: the iterations, the budget split between training and the final image;
//! - [`combine`]: the training's images kept, averaged with the final one by their noise.
//!
//! The crate's workbench (its binary, `render --guiding off|radiance|variance`, and the
//! figures) is `lab`, in the folder `lab/` beside `src/`, built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod combine;
pub mod directions;
pub mod guided_bsdf;
#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;
pub mod path;
pub mod quadtree;
pub mod selection;
pub mod spatial;
pub mod target;
pub mod training;

pub use combine::PassWeighting;
pub use path::GuidedPathTracer;
pub use target::GuidingTarget;
pub use training::{GuidingOptions, Trained, TrainingIteration};

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{CameraRays, MotionScene, TimeSampler};
use ch07_soft_shadows::{AreaLights, LightSampling};
use ch08_path_tracing::{Materials, PathOptions, PathTracer, SceneLights};
use common::film::Filter;
use common::image::Image;
use common::render::{self, Budget, RenderOutput, RenderSettings, RenderStats, Totals};
use std::time::Instant;

/// A guided render: its image, and what the training before it learnt and cost.
#[derive(Clone, Debug)]
pub struct GuidedRender {
    /// The image: the training's and the final pass's averaged as
    /// [`GuidingOptions::passes`] says ([`combine`]) when the film's filter is a box of one
    /// pixel and no stop cut the final pass short; else the final pass's alone. Its
    /// statistics count the whole render, training included (seconds and rays), and its
    /// samples per pixel are those of the passes it averages.
    pub output: RenderOutput,
    /// The training; `None` when guiding is off.
    pub training: Option<Trained>,
    /// The weight of each pass in the image, the training's iterations then the final pass;
    /// empty when the final pass alone makes it.
    pub pass_weights: Vec<f64>,
}

// ANCHOR: render_guided
/// Path-traces `world` through `lens` with `materials` and chapter 08's `options`, guided as
/// `guiding` says (`None`: chapter 08's own render, every sample of the budget in its image).
/// With guiding, the budget in `settings` pays for the training and the final pass together
/// ([`training`]). The same seed gives the same image on any number of threads.
#[allow(clippy::too_many_arguments)]
pub fn render_guided<S: TimeSampler, M: Materials>(
    world: &MotionScene,
    materials: M,
    options: PathOptions,
    guiding: Option<GuidingOptions>,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> GuidedRender {
    let start = Instant::now();
    let camera_rays = CameraRays::new(world, lens, settings.width, settings.height);
    let area_lights = AreaLights::of(&world.scene);
    let tracer = PathTracer {
        world,
        lights: SceneLights::of(world, &area_lights, LightSampling::solid_angle()),
        options,
        materials,
    };
    let Some(guiding) = guiding else {
        let output = render::render(settings, sampler, filter, |p_film, sampler| {
            tracer.radiance(&camera_rays.generate(world, p_film, sampler), sampler)
        });
        return GuidedRender {
            output,
            training: None,
            pass_weights: Vec::new(),
        };
    };

    // Training: iterations of doubling samples, each learning from its own paths.
    let bounds = world.scene.geometry.bounds();
    let camera_ray = |p_film, sampler: &mut _| camera_rays.generate(world, p_film, sampler);
    let trained = training::train(settings, sampler, guiding, bounds, &tracer, camera_ray);

    // Stopped while training: the image is the last iteration completed (each is unbiased),
    // or none.
    if trained.interrupted {
        return stopped_in_training(settings, start, trained);
    }

    // The final pass: guided by what was learnt, recording nothing, with what is left of the
    // budget and sample indices after the training's.
    let mut final_settings = settings.clone();
    final_settings.budget = match settings.budget {
        Budget::Samples(total) => Budget::Samples(total.saturating_sub(trained.spp).max(1)),
        Budget::Seconds(total) => Budget::Seconds(total - start.elapsed().as_secs_f64()),
    };
    let guided = GuidedPathTracer {
        tracer: &tracer,
        guides: &trained.guides,
        bsdf_fraction: guiding.bsdf_fraction,
    };
    let offset = training::Offset {
        inner: sampler.clone(),
        first_index: trained.spp,
    };
    let mut output = render::render(&final_settings, &offset, filter, |p_film, sampler| {
        let ray = camera_rays.generate(world, p_film, sampler);
        guided.radiance(&ray, sampler, None)
    });
    // The training's images are kept, averaged with the final pass's (by weights fixed in
    // advance unless asked otherwise), when they are means of the same kind.
    let mut pass_weights = Vec::new();
    if guiding.passes != PassWeighting::FinalOnly
        && combine::makes_pixel_means(filter)
        && !output.stats.interrupted
    {
        let passes: Vec<combine::Pass<'_>> = trained
            .images
            .iter()
            .zip(&trained.iterations)
            .map(|(image, i)| combine::Pass { image, spp: i.spp })
            .chain(std::iter::once(combine::Pass {
                image: &output.image,
                spp: output.stats.spp,
            }))
            .collect();
        pass_weights = match guiding.passes {
            PassWeighting::ByMeasuredNoise => combine::inverse_variance_weights(&passes),
            PassWeighting::ByLearning => combine::learning_weights(&passes),
            _ => combine::sample_count_weights(&passes),
        };
        output.image = combine::combine(&passes, &pass_weights);
    }
    // The statistics count the whole render, training included: its time, samples and rays
    // (and so their rates); the samples per pixel are the image's.
    let pixels = u64::from(settings.width) * u64::from(settings.height);
    let training = Totals {
        rays: trained.iterations.iter().map(|i| i.rays).sum(),
        samples: trained.spp * pixels,
        nonfinite_samples: trained.iterations.iter().map(|i| i.nonfinite_samples).sum(),
    };
    let mut totals = Totals {
        rays: output.stats.rays,
        samples: output.stats.samples,
        nonfinite_samples: output.stats.nonfinite_samples,
    };
    totals.add(&training);
    let spp = output.stats.spp
        + if pass_weights.is_empty() {
            0
        } else {
            trained.spp
        };
    let seconds = start.elapsed().as_secs_f64();
    output.stats = RenderStats::new(settings, spp, output.stats.interrupted, seconds, &totals);
    GuidedRender {
        output,
        training: Some(trained),
        pass_weights,
    }
}
// ANCHOR_END: render_guided

/// A render stopped during its training: the image of the last iteration completed (its
/// samples per pixel the image's), black with none.
fn stopped_in_training(
    settings: &RenderSettings,
    start: Instant,
    trained: Trained,
) -> GuidedRender {
    let last = trained.iterations.last();
    let spp = last.map_or(0, |i| i.spp);
    let totals = Totals {
        rays: trained.iterations.iter().map(|i| i.rays).sum(),
        samples: spp * u64::from(settings.width) * u64::from(settings.height),
        nonfinite_samples: last.map_or(0, |i| i.nonfinite_samples),
    };
    let seconds = start.elapsed().as_secs_f64();
    let stats = RenderStats::new(settings, spp, true, seconds, &totals);
    let image = trained
        .images
        .last()
        .cloned()
        .unwrap_or_else(|| Image::new(settings.width, settings.height));
    GuidedRender {
        output: RenderOutput { image, stats },
        training: Some(trained),
        pass_weights: Vec::new(),
    }
}
