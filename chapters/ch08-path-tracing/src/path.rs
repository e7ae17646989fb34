//! The path tracer: one path per camera ray, one direction per bounce.
//!
//! Chapter 06's tracer branches: glass may follow both rays, and every matte surface sends
//! shadow rays to every light. A path tracer keeps one sample per step, so a sample costs a
//! path of at most `max_depth` segments (plus one shadow ray per bounce), and every kind of
//! light transport, indirect diffuse light included, is one integral estimated by one path.
//! The loop carries the *throughput* `β`, the product of the BSDF weights so far: what one
//! unit of radiance found at the path's end contributes to the pixel.
//!
//! At each surface a segment reaches ([`PathTracer::radiance`] and its segments):
//!
//! 1. what the surface emits, weighted against the light sample that could have found it
//!    too (multiple importance sampling, [`crate::mis`]);
//! 2. while `max_depth` allows it, at a non-delta surface, next-event estimation: a shadow
//!    ray to every point light, and one light sample among the lights a ray can find (area
//!    lights and the environment); then one BSDF sample that extends the path;
//! 3. from `rr_depth` on, Russian roulette.
//!
//! A ray that leaves the scene finds the environment, weighted like an emitter.
//!
//! Random numbers, after the camera's: per bounce, the light pick (only with several lights
//! to pick from) and the light point (two) when NEE samples a light, then the BSDF's (see
//! [`crate::bsdf`]), then one for the roulette when it is active. Point lights draw none. A
//! scene pays only for what it has: with point lights alone nothing is picked or sampled, and
//! when no ray can find emission (no area light, no environment) the last segment, which
//! could only find emission, is not traced. [`crate::dimensions`] counts the numbers a path
//! draws.

use crate::bsdf::Bsdf;
use crate::lights::SceneLights;
use crate::microfacet::coating::Coatings;
use crate::nee::{directional_lights, point_lights};
use crate::options::PathOptions;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::FuzzMethod;
use common::Ray;
use common::render::SampleCounters;
use common::sampler::Sampler;
use glam::Vec3;

/// Where the previous bounce was, and how its direction was chosen: what the MIS weight of
/// light found by that direction needs.
#[derive(Clone, Copy, Debug)]
pub struct Previous {
    /// The surface point the direction left from.
    pub p: Vec3,
    /// The BSDF's density of the direction; infinite for a delta.
    pub pdf: f32,
}

/// What a path carries from one segment to the next.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Carried {
    /// The product of the BSDF weights (and roulette factors) so far: what one unit of
    /// radiance found at the path's end adds to the pixel.
    pub throughput: Vec3,
    /// The product of the radiance scalings `(eta_i / eta_t)²` inside `throughput`.
    pub eta_scale: f32,
}

/// A path between two of its segments: what it has gathered, what it carries on, and how its
/// last direction was chosen.
#[derive(Clone, Copy, Debug)]
pub struct PathState {
    /// The radiance gathered so far.
    pub radiance: Vec3,
    /// What the next segment's light is multiplied by.
    pub carried: Carried,
    /// The bounce the last direction left from; `None` for the camera ray (no MIS).
    pub previous: Option<Previous>,
}

impl PathState {
    /// A path about to trace its camera ray: nothing gathered, everything carried.
    pub const START: PathState = PathState {
        radiance: Vec3::ZERO,
        carried: Carried {
            throughput: Vec3::ONE,
            eta_scale: 1.0,
        },
        previous: None,
    };

    /// Adds `light` arriving at the current segment's end, times what the path carries.
    pub fn gather(&mut self, light: Vec3) {
        self.radiance += self.carried.throughput * light;
    }
}

/// The path's next segment: its ray, what it carries, and how its direction was chosen.
#[derive(Clone, Copy, Debug)]
pub struct NextSegment {
    /// The segment's ray.
    pub ray: Ray,
    /// What the path carries along it.
    pub carried: Carried,
    /// The bounce its direction left from.
    pub previous: Previous,
}

/// A path tracer over a scene.
#[derive(Clone)]
pub struct PathTracer<'a> {
    /// The scene with its motion: shapes, surfaces, point lights, environment, camera.
    pub world: &'a MotionScene,
    /// Its lights as one list.
    pub lights: SceneLights<'a>,
    /// NEE, MIS, roulette, depth.
    pub options: PathOptions,
    /// How fuzzy lobes spread.
    pub fuzz: FuzzMethod,
    /// The rough plastics' coatings, tabulated from the scene before the render
    /// ([`Coatings::of`]).
    pub coatings: Coatings,
}

impl PathTracer<'_> {
    // ANCHOR: radiance
    /// The radiance arriving along `camera_ray`: the path, traced segment after segment
    /// until one of them ends it. Every ray of the path keeps the camera ray's time.
    pub fn radiance<S: Sampler>(
        &self,
        camera_ray: &Ray,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        let mut path = PathState::START;
        let mut depth = 1;
        let camera_ray = self.past_hidden_emitters(camera_ray, counters);
        let mut next = self.segment(&camera_ray, depth, &mut path, sampler, counters);
        while let Some(ray) = next {
            depth += 1;
            next = self.segment(&ray, depth, &mut path, sampler, counters);
        }
        path.radiance
    }
    // ANCHOR_END: radiance

    /// The camera ray as Mitsuba's `hide_emitters` has it: for the camera, shapes that emit
    /// light are not there. The ray passes through each one it meets and goes on from its far
    /// side, so that a hidden lamp shows what is behind it rather than a black silhouette.
    /// They still block shadow rays and later segments, and still light the scene. Without
    /// `hide_emitters`, the ray itself. Draws no random number, so every other pixel keeps
    /// its samples.
    pub(crate) fn past_hidden_emitters(
        &self,
        camera_ray: &Ray,
        counters: &mut SampleCounters,
    ) -> Ray {
        if self.options.hide_emitters && self.lights.has_area_lights() {
            self.through_emitters(camera_ray, counters)
        } else {
            *camera_ray
        }
    }

    /// The camera ray continued through every emitting shape it meets, for
    /// [`past_hidden_emitters`](Self::past_hidden_emitters).
    fn through_emitters(&self, camera_ray: &Ray, counters: &mut SampleCounters) -> Ray {
        use ch01_whitted::world::World;
        /// More emitting surfaces in a row than any scene stacks; a hostile one that does
        /// shows the last as a black surface instead of looping on.
        const MOST_SKIPPED: usize = 1024;
        let mut ray = *camera_ray;
        for _ in 0..MOST_SKIPPED {
            counters.rays += 1;
            match self.world.intersect(&ray) {
                Some(hit) if self.lights.area_light_of(hit.shape).is_some() => {
                    ray = hit.spawn_ray(ray.dir, ray.time);
                }
                _ => break,
            }
        }
        ray
    }

    // ANCHOR: segment
    /// Segment `depth` of `path` (the camera ray is segment 1), along `ray`: where it ends,
    /// the light it finds there, the light sampled at that surface, and the ray of the next
    /// segment, or `None` where the path ends.
    ///
    /// Light can reach the path two ways here: found by this segment (a surface that glows,
    /// or the environment when the ray leaves the scene) and sampled at its end (next-event
    /// estimation, [`next_event`](Self::next_event)); the render's options say whether light
    /// samples are taken at all (`self.options.nee`) and how the two share a light
    /// (`self.options.mis`). Which of the two counts how much, when the previous bounce could
    /// have sampled the light this segment found? Which lights can
    /// only one of them find? What does `max_depth` (Mitsuba's, counting the camera ray)
    /// still allow at this depth: a light sample, a further segment, neither?
    /// [`PathState::gather`] adds light times what the path carries, and
    /// [`extend_path`](Self::extend_path) chooses the next segment. When the scene hides its
    /// emitters (`self.options.hide_emitters`), what the camera ray itself finds counts for
    /// nothing.
    fn segment<S: Sampler>(
        &self,
        ray: &Ray,
        depth: u32,
        path: &mut PathState,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Option<Ray> {
        // Every segment's ray has a unit direction (the camera's and the BSDF's are built
        // unit), so `-ray.dir` needs no normalising; every test render checks it.
        debug_assert!(
            (ray.dir.length_squared() - 1.0).abs() < 1e-4,
            "a segment's ray of length {}: the ray a segment starts from (the camera's, or the \
             one extend_path chose from the BSDF's sample) must have a unit direction",
            ray.dir.length()
        );
        // BEGIN SOLUTION
        use crate::mis::MisHeuristic;
        use ch01_whitted::world::World;
        // The MIS weight of light this segment finds, which the light sample of the previous
        // bounce would have chosen with density `light_pdf`: 1 after the camera, after a
        // delta bounce (no light sample could be taken there) or without NEE; 0 with NEE but
        // no MIS (the light sample counted it).
        let previous = path.previous;
        let weighted = |previous: Previous| self.options.nee && previous.pdf.is_finite();
        let emission_weight = |light_pdf: f32| match previous {
            Some(previous) if weighted(previous) => match self.options.mis {
                MisHeuristic::None => 0.0,
                mis => mis.weight(previous.pdf, light_pdf),
            },
            _ => 1.0,
        };
        // Light found by the camera ray itself is left out when the scene hides its emitters.
        let finds_emission = depth > 1 || !self.options.hide_emitters;
        // Where the segment ends, or the environment if it leaves the scene.
        counters.rays += 1;
        let Some(hit) = self.world.intersect(ray) else {
            if finds_emission && self.lights.has_environment() {
                let weight = emission_weight(self.lights.environment_pdf(ray.dir));
                path.gather(self.lights.environment.radiance(ray.dir) * weight);
            }
            return None;
        };
        // 1. What the surface emits, weighted against the light sample that could have found
        //    it.
        if finds_emission
            && self.lights.has_area_lights()
            && let Some(light) = self.lights.area_light_of(hit.shape)
        {
            let le = self
                .lights
                .emitted(light, hit.shape, hit.n, || Some(hit.uv), -ray.dir);
            if le != Vec3::ZERO {
                let light_pdf = match previous {
                    Some(previous) if weighted(previous) => {
                        self.lights.area_pdf(light, previous.p, hit.p, hit.n)
                    }
                    _ => 0.0,
                };
                path.gather(le * emission_weight(light_pdf));
            }
        }
        if depth >= self.options.max_depth {
            return None; // no segment left for a light sample or a bounce
        }
        let bsdf = Bsdf {
            material: &self.world.scene.material_at(hit.shape, hit.uv),
            hit: &hit,
            fuzz: self.fuzz,
            coatings: &self.coatings,
        };
        let wo = -ray.dir;
        // 2. Next-event estimation, where the BSDF is not a delta.
        if self.options.nee && !bsdf.is_delta() {
            path.gather(self.next_event(&bsdf, wo, ray.time, sampler, counters));
        }
        if depth + 1 >= self.options.max_depth && !self.lights.can_be_hit() {
            // The next segment would be the last: all it could find is emission, and no
            // ray can hit a point light. Its direction, ray and numbers are skipped; they
            // were the sample's last, so the image is the same.
            return None;
        }
        // 3. A BSDF sample extends the path; from `rr_depth` on, the roulette may end it.
        let next = self.extend_path(&bsdf, wo, ray.time, depth, path.carried, sampler)?;
        path.carried = next.carried;
        path.previous = Some(next.previous);
        Some(next.ray)
        // END SOLUTION
    }
    // ANCHOR_END: segment

    // ANCHOR: extend_path
    /// The path's next segment from the surface of `bsdf`, seen from `wo`, where segment
    /// `depth` ended: a direction sampled from the BSDF, the throughput multiplied by its
    /// weight, then, from `rr_depth` on, Russian roulette on the throughput without its
    /// radiance scaling (`throughput / eta_scale`). The segment's ray leaves the surface at the
    /// path's shutter `time`, and [`Previous`] keeps where it left from and the sample's
    /// density. `None` when the path ends: no direction, nothing carried, or the roulette says
    /// so.
    pub fn extend_path<S: Sampler>(
        &self,
        bsdf: &Bsdf,
        wo: Vec3,
        time: f32,
        depth: u32,
        carried: Carried,
        sampler: &mut S,
    ) -> Option<NextSegment> {
        // BEGIN SOLUTION
        use crate::roulette::russian_roulette;
        let sample = bsdf.sample(wo, sampler)?;
        let mut throughput = carried.throughput * sample.weight;
        let eta_scale = carried.eta_scale * sample.eta_scale;
        // A throughput that is not finite is a bug at its source: it is not hidden here,
        // but reaches the film, which counts it (`nonfinite_samples`).
        if throughput == Vec3::ZERO {
            return None;
        }
        if let Some(rr_depth) = self.options.rr_depth
            && depth >= rr_depth
        {
            throughput *= russian_roulette(throughput.max_element() / eta_scale, sampler.get_1d())?;
        }
        Some(NextSegment {
            ray: bsdf.hit.spawn_ray(sample.wi, time),
            carried: Carried {
                throughput,
                eta_scale,
            },
            previous: Previous {
                p: bsdf.hit.p,
                pdf: sample.pdf,
            },
        })
        // END SOLUTION
    }
    // ANCHOR_END: extend_path

    // ANCHOR: next_event
    /// Next-event estimation at the surface of `bsdf`, seen from `wo`: every point light and
    /// every directional light through its own shadow ray (a delta has nothing to sample),
    /// and one light sample among the lights a ray can find.
    #[inline]
    pub fn next_event<S: Sampler>(
        &self,
        bsdf: &Bsdf,
        wo: Vec3,
        time: f32,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        let world = self.world;
        let mut light = Vec3::ZERO;
        if !self.lights.points.is_empty() {
            light += point_lights(world, &self.lights, bsdf, wo, time, counters);
        }
        if !self.lights.directionals.is_empty() {
            light += directional_lights(world, &self.lights, bsdf, wo, time, counters);
        }
        if self.lights.can_be_hit() {
            light += self.light_sample(bsdf, wo, time, sampler, counters);
        }
        light
    }
    // ANCHOR_END: next_event

    // ANCHOR: nee_light_sample
    /// One light sample at the non-delta surface of `bsdf`, seen from `wo`: a light picked
    /// uniformly among the area lights and the environment ([`SceneLights::pick`]), a
    /// direction to it ([`SceneLights::sample`]), its MIS-weighted contribution
    /// ([`light_sample_contribution`](crate::nee::light_sample_contribution)), and the shadow
    /// ray at shutter time `time`, counted in `counters.rays`.
    ///
    /// A scene pays only for what it has: with a single light to pick from, the pick draws no
    /// number. What does the BSDF say about the sampled direction, for the term and for the
    /// weight? When is a shadow ray worth tracing? It must not be blocked by the light it aims
    /// at, which is itself a shape of the world.
    pub fn light_sample<S: Sampler>(
        &self,
        bsdf: &Bsdf,
        wo: Vec3,
        time: f32,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        // BEGIN SOLUTION
        use crate::nee::light_sample_contribution;
        use ch01_whitted::world::World;
        // With one light to pick from there is nothing to choose: no number is drawn.
        let u_pick = if self.lights.count() > 1 {
            sampler.get_1d()
        } else {
            0.0
        };
        let Some(light) = self.lights.pick(u_pick) else {
            return Vec3::ZERO;
        };
        let Some(sample) = self.lights.sample(light, bsdf.hit, sampler.get_2d()) else {
            return Vec3::ZERO;
        };
        let f_cos = bsdf.eval(wo, sample.wi);
        let bsdf_pdf = bsdf.pdf(wo, sample.wi);
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
        if self.world.occluded(&sample.shadow_ray(bsdf.hit, time)) {
            Vec3::ZERO
        } else {
            contribution
        }
        // END SOLUTION
    }
    // ANCHOR_END: nee_light_sample
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bsdf::test_support::floor_hit;
    use crate::furnace::spheres;
    use crate::mis::MisHeuristic;
    use ch01_whitted::world::World;
    use ch07_soft_shadows::reference::sphere_irradiance;
    use ch07_soft_shadows::{AreaLights, LightSampling};
    use common::sampler::IndependentSampler;
    use common::scene::Material as Smooth;
    use common::scene::Material;
    use glam::UVec2;
    use std::f64::consts::PI as PI64;

    /// A tracer over a furnace scene (one sphere of `material` in a sky of radiance 1).
    fn with_tracer<R>(
        material: Material,
        options: PathOptions,
        use_tracer: impl FnOnce(&PathTracer) -> R,
    ) -> R {
        let world = spheres(&[material], options.max_depth);
        let area_lights = AreaLights::of(&world.scene);
        let tracer = PathTracer {
            world: &world,
            lights: SceneLights::of(&world, &area_lights, LightSampling::solid_angle()),
            options,
            fuzz: FuzzMethod::Lobe,
            coatings: Coatings::of(&world.scene),
        };
        use_tracer(&tracer)
    }

    /// Extends a path from the floor hit, seen from straight above, `n` times with sample
    /// streams 0..n; the extensions that happened.
    fn extensions(
        tracer: &PathTracer,
        material: &Material,
        depth: u32,
        carried: Carried,
        n: u64,
    ) -> Vec<NextSegment> {
        let hit = floor_hit();
        let bsdf = Bsdf {
            material,
            hit: &hit,
            fuzz: FuzzMethod::Lobe,
            coatings: &tracer.coatings,
        };
        let mut sampler = IndependentSampler::new(11);
        (0..n)
            .filter_map(|i| {
                sampler.start_pixel_sample(UVec2::ZERO, i);
                tracer.extend_path(&bsdf, Vec3::Y, 0.25, depth, carried, &mut sampler)
            })
            .collect()
    }

    #[test]
    fn exercise_extend_path_multiplies_the_throughput_and_keeps_the_density() {
        let grey = Smooth::diffuse(Vec3::new(0.5, 0.25, 1.0));
        let options = PathOptions {
            rr_depth: None,
            ..PathOptions::with_depth(8)
        };
        let carried = Carried {
            throughput: Vec3::new(0.5, 1.0, 2.0),
            eta_scale: 1.0,
        };
        with_tracer(grey.clone(), options, |tracer| {
            let next = extensions(tracer, &grey, 1, carried, 64);
            assert_eq!(
                next.len(),
                64,
                "extend_path: a matte surface seen from its front always scatters, so the path \
                 always goes on here (no roulette before rr_depth); yours ended {} of 64 paths",
                64 - next.len()
            );
            for segment in next {
                // A cosine-sampled matte surface: weight = albedo, pdf = cos θ / π.
                let throughput = segment.carried.throughput;
                let expected = Vec3::new(0.25, 0.25, 2.0);
                let why = if throughput == carried.throughput {
                    "the throughput was not multiplied by the sample's weight"
                } else if throughput == Vec3::new(0.5, 0.25, 1.0) {
                    "the throughput became the sample's weight: it is multiplied into what the \
                     path already carries"
                } else {
                    "it is what the path carried times the sample's weight"
                };
                assert!(
                    (throughput - expected).abs().max_element() < 1e-6,
                    "extend_path: the new throughput is {throughput}, expected {expected}: {why} \
                     (carried {}, albedo (0.5, 0.25, 1))",
                    carried.throughput
                );
                assert!(
                    segment.carried.eta_scale == 1.0,
                    "extend_path: a matte bounce scales no radiance, so eta_scale stays 1, not {}",
                    segment.carried.eta_scale
                );
                let cos = segment.ray.dir.dot(Vec3::Y);
                assert!(
                    cos > 0.0,
                    "extend_path: the next ray {:?} does not leave on the lit side of the floor: \
                     its direction is the BSDF sample's",
                    segment.ray
                );
                let pdf = cos * std::f32::consts::FRAC_1_PI;
                assert!(
                    (segment.previous.pdf - pdf).abs() < 1e-5 * pdf.max(1.0),
                    "extend_path: Previous keeps the density {}, but the BSDF sampled that \
                     direction with density {pdf}: MIS at the next hit needs the sample's own pdf",
                    segment.previous.pdf
                );
                assert!(
                    segment.previous.p == Vec3::ZERO,
                    "extend_path: Previous keeps the point {}, not the hit point the direction \
                     leaves from (0, 0, 0)",
                    segment.previous.p
                );
                assert!(
                    segment.ray.origin.y > 0.0,
                    "extend_path: the next ray starts at {}, on or below the surface: spawn it \
                     from the hit, offset off the surface",
                    segment.ray.origin
                );
                assert!(
                    segment.ray.time == 0.25,
                    "extend_path: the next ray's time is {}, not the path's 0.25: every ray of a \
                     path keeps the shutter time",
                    segment.ray.time
                );
            }
        });
    }

    #[test]
    fn exercise_extend_path_plays_an_unbiased_roulette_on_the_unscaled_throughput() {
        let white = Smooth::diffuse(Vec3::ONE);
        let options = PathOptions {
            rr_depth: Some(3),
            ..PathOptions::with_depth(8)
        };
        // Through glass the throughput holds η² = 2.25, which says nothing about how much the
        // path still matters: the roulette must look at 0.2 · 2.25 / 2.25 = 0.2.
        let carried = Carried {
            throughput: Vec3::splat(0.2 * 2.25),
            eta_scale: 2.25,
        };
        with_tracer(white.clone(), options, |tracer| {
            let before_rr = extensions(tracer, &white, 2, carried, 1000);
            assert_eq!(
                before_rr.len(),
                1000,
                "extend_path: before rr_depth no path is ended by the roulette; {} of 1000 were",
                1000 - before_rr.len()
            );
            let n = 20_000;
            let survivors = extensions(tracer, &white, 3, carried, n);
            // Survival with probability q = 0.2: the count is binomial(n, 0.2).
            let q = 0.2;
            let sigma = (n as f64 * q * (1.0 - q)).sqrt();
            let expected = n as f64 * q;
            let count = survivors.len() as f64;
            let why = if count == n as f64 {
                "none was ended, at depth 3 with rr_depth 3: the roulette is played from \
                 segment rr_depth on, that one included"
            } else {
                "the path carries 0.45 through glass that scaled its radiance by 2.25, so the \
                 roulette must look at 0.45 / 2.25 = 0.2 (the throughput without its radiance \
                 scaling)"
            };
            assert!(
                (count - expected).abs() < 5.0 * sigma,
                "extend_path: {count} of {n} paths survived the roulette, expected about \
                 {expected} ± {sigma:.1}: {why}"
            );
            // Each survivor carries throughput / q, so the mean over all paths is unchanged.
            for segment in &survivors {
                let kept = segment.carried.throughput.x;
                assert!(
                    (kept - 0.45 / 0.2).abs() < 1e-5,
                    "extend_path: a survivor carries {kept}; surviving with probability 0.2 it \
                     must carry 0.45 / 0.2 = 2.25, so that the mean over all paths is unchanged"
                );
                assert!(
                    segment.carried.eta_scale == 2.25,
                    "extend_path: eta_scale is {}, but a matte bounce leaves the path's 2.25 as it is",
                    segment.carried.eta_scale
                );
            }
        });
    }

    #[test]
    fn exercise_extend_path_carries_the_radiance_scaling_through_glass() {
        // Smooth glass refracts part of the time, scaling radiance by (eta_i / eta_t)²: the
        // path's eta_scale gathers those factors, as its throughput gathers the weights.
        let glass = Smooth::glass(1.5);
        let options = PathOptions {
            rr_depth: None,
            ..PathOptions::with_depth(8)
        };
        let carried = Carried {
            throughput: Vec3::new(0.5, 1.0, 2.0),
            eta_scale: 0.8,
        };
        with_tracer(glass.clone(), options, |tracer| {
            let hit = floor_hit();
            let bsdf = Bsdf {
                material: &glass,
                hit: &hit,
                fuzz: FuzzMethod::Lobe,
                coatings: &crate::microfacet::coating::Coatings::default(),
            };
            let wo = Vec3::new(0.3, 1.0, 0.2).normalize();
            let mut sampler = IndependentSampler::new(13);
            let mut refracted = 0;
            for i in 0..64 {
                // The BSDF's own sample from the same numbers, then the extension.
                sampler.start_pixel_sample(UVec2::ZERO, i);
                let Some(sample) = bsdf.sample(wo, &mut sampler) else {
                    continue;
                };
                sampler.start_pixel_sample(UVec2::ZERO, i);
                let Some(next) = tracer.extend_path(&bsdf, wo, 0.0, 1, carried, &mut sampler)
                else {
                    panic!(
                        "extend_path: glass gave a direction ({sample:?}) and the path carries \
                         something, so it goes on (no roulette before rr_depth); yours ended it"
                    );
                };
                refracted += usize::from(sample.eta_scale != 1.0);
                let expected = carried.eta_scale * sample.eta_scale;
                let got = next.carried.eta_scale;
                if (got - expected).abs() > 1e-6 * expected {
                    let why = if got == carried.eta_scale {
                        "the sample's radiance scaling was not multiplied in"
                    } else if (got - sample.eta_scale).abs() <= 1e-6 * sample.eta_scale {
                        "the sample's scaling replaced what the path carried; it is multiplied \
                         into it"
                    } else if (got - carried.eta_scale / sample.eta_scale).abs() <= 1e-6 * got {
                        "the path's eta_scale was divided by the sample's; it is multiplied by it"
                    } else {
                        "it is the path's eta_scale times the sample's"
                    };
                    panic!(
                        "extend_path: through glass the sample scales radiance by {}, so the \
                         path's eta_scale goes from {} to {expected}; yours is {got}: {why}",
                        sample.eta_scale, carried.eta_scale
                    );
                }
                let throughput = carried.throughput * sample.weight;
                assert!(
                    (next.carried.throughput - throughput).abs().max_element()
                        <= 1e-5 * throughput.max_element(),
                    "extend_path: through glass the new throughput is {}, expected {throughput}: \
                     what the path carried times the sample's weight",
                    next.carried.throughput
                );
            }
            assert!(refracted > 0, "the check's samples refract");
        });
    }

    #[test]
    fn exercise_extend_path_ends_paths_that_carry_nothing() {
        let black = Smooth::diffuse(Vec3::ZERO);
        let carried = Carried {
            throughput: Vec3::ONE,
            eta_scale: 1.0,
        };
        with_tracer(black.clone(), PathOptions::with_depth(8), |tracer| {
            let went_on = extensions(tracer, &black, 1, carried, 16).len();
            assert!(
                went_on == 0,
                "extend_path: after a black surface the path carries nothing, so it ends; {went_on} \
                 of 16 went on (each costs rays and can add nothing)"
            );
        });
    }

    #[test]
    fn exercise_extend_path_lets_the_furnace_return_one() {
        // Paths made of `extend_path` alone: a white matte sphere under a sky of 1 sends back
        // exactly 1 whatever the bounces, so every path that leaves the sphere carries 1.
        let white = Smooth::diffuse(Vec3::ONE);
        let options = PathOptions {
            nee: false,
            rr_depth: None,
            ..PathOptions::with_depth(64)
        };
        with_tracer(white.clone(), options, |tracer| {
            let world = tracer.world;
            let eye = Vec3::new(0.0, 0.5, 4.0);
            let mut sampler = IndependentSampler::new(5);
            let mut bounces = 0;
            for i in 0..256 {
                sampler.start_pixel_sample(UVec2::ZERO, i);
                let mut ray = Ray::new(eye, (Vec3::new(0.1, 0.2, 0.0) - eye).normalize());
                let mut carried = PathState::START.carried;
                let mut depth = 1;
                while let Some(hit) = world.intersect(&ray) {
                    let bsdf = Bsdf {
                        material: &white,
                        hit: &hit,
                        fuzz: FuzzMethod::Lobe,
                        coatings: &crate::microfacet::coating::Coatings::default(),
                    };
                    let Some(next) =
                        tracer.extend_path(&bsdf, -ray.dir, 0.0, depth, carried, &mut sampler)
                    else {
                        panic!(
                            "extend_path: a white matte sphere seen from outside always \
                             scatters, but the path ended at depth {depth}"
                        );
                    };
                    (ray, carried, depth) = (next.ray, next.carried, depth + 1);
                    bounces += 1;
                    assert!(depth < 64, "extend_path: the path never leaves the sphere");
                }
                let l = carried.throughput;
                assert!(
                    (l - Vec3::ONE).abs().max_element() < 1e-4,
                    "extend_path: a white matte sphere under a sky of radiance 1 sends back \
                     exactly 1 however the path bounces; this path carried {l} to the sky"
                );
            }
            assert!(bounces >= 256, "the paths bounced");
        });
    }

    // The path's segment: the capstone.

    /// The mean and the standard error of the radiance along `ray` (its green channel) over
    /// `n` paths with sample streams `0..n` of seed `seed`. Panics on a non-finite path.
    fn mean_radiance(tracer: &PathTracer, ray: &Ray, n: u64, seed: u64) -> (f64, f64) {
        let mut sampler = IndependentSampler::new(seed);
        let mut counters = SampleCounters::default();
        let (mut sum, mut sum2) = (0.0f64, 0.0f64);
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            let l = tracer.radiance(ray, &mut sampler, &mut counters);
            assert!(
                l.is_finite() && l.cmpge(Vec3::ZERO).all(),
                "segment: a path brought back {l}: radiance is never negative, NaN or infinite"
            );
            let x = f64::from(l.y);
            sum += x;
            sum2 += x * x;
        }
        let mean = sum / n as f64;
        let variance = (sum2 / n as f64 - mean * mean).max(0.0);
        (mean, (variance / n as f64).sqrt())
    }

    /// The furnace's eye, and rays from it to the sphere's front and past it, into the sky.
    fn furnace_rays() -> (Ray, Ray) {
        let eye = Vec3::new(0.0, 0.5, 4.0);
        let to_sphere = Ray::new(eye, (Vec3::new(0.1, 0.3, 0.0) - eye).normalize());
        let to_sky = Ray::new(eye, (Vec3::new(0.0, 5.0, 0.0) - eye).normalize());
        (to_sphere, to_sky)
    }

    #[test]
    fn exercise_segment_counts_what_the_camera_ray_finds() {
        // max_depth 1: the camera ray alone, which sees what glows and nothing lit.
        let grey = Smooth::diffuse(Vec3::splat(0.5));
        let (to_sphere, to_sky) = furnace_rays();
        with_tracer(grey.clone(), PathOptions::with_depth(1), |tracer| {
            let (sky, _) = mean_radiance(tracer, &to_sky, 16, 1);
            assert!(
                (sky - 1.0).abs() < 1e-6,
                "segment: a camera ray that leaves the scene sees the sky of radiance 1, yours \
                 brought back {sky}: {}",
                if sky == 0.0 {
                    "the camera ray's own light is missing (nothing came before it, so \
                     whatever it finds counts in full)"
                } else {
                    "what the camera ray finds counts in full, with weight 1"
                }
            );
            let (sphere, _) = mean_radiance(tracer, &to_sphere, 64, 2);
            assert!(
                sphere == 0.0,
                "segment: at max_depth 1 a path is the camera ray alone, which sees only what \
                 glows; the grey sphere does not glow but brought back {sphere}: the depth \
                 limit is off by one (no light sample and no bounce after the last segment)"
            );
        });
        // A sphere light seen by the camera, at every depth.
        for max_depth in [1, 2, 5] {
            let (world, _) = sphere_light_scene(max_depth);
            with_path_tracer(&world, PathOptions::with_depth(max_depth), |tracer| {
                let eye = Vec3::new(2.0, 1.0, 0.0);
                let to_light = Ray::new(eye, (Vec3::new(0.0, 1.5, 0.0) - eye).normalize());
                let (l, _) = mean_radiance(tracer, &to_light, 16, 3);
                assert!(
                    (l - 1.0).abs() < 1e-6,
                    "segment: the camera sees a sphere light of radiance 1 at max_depth \
                     {max_depth}; yours brought back {l}: {}",
                    if l == 0.0 {
                        "the camera ray's own light is missing (what glows where the camera \
                         ray ends counts in full: no light sample came before it)"
                    } else {
                        "what the camera ray finds counts once, in full"
                    }
                );
            });
        }
    }

    #[test]
    fn exercise_segment_lights_the_furnace_once() {
        // A convex grey sphere of albedo 0.5 under a sky of 1 sends back exactly 0.5 from
        // max_depth 2 on: each bounce leaves for the sky. The light sample and the BSDF sample
        // share that light by the power heuristic; with one light the environment's density
        // is 1/(4π) and the cosine lobe's cos θ/π, so the light sample's share of the
        // expectation is A = ∫ 2c/(1 + 16c²) dc = ln(17)/16, the BSDF sample's 1 - A.
        let albedo = 0.5;
        let grey = Smooth::diffuse(Vec3::splat(albedo));
        let (to_sphere, _) = furnace_rays();
        let a = 17f64.ln() / 16.0;
        let albedo = f64::from(albedo);
        for max_depth in [2, 3, 6] {
            with_tracer(grey.clone(), PathOptions::with_depth(max_depth), |tracer| {
                let (mean, se) = mean_radiance(tracer, &to_sphere, 4000, 4);
                let tolerance = 5.0 * se + 1e-3;
                if (mean - albedo).abs() < tolerance {
                    return;
                }
                // What the usual slips give, in expectation.
                let slips = [
                    (
                        albedo * (1.0 - a),
                        "NEE is skipped at the last surface the path may bounce from: at \
                         max_depth 2 the first hit is the last bounce, and its light sample \
                         must still be taken (only the next segment's bounce is not allowed)",
                    ),
                    (
                        albedo * (a + 1.0),
                        "the sky is counted twice: the BSDF ray that finds it adds it without \
                         its MIS weight, although the light sample at the same bounce counted \
                         its share already",
                    ),
                    (
                        albedo * a + (1.0 - a),
                        "the throughput was not carried: light found after a bounce is \
                         multiplied by what the path carries after that bounce (the albedo \
                         here), not by 1",
                    ),
                    (
                        2.0 * albedo * a,
                        "the MIS weight of light found by the BSDF ray uses the densities the \
                         wrong way round: that direction came from the BSDF, so its weight is \
                         the BSDF's density against the light sample's",
                    ),
                    (
                        0.0,
                        "nothing lit the sphere: at max_depth 2 the path takes a light sample \
                         at its first hit and may bounce once (is the depth limit off by one?)",
                    ),
                ];
                let why = slips
                    .iter()
                    .find(|(value, _)| (mean - value).abs() < tolerance)
                    .map_or(
                        "each light must be counted once: in full where only one strategy \
                         can find it, shared by the MIS weights where both can",
                        |(_, why)| why,
                    );
                panic!(
                    "segment: a grey sphere of albedo 0.5 under a sky of radiance 1 sends back \
                     0.5 at max_depth {max_depth}; yours averaged {mean:.4} ± {se:.4} over 4000 \
                     paths: {why}"
                );
            });
        }
    }

    #[test]
    fn exercise_segment_follows_the_options() {
        let grey = Smooth::diffuse(Vec3::splat(0.5));
        let (to_sphere, to_sky) = furnace_rays();
        // Without NEE no light sample takes a share: the BSDF rays find the whole sky.
        let no_nee = PathOptions {
            nee: false,
            ..PathOptions::with_depth(3)
        };
        with_tracer(grey.clone(), no_nee, |tracer| {
            let (mean, se) = mean_radiance(tracer, &to_sphere, 4000, 6);
            assert!(
                (mean - 0.5).abs() < 5.0 * se + 1e-3,
                "segment: without next-event estimation, a grey sphere of albedo 0.5 under a \
                 sky of radiance 1 sends back 0.5 at max_depth 3; yours averaged {mean:.4} ± \
                 {se:.4}: {}",
                if mean < 0.5 {
                    "without NEE no light sample takes a share of the light, so what a BSDF ray \
                     finds counts in full"
                } else {
                    "each light is counted once"
                }
            );
        });
        // A scene that hides its emitters: the camera ray's own finds count for nothing, what
        // later segments find counts as always.
        for max_depth in [1, 3] {
            let hidden = PathOptions {
                hide_emitters: true,
                ..PathOptions::with_depth(max_depth)
            };
            with_tracer(grey.clone(), hidden, |tracer| {
                let (sky, _) = mean_radiance(tracer, &to_sky, 16, 7);
                assert!(
                    sky == 0.0,
                    "segment: the scene hides its emitters (hide_emitters), so a camera ray that \
                     leaves it sees nothing of the sky; yours brought back {sky} at max_depth \
                     {max_depth}"
                );
                if max_depth > 1 {
                    let (mean, se) = mean_radiance(tracer, &to_sphere, 4000, 8);
                    assert!(
                        (mean - 0.5).abs() < 5.0 * se + 1e-3,
                        "segment: the scene hides its emitters from the camera ray only: the \
                         sky still lights the grey sphere, which sends back 0.5 at max_depth \
                         {max_depth}; yours averaged {mean:.4} ± {se:.4}"
                    );
                }
            });
        }
    }

    #[test]
    fn exercise_segment_shares_a_sphere_light_between_its_two_samples() {
        // A matte floor of albedo 0.5 under a sphere light of radius 0.5 whose centre is 1.5
        // above the floor's origin: the origin receives E = π L (R/d)² and reflects
        // 0.5 E / π, at any depth from 2 on (the light's surface is black, no sky).
        let reference = 0.5 * f64::from(sphere_irradiance(Vec3::ONE, 0.5, 1.5, 1.0).y) / PI64;
        for (max_depth, options) in [
            (2, PathOptions::with_depth(2)),
            (4, PathOptions::with_depth(4)),
            (
                3,
                PathOptions {
                    mis: MisHeuristic::Balance,
                    ..PathOptions::with_depth(3)
                },
            ),
        ] {
            let (world, floor_point) = sphere_light_scene(max_depth);
            with_path_tracer(&world, options, |tracer| {
                let eye = Vec3::new(2.0, 1.0, 0.0);
                let ray = Ray::new(eye, (floor_point - eye).normalize());
                let (mean, se) = mean_radiance(tracer, &ray, 2000, 5);
                let tolerance = 5.0 * se + 1e-3 * reference;
                assert!(
                    (mean - reference).abs() < tolerance,
                    "segment: a floor of albedo 0.5 under a sphere light should reflect \
                     {reference:.5} at max_depth {max_depth} ({:?}); yours averaged {mean:.5} ± \
                     {se:.5} over 2000 paths ({:+.0} %): {}",
                    options.mis,
                    100.0 * (mean / reference - 1.0),
                    if mean > reference {
                        "too bright: the light the BSDF ray finds and the light sample's share \
                         of it add up to more than the light: is its MIS weight there, and is \
                         the light sample's density per unit solid angle seen from the previous \
                         bounce (the same density the light sample used)?"
                    } else if mean == 0.0 {
                        "the floor got no light: a light sample at the first hit, and a \
                         bounce that may find the light, are both allowed at max_depth 2"
                    } else {
                        "too dark: part of the light is lost (a light sample not taken, or a \
                         weight that is too small)"
                    }
                );
            });
        }
    }

    // One light sample.

    /// The mean and standard error (green channel) of `light_sample` at the floor's origin of
    /// `world`, seen from (2, 1, 0), over `n` sample streams; and the shadow rays it traced.
    fn light_samples_at_origin(world: &MotionScene, mis: MisHeuristic, n: u64) -> (f64, f64, u64) {
        let options = PathOptions {
            mis,
            ..PathOptions::with_depth(2)
        };
        with_path_tracer(world, options, |tracer| {
            let eye = Vec3::new(2.0, 1.0, 0.0);
            let ray = Ray::new(eye, -eye.normalize());
            let hit = world.intersect(&ray).expect("the floor");
            let bsdf = Bsdf {
                material: &world.scene.material_at(hit.shape, hit.uv),
                hit: &hit,
                fuzz: FuzzMethod::Lobe,
                coatings: &tracer.coatings,
            };
            let mut sampler = IndependentSampler::new(9);
            let mut counters = SampleCounters::default();
            let (mut sum, mut sum2) = (0.0f64, 0.0f64);
            for i in 0..n {
                sampler.start_pixel_sample(UVec2::ZERO, i);
                let l = tracer.light_sample(&bsdf, -ray.dir, 0.0, &mut sampler, &mut counters);
                assert!(
                    l.is_finite() && l.cmpge(Vec3::ZERO).all(),
                    "light_sample: a light sample gave {l}: never negative, NaN or infinite"
                );
                let x = f64::from(l.y);
                (sum, sum2) = (sum + x, sum2 + x * x);
            }
            let mean = sum / n as f64;
            let variance = (sum2 / n as f64 - mean * mean).max(0.0);
            (mean, (variance / n as f64).sqrt(), counters.rays)
        })
    }

    /// What a floor of albedo 0.5 at the origin reflects of the sphere light of
    /// [`sphere_light_scene`]: 0.5 E / π.
    fn floor_reference() -> f64 {
        0.5 * f64::from(sphere_irradiance(Vec3::ONE, 0.5, 1.5, 1.0).y) / PI64
    }

    #[test]
    fn exercise_nee_light_sample_finds_the_light() {
        // Without MIS the light sample alone finds the whole light.
        let (world, _) = sphere_light_scene(2);
        let reference = floor_reference();
        let (mean, se, rays) = light_samples_at_origin(&world, MisHeuristic::None, 4000);
        assert!(
            rays <= 4000,
            "light_sample: {rays} shadow rays for 4000 light samples: one each at most"
        );
        assert!(
            (mean - reference).abs() < 5.0 * se + 1e-3 * reference,
            "light_sample: with NEE and no MIS the light sample alone must find the sphere \
             light's {reference:.5} at the floor; yours averaged {mean:.5} ± {se:.5}: {}",
            if mean == 0.0 {
                "no light arrived, although nothing stands between them: the shadow ray was \
                 blocked by the light itself (it must stop short of the light it aims at)"
            } else if se == 0.0 {
                "every sample gave the same value, as if the sampled direction changed nothing: \
                 f cos θ is the BSDF's for that direction, bsdf.eval(wo, wi) with the direction \
                 towards the viewer first and the cosine the sampled direction's"
            } else {
                "the sample's term is L f cos θ / p_light (light_sample_contribution), with the \
                 density the light was sampled with"
            }
        );
    }

    #[test]
    fn exercise_nee_light_sample_shares_the_light_with_the_bsdf_sample() {
        // The BSDF sample's share, computed here on its own: cosine-weighted directions from
        // the floor's origin, those that hit the sphere weighted against the cone's density.
        let (world, _) = sphere_light_scene(2);
        let reference = floor_reference();
        let center = Vec3::new(0.0, 1.5, 0.0);
        let s = 0.5f64 / 1.5;
        let cone_pdf = (1.0 / (2.0 * PI64 * s * s / (1.0 + (1.0 - s * s).sqrt()))) as f32;
        for mis in [MisHeuristic::Power, MisHeuristic::Balance] {
            let directions = 200_000;
            let mut bsdf_share = 0.0f64;
            let mut rng = IndependentSampler::new(17);
            rng.start_pixel_sample(UVec2::ONE, 0);
            for _ in 0..directions {
                let local = ch02_monte_carlo::warps::sample_cosine_hemisphere(rng.get_2d());
                let w = Vec3::new(local.x, local.z, local.y);
                let b = w.dot(center);
                let hits = b > 0.0 && b * b - (center.length_squared() - 0.25) > 0.0;
                if hits {
                    // Albedo 0.5 times radiance 1, weighted.
                    bsdf_share += 0.5 * f64::from(mis.weight(w.y / std::f32::consts::PI, cone_pdf));
                }
            }
            let bsdf_share = bsdf_share / directions as f64;
            let (light_share, se) = {
                let (mean, se, _) = light_samples_at_origin(&world, mis, 4000);
                (mean, se)
            };
            let total = light_share + bsdf_share;
            assert!(
                (total - reference).abs() < 5.0 * se + 5e-3 * reference,
                "light_sample: with the {mis:?} heuristic the light sample's share \
                 ({light_share:.5} ± {se:.5}) and the BSDF sample's ({bsdf_share:.5}) must add \
                 up to the light, {reference:.5}, but add up to {total:.5}: {}",
                if se == 0.0 {
                    "every light sample gave the same value, as if the sampled direction changed \
                     nothing: f cos θ is the BSDF's for that direction, bsdf.eval(wo, wi) with \
                     the direction towards the viewer first"
                } else if total > reference {
                    "too much: the weight of a light sample is the light's density against the \
                     BSDF's density of the same direction, which the BSDF tells"
                } else {
                    "too little: the weight of a light sample is the light's density against \
                     the BSDF's, not the other way round"
                }
            );
        }
    }

    #[test]
    fn exercise_nee_light_sample_draws_only_what_it_needs() {
        // One light to pick from: nothing to choose, so only the point on it is drawn.
        let (world, _) = sphere_light_scene(2);
        with_path_tracer(&world, PathOptions::with_depth(2), |tracer| {
            let eye = Vec3::new(2.0, 1.0, 0.0);
            let ray = Ray::new(eye, -eye.normalize());
            let hit = world.intersect(&ray).expect("the floor");
            let bsdf = Bsdf {
                material: &world.scene.material_at(hit.shape, hit.uv),
                hit: &hit,
                fuzz: FuzzMethod::Lobe,
                coatings: &tracer.coatings,
            };
            let tally = crate::dimensions::DimensionTally::default();
            let mut sampler =
                crate::dimensions::CountingSampler::new(IndependentSampler::new(3), &tally);
            sampler.start_pixel_sample(UVec2::ZERO, 0);
            let mut counters = SampleCounters::default();
            tracer.light_sample(&bsdf, -ray.dir, 0.0, &mut sampler, &mut counters);
            assert!(
                sampler.drawn() == 2,
                "light_sample: with a single light to pick from, one light sample drew {} \
                 numbers; the pick needs no number then (a scene pays only for what it has), \
                 and the point on the light needs two",
                sampler.drawn()
            );
        });
    }

    #[test]
    fn exercise_nee_light_sample_picks_among_several_lights() {
        // Two sphere lights of different size and radiance: the pick takes a number and each
        // light is found with its own share.
        use common::geometry::{Parallelogram, Shape, Sphere};
        use common::scene::{Camera, CameraFrame, FilmSettings, SceneBuilder};
        let floor =
            Parallelogram::new(Vec3::new(-10.0, 0.0, -10.0), 20.0 * Vec3::Z, 20.0 * Vec3::X);
        let lights = [
            (Vec3::new(0.0, 1.5, 0.0), 0.5, 1.0),
            (Vec3::new(1.2, 1.0, -0.8), 0.25, 3.0),
        ];
        let builder = SceneBuilder::new().shape(
            Shape::Parallelogram(floor),
            Smooth::diffuse(Vec3::splat(0.5)),
        );
        let scene = lights
            .iter()
            .fold(builder, |b, &(center, radius, radiance)| {
                b.area_light(
                    Shape::Sphere(Sphere::new(center, radius)),
                    Smooth::diffuse(Vec3::ZERO),
                    Vec3::splat(radiance),
                )
            })
            .build(
                Camera::pinhole(
                    CameraFrame::look_at(Vec3::new(2.0, 1.0, 0.0), Vec3::ZERO, Vec3::Y).unwrap(),
                    40.0,
                ),
                FilmSettings::new(16, 16),
                2,
            );
        let world = MotionScene::still(scene);
        let each = lights.map(|(center, radius, radiance)| {
            let d = center.length();
            0.5 * f64::from(sphere_irradiance(Vec3::splat(radiance), radius, d, center.y / d).y)
                / PI64
        });
        let reference = each[0] + each[1];
        let (mean, se, _) = light_samples_at_origin(&world, MisHeuristic::None, 8000);
        let tolerance = 5.0 * se + 1e-3 * reference;
        if (mean - reference).abs() >= tolerance {
            let why = match each
                .iter()
                .position(|&share| (mean - 2.0 * share).abs() < tolerance)
            {
                Some(i) => format!(
                    "that is twice light {}'s share and nothing of the other's: only one light \
                     was ever picked (with several lights to pick from, the pick takes the \
                     sampler's next number)",
                    i + 1
                ),
                None => "each light is picked with its probability, and its sample's density \
                         holds that probability"
                    .to_string(),
            };
            panic!(
                "light_sample: a floor under two sphere lights should get {reference:.5} (their \
                 shares {:.5} and {:.5}) from the light samples alone; yours averaged \
                 {mean:.5} ± {se:.5}: {why}",
                each[0], each[1]
            );
        }
    }

    #[test]
    fn exercise_nee_light_sample_is_stopped_by_what_blocks_the_light() {
        // A panel between the floor's origin and the light.
        let (world, _) = sphere_light_scene_blocked(2);
        let (mean, _, rays) = light_samples_at_origin(&world, MisHeuristic::Power, 500);
        assert!(
            mean == 0.0,
            "light_sample: a panel stands between the floor and the light, yet light arrived \
             through the blocker ({mean:.5} on average): a light sample counts only when its \
             shadow ray reaches the light"
        );
        assert!(
            rays > 0,
            "light_sample: no shadow ray was counted: every shadow ray traced adds 1 to \
             counters.rays"
        );
    }

    /// A matte floor (albedo 0.5, y = 0, 20 wide) under a sphere light (radius 0.5, radiance
    /// 1, black surface) centred 1.5 above the origin, no sky; and the floor's origin.
    fn sphere_light_scene(max_depth: u32) -> (MotionScene, Vec3) {
        light_scene(max_depth, false)
    }

    /// The same with a black 1 x 1 panel 0.7 above the origin, between it and the light.
    fn sphere_light_scene_blocked(max_depth: u32) -> (MotionScene, Vec3) {
        light_scene(max_depth, true)
    }

    fn light_scene(max_depth: u32, blocked: bool) -> (MotionScene, Vec3) {
        use common::geometry::{Parallelogram, Shape, Sphere};
        use common::scene::{Camera, CameraFrame, FilmSettings, SceneBuilder};
        let floor =
            Parallelogram::new(Vec3::new(-10.0, 0.0, -10.0), 20.0 * Vec3::Z, 20.0 * Vec3::X);
        let light = Sphere::new(Vec3::new(0.0, 1.5, 0.0), 0.5);
        let mut builder = SceneBuilder::new()
            .shape(
                Shape::Parallelogram(floor),
                Smooth::diffuse(Vec3::splat(0.5)),
            )
            .area_light(Shape::Sphere(light), Smooth::diffuse(Vec3::ZERO), Vec3::ONE);
        if blocked {
            let panel = Parallelogram::new(Vec3::new(-0.5, 0.7, -0.5), Vec3::Z, Vec3::X);
            builder = builder.shape(Shape::Parallelogram(panel), Smooth::diffuse(Vec3::ZERO));
        }
        let scene = builder.build(
            Camera::pinhole(
                CameraFrame::look_at(Vec3::new(2.0, 1.0, 0.0), Vec3::ZERO, Vec3::Y).unwrap(),
                40.0,
            ),
            FilmSettings::new(16, 16),
            max_depth,
        );
        (MotionScene::still(scene), Vec3::ZERO)
    }

    /// A path tracer over `world`, its sphere lights sampled by solid angle.
    fn with_path_tracer<R>(
        world: &MotionScene,
        options: PathOptions,
        use_tracer: impl FnOnce(&PathTracer) -> R,
    ) -> R {
        let area_lights = AreaLights::of(&world.scene);
        let tracer = PathTracer {
            world,
            lights: SceneLights::of(world, &area_lights, LightSampling::solid_angle()),
            options,
            fuzz: FuzzMethod::Lobe,
            coatings: Coatings::of(&world.scene),
        };
        use_tracer(&tracer)
    }
}
