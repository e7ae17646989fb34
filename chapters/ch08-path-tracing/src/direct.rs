//! Mitsuba's `direct` integrator with its sample counts: `emitter_samples` light samples and
//! `bsdf_samples` BSDF samples at the surface the camera sees, and nothing after.
//!
//! With one of each it is the path tracer stopped after its first bounce, and the chapter
//! renders it that way ([`PathTracer::radiance`] with `max_depth` 2). Other counts change how
//! the two strategies share the work. With `n_l` light samples and `n_b` BSDF samples, each
//! strategy's density enters the heuristic together with its count (Veach's multi-sample
//! model), and each sample's estimate is divided by the count of its kind. The light samples
//! are the path tracer's own ([`PathTracer::light_sample`], given the counts). A count of 0
//! leaves the other strategy alone, with weight 1: `emitter_samples` 0 is pure
//! BSDF sampling, `bsdf_samples` 0 pure light sampling.
//!
//! Point lights, which no BSDF sample can find, are connected once per hit whenever there
//! are light samples, as the path tracer does ([`PathTracer::delta_lights`]), and counted
//! `emitter_samples` times. That is Mitsuba 3's image, not the physical one: Mitsuba picks a
//! point light among its other emitters and weighs each pick of it by 1 where any other
//! light sample is weighed by `1 / emitter_samples`, so its point lights come out
//! `emitter_samples` times too bright (measured with Mitsuba 3.9.1: a plane under one point
//! light, 4 emitter samples, 4.00 times as bright as with 1). Scene files written for Mitsuba
//! are lit for what Mitsuba shows, so the workbook shows the same; with one emitter sample,
//! the default, the two agree with physics.

use crate::bsdf::{Materials, SurfaceBsdf};
use crate::path::PathTracer;
use ch01_whitted::world::World;
use common::Ray;
use common::sampler::Sampler;
use common::scene::DirectSamples;
use glam::Vec3;

impl<M: Materials> PathTracer<'_, M> {
    /// The radiance arriving along `camera_ray` by Mitsuba's `direct` integrator with
    /// `samples`: what the surface it meets emits, and the light reaching that surface
    /// straight from the lights, estimated by both strategies (see the module).
    pub fn direct<S: Sampler>(
        &self,
        camera_ray: &Ray,
        samples: DirectSamples,
        sampler: &mut S,
    ) -> Vec3 {
        let ray = self.past_hidden_emitters(camera_ray);
        let shown = !self.options.hide_emitters;
        let Some(hit) = self.world.intersect(&ray) else {
            return if shown {
                self.lights.environment.radiance(ray.dir)
            } else {
                Vec3::ZERO
            };
        };
        let mut radiance = Vec3::ZERO;
        if shown && let Some(light) = self.lights.area_light_of(hit.shape) {
            radiance += self
                .lights
                .emitted(light, hit.shape, hit.n, || Some(hit.uv), -ray.dir);
        }
        let material = self.world.material_at(&hit);
        let bsdf = self.materials.bsdf(&material, &hit);
        let wo = -ray.dir;
        let counts = DirectSamples {
            emitter: if self.options.nee { samples.emitter } else { 0 },
            bsdf: samples.bsdf,
        };
        if counts.emitter > 0 && !bsdf.is_delta() {
            if self.lights.has_delta_lights() {
                // Mitsuba's count, `emitter_samples` times (see the module).
                let mitsuba_count = counts.emitter as f32;
                radiance += mitsuba_count * self.delta_lights(&bsdf, wo, ray.time);
            }
            if self.lights.can_be_hit() {
                for _ in 0..counts.emitter {
                    radiance += self.light_sample(&bsdf, wo, ray.time, counts, sampler);
                }
            }
        }
        for _ in 0..counts.bsdf {
            radiance += self.counted_bsdf_sample(&bsdf, wo, ray.time, counts, sampler);
        }
        radiance
    }

    /// One of `counts.bsdf` BSDF samples at the surface of `bsdf`: the light its ray finds
    /// (a glowing surface or the environment), weighed against the `counts.emitter` light
    /// samples and divided by its own count.
    fn counted_bsdf_sample<S: Sampler>(
        &self,
        bsdf: &impl SurfaceBsdf,
        wo: Vec3,
        time: f32,
        counts: DirectSamples,
        sampler: &mut S,
    ) -> Vec3 {
        let Some(sample) = bsdf.sample(wo, sampler) else {
            return Vec3::ZERO;
        };
        let (emitted, light_pdf) = match self
            .world
            .intersect(&bsdf.hit().spawn_ray(sample.wi, time))
        {
            Some(found) => match self.lights.area_light_of(found.shape) {
                Some(light) => (
                    self.lights
                        .emitted(light, found.shape, found.n, || Some(found.uv), -sample.wi),
                    self.lights.area_pdf(light, bsdf.hit().p, found.p, found.n),
                ),
                None => return Vec3::ZERO,
            },
            None if self.lights.has_environment() => (
                self.lights.environment.radiance(sample.wi),
                self.lights.environment_pdf(sample.wi),
            ),
            None => return Vec3::ZERO,
        };
        // A delta direction no light sample could have drawn, and no light samples at all,
        // leave the BSDF sample alone; otherwise the heuristic shares the light.
        let (n_light, n_bsdf) = (counts.emitter as f32, counts.bsdf as f32);
        let weight = if sample.is_delta() || counts.emitter == 0 {
            1.0
        } else {
            self.options
                .mis
                .bsdf_sample_weight(n_bsdf * sample.pdf, n_light * light_pdf)
        };
        let contribution = sample.weight * emitted * (weight / n_bsdf);
        if contribution.is_finite() {
            contribution
        } else {
            Vec3::ZERO
        }
    }
}
