//! # Beyond the lecture: Mitsuba's materials
//!
//! Chapter 08's path loop takes its materials from outside (`ch08_path_tracing::Materials`):
//! it renders the lecture's own, and the chapters' ladder stands the lecture's mirror or
//! lobe in for a metal and refuses the rest. This crate gives the same loop every material a
//! Mitsuba 3 scene file may name, as pbrt-v4 keeps its `PathIntegrator` beside the
//! `SimplePathIntegrator` of the lecture:
//!
//! - [`bsdf`]: [`SceneMaterials`], the BSDF of every material at a hit (the lecture's
//!   delegated to chapter 08's), and Mitsuba's smooth ones, one module each: metals by their
//!   complex index of refraction ([`bsdf::conductor`]), plastic, a thin pane, tinted glass,
//!   masks;
//! - [`microfacet`]: Mitsuba 3's `roughconductor`, `roughdielectric` and `roughplastic`
//!   (Beckmann and GGX, visible-normal sampling), in the local frame;
//! - [`render_with`]: chapter 08's path tracer over them.
//!
//! The crate's workbench (its binary, the renderer for real scene files, the book's figures
//! of the microfacet models, agreement with Mitsuba 3 on scenes with its materials) is `lab`,
//! in the folder `lab/` beside `src/`, built with the `lab` feature.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bsdf;
pub mod microfacet;

#[cfg(feature = "lab")]
#[path = "../lab/mod.rs"]
pub mod lab;

pub use bsdf::{SceneBsdf, SceneMaterials};

use ch04_depth_of_field::Lens;
use ch05_motion_blur::{MotionScene, TimeSampler};
use ch08_path_tracing::{Method, render_with_materials};
use common::film::Filter;
use common::render::{RenderOutput, RenderSettings};

/// Path-traces `world` through `lens` with every material it names: chapter 08's
/// `render_with` over [`SceneMaterials`], whose tables are made here, before the threads
/// start. On a scene of the lecture's materials alone it is chapter 08's image, bit for bit.
pub fn render_with<S: TimeSampler>(
    world: &MotionScene,
    method: Method,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let materials = SceneMaterials::of(&world.scene, method.fuzz);
    render_with_materials(world, method, materials, lens, settings, sampler, filter)
}
