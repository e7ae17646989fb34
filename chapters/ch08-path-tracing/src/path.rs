//! The path tracer: one path per camera ray, one direction per bounce.
//!
//! Chapter 06's tracer branches: glass may follow both rays, and every matte surface sends
//! shadow rays to every light. A path tracer keeps one sample per step, so a sample costs a
//! path of at most `max_depth` segments (plus its shadow rays at each bounce), and every kind
//! of light transport, indirect diffuse light included, is one integral estimated by one path.
//!
//! [`PathTracer::radiance`] is the whole path in one loop over local variables, as Mitsuba 3's
//! `path` integrator and pbrt-v4's `SimplePathIntegrator` write it. The loop carries the
//! *throughput* `β`, the product of the BSDF weights so far: what one unit of radiance found
//! at the path's end contributes to the pixel. Each turn of the loop is one segment:
//!
//! 1. find the surface the segment's ray meets, or the environment when it leaves the scene;
//! 2. add what it emits, weighted against the light sample that could have found it too
//!    (multiple importance sampling, [`crate::mis`]);
//! 3. stop at `max_depth`;
//! 4. at a non-delta surface, sample the lights (next-event estimation, [`crate::nee`]): a
//!    shadow ray to every point light, and one light sample among the lights a ray can find
//!    (area lights and the environment);
//! 5. sample the BSDF for the next direction ([`extend_path`]);
//! 6. from `rr_depth` on, Russian roulette ([`crate::roulette`]).
//!
//! Random numbers, after the camera's: per bounce, the light pick (only with several lights
//! to pick from) and the light point (two) when NEE samples a light, then the BSDF's (see
//! [`crate::bsdf`]), then one for the roulette when it is active. Point lights draw none. A
//! scene pays only for what it has: with point lights alone nothing is picked or sampled, and
//! when no ray can find emission (no area light, no environment) the last segment, which
//! could only find emission, is not traced. [`crate::dimensions`] counts the numbers a path
//! draws.

use crate::bsdf::{BsdfSample, LectureMaterials, Materials, SurfaceBsdf};
use crate::lights::SceneLights;
use crate::options::PathOptions;
use ch01_whitted::world::World;
use ch05_motion_blur::MotionScene;
use common::Ray;
use common::sampler::Sampler;
use glam::Vec3;

/// A path tracer over a scene, with the materials it knows (`M`, the lecture's unless told):
/// the loop is the same whatever materials it is given.
#[derive(Clone)]
pub struct PathTracer<'a, M: Materials = LectureMaterials> {
    /// The scene with its motion: shapes, surfaces, point lights, environment, camera.
    pub world: &'a MotionScene,
    /// Its lights as one list.
    pub lights: SceneLights<'a>,
    /// NEE, MIS, roulette, depth.
    pub options: PathOptions,
    /// The materials: what the BSDF of a surface is at a hit.
    pub materials: M,
}

impl<M: Materials> PathTracer<'_, M> {
    // ANCHOR: radiance
    /// The radiance arriving along `camera_ray`: one path, segment after segment (the camera
    /// ray is segment 1), until the scene's edge, `max_depth`, the BSDF or the roulette ends
    /// it. Every ray of the path keeps the camera ray's shutter time.
    ///
    /// Each segment finds a surface (or the environment) and adds the light it emits; while
    /// `max_depth` allows another segment, it samples the lights at a non-delta surface
    /// ([`delta_lights`](Self::delta_lights), [`light_sample`](Self::light_sample)), then the
    /// BSDF ([`extend_path`]), and from `rr_depth` on it plays the roulette
    /// ([`russian_roulette`](crate::roulette::russian_roulette)). Light found by a ray and light
    /// sampled at the surface the ray left can be the same light: how much of it does each
    /// count, and when can only one of them find it? What must the loop remember of a bounce
    /// for the next segment? Which throughput does the roulette look at after glass has scaled
    /// the radiance? The options say whether light is sampled at all (`nee`), how the two share
    /// a light (`mis`), and whether the camera hides what glows (`hide_emitters`,
    /// [`past_hidden_emitters`](Self::past_hidden_emitters)).
    pub fn radiance<S: Sampler>(&self, camera_ray: &Ray, sampler: &mut S) -> Vec3 {
        // BEGIN SOLUTION
        use crate::roulette::russian_roulette;
        use common::scene::DirectSamples;
        let mut ray = self.past_hidden_emitters(camera_ray);
        let mut radiance = Vec3::ZERO;
        // What the path carries, and the radiance scalings (eta_i / eta_t)² inside it.
        let (mut throughput, mut eta_scale) = (Vec3::ONE, 1.0);
        // The vertex the ray left and the BSDF's density of its direction, for the MIS
        // weight of the light the ray finds; infinite, as after a delta, for the camera ray.
        let (mut previous_p, mut previous_pdf) = (ray.origin, f32::INFINITY);
        for depth in 1.. {
            // The camera's and the BSDF's directions are unit: `-ray.dir` needs no normalising.
            debug_assert!(ray.dir.is_normalized(), "segment {depth}'s ray is not unit");
            // Light this ray finds shares with the light sample taken where it left (with
            // NEE, after a bounce that is not a delta); the camera's may be hidden.
            let weighed = self.options.nee && previous_pdf.is_finite();
            let shown = depth > 1 || !self.options.hide_emitters;

            // 1. Find the surface; a ray that leaves the scene finds the environment.
            let Some(hit) = self.world.intersect(&ray) else {
                if shown && self.lights.has_environment() {
                    let weight = if weighed {
                        let light_pdf = self.lights.environment_pdf(ray.dir);
                        self.options.mis.bsdf_sample_weight(previous_pdf, light_pdf)
                    } else {
                        1.0
                    };
                    radiance += throughput * (self.lights.environment.radiance(ray.dir) * weight);
                }
                break;
            };

            // 2. Add what the surface emits, with its MIS weight.
            if shown
                && self.lights.has_area_lights()
                && let Some(light) = self.lights.area_light_of(hit.shape)
            {
                let le = self
                    .lights
                    .emitted(light, hit.shape, hit.n, || Some(hit.uv), -ray.dir);
                if le != Vec3::ZERO {
                    let weight = if weighed {
                        let light_pdf = self.lights.area_pdf(light, previous_p, hit.p, hit.n);
                        self.options.mis.bsdf_sample_weight(previous_pdf, light_pdf)
                    } else {
                        1.0
                    };
                    radiance += throughput * (le * weight);
                }
            }

            // 3. Stop at the depth: no segment left for a light sample or a bounce.
            if depth >= self.options.max_depth {
                break;
            }
            let material = self.world.material_at(&hit);
            let bsdf = self.materials.bsdf(&material, &hit);
            let wo = -ray.dir;

            // 4. Sample a light (NEE) where the BSDF is not a delta: each point and
            //    directional light by its own shadow ray, one light a ray can find by a sample.
            if self.options.nee && !bsdf.is_delta() {
                let mut direct = Vec3::ZERO;
                if self.lights.has_delta_lights() {
                    direct += self.delta_lights(&bsdf, wo, ray.time);
                }
                if self.lights.can_be_hit() {
                    let one_each = DirectSamples::ONE_EACH;
                    direct += self.light_sample(&bsdf, wo, ray.time, one_each, sampler);
                }
                radiance += throughput * direct;
            }
            // The next segment would be the last, and no ray can find light: it is skipped
            // with its numbers, the sample's last, so the image is the same.
            if depth + 1 >= self.options.max_depth && !self.lights.can_be_hit() {
                break;
            }

            // 5. Sample the BSDF: the next direction, its weight carried in the throughput.
            let Some(sample) = extend_path(&bsdf, wo, &mut throughput, &mut eta_scale, sampler)
            else {
                break;
            };
            (previous_p, previous_pdf) = (hit.p, sample.pdf);
            ray = hit.spawn_ray(sample.wi, ray.time);

            // 6. Russian roulette from rr_depth on, on the throughput without its radiance scaling.
            if let Some(rr_depth) = self.options.rr_depth
                && depth >= rr_depth
            {
                let throughput_max = throughput.max_element() / eta_scale;
                let Some(survivor) = russian_roulette(throughput_max, sampler.get_1d()) else {
                    break;
                };
                throughput *= survivor;
            }
        }
        radiance
        // END SOLUTION
    }
    // ANCHOR_END: radiance

    /// The camera ray as Mitsuba's `hide_emitters` has it: for the camera, shapes that emit
    /// light are not there. The ray passes through each one it meets and goes on from its far
    /// side, so that a hidden lamp shows what is behind it rather than a black silhouette.
    /// They still block shadow rays and later segments, and still light the scene. Without
    /// `hide_emitters`, the ray itself. Draws no random number, so every other pixel keeps
    /// its samples.
    pub fn past_hidden_emitters(&self, camera_ray: &Ray) -> Ray {
        if self.options.hide_emitters && self.lights.has_area_lights() {
            self.through_emitters(camera_ray)
        } else {
            *camera_ray
        }
    }

    /// The camera ray continued through every emitting shape it meets, for
    /// [`past_hidden_emitters`](Self::past_hidden_emitters).
    fn through_emitters(&self, camera_ray: &Ray) -> Ray {
        /// More emitting surfaces in a row than any scene stacks; a hostile one that does
        /// shows the last as a black surface instead of looping on.
        const MOST_SKIPPED: usize = 1024;
        let mut ray = *camera_ray;
        for _ in 0..MOST_SKIPPED {
            match self.world.intersect(&ray) {
                Some(hit) if self.lights.area_light_of(hit.shape).is_some() => {
                    ray = hit.spawn_ray(ray.dir, ray.time);
                }
                _ => break,
            }
        }
        ray
    }
}

// ANCHOR: extend_path
/// The BSDF step at the surface of `bsdf`, seen from `wo`: a direction sampled from the BSDF,
/// and what that sample does to the two numbers the path carries: `throughput`, what the path
/// carries to the camera, and `eta_scale`, the product of the radiance scalings of refraction
/// (chapter 01) that `throughput` holds. Returns the sample, whose direction the next segment
/// follows and whose density the MIS weight of what that segment finds needs; `None` when the
/// path ends here: no direction, or nothing left to carry.
pub fn extend_path<S: Sampler>(
    bsdf: &impl SurfaceBsdf,
    wo: Vec3,
    throughput: &mut Vec3,
    eta_scale: &mut f32,
    sampler: &mut S,
) -> Option<BsdfSample> {
    // BEGIN SOLUTION
    let sample = bsdf.sample(wo, sampler)?;
    *throughput *= sample.weight;
    *eta_scale *= sample.eta_scale;
    // A throughput that is not finite is a bug at its source: it is not hidden here, but
    // reaches the film, which counts it (`nonfinite_samples`).
    if *throughput == Vec3::ZERO {
        return None;
    }
    Some(sample)
    // END SOLUTION
}
// ANCHOR_END: extend_path

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::bsdf::Bsdf;
    use crate::bsdf::test_support::floor_hit;
    use crate::furnace::spheres;
    use crate::mis::MisHeuristic;
    use ch01_whitted::world::World;
    use ch06_fuzzy_reflections::FuzzMethod;
    use ch07_soft_shadows::reference::sphere_irradiance;
    use ch07_soft_shadows::{AreaLights, LightSampling};
    use common::sampler::IndependentSampler;
    use common::scene::Material as Smooth;
    use common::scene::Material;
    use glam::{UVec2, Vec2};
    use std::f64::consts::PI as PI64;

    /// A tracer over a furnace scene (one sphere of `material` in a sky of radiance 1).
    fn with_tracer<R>(
        material: Material,
        options: PathOptions,
        use_tracer: impl FnOnce(&PathTracer) -> R,
    ) -> R {
        let world = spheres(&[material], options.max_depth);
        with_path_tracer(&world, options, use_tracer)
    }

    /// What one call of `extend_path` did to a path carrying `throughput` and `eta_scale`:
    /// the sample it returned, and what the path carries after it.
    struct Extension {
        sample: Option<BsdfSample>,
        throughput: Vec3,
        eta_scale: f32,
    }

    /// `extend_path` at the surface of `bsdf`, seen from `wo`, on sample stream `i` of seed
    /// 11, for a path carrying `throughput` and `eta_scale`.
    fn extend(bsdf: &Bsdf, wo: Vec3, throughput: Vec3, eta_scale: f32, i: u64) -> Extension {
        let mut sampler = IndependentSampler::new(11);
        sampler.start_pixel_sample(UVec2::ZERO, i);
        let (mut throughput, mut eta_scale) = (throughput, eta_scale);
        let sample = extend_path(bsdf, wo, &mut throughput, &mut eta_scale, &mut sampler);
        Extension {
            sample,
            throughput,
            eta_scale,
        }
    }

    /// The BSDF's own sample from the numbers `extend` gives stream `i`.
    fn own_sample(bsdf: &Bsdf, wo: Vec3, i: u64) -> Option<BsdfSample> {
        let mut sampler = IndependentSampler::new(11);
        sampler.start_pixel_sample(UVec2::ZERO, i);
        bsdf.sample(wo, &mut sampler)
    }

    #[test]
    fn exercise_extend_path_multiplies_the_throughput_and_returns_the_sample() {
        let grey = Smooth::diffuse(Vec3::new(0.5, 0.25, 1.0));
        let hit = floor_hit();
        let bsdf = Bsdf {
            material: &grey,
            hit: &hit,
            fuzz: FuzzMethod::Lobe,
        };
        let carried = Vec3::new(0.5, 1.0, 2.0);
        for i in 0..64 {
            let next = extend(&bsdf, Vec3::Y, carried, 1.0, i);
            let Some(sample) = next.sample else {
                panic!(
                    "extend_path: a matte surface seen from its front always scatters, so the \
                     path goes on; yours ended it"
                );
            };
            // A cosine-sampled matte surface: weight = albedo, pdf = cos θ / π.
            let expected = Vec3::new(0.25, 0.25, 2.0);
            let throughput = next.throughput;
            let why = if throughput == carried {
                "the throughput was not multiplied by the sample's weight"
            } else if throughput == Vec3::new(0.5, 0.25, 1.0) {
                "the throughput became the sample's weight: it is multiplied into what the path \
                 already carries"
            } else {
                "what does the sample's weight do to what the path already carries?"
            };
            assert!(
                (throughput - expected).abs().max_element() < 1e-6,
                "extend_path: the new throughput is {throughput}, expected {expected}: {why} \
                 (carried {carried}, albedo (0.5, 0.25, 1))"
            );
            assert!(
                next.eta_scale == 1.0,
                "extend_path: a matte bounce scales no radiance, so eta_scale stays 1, not {}",
                next.eta_scale
            );
            let own = own_sample(&bsdf, Vec3::Y, i).expect("a matte floor scatters");
            assert!(
                sample == own,
                "extend_path: it returned {sample:?}, but the BSDF sampled {own:?} from the \
                 same numbers: return the BSDF's sample as it is, since the next segment follows \
                 its direction and the MIS weight at the next hit needs its density"
            );
        }
    }

    #[test]
    fn exercise_extend_path_carries_the_radiance_scaling_through_glass() {
        // Smooth glass refracts part of the time, scaling radiance by (eta_i / eta_t)²: the
        // path's eta_scale gathers those factors, as its throughput gathers the weights.
        let glass = Smooth::glass(1.5);
        let hit = floor_hit();
        let bsdf = Bsdf {
            material: &glass,
            hit: &hit,
            fuzz: FuzzMethod::Lobe,
        };
        let wo = Vec3::new(0.3, 1.0, 0.2).normalize();
        let (carried, carried_eta) = (Vec3::new(0.5, 1.0, 2.0), 0.8);
        let mut refracted = 0;
        for i in 0..64 {
            let Some(sample) = own_sample(&bsdf, wo, i) else {
                continue;
            };
            let next = extend(&bsdf, wo, carried, carried_eta, i);
            if next.sample.is_none() {
                panic!(
                    "extend_path: glass gave a direction ({sample:?}) and the path carries \
                     something, so it goes on; yours ended it"
                );
            }
            refracted += usize::from(sample.eta_scale != 1.0);
            let expected = carried_eta * sample.eta_scale;
            let got = next.eta_scale;
            if (got - expected).abs() > 1e-6 * expected {
                let why = if got == carried_eta {
                    "the sample's radiance scaling was not multiplied in"
                } else if (got - sample.eta_scale).abs() <= 1e-6 * sample.eta_scale {
                    "the sample's scaling replaced what the path carried; it is multiplied into \
                     it"
                } else if (got - carried_eta / sample.eta_scale).abs() <= 1e-6 * got {
                    "the path's eta_scale was divided by the sample's; it is multiplied by it"
                } else {
                    "what does the sample's radiance scaling do to the path's?"
                };
                panic!(
                    "extend_path: through glass the sample scales radiance by {}, so the path's \
                     eta_scale goes from {carried_eta} to {expected}; yours is {got}: {why}",
                    sample.eta_scale
                );
            }
            let throughput = carried * sample.weight;
            assert!(
                (next.throughput - throughput).abs().max_element()
                    <= 1e-5 * throughput.max_element(),
                "extend_path: through glass the new throughput is {}, expected {throughput}: \
                 the sample's weight carries over to the path as on a matte surface",
                next.throughput
            );
        }
        assert!(refracted > 0, "the check's samples refract");
    }

    #[test]
    fn exercise_extend_path_ends_paths_that_carry_nothing() {
        let black = Smooth::diffuse(Vec3::ZERO);
        let hit = floor_hit();
        let bsdf = Bsdf {
            material: &black,
            hit: &hit,
            fuzz: FuzzMethod::Lobe,
        };
        let went_on = (0..16)
            .filter(|&i| extend(&bsdf, Vec3::Y, Vec3::ONE, 1.0, i).sample.is_some())
            .count();
        assert!(
            went_on == 0,
            "extend_path: after a black surface the path carries nothing, so it ends; {went_on} \
             of 16 went on (each costs rays and can add nothing)"
        );
    }

    #[test]
    fn exercise_extend_path_lets_the_furnace_return_one() {
        // Paths made of `extend_path` alone: a white matte sphere under a sky of 1 sends back
        // exactly 1 whatever the bounces, so every path that leaves the sphere carries 1.
        let white = Smooth::diffuse(Vec3::ONE);
        let world = spheres(std::slice::from_ref(&white), 64);
        let eye = Vec3::new(0.0, 0.5, 4.0);
        let mut sampler = IndependentSampler::new(5);
        let mut bounces = 0;
        for i in 0..256 {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            let mut ray = Ray::new(eye, (Vec3::new(0.1, 0.2, 0.0) - eye).normalize());
            let (mut throughput, mut eta_scale) = (Vec3::ONE, 1.0);
            let mut depth = 1;
            while let Some(hit) = world.intersect(&ray) {
                let bsdf = Bsdf {
                    material: &white,
                    hit: &hit,
                    fuzz: FuzzMethod::Lobe,
                };
                let next = extend_path(
                    &bsdf,
                    -ray.dir,
                    &mut throughput,
                    &mut eta_scale,
                    &mut sampler,
                );
                let Some(sample) = next else {
                    panic!(
                        "extend_path: a white matte sphere seen from outside always scatters, \
                         but the path ended at depth {depth}"
                    );
                };
                ray = hit.spawn_ray(sample.wi, 0.0);
                depth += 1;
                bounces += 1;
                assert!(depth < 64, "extend_path: the path never leaves the sphere");
            }
            assert!(
                (throughput - Vec3::ONE).abs().max_element() < 1e-4,
                "extend_path: a white matte sphere under a sky of radiance 1 sends back exactly \
                 1 however the path bounces; this path carried {throughput} to the sky"
            );
        }
        assert!(bounces >= 256, "the paths bounced");
    }

    // The path loop: the capstone.

    /// The mean and the standard error of the radiance along `ray` (its green channel) over
    /// `n` paths with sample streams `0..n` of seed `seed`. Panics on a non-finite path.
    fn mean_radiance(tracer: &PathTracer, ray: &Ray, n: u64, seed: u64) -> (f64, f64) {
        let mut sampler = IndependentSampler::new(seed);
        let (mut sum, mut sum2) = (0.0f64, 0.0f64);
        for i in 0..n {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            let l = tracer.radiance(ray, &mut sampler);
            assert!(
                l.is_finite() && l.cmpge(Vec3::ZERO).all(),
                "radiance: a path brought back {l}: radiance is never negative, NaN or infinite"
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
    fn exercise_path_loop_counts_what_the_camera_ray_finds() {
        // max_depth 1: the camera ray alone, which sees what glows and nothing lit.
        let grey = Smooth::diffuse(Vec3::splat(0.5));
        let (to_sphere, to_sky) = furnace_rays();
        with_tracer(grey.clone(), PathOptions::with_depth(1), |tracer| {
            let (sky, _) = mean_radiance(tracer, &to_sky, 16, 1);
            assert!(
                (sky - 1.0).abs() < 1e-6,
                "radiance: a camera ray that leaves the scene sees the sky of radiance 1, yours \
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
                "radiance: at max_depth 1 a path is the camera ray alone, which sees only what \
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
                    "radiance: the camera sees a sphere light of radiance 1 at max_depth \
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
    fn exercise_path_loop_lights_the_furnace_once() {
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
                    "radiance: a grey sphere of albedo 0.5 under a sky of radiance 1 sends back \
                     0.5 at max_depth {max_depth}; yours averaged {mean:.4} ± {se:.4} over 4000 \
                     paths: {why}"
                );
            });
        }
    }

    #[test]
    fn exercise_path_loop_follows_the_options() {
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
                "radiance: without next-event estimation, a grey sphere of albedo 0.5 under a \
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
                    "radiance: the scene hides its emitters (hide_emitters), so a camera ray that \
                     leaves it sees nothing of the sky; yours brought back {sky} at max_depth \
                     {max_depth}"
                );
                if max_depth > 1 {
                    let (mean, se) = mean_radiance(tracer, &to_sphere, 4000, 8);
                    assert!(
                        (mean - 0.5).abs() < 5.0 * se + 1e-3,
                        "radiance: the scene hides its emitters from the camera ray only: the \
                         sky still lights the grey sphere, which sends back 0.5 at max_depth \
                         {max_depth}; yours averaged {mean:.4} ± {se:.4}"
                    );
                }
            });
        }
    }

    #[test]
    fn exercise_path_loop_shares_a_sphere_light_between_its_two_samples() {
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
                    "radiance: a floor of albedo 0.5 under a sphere light should reflect \
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

    #[test]
    fn exercise_path_loop_keeps_the_shutter_time() {
        // A grey sphere under a sky of 1, and a black lid that covers the sky above it at
        // shutter time 0 and has slid 10 000 units aside by time 1. A camera ray of time 1
        // sees the sphere lit by the whole sky (0.5) only if every later ray of its path,
        // bounce and shadow ray alike, is traced at time 1 too.
        use ch05_motion_blur::Shutter;
        use common::geometry::{Parallelogram, Shape, Sphere};
        use common::scene::{Camera, CameraFrame, FilmSettings, SceneBuilder};
        let lid = Parallelogram::new(
            Vec3::new(-50.0, 1.5, -50.0),
            100.0 * Vec3::Z,
            100.0 * Vec3::X,
        );
        let slide = vec![
            (0.0, glam::Mat4::IDENTITY),
            (1.0, glam::Mat4::from_translation(Vec3::new(1e4, 0.0, 0.0))),
        ];
        let eye = Vec3::new(0.0, 0.5, 4.0);
        let max_depth = 3;
        let mut camera = Camera::pinhole(
            CameraFrame::look_at(eye, Vec3::ZERO, Vec3::Y).expect("a valid camera"),
            40.0,
        );
        let shutter = Shutter::new(0.0, 1.0).expect("a valid shutter");
        (camera.shutter_open, camera.shutter_close) = (shutter.open, shutter.close);
        let scene = SceneBuilder::new()
            .shape(
                Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0)),
                Smooth::diffuse(Vec3::splat(0.5)),
            )
            .moving(
                Shape::Parallelogram(lid),
                slide,
                Smooth::diffuse(Vec3::ZERO),
            )
            .environment(Vec3::ONE)
            .build(camera, FilmSettings::new(16, 16), max_depth);
        let world = MotionScene::new(scene).expect("a valid motion");
        with_path_tracer(&world, PathOptions::with_depth(max_depth), |tracer| {
            let (to_sphere, _) = furnace_rays();
            let (mean, se) = mean_radiance(tracer, &to_sphere.with_time(1.0), 4000, 9);
            assert!(
                (mean - 0.5).abs() < 5.0 * se + 1e-3,
                "radiance: at shutter time 0 a black lid covers the grey sphere's sky, by time 1 \
                 it has slid far away; a camera ray of time 1 sees the sphere lit by the whole \
                 sky, 0.5, but yours averaged {mean:.4} ± {se:.4}: {}",
                if mean < 0.5 {
                    "every ray of a path keeps the camera ray's shutter time, the bounce's next \
                     ray and the light sample's shadow ray alike"
                } else {
                    "each light must be counted once"
                }
            );
        });
    }

    /// A sampler whose every number is `self.0`: a path whose every choice is known.
    #[derive(Clone)]
    struct Constant(f32);

    impl Sampler for Constant {
        fn start_pixel_sample(&mut self, _: UVec2, _: u64) {}
        fn get_pixel_2d(&mut self) -> Vec2 {
            Vec2::splat(self.0)
        }
        fn get_1d(&mut self) -> f32 {
            self.0
        }
    }

    #[test]
    fn exercise_path_loop_plays_the_roulette_from_rr_depth_on_the_unscaled_throughput() {
        // A glass sphere under a sky of 1, every number 0.6: the path refracts into the glass
        // (its radiance scaled by 1/1.5² = 0.44), out of it (scaled back by 1.5²), and leaves
        // for the sky. With roulette from segment 1, both bounces see the throughput without
        // its scaling, 1, so they survive with the chance MAX_SURVIVAL = 0.95 (0.6 is below
        // it) and each carries the roulette's factor for a survivor: the path brings back
        // that factor twice over.
        use crate::roulette::russian_roulette;
        let (to_sphere, _) = furnace_rays();
        let factor = russian_roulette(1.0, 0.6).expect("a throughput of 1 survives 0.6");
        let expected = factor * factor;
        let played = PathOptions {
            rr_depth: Some(1),
            ..PathOptions::with_depth(8)
        };
        with_tracer(Smooth::glass(1.5), played, |tracer| {
            let l = tracer.radiance(&to_sphere, &mut Constant(0.6)).y;
            if (l - expected).abs() > 1e-4 {
                let why = if l == 0.0 {
                    "the path ended at its first bounce, where the roulette saw 0.44: it looks at \
                     the throughput without its radiance scaling (throughput / eta_scale, 1 here), \
                     which says how much the path still matters"
                } else if (l - factor).abs() < 1e-4 {
                    "only the second bounce played the roulette: it is played from segment \
                     rr_depth on, that one included"
                } else if (l - 1.0).abs() < 1e-4 {
                    "no survivor carried more: a path that survives the roulette multiplies its \
                     throughput by the factor russian_roulette returns"
                } else {
                    "each bounce from rr_depth on plays the roulette once, on the throughput \
                     without its radiance scaling"
                };
                panic!(
                    "radiance: with roulette from segment 1 and every number 0.6, a path through \
                     a glass sphere survives both bounces and brings back the survivor's factor \
                     {factor:.4} twice over, {expected:.4}; yours brought back {l:.4}: {why}"
                );
            }
        });
        let off = PathOptions {
            rr_depth: None,
            ..PathOptions::with_depth(8)
        };
        with_tracer(Smooth::glass(1.5), off, |tracer| {
            let l = tracer.radiance(&to_sphere, &mut Constant(0.6)).y;
            assert!(
                (l - 1.0).abs() < 1e-4,
                "radiance: without roulette (rr_depth None) the same path through a glass sphere \
                 brings back the sky's 1; yours brought back {l:.4}"
            );
        });
    }

    /// A matte floor (albedo 0.5, y = 0, 20 wide) under a sphere light (radius 0.5, radiance
    /// 1, black surface) centred 1.5 above the origin, no sky; and the floor's origin.
    pub(crate) fn sphere_light_scene(max_depth: u32) -> (MotionScene, Vec3) {
        light_scene(max_depth, false)
    }

    /// The same with a black 1 x 1 panel 0.7 above the origin, between it and the light.
    pub(crate) fn sphere_light_scene_blocked(max_depth: u32) -> (MotionScene, Vec3) {
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
    pub(crate) fn with_path_tracer<R>(
        world: &MotionScene,
        options: PathOptions,
        use_tracer: impl FnOnce(&PathTracer) -> R,
    ) -> R {
        let area_lights = AreaLights::of(&world.scene);
        let tracer = PathTracer {
            world,
            lights: SceneLights::of(world, &area_lights, LightSampling::solid_angle()),
            options,
            materials: LectureMaterials {
                fuzz: FuzzMethod::Lobe,
            },
        };
        use_tracer(&tracer)
    }
}
