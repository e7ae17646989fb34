//! Next-event estimation: at each bounce, a shadow ray to every point light (and every
//! directional light) and one to one sampled light.
//!
//! The light sample ([`PathTracer::light_sample`]) estimates `∫ L_e f cos θ dω` from one
//! direction drawn towards a light, weighted by MIS against the BSDF sample that could have
//! found the same light ([`mis_weighted_contribution`]). A point light is a delta: no BSDF sample can
//! find it, so its weight is 1, and since there is nothing on it to sample, [`point_lights`]
//! counts every one of them with certainty.

use crate::bsdf::{Materials, SurfaceBsdf};
use crate::lights::SceneLights;
use crate::mis::MisHeuristic;
use crate::path::PathTracer;
use ch01_whitted::world::World;
use common::sampler::Sampler;
use common::scene::DirectSamples;
use glam::Vec3;

// ANCHOR: mis_weighted_contribution
/// The contribution of one light sample, visibility aside, for the radiance `emitted` arriving
/// along the sampled direction, `f_cos` (`f cos θ` there), the light's density `light_pdf`
/// (per solid angle, the pick of the light included), and the density `bsdf_pdf` with which
/// the BSDF would have sampled the same direction, combined by the heuristic `mis`.
///
/// A delta light (`light_pdf` infinite: a point light, where `emitted` is already `I / d²`,
/// picked with probability `pick_probability`) cannot be found by the BSDF. Anything with no
/// chance (a density of 0, or NaN), or carrying nothing, is 0, never NaN.
pub fn mis_weighted_contribution(
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
// ANCHOR_END: mis_weighted_contribution

impl<M: Materials> PathTracer<'_, M> {
    /// The light of every point light and every directional light at the surface of `bsdf`,
    /// seen from `wo`, each through its own shadow ray at shutter time `time`
    /// ([`point_lights`], [`directional_lights`]): deltas, with nothing to sample, so no number
    /// is drawn.
    pub fn delta_lights(&self, bsdf: &impl SurfaceBsdf, wo: Vec3, time: f32) -> Vec3 {
        let mut light = Vec3::ZERO;
        if !self.lights.points.is_empty() {
            light += point_lights(self.world, &self.lights, bsdf, wo, time);
        }
        if !self.lights.directionals.is_empty() {
            light += directional_lights(self.world, &self.lights, bsdf, wo, time);
        }
        light
    }

    // ANCHOR: nee_light_sample
    /// One light sample at the non-delta surface of `bsdf`, seen from `wo`: a light picked
    /// among the emitters and the environment ([`SceneLights::pick_with_rest`]), a
    /// direction to it ([`SceneLights::sample`]), its MIS-weighted contribution
    /// ([`mis_weighted_contribution`]), and the shadow ray at shutter time `time`.
    ///
    /// `counts` says how many light samples and BSDF samples the surface takes: the path
    /// takes one of each ([`DirectSamples::ONE_EACH`]), Mitsuba's `direct` integrator may take
    /// more ([`crate::direct`]). In Veach's multi-sample model the counts matter twice: in the
    /// heuristic, where each strategy's density stands for all of its samples, and in the
    /// estimate, where one sample is one of several (the page asks how).
    ///
    /// A scene pays only for what it has: the pick draws no number of its own, the first
    /// coordinate of the 2D number that places the point picks the light first, as in
    /// Mitsuba 3 (and a sampler that places its 2D draws places the two together). What does
    /// the BSDF say about the sampled direction, for the term and for the
    /// weight? When is a shadow ray worth tracing? It must not be blocked by the light it aims
    /// at, which is itself a shape of the world.
    pub fn light_sample<S: Sampler>(
        &self,
        bsdf: &impl SurfaceBsdf,
        wo: Vec3,
        time: f32,
        counts: DirectSamples,
        sampler: &mut S,
    ) -> Vec3 {
        // BEGIN SOLUTION
        // One 2D number: its first coordinate picks the light, and what is left of it, with
        // the second, places the point on that light. Picking draws no number of its own.
        let u = sampler.get_2d();
        let Some((light, rest)) = self.lights.pick_with_rest(u.x) else {
            return Vec3::ZERO;
        };
        let Some(sample) = self
            .lights
            .sample(light, bsdf.hit(), glam::Vec2::new(rest, u.y))
        else {
            return Vec3::ZERO;
        };
        // Nothing to carry (the light's back, a direction the surface does not scatter to,
        // a point with no chance): no shadow ray, and no density to weigh with.
        let f_cos = bsdf.eval(wo, sample.wi);
        let no_chance = sample.pdf.is_nan() || sample.pdf <= 0.0;
        if sample.radiance == Vec3::ZERO || f_cos == Vec3::ZERO || no_chance {
            return Vec3::ZERO;
        }
        if self.world.occluded(&sample.shadow_ray(bsdf.hit(), time)) {
            return Vec3::ZERO;
        }
        // Each density times its count: the weight is the multi-sample heuristic's, and
        // dividing by `n_light p_light` divides the estimate by the count as well.
        let (n_light, n_bsdf) = (counts.emitter as f32, counts.bsdf as f32);
        mis_weighted_contribution(
            sample.radiance,
            f_cos,
            n_light * sample.pdf,
            n_bsdf * bsdf.pdf(wo, sample.wi),
            self.lights.pick_probability(),
            self.options.mis,
        )
        // END SOLUTION
    }
    // ANCHOR_END: nee_light_sample
}

// ANCHOR: point_lights
/// The light of every point light at the surface of `bsdf`, seen from `wo`: one shadow ray
/// each at shutter time `time`, traced only where the light would add something. A point
/// light is a delta, so no number is drawn and no MIS weight is needed: each one is counted
/// with probability 1, as chapter 01 lights its matte surfaces.
pub fn point_lights<W: World>(
    world: &W,
    lights: &SceneLights,
    bsdf: &impl SurfaceBsdf,
    wo: Vec3,
    time: f32,
) -> Vec3 {
    let mut sum = Vec3::ZERO;
    for light in lights.points {
        let to_light = light.position - bsdf.hit().p;
        let d2 = to_light.length_squared();
        let f_cos = bsdf.eval(wo, to_light / d2.sqrt());
        // A delta light: its density is infinite and only `I / d²` arrives.
        let contribution = mis_weighted_contribution(
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
        if !world.occluded(&bsdf.hit().spawn_ray_to(light.position, time)) {
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
pub fn directional_lights<W: World>(
    world: &W,
    lights: &SceneLights,
    bsdf: &impl SurfaceBsdf,
    wo: Vec3,
    time: f32,
) -> Vec3 {
    let mut sum = Vec3::ZERO;
    for light in lights.directionals {
        let wi = -light.direction;
        let contribution = mis_weighted_contribution(
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
        if !world.occluded(&bsdf.hit().spawn_ray(wi, time)) {
            sum += contribution;
        }
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bsdf::Bsdf;
    use crate::options::PathOptions;
    use crate::path::tests::{sphere_light_scene, sphere_light_scene_blocked, with_path_tracer};
    use ch05_motion_blur::MotionScene;
    use ch06_fuzzy_reflections::FuzzMethod;
    use ch07_soft_shadows::reference::sphere_irradiance;
    use common::Ray;
    use common::render::counting_rays;
    use common::sampler::IndependentSampler;
    use common::scene::Material as Smooth;
    use glam::UVec2;
    use std::f64::consts::PI as PI64;

    /// One light sample and one BSDF sample at a surface, as the path takes them.
    const ONE_EACH: DirectSamples = DirectSamples::ONE_EACH;

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
                "plain NEE: no heuristic, the light sample counts in full",
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
                "a point light (infinite density) cannot be found by the BSDF; what makes up for picking it one time in four?",
            ),
            (
                0.5,
                3.0,
                0.25,
                MisHeuristic::None,
                Vec3::new(1.0, 2.0, 4.0),
                "the light's density already holds the chance of picking the light",
            ),
        ];
        for (light_pdf, bsdf_pdf, pick, mis, expected, why) in cases {
            let c = mis_weighted_contribution(le, f, light_pdf, bsdf_pdf, pick, mis);
            if (c - expected).abs().max_element() < 1e-6 {
                continue;
            }
            // The usual slips, by how far they are off the expected value: the light
            // strategy's weight left out, or the BSDF strategy's used instead.
            let (light_weight, bsdf_weight) = (
                mis.weight(light_pdf, bsdf_pdf),
                mis.weight(bsdf_pdf, light_pdf),
            );
            let off_by = |factor: f32| (c - expected * factor).abs().max_element() < 1e-6;
            let mistake =
                if light_pdf.is_finite() && mis != MisHeuristic::None && off_by(1.0 / light_weight)
                {
                    "the MIS weight is missing".to_string()
                } else if light_pdf.is_finite() && off_by(bsdf_weight / light_weight) {
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
                "mis_weighted_contribution: {mistake}.\n  L = {le}, f cos = {f}, p_light = \
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
            let c = mis_weighted_contribution(emitted, f, light_pdf, bsdf_pdf, 1.0, mis);
            assert!(
                c == Vec3::ZERO,
                "mis_weighted_contribution: a sample the light could not have drawn (density \
                 {light_pdf}) or that carries nothing contributes 0, never NaN or infinity; \
                 L = {emitted}, p_bsdf = {bsdf_pdf} gave {c}"
            );
        }
    }

    // One light sample.

    /// The mean and standard error (green channel) of `light_sample` with `counts` at the
    /// floor's origin of `world`, seen from (2, 1, 0), over `n` sample streams; and the shadow
    /// rays it traced.
    fn light_samples_at_origin(
        world: &MotionScene,
        mis: MisHeuristic,
        counts: DirectSamples,
        n: u64,
    ) -> (f64, f64, u64) {
        let options = PathOptions {
            mis,
            ..PathOptions::with_depth(2)
        };
        with_path_tracer(world, options, |tracer| {
            let eye = Vec3::new(2.0, 1.0, 0.0);
            let ray = Ray::new(eye, -eye.normalize());
            let hit = world.intersect(&ray).expect("the floor");
            let bsdf = Bsdf {
                material: &world.material_at(&hit),
                hit: &hit,
                fuzz: FuzzMethod::Lobe,
            };
            let mut sampler = IndependentSampler::new(9);
            let (mut sum, mut sum2, mut shadow_rays) = (0.0f64, 0.0f64, 0);
            for i in 0..n {
                sampler.start_pixel_sample(UVec2::ZERO, i);
                let (l, rays) = counting_rays(|| {
                    tracer.light_sample(&bsdf, -ray.dir, 0.0, counts, &mut sampler)
                });
                shadow_rays += rays;
                assert!(
                    l.is_finite() && l.cmpge(Vec3::ZERO).all(),
                    "light_sample: a light sample gave {l}: never negative, NaN or infinite"
                );
                let x = f64::from(l.y);
                (sum, sum2) = (sum + x, sum2 + x * x);
            }
            let mean = sum / n as f64;
            let variance = (sum2 / n as f64 - mean * mean).max(0.0);
            (mean, (variance / n as f64).sqrt(), shadow_rays)
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
        let (mean, se, rays) = light_samples_at_origin(&world, MisHeuristic::None, ONE_EACH, 4000);
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
                "the sample's term is L f cos θ / p_light (mis_weighted_contribution), with the \
                 density the light was sampled with"
            }
        );
    }

    /// What the BSDF samples that go with light samples of `counts` find of the sphere light of
    /// [`sphere_light_scene`] at the floor's origin, computed here on their own: all of them
    /// together, as `direct` weighs and divides them (cosine-weighted directions, those that
    /// hit the sphere weighted against the cone's density, each density times its count).
    fn bsdf_share(mis: MisHeuristic, counts: DirectSamples) -> f64 {
        let center = Vec3::new(0.0, 1.5, 0.0);
        let s = 0.5f64 / 1.5;
        let cone_pdf = (1.0 / (2.0 * PI64 * s * s / (1.0 + (1.0 - s * s).sqrt()))) as f32;
        let (n_light, n_bsdf) = (counts.emitter as f32, counts.bsdf as f32);
        if counts.bsdf == 0 {
            return 0.0;
        }
        let directions = 200_000;
        let mut share = 0.0f64;
        let mut rng = IndependentSampler::new(17);
        rng.start_pixel_sample(UVec2::ONE, 0);
        for _ in 0..directions {
            let local = ch02_monte_carlo::warps::sample_cosine_hemisphere(rng.get_2d());
            let w = Vec3::new(local.x, local.z, local.y);
            let b = w.dot(center);
            let hits = b > 0.0 && b * b - (center.length_squared() - 0.25) > 0.0;
            if hits {
                // Albedo 0.5 times radiance 1, weighted.
                let bsdf_pdf = w.y / std::f32::consts::PI;
                share += 0.5 * f64::from(mis.weight(n_bsdf * bsdf_pdf, n_light * cone_pdf));
            }
        }
        share / directions as f64
    }

    #[test]
    fn exercise_nee_light_sample_shares_the_light_with_the_bsdf_sample() {
        let (world, _) = sphere_light_scene(2);
        let reference = floor_reference();
        for mis in [MisHeuristic::Power, MisHeuristic::Balance] {
            let bsdf_share = bsdf_share(mis, ONE_EACH);
            let (light_share, se) = {
                let (mean, se, _) = light_samples_at_origin(&world, mis, ONE_EACH, 4000);
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
        // One 2D number picks the light and places the point on it: two numbers.
        let (world, _) = sphere_light_scene(2);
        with_path_tracer(&world, PathOptions::with_depth(2), |tracer| {
            let eye = Vec3::new(2.0, 1.0, 0.0);
            let ray = Ray::new(eye, -eye.normalize());
            let hit = world.intersect(&ray).expect("the floor");
            let bsdf = Bsdf {
                material: &world.material_at(&hit),
                hit: &hit,
                fuzz: FuzzMethod::Lobe,
            };
            let tally = crate::dimensions::DimensionTally::default();
            let mut sampler =
                crate::dimensions::CountingSampler::new(IndependentSampler::new(3), &tally);
            sampler.start_pixel_sample(UVec2::ZERO, 0);
            tracer.light_sample(&bsdf, -ray.dir, 0.0, ONE_EACH, &mut sampler);
            assert!(
                sampler.drawn() == 2,
                "light_sample: one light sample drew {} numbers; the point on the light \
                 needs two, and the pick needs no number of its own: it reads the first of \
                 the two and leaves the rest of it to the point (a scene pays only for what it \
                 has)",
                sampler.drawn()
            );
        });
    }

    #[test]
    fn exercise_nee_light_sample_picks_among_several_lights() {
        // Two sphere lights of different size and radiance: the pick reads a number and each
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
        let (mean, se, _) = light_samples_at_origin(&world, MisHeuristic::None, ONE_EACH, 8000);
        let tolerance = 5.0 * se + 1e-3 * reference;
        if (mean - reference).abs() >= tolerance {
            let why = match each
                .iter()
                .position(|&share| (mean - 2.0 * share).abs() < tolerance)
            {
                Some(i) => format!(
                    "that is twice light {}'s share and nothing of the other's: only one light \
                     was ever picked (with several lights to pick from, the pick reads the \
                     first coordinate of the light sample's 2D number)",
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
        let (mean, _, rays) = light_samples_at_origin(&world, MisHeuristic::Power, ONE_EACH, 500);
        assert!(
            mean == 0.0,
            "light_sample: a panel stands between the floor and the light, yet light arrived \
             through the blocker ({mean:.5} on average): a light sample counts only when its \
             shadow ray reaches the light"
        );
        assert!(
            rays > 0,
            "light_sample: no shadow ray was traced, though the light sample carries light to \
             the floor when nothing blocks it"
        );
    }

    #[test]
    fn exercise_nee_light_sample_weighs_each_density_by_its_count() {
        // Mitsuba's `direct` integrator takes several samples of each kind at a surface: a
        // light sample is then one of `emitter` light samples, weighed against `bsdf` BSDF
        // samples. All of them together must still find the light once.
        let (world, _) = sphere_light_scene(2);
        let reference = floor_reference();
        let mis = MisHeuristic::Power;
        let (alone, _, _) = light_samples_at_origin(&world, mis, ONE_EACH, 4000);
        for (emitter, bsdf) in [(3, 0), (2, 1), (1, 3)] {
            let counts = DirectSamples { emitter, bsdf };
            let (mean, se, _) = light_samples_at_origin(&world, mis, counts, 4000);
            let bsdf_share = bsdf_share(mis, counts);
            let total = f64::from(emitter) * mean + bsdf_share;
            if (total - reference).abs() < f64::from(emitter) * 5.0 * se + 5e-3 * reference {
                continue;
            }
            let why = if mean == alone {
                "each light sample was weighed as the only one beside a single BSDF sample: each \
                 density enters the heuristic multiplied by its strategy's count (counts.emitter \
                 and counts.bsdf), and dividing by the light's density so multiplied divides the \
                 term by the count as well"
            } else {
                "each density enters the heuristic multiplied by its strategy's count, and \
                 dividing by the light's density so multiplied divides the term by the count"
            };
            panic!(
                "light_sample: with {emitter} light samples and {bsdf} BSDF samples at a surface, \
                 the light samples' share ({emitter} x {mean:.5} ± {se:.5}) and the BSDF \
                 samples' ({bsdf_share:.5}) must add up to the light, {reference:.5}, but add up \
                 to {total:.5}: {why}"
            );
        }
    }
}
