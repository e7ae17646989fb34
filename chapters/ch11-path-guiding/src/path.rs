//! The guided path tracer: chapter 08's path, its directions drawn from the BSDF and the guide
//! together, and, while training, what each vertex saw recorded for the guide to learn.
//!
//! [`GuidedPathTracer::radiance`] is chapter 08's loop, segment after segment, with two
//! changes. At a surface the BSDF is mixed with the guide of the surface's region
//! ([`GuidedBsdf`]), and the light sample and the BSDF step, chapter 08's own, take the mixture
//! as they take any BSDF. And while training, each vertex that drew a direction by density
//! (not a delta) is remembered; when the path ends, all it brought back after the vertex,
//! over what it carried from there on, estimates the light that arrived along that
//! direction, and the vertex's [`VertexRecord`] becomes one record for its guide
//! ([`GuidingTarget::recorded_value`]) and, where the BSDF and the guide were mixed, one sample
//! for learning the region's BSDF fraction ([`crate::selection`]).
//!
//! Random numbers per bounce: the light sample's, as in chapter 08, then, where a guide is
//! mixed in, one for the choice and the BSDF's numbers or the guide's two, then the roulette's.
//! Without a guide anywhere (guiding off, or the first training iteration) the path draws
//! exactly chapter 08's numbers and gives exactly its radiance.

use crate::directions::point_of;
use crate::guided_bsdf::{GuidedBsdf, MixtureSample};
use crate::selection::{self, FractionSample};
use crate::spatial::SpatialTree;
use crate::target::{GuidingTarget, VertexRecord};
use ch01_whitted::world::World;
use ch08_path_tracing::roulette::russian_roulette;
use ch08_path_tracing::{Materials, PathTracer, SurfaceBsdf};
use common::Ray;
use common::sampler::Sampler;
use common::scene::DirectSamples;
use glam::{Vec2, Vec3};

/// One record for a guide: the value a vertex adds at the point of its direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GuideRecord {
    /// The guide of the vertex's region ([`SpatialTree::guides`]).
    pub guide: u32,
    /// The direction, as a point of the unit square.
    pub point: Vec2,
    /// The value ([`GuidingTarget::recorded_value`]).
    pub value: f32,
    /// What it says on the guide's BSDF fraction, if the direction came from a mixture whose
    /// fraction is learnt.
    pub fraction: Option<FractionSample>,
}

/// What a training path learns with, and where its records go.
pub struct Learning<'r> {
    /// What the guides follow.
    pub target: GuidingTarget,
    /// The estimate of the path's pixel from the iteration before.
    pub pixel_estimate: f32,
    /// The records, in the order the vertices were met, path after path.
    pub records: &'r mut Vec<GuideRecord>,
}

/// A path tracer whose directions are guided.
pub struct GuidedPathTracer<'a, M: Materials> {
    /// Chapter 08's tracer: the scene, its lights, the options, the materials.
    pub tracer: &'a PathTracer<'a, M>,
    /// The guides, region by region.
    pub guides: &'a SpatialTree,
    /// The probability of drawing a direction from the BSDF rather than the guide; `None`:
    /// each region's learnt fraction.
    pub bsdf_fraction: Option<f32>,
}

/// A vertex of a training path, until the path ends.
struct PendingVertex {
    guide: u32,
    /// The direction, as a point of the unit square.
    point: Vec2,
    /// What the path carried to the vertex, and after its bounce.
    throughput_before: Vec3,
    throughput_after: Vec3,
    f_cos: Vec3,
    pdf: f32,
    /// The path's radiance before anything found after the vertex, and the light its own
    /// ray found directly, which is left to the light sample (see `radiance`).
    radiance_before: Vec3,
    /// The segment the vertex ends.
    depth: u32,
    /// The BSDF's and the guide's densities of the direction and the fraction it was drawn
    /// with, if they were mixed with a fraction being learnt.
    mixture: Option<(f32, f32, f32)>,
}

/// Leaves out of what the vertex of the segment before `depth` learns the light `found`
/// directly by its ray: with the light sample on, direct light is the light sample's to find,
/// and a guide taught it would spend its directions on what is already well sampled (Müller
/// et al. guide towards indirect light only).
fn leave_direct_light(vertices: &mut [PendingVertex], depth: u32, found: Vec3) {
    if let Some(v) = vertices.last_mut().filter(|v| v.depth + 1 == depth) {
        v.radiance_before += found;
    }
}

impl<M: Materials> GuidedPathTracer<'_, M> {
    // ANCHOR: radiance
    /// The radiance arriving along `camera_ray`, one guided path (see the module's opening);
    /// with `learning`, the path's records are pushed to it when the path ends.
    pub fn radiance<S: Sampler>(
        &self,
        camera_ray: &Ray,
        sampler: &mut S,
        learning: Option<Learning<'_>>,
    ) -> Vec3 {
        let (tracer, options) = (self.tracer, &self.tracer.options);
        let mut ray = tracer.past_hidden_emitters(camera_ray);
        let mut radiance = Vec3::ZERO;
        let (mut throughput, mut eta_scale) = (Vec3::ONE, 1.0);
        let (mut previous_p, mut previous_pdf) = (ray.origin, f32::INFINITY);
        let mut vertices: Vec<PendingVertex> = Vec::new();
        for depth in 1.. {
            let weighed = options.nee && previous_pdf.is_finite();
            let shown = depth > 1 || !options.hide_emitters;

            // 1. The surface, or the environment.
            let Some(hit) = tracer.world.intersect(&ray) else {
                if shown && tracer.lights.has_environment() {
                    let weight = if weighed {
                        let light_pdf = tracer.lights.environment_pdf(ray.dir);
                        options.mis.bsdf_sample_weight(previous_pdf, light_pdf)
                    } else {
                        1.0
                    };
                    let found = throughput * (tracer.lights.environment.radiance(ray.dir) * weight);
                    radiance += found;
                    if options.nee {
                        leave_direct_light(&mut vertices, depth, found);
                    }
                }
                break;
            };

            // 2. What the surface emits, weighed against the light sample that could find it.
            if shown
                && tracer.lights.has_area_lights()
                && let Some(light) = tracer.lights.area_light_of(hit.shape)
            {
                let le = tracer
                    .lights
                    .emitted(light, hit.shape, hit.n, || Some(hit.uv), -ray.dir);
                if le != Vec3::ZERO {
                    let weight = if weighed {
                        let light_pdf = tracer.lights.area_pdf(light, previous_p, hit.p, hit.n);
                        options.mis.bsdf_sample_weight(previous_pdf, light_pdf)
                    } else {
                        1.0
                    };
                    let found = throughput * (le * weight);
                    radiance += found;
                    if options.nee {
                        leave_direct_light(&mut vertices, depth, found);
                    }
                }
            }

            // 3. The depth.
            if depth >= options.max_depth {
                break;
            }
            let material = tracer.world.material_at(&hit);
            let guide = self.guides.guide_of(hit.p);
            let region = &self.guides.guides[guide as usize];
            let fraction = self
                .bsdf_fraction
                .unwrap_or_else(|| region.fraction.fraction());
            let bsdf = GuidedBsdf::new(
                tracer.materials.bsdf(&material, &hit),
                Some(&region.sampling),
                fraction,
            );
            let wo = -ray.dir;

            // 4. The light sample, its MIS weight against the mixture's density.
            if options.nee && !bsdf.is_delta() {
                let mut direct = Vec3::ZERO;
                if tracer.lights.has_delta_lights() {
                    direct += tracer.delta_lights(&bsdf, wo, ray.time);
                }
                if tracer.lights.can_be_hit() {
                    direct +=
                        tracer.light_sample(&bsdf, wo, ray.time, DirectSamples::ONE_EACH, sampler);
                }
                radiance += throughput * direct;
            }
            if depth + 1 >= options.max_depth && !tracer.lights.can_be_hit() {
                break;
            }

            // 5. The next direction, from the BSDF and the guide: chapter 08's BSDF step
            // (`extend_path`), keeping what the mixture knew of the direction for the records.
            let throughput_before = throughput;
            let Some(MixtureSample { sample, mixed }) = bsdf.sample_mixture(wo, sampler) else {
                break;
            };
            throughput *= sample.weight;
            eta_scale *= sample.eta_scale;
            if throughput == Vec3::ZERO {
                break;
            }
            if learning.is_some() && !sample.is_delta() {
                let mixture = match self.bsdf_fraction {
                    Some(_) => None,
                    None => mixed.map(|m| (m.bsdf_pdf, m.guide_pdf, fraction)),
                };
                vertices.push(PendingVertex {
                    guide,
                    point: mixed.map_or_else(|| point_of(sample.wi), |m| m.point),
                    throughput_before,
                    throughput_after: throughput,
                    f_cos: sample.weight * sample.pdf,
                    pdf: sample.pdf,
                    radiance_before: radiance,
                    depth,
                    mixture,
                });
            }
            (previous_p, previous_pdf) = (hit.p, sample.pdf);
            ray = hit.spawn_ray(sample.wi, ray.time);

            // 6. Russian roulette.
            if let Some(rr_depth) = options.rr_depth
                && depth >= rr_depth
            {
                let throughput_max = throughput.max_element() / eta_scale;
                let Some(survivor) = russian_roulette(throughput_max, sampler.get_1d()) else {
                    break;
                };
                throughput *= survivor;
            }
        }

        // The path has ended: what it brought back after each vertex, over what it carried
        // from there, is the light that arrived along the vertex's direction.
        if let Some(learning) = learning {
            let loss = selection::loss_of(learning.target);
            for v in &vertices {
                let after = radiance - v.radiance_before;
                let carried = v.throughput_after;
                let incident = Vec3::select(carried.cmpgt(Vec3::ZERO), after / carried, Vec3::ZERO);
                let record = VertexRecord {
                    incident,
                    throughput: v.throughput_before,
                    f_cos: v.f_cos,
                    pdf: v.pdf,
                    pixel_estimate: learning.pixel_estimate,
                };
                let fraction = v.mixture.map(|(bsdf_pdf, guide_pdf, drawn_with)| {
                    let integrand = selection::integrand(
                        loss,
                        v.throughput_before,
                        v.f_cos,
                        incident,
                        learning.pixel_estimate,
                    );
                    FractionSample {
                        integrand,
                        bsdf_pdf,
                        guide_pdf,
                        drawn_with,
                    }
                });
                learning.records.push(GuideRecord {
                    guide: v.guide,
                    point: v.point,
                    value: learning.target.recorded_value(&record),
                    fraction,
                });
            }
        }
        radiance
    }
    // ANCHOR_END: radiance
}
