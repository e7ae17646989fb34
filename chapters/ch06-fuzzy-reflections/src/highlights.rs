//! Highlights: what a fuzzy surface reflects of the point lights.
//!
//! A point light is a single direction, which no sampled reflection ray will ever hit. A
//! perfect mirror therefore never shows one (chapter 01), but a fuzzy mirror does: its lobe
//! has a density in every direction, so the light arriving from a point light's direction
//! `l` is reflected in the proportion the lobe's density `p(l)` per solid angle (around the
//! ideal direction) gives it. How much of the light's intensity `I` arrives from distance `r`,
//! and how much of it goes back towards the viewer, is the chapter's highlights exercise. The
//! result is the glossy highlight, a blurred image of the light, tight and bright for a large
//! exponent, wide and dim for a small one.

use crate::fuzz::FuzzMethod;
use ch01_whitted::world::World;
use common::geometry::SurfaceHit;
use glam::Vec3;

/// The lobe a surface scatters into: its ideal direction, its exponent, and the side of the
/// surface it leaves on.
#[derive(Clone, Copy, Debug)]
pub struct Lobe {
    /// The mirror or refracted direction the lobe is centred on.
    pub center: Vec3,
    /// The lobe's exponent; infinite for a smooth surface.
    pub exponent: f32,
    /// The unit normal on the side the scattered light leaves from.
    pub side: Vec3,
    /// How the lobe's directions are spread.
    pub method: FuzzMethod,
}

// ANCHOR: highlights
/// The radiance `lobe` scatters back along the incoming ray from every point light of the
/// scene that `hit` sees, at the shutter `time`, on the lobe's side of the surface (the
/// material's reflectance is applied by the caller). A light the lobe cannot send light from
/// needs no shadow ray, and a smooth lobe (an infinite exponent, a mirror) shows no point
/// light at all.
///
/// How much of a light's intensity arrives at the point, and what share of it does the lobe
/// send back along the ray?
pub fn point_light_highlights<W: World>(
    world: &W,
    hit: &SurfaceHit,
    lobe: &Lobe,
    time: f32,
) -> Vec3 {
    // BEGIN SOLUTION
    if !lobe.exponent.is_finite() {
        return Vec3::ZERO; // a mirror's lobe is a single direction: no highlight
    }
    let mut radiance = Vec3::ZERO;
    for light in &world.scene().point_lights {
        let to_light = light.position - hit.p;
        let distance_squared = to_light.length_squared();
        let l = to_light / distance_squared.sqrt();
        let cos_side = l.dot(lobe.side);
        // Written so that the NaN of a light sitting on the surface is skipped too.
        if cos_side.is_nan() || cos_side <= 0.0 {
            continue;
        }
        let density = lobe.method.pdf(l.dot(lobe.center), lobe.exponent);
        if density == 0.0 {
            continue; // outside the lobe: no shadow ray needed
        }
        if world.occluded(&hit.spawn_ray_to(light.position, time)) {
            continue;
        }
        radiance += density * light.intensity / distance_squared;
    }
    radiance
    // END SOLUTION
}
// ANCHOR_END: highlights
