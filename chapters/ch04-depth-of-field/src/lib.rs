//! # Chapter 04: depth of field
//!
//! A pinhole camera sees everything sharp. A real camera has a lens with an opening of finite
//! size, and only one distance is in focus: nearer and farther things blur, the more the
//! larger the opening. This chapter replaces chapter 01's pinhole by a thin lens, and the one
//! ray per film position by an integral over the aperture, sampled at random.
//!
//! - [`lens`]: the thin lens: aperture radius (or focal length and f-number) and focus distance.
//! - [`aperture`]: the aperture's shape (disc or polygon) and how a uniform point of it is
//!   drawn; the naive disc warp, kept to show what it does wrong.
//! - [`thin_lens`]: the thin-lens camera, Mitsuba's `thinlens` sensor.
//! - [`circle_of_confusion`]: how large a point at another depth appears.
//! - [`scenes`]: what to look at.
//!
//! The chapter's workbench (its binary and lens options, the lens a scene file asks for, the
//! book's figures, agreement with Mitsuba 3) is `lab`, in the folder `lab/` beside `src/`,
//! built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod aperture;
pub mod circle_of_confusion;
pub mod lens;
pub mod scenes;
pub mod thin_lens;

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;

pub use aperture::{Aperture, LensWarp};
pub use lens::Lens;
pub use thin_lens::ThinLensCamera;

use ch01_whitted::camera::PinholeCamera;
use ch01_whitted::tracer;
use common::film::Filter;
use common::render::{self, RenderOutput, RenderSettings};
use common::sampler::Sampler;
use common::scene::Scene;

// ANCHOR: render_with
/// Renders `scene` through `lens`: pixel positions from `sampler` (its first dimension), then
/// the lens point from its next two; `filter` reconstructs the pixels. With a zero aperture
/// this is the pinhole render, bit for bit.
pub fn render_with<S: Sampler>(
    scene: &Scene,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let pinhole = PinholeCamera::of(&scene.camera, settings.width, settings.height);
    let camera = ThinLensCamera::new(pinhole, *lens);
    render::render(settings, sampler, filter, |p_film, sampler| {
        let ray = camera.generate_ray(p_film, sampler);
        tracer::trace(scene, &ray, 1)
    })
}
// ANCHOR_END: render_with
