//! Next-event estimation: at each bounce, a shadow ray to every point light and one to one
//! sampled light.
//!
//! The light sample estimates `∫ L_e f cos θ dω` by `L_e f cos θ / p_light`, weighted by MIS
//! against the BSDF sample that could have found the same light. A point light is a delta:
//! no BSDF sample can find it, so its weight is 1, and since there is nothing on it to
//! sample, [`point_lights`] counts every one of them with certainty.

use crate::bsdf::Bsdf;
use crate::lights::SceneLights;
use crate::mis::MisHeuristic;
use ch01_whitted::scene::World;
use common::render::SampleCounters;
use glam::Vec3;

// ANCHOR: light_sample_contribution
/// The contribution of one light sample, visibility aside: the radiance `emitted` arriving
/// along the sampled direction, times `f_cos` (`f cos θ` there), over the light's density
/// `light_pdf` (per solid angle, the pick of the light included), weighted by `mis` against
/// the density `bsdf_pdf` with which the BSDF would have sampled the same direction.
///
/// A delta light (`light_pdf` infinite: a point light, where `emitted` is already `I / d²`
/// and only the pick's `pick_probability` divides) takes weight 1. Anything with no chance,
/// or carrying nothing, is 0, never NaN.
#[inline]
pub fn light_sample_contribution(
    emitted: Vec3,
    f_cos: Vec3,
    light_pdf: f32,
    bsdf_pdf: f32,
    pick_probability: f32,
    mis: MisHeuristic,
) -> Vec3 {
    // BEGIN SOLUTION
    if light_pdf.is_infinite() {
        return emitted * f_cos / pick_probability;
    }
    if light_pdf.is_nan() || light_pdf <= 0.0 || emitted == Vec3::ZERO || f_cos == Vec3::ZERO {
        return Vec3::ZERO;
    }
    emitted * f_cos * (mis.weight(light_pdf, bsdf_pdf) / light_pdf)
    // END SOLUTION
}
// ANCHOR_END: light_sample_contribution

// ANCHOR: point_lights
/// The light of every point light at the surface of `bsdf`, seen from `wo`: one shadow ray
/// each at shutter time `time`, traced only where the light would add something. A point
/// light is a delta, so no number is drawn and no MIS weight is needed: each one is counted
/// with probability 1, as chapter 01 lights its matte surfaces.
#[inline]
pub fn point_lights<W: World>(
    world: &W,
    lights: &SceneLights,
    bsdf: &Bsdf,
    wo: Vec3,
    time: f32,
    counters: &mut SampleCounters,
) -> Vec3 {
    let mut sum = Vec3::ZERO;
    for light in lights.points {
        let to_light = light.position - bsdf.hit.p;
        let d2 = to_light.length_squared();
        let f_cos = bsdf.eval(wo, to_light / d2.sqrt());
        // A delta light: its density is infinite and only `I / d²` arrives.
        let contribution = light_sample_contribution(
            light.intensity / d2,
            f_cos,
            f32::INFINITY,
            0.0,
            1.0,
            MisHeuristic::None,
        );
        // `is_finite` also refuses a light on the surface itself (d = 0).
        if contribution == Vec3::ZERO || !contribution.is_finite() {
            continue; // behind the surface, or nowhere to come from: no shadow ray
        }
        counters.rays += 1;
        if !world.occluded(&bsdf.hit.spawn_ray_to(light.position, time)) {
            sum += contribution;
        }
    }
    sum
}
// ANCHOR_END: point_lights

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exercise_light_sample_contribution_weights_and_divides() {
        let (le, f) = (Vec3::new(2.0, 4.0, 8.0), Vec3::splat(0.25));
        // Plain NEE: L f / p.
        let c = light_sample_contribution(le, f, 0.5, 3.0, 1.0, MisHeuristic::None);
        assert!(
            (c - Vec3::new(1.0, 2.0, 4.0)).abs().max_element() < 1e-6,
            "{c}"
        );
        // Power heuristic with p_light = 1, p_bsdf = 1: half of it.
        let c = light_sample_contribution(le, f, 1.0, 1.0, 1.0, MisHeuristic::Power);
        assert!(
            (c - Vec3::new(0.25, 0.5, 1.0)).abs().max_element() < 1e-6,
            "{c}"
        );
        // Balance with p_light = 1, p_bsdf = 3: a quarter.
        let c = light_sample_contribution(le, f, 1.0, 3.0, 1.0, MisHeuristic::Balance);
        assert!(
            (c - Vec3::new(0.125, 0.25, 0.5)).abs().max_element() < 1e-6,
            "{c}"
        );
        // A point light picked with probability 1/4: weight 1, times 4.
        let c = light_sample_contribution(le, f, f32::INFINITY, 5.0, 0.25, MisHeuristic::Power);
        assert!(
            (c - Vec3::new(2.0, 4.0, 8.0)).abs().max_element() < 1e-6,
            "{c}"
        );
        // Nothing to divide by, nothing emitted: 0, not NaN.
        assert_eq!(
            light_sample_contribution(le, f, 0.0, 1.0, 1.0, MisHeuristic::Power),
            Vec3::ZERO
        );
        assert_eq!(
            light_sample_contribution(Vec3::ZERO, f, 0.0, 0.0, 1.0, MisHeuristic::Balance),
            Vec3::ZERO
        );
    }
}
