//! The path tracer: one path per camera ray, one direction per bounce.
//!
//! Chapter 06's tracer branches: glass may follow both rays, and every matte surface sends
//! shadow rays to every light. A path tracer keeps one sample per step, so a sample costs a
//! path of at most `max_depth` segments (plus one shadow ray per bounce), and every kind of
//! light transport, indirect diffuse light included, is one integral estimated by one path.
//! The loop carries the *throughput* `β`, the product of the BSDF weights so far: what one
//! unit of radiance found at the path's end contributes to the pixel.
//!
//! At each surface the path reached by segment `depth`:
//!
//! 1. what the surface emits, counted with the MIS weight of the BSDF sample that found it
//!    (1 after the camera or a delta bounce, or without NEE);
//! 2. if `depth < max_depth` (the next segment is allowed): one light sample (NEE) at a
//!    non-delta surface, then one BSDF sample that extends the path;
//! 3. from `rr_depth` on, Russian roulette.
//!
//! A ray that leaves the scene finds the environment, weighted like an emitter.
//!
//! Random numbers, after the camera's: per bounce, the light pick (only with several lights)
//! and the light point (two; none for a point light) when NEE runs, then the BSDF's (see
//! [`crate::bsdf`]), then one for the roulette when it is active. A scene pays only for what
//! it has: without lights there is no light sample, and when no ray can find emission (no
//! area light, no environment) the last segment, which could only find emission, is not
//! traced. [`crate::dimensions`] counts the numbers a path draws.

use crate::bsdf::Bsdf;
use crate::lights::SceneLights;
use crate::mis::MisHeuristic;
use crate::nee::light_sample_contribution;
use crate::options::PathOptions;
use crate::roulette::russian_roulette;
use ch01_whitted::scene::World;
use ch06_fuzzy_reflections::FuzzMethod;
use ch07_soft_shadows::SoftShadowScene;
use common::Ray;
use common::geometry::SurfaceHit;
use common::render::SampleCounters;
use common::sampler::Sampler;
use glam::{Vec2, Vec3};

/// Where the previous bounce was, and how its direction was chosen: what the MIS weight of
/// light found by that direction needs.
#[derive(Clone, Copy, Debug)]
struct Previous {
    /// The surface point the direction left from.
    p: Vec3,
    /// The BSDF's density of the direction; infinite for a delta.
    pdf: f32,
}

/// A path tracer over a chapter 07 scene.
#[derive(Clone, Copy)]
pub struct PathTracer<'a> {
    /// The scene: shapes, materials, area and point lights, environment, camera.
    pub scene: &'a SoftShadowScene,
    /// Its lights as one list.
    pub lights: SceneLights<'a>,
    /// NEE, MIS, roulette, depth.
    pub options: PathOptions,
    /// How fuzzy lobes spread.
    pub fuzz: FuzzMethod,
}

impl PathTracer<'_> {
    // ANCHOR: radiance
    /// The radiance arriving along the camera ray `ray`; every ray of the path keeps its time.
    pub fn radiance<S: Sampler>(
        &self,
        ray: Ray,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        let world = &self.scene.scene.world;
        let mut ray = ray;
        let mut radiance = Vec3::ZERO;
        let mut throughput = Vec3::ONE;
        let mut eta_scale = 1.0f32;
        let mut previous: Option<Previous> = None; // the camera ray: no MIS
        for depth in 1.. {
            counters.rays += 1;
            let Some(hit) = world.intersect(&ray) else {
                if self.lights.has_environment() {
                    let pdf = self.lights.environment_pdf();
                    radiance +=
                        throughput * self.lights.environment * self.emission_weight(previous, pdf);
                }
                break;
            };
            radiance += throughput * self.emitted(&hit, &ray, previous);
            if depth >= self.options.max_depth {
                break; // no segment left for a light sample or a bounce
            }
            let bsdf = Bsdf {
                material: &self.scene.scene.materials[hit.shape as usize],
                hit: &hit,
                fuzz: self.fuzz,
            };
            let wo = -ray.dir.normalize();
            if self.options.nee && self.lights.count() > 0 && !bsdf.is_delta() {
                radiance += throughput * self.light_sample(&bsdf, wo, ray.time, sampler, counters);
            }
            if depth + 1 >= self.options.max_depth && !self.lights.can_be_hit() {
                // The next segment would be the last: all it could find is emission, and no
                // ray can hit a point light. Its direction, ray and numbers are skipped; they
                // were the sample's last, so the image is the same.
                break;
            }
            let Some(sample) = bsdf.sample(wo, sampler) else {
                break;
            };
            throughput *= sample.weight;
            eta_scale *= sample.eta_scale;
            // A throughput that is not finite is a bug at its source: it is not hidden here,
            // but reaches the film, which counts it (`nonfinite_samples`).
            if throughput == Vec3::ZERO {
                break;
            }
            if let Some(rr_depth) = self.options.rr_depth
                && depth >= rr_depth
            {
                let Some(factor) =
                    russian_roulette(throughput.max_element() / eta_scale, sampler.get_1d())
                else {
                    break;
                };
                throughput *= factor;
            }
            previous = Some(Previous {
                p: hit.p,
                pdf: sample.pdf,
            });
            ray = hit.spawn_ray(sample.wi, ray.time);
        }
        radiance
    }
    // ANCHOR_END: radiance

    /// What the surface at `hit` emits back along `ray`, MIS-weighted against the light
    /// sample taken at the previous bounce.
    fn emitted(&self, hit: &SurfaceHit, ray: &Ray, previous: Option<Previous>) -> Vec3 {
        let Some(light) = self.lights.area_light_of(hit.shape) else {
            return Vec3::ZERO;
        };
        let le = light.emitted(hit.n, -ray.dir);
        if le == Vec3::ZERO {
            return Vec3::ZERO;
        }
        let light_pdf = match previous {
            Some(previous) if self.needs_weight(previous) => {
                self.lights.area_pdf(light, previous.p, hit.p, hit.n)
            }
            _ => 0.0,
        };
        le * self.emission_weight(previous, light_pdf)
    }

    /// Whether light found after `previous` could also have come from its light sample.
    fn needs_weight(&self, previous: Previous) -> bool {
        self.options.nee && previous.pdf.is_finite()
    }

    /// The MIS weight of light found by the BSDF direction of `previous`, which the light
    /// sample would have chosen with density `light_pdf`: 1 for the camera ray, after a delta
    /// bounce, or without NEE; 0 with NEE but no MIS (the light sample counted it).
    fn emission_weight(&self, previous: Option<Previous>, light_pdf: f32) -> f32 {
        match previous {
            Some(previous) if self.needs_weight(previous) => match self.options.mis {
                MisHeuristic::None => 0.0,
                mis => mis.weight(previous.pdf, light_pdf),
            },
            _ => 1.0,
        }
    }

    // ANCHOR: light_sample
    /// One light sample at a non-delta surface: a light picked uniformly, a direction to it,
    /// and the shadow ray, traced only when the sample carries something.
    fn light_sample<S: Sampler>(
        &self,
        bsdf: &Bsdf,
        wo: Vec3,
        time: f32,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        let u_pick = if self.lights.count() > 1 {
            sampler.get_1d()
        } else {
            0.0
        };
        let Some(light) = self.lights.pick(u_pick) else {
            return Vec3::ZERO;
        };
        let u = match light {
            crate::lights::LightRef::Point(_) => Vec2::ZERO,
            _ => sampler.get_2d(),
        };
        let Some(sample) = self.lights.sample(light, bsdf.hit, u) else {
            return Vec3::ZERO;
        };
        let f_cos = bsdf.eval(wo, sample.wi);
        // A point light's weight is 1 whatever the BSDF's density, so it is not computed.
        let bsdf_pdf = if sample.pdf.is_finite() {
            bsdf.pdf(wo, sample.wi)
        } else {
            0.0
        };
        let contribution = light_sample_contribution(
            sample.radiance,
            f_cos,
            sample.pdf,
            bsdf_pdf,
            self.lights.pick_probability(),
            self.options.mis,
        );
        if contribution == Vec3::ZERO {
            return Vec3::ZERO; // nothing to carry: no shadow ray
        }
        counters.rays += 1;
        if self
            .scene
            .scene
            .world
            .occluded(&sample.shadow_ray(bsdf.hit, time))
        {
            Vec3::ZERO
        } else {
            contribution
        }
    }
    // ANCHOR_END: light_sample
}
