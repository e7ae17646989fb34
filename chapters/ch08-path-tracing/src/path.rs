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
//! 2. if `depth < max_depth` (the next segment is allowed), at a non-delta surface,
//!    next-event estimation: a shadow ray to every point light, and one light sample among
//!    the lights a ray can find (area lights and the environment); then one BSDF sample that
//!    extends the path;
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
use crate::mis::MisHeuristic;
use crate::nee::{light_sample_contribution, point_lights};
use crate::options::PathOptions;
use ch01_whitted::scene::World;
use ch05_motion_blur::MotionScene;
use ch06_fuzzy_reflections::FuzzMethod;
use common::Ray;
use common::geometry::SurfaceHit;
use common::render::SampleCounters;
use common::sampler::Sampler;
use glam::Vec3;

/// Where the previous bounce was, and how its direction was chosen: what the MIS weight of
/// light found by that direction needs.
#[derive(Clone, Copy, Debug)]
struct Previous {
    /// The surface point the direction left from.
    p: Vec3,
    /// The BSDF's density of the direction; infinite for a delta.
    pdf: f32,
}

/// What a path carries from one segment to the next.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Carried {
    /// The product of the BSDF weights (and roulette factors) so far: what one unit of
    /// radiance found at the path's end adds to the pixel.
    throughput: Vec3,
    /// The product of the radiance scalings `(eta_i / eta_t)²` inside `throughput`.
    eta_scale: f32,
}

/// A path between two of its segments: what it has gathered, what it carries on, and how its
/// last direction was chosen.
#[derive(Clone, Copy, Debug)]
struct PathState {
    /// The radiance gathered so far.
    radiance: Vec3,
    /// What the next segment's light is multiplied by.
    carried: Carried,
    /// The bounce the last direction left from; `None` for the camera ray (no MIS).
    previous: Option<Previous>,
}

impl PathState {
    /// A path about to trace its camera ray: nothing gathered, everything carried.
    const START: PathState = PathState {
        radiance: Vec3::ZERO,
        carried: Carried {
            throughput: Vec3::ONE,
            eta_scale: 1.0,
        },
        previous: None,
    };

    /// Adds `light` arriving at the current segment's end, times what the path carries.
    fn gather(&mut self, light: Vec3) {
        self.radiance += self.carried.throughput * light;
    }
}

/// The path's next segment: its ray, what it carries, and how its direction was chosen.
#[derive(Clone, Copy, Debug)]
struct NextSegment {
    ray: Ray,
    carried: Carried,
    previous: Previous,
}

/// A path tracer over a scene.
#[derive(Clone, Copy)]
pub struct PathTracer<'a> {
    /// The scene with its motion: shapes, surfaces, point lights, environment, camera.
    pub world: &'a MotionScene,
    /// Its lights as one list.
    pub lights: SceneLights<'a>,
    /// NEE, MIS, roulette, depth.
    pub options: PathOptions,
    /// How fuzzy lobes spread.
    pub fuzz: FuzzMethod,
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
        let mut next = self.segment(camera_ray, depth, &mut path, sampler, counters);
        while let Some(ray) = next {
            depth += 1;
            next = self.segment(&ray, depth, &mut path, sampler, counters);
        }
        path.radiance
    }

    /// Segment `depth` of `path`, along `ray`: the light it finds, the light sampled where it
    /// ends, and the ray of the next segment (`None` where the path ends).
    fn segment<S: Sampler>(
        &self,
        ray: &Ray,
        depth: u32,
        path: &mut PathState,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Option<Ray> {
        // Where the segment ends, or the environment if it leaves the scene.
        counters.rays += 1;
        let Some(hit) = self.world.intersect(ray) else {
            if self.lights.has_environment() {
                let pdf = self.lights.environment_pdf();
                let weight = self.emission_weight(path.previous, pdf);
                path.gather(self.lights.environment * weight);
            }
            return None;
        };
        // 1. What the surface emits, weighted against the light sample that could have found
        //    it.
        if self.lights.has_area_lights() {
            path.gather(self.emitted(&hit, ray, path.previous));
        }
        if depth >= self.options.max_depth {
            return None; // no segment left for a light sample or a bounce
        }
        let bsdf = Bsdf {
            material: &self.world.scene.surface(hit.shape).material,
            hit: &hit,
            fuzz: self.fuzz,
        };
        // Every ray of a path has a unit direction (the camera's and the BSDF's are built
        // unit), so `wo` needs no normalising; every test render checks it.
        debug_assert!(
            (ray.dir.length_squared() - 1.0).abs() < 1e-4,
            "a path ray of length {}",
            ray.dir.length()
        );
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
    }
    // ANCHOR_END: radiance

    // ANCHOR: extend_path
    /// The path's next segment from the surface of `bsdf`, seen from `wo`, where segment
    /// `depth` ended: a direction sampled from the BSDF, the throughput multiplied by its
    /// weight, then, from `rr_depth` on, Russian roulette on the throughput without its
    /// radiance scaling (`throughput / eta_scale`). `None` when the path ends: no direction,
    /// nothing carried, or the roulette says so.
    fn extend_path<S: Sampler>(
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

    /// What the surface at `hit` emits back along `ray`, MIS-weighted against the light
    /// sample taken at the previous bounce.
    #[inline]
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

    // ANCHOR: next_event
    /// Next-event estimation at the surface of `bsdf`, seen from `wo`: every point light
    /// through its own shadow ray (a delta has nothing to sample), and one light sample among
    /// the lights a ray can find.
    #[inline]
    fn next_event<S: Sampler>(
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
        if self.lights.can_be_hit() {
            light += self.light_sample(bsdf, wo, time, sampler, counters);
        }
        light
    }
    // ANCHOR_END: next_event

    // ANCHOR: light_sample
    /// One light sample at a non-delta surface: a light picked uniformly among the area
    /// lights and the environment, a direction to it, and the shadow ray, traced only when
    /// the sample carries something.
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
    }
    // ANCHOR_END: light_sample
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bsdf::test_support::floor_hit;
    use crate::furnace::spheres;
    use ch07_soft_shadows::{AreaLights, LightSampling};
    use common::sampler::IndependentSampler;
    use common::scene::Material as Smooth;
    use common::scene::Material;
    use glam::UVec2;

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
        with_tracer(grey, options, |tracer| {
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
        with_tracer(white, options, |tracer| {
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
            assert!(
                (count - expected).abs() < 5.0 * sigma,
                "extend_path: {count} of {n} paths survived the roulette, expected about \
                 {expected} ± {sigma:.1}: the path carries 0.45 through glass that scaled its \
                 radiance by 2.25, so the roulette must look at 0.45 / 2.25 = 0.2 (the \
                 throughput without its radiance scaling)"
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
    fn exercise_extend_path_ends_paths_that_carry_nothing() {
        let black = Smooth::diffuse(Vec3::ZERO);
        let carried = Carried {
            throughput: Vec3::ONE,
            eta_scale: 1.0,
        };
        with_tracer(black, PathOptions::with_depth(8), |tracer| {
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
        // The whole loop through `extend_path`: a white matte sphere under a sky of 1 sends
        // back exactly 1 whatever the bounces (mean of 256 paths through the centre pixel).
        let white = Smooth::diffuse(Vec3::ONE);
        let options = PathOptions {
            nee: false,
            rr_depth: None,
            ..PathOptions::with_depth(64)
        };
        with_tracer(white, options, |tracer| {
            let world = tracer.world;
            let camera = ch01_whitted::camera::PinholeCamera::of(&world.scene.camera, 64, 48);
            let ray = camera.generate_ray(glam::Vec2::new(32.5, 24.5));
            let mut sampler = IndependentSampler::new(5);
            let mut counters = SampleCounters::default();
            for i in 0..256 {
                sampler.start_pixel_sample(UVec2::ZERO, i);
                let l = tracer.radiance(&ray, &mut sampler, &mut counters);
                assert!(
                    (l - Vec3::ONE).abs().max_element() < 1e-4,
                    "extend_path: a white matte sphere under a sky of radiance 1 sends back \
                     exactly 1 however the path bounces; this path brought back {l}"
                );
            }
            assert!(counters.rays > 256, "the paths bounced");
        });
    }
}
