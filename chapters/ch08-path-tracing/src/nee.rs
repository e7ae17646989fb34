//! Next-event estimation: at each bounce, a shadow ray to every point light (and every
//! directional light) and one to one sampled light.
//!
//! The light sample estimates `∫ L_e f cos θ dω` by `L_e f cos θ / p_light`, weighted by MIS
//! against the BSDF sample that could have found the same light. A point light is a delta:
//! no BSDF sample can find it, so its weight is 1, and since there is nothing on it to
//! sample, [`point_lights`] counts every one of them with certainty.

use crate::bsdf::Bsdf;
use crate::lights::SceneLights;
use crate::mis::MisHeuristic;
use ch01_whitted::world::World;
use common::render::SampleCounters;
use glam::Vec3;

// ANCHOR: light_sample_contribution
/// The contribution of one light sample, visibility aside, for the radiance `emitted` arriving
/// along the sampled direction, `f_cos` (`f cos θ` there), the light's density `light_pdf`
/// (per solid angle, the pick of the light included), and the density `bsdf_pdf` with which
/// the BSDF would have sampled the same direction, combined by the heuristic `mis`.
///
/// A delta light (`light_pdf` infinite: a point light, where `emitted` is already `I / d²`,
/// picked with probability `pick_probability`) cannot be found by the BSDF. Anything with no
/// chance (a density of 0, or NaN), or carrying nothing, is 0, never NaN.
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

/// The light of every directional light (the sun's model, infinitely far away) at the surface
/// of `bsdf`, seen from `wo`: like a point light, a delta counted with certainty through one
/// shadow ray, but from one direction everywhere and with no fall-off: its irradiance on a
/// surface facing it. The shadow ray leaves the scene unbounded.
#[inline]
pub fn directional_lights<W: World>(
    world: &W,
    lights: &SceneLights,
    bsdf: &Bsdf,
    wo: Vec3,
    time: f32,
    counters: &mut SampleCounters,
) -> Vec3 {
    let mut sum = Vec3::ZERO;
    for light in lights.directionals {
        let wi = -light.direction;
        let contribution = light_sample_contribution(
            light.irradiance,
            bsdf.eval(wo, wi),
            f32::INFINITY,
            0.0,
            1.0,
            MisHeuristic::None,
        );
        if contribution == Vec3::ZERO || !contribution.is_finite() {
            continue; // behind the surface: no shadow ray
        }
        counters.rays += 1;
        if !world.occluded(&bsdf.hit.spawn_ray(wi, time)) {
            sum += contribution;
        }
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exercise_light_sample_contribution_weights_and_divides() {
        let (le, f) = (Vec3::new(2.0, 4.0, 8.0), Vec3::splat(0.25));
        // (light pdf, BSDF pdf, pick probability, heuristic, expected, what the case shows)
        let cases = [
            (
                0.5,
                3.0,
                1.0,
                MisHeuristic::None,
                Vec3::new(1.0, 2.0, 4.0),
                "plain NEE: L f cos / p_light",
            ),
            (
                1.0,
                1.0,
                1.0,
                MisHeuristic::Power,
                Vec3::new(0.25, 0.5, 1.0),
                "equal densities share the sample: the power weight is 1/2",
            ),
            (
                1.0,
                3.0,
                1.0,
                MisHeuristic::Balance,
                Vec3::new(0.125, 0.25, 0.5),
                "the balance weight of p_light = 1 against p_bsdf = 3 is 1/4",
            ),
            (
                2.0,
                1.0,
                1.0,
                MisHeuristic::Power,
                Vec3::new(0.2, 0.4, 0.8),
                "the weight is the light strategy's, p_light against p_bsdf (here 4/5), not the BSDF's",
            ),
            (
                f32::INFINITY,
                5.0,
                0.25,
                MisHeuristic::Power,
                Vec3::new(2.0, 4.0, 8.0),
                "a point light (infinite density) takes weight 1 and is divided only by the chance of picking it",
            ),
            (
                0.5,
                3.0,
                0.25,
                MisHeuristic::None,
                Vec3::new(1.0, 2.0, 4.0),
                "the light's density already holds the chance of picking the light: only a delta light, which has no density, is divided by that chance",
            ),
        ];
        for (light_pdf, bsdf_pdf, pick, mis, expected, why) in cases {
            let c = light_sample_contribution(le, f, light_pdf, bsdf_pdf, pick, mis);
            if (c - expected).abs().max_element() < 1e-6 {
                continue;
            }
            let unweighted = le * f / light_pdf;
            let mistake = if light_pdf.is_finite()
                && (c - unweighted).abs().max_element() < 1e-6
                && mis != MisHeuristic::None
            {
                "the MIS weight is missing".to_string()
            } else if light_pdf.is_finite()
                && (c - le * f * mis.weight(bsdf_pdf, light_pdf) / light_pdf)
                    .abs()
                    .max_element()
                    < 1e-6
            {
                "the weight is the BSDF strategy's: this sample came from the light, so its \
                 weight is the light's density against the BSDF's"
                    .to_string()
            } else if light_pdf.is_finite()
                && pick < 1.0
                && (c * pick - expected).abs().max_element() < 1e-6
            {
                "divided by the chance of picking the light twice: the light's density already \
                 holds it"
                    .to_string()
            } else if !c.is_finite() {
                format!("{c} is not finite")
            } else {
                why.to_string()
            };
            panic!(
                "light_sample_contribution: {mistake}.\n  L = {le}, f cos = {f}, p_light = \
                 {light_pdf}, p_bsdf = {bsdf_pdf}, pick {pick}, {mis:?}: yours gave {c}, \
                 expected {expected} ({why})"
            );
        }
        // Nothing to divide by, nothing emitted: 0, not NaN.
        for (emitted, light_pdf, bsdf_pdf, mis) in [
            (le, 0.0, 1.0, MisHeuristic::Power),
            (Vec3::ZERO, 0.0, 0.0, MisHeuristic::Balance),
            (le, f32::NAN, 1.0, MisHeuristic::Power),
        ] {
            let c = light_sample_contribution(emitted, f, light_pdf, bsdf_pdf, 1.0, mis);
            assert!(
                c == Vec3::ZERO,
                "light_sample_contribution: a sample the light could not have drawn (density \
                 {light_pdf}) or that carries nothing contributes 0, never NaN or infinity; \
                 L = {emitted}, p_bsdf = {bsdf_pdf} gave {c}"
            );
        }
    }
}
