//! Chapter 06's `Lighting` hook answered for area lights.
//!
//! Chapter 06's tracer asks the lights two questions: what a surface a ray hits emits, and
//! what a matte surface reflects of the lights it sees. [`AreaLighting`] answers both:
//!
//! - **emitted**: a light is an ordinary shape of the world, so camera rays, mirror rays and
//!   rays through glass hit it like anything else. The hit's shape index says which light it
//!   is (a table with one entry per shape), and the light sends its radiance along the ray
//!   when the ray arrives on its front side;
//! - **matte**: chapter 01's point lights as before, plus, for every area light, `N` shadow
//!   rays to points on it, averaged by the estimator of [`crate::estimator`].
//!
//! No light is counted twice. A matte surface spawns no ray, so the area lights reach it only
//! through the shadow rays; a mirror, glass or a glossy surface sends no shadow ray to an area
//! light, so the lights reach it only through the rays it traces, which find the light's
//! surface and ask `emitted`.
//!
//! The random numbers: at each matte hit, light by light in the scene's order, the `2N`
//! numbers of that light's points, after the camera's and the earlier bounces' (pbrt-v4's
//! order). A scene without area lights draws none, and renders as chapter 06 does, bit for bit.

use crate::area_lights::{AreaLight, AreaLights};
use crate::shadow_rays::LightOptions;
use ch01_whitted::world::World;
use ch06_fuzzy_reflections::Lighting;
use common::Ray;
use common::geometry::SurfaceHit;
use common::sampler::Sampler;
use glam::Vec3;

/// The lights of a scene, point and area, for chapter 06's tracer.
#[derive(Clone, Copy, Debug)]
pub struct AreaLighting<'a> {
    /// The area lights, in the order their random numbers are drawn.
    pub lights: &'a [AreaLight],
    /// For every shape of the world (`SurfaceHit::shape`), the index of the light it is, if
    /// it is one.
    pub light_of_shape: &'a [Option<u32>],
    /// Shadow rays per light, their strata, and how points are chosen.
    pub options: LightOptions,
}

impl AreaLights {
    /// The lights for chapter 06's tracer, sampled as `options` say.
    pub fn lighting(&self, options: LightOptions) -> AreaLighting<'_> {
        AreaLighting {
            lights: &self.lights,
            light_of_shape: &self.light_of_shape,
            options,
        }
    }
}

impl AreaLighting<'_> {
    /// The area light the shape `shape` is, if any.
    pub fn light_of(&self, shape: u32) -> Option<&AreaLight> {
        let index = (*self.light_of_shape.get(shape as usize)?)?;
        self.lights.get(index as usize)
    }
}

impl Lighting for AreaLighting<'_> {
    fn emitted(&self, hit: &SurfaceHit, ray: &Ray) -> Vec3 {
        match self.light_of(hit.shape) {
            Some(light) => light.emitted(hit.n, -ray.dir),
            None => Vec3::ZERO,
        }
    }

    // ANCHOR: matte
    /// What a matte surface of albedo `albedo` at `hit` reflects towards the camera of every
    /// light: the point lights as chapter 01 lights them, and each area light estimated from
    /// `self.options.samples` shadow rays to points on it, drawn from `sampler` with
    /// [`LightOptions::points`].
    ///
    /// The surface's normal is its shading normal, turned to the side the ray arrives from;
    /// the back of a one-sided surface is black. For one point of a light ([`AreaLight::sample`]), in which measure was
    /// it chosen, and what does its term need in that measure
    /// ([`area_light_contribution`](crate::estimator::area_light_contribution) is the term
    /// per unit area)? Where must its shadow ray ([`LightSample::shadow_ray`]) stop, when the
    /// light is itself a shape of the world? How do the terms of one light make one estimate,
    /// and how does a matte surface turn irradiance into radiance?
    ///
    /// [`LightSample::shadow_ray`]: crate::light_sample::LightSample::shadow_ray
    fn matte<W: World, S: Sampler>(
        &self,
        world: &W,
        ray: &Ray,
        hit: &SurfaceHit,
        albedo: Vec3,
        two_sided: bool,
        sampler: &mut S,
    ) -> Vec3 {
        // BEGIN SOLUTION
        use crate::estimator::area_light_contribution;
        use ch01_whitted::tracer::direct_light;
        use glam::DVec3;
        let point_lights = direct_light(world, ray, hit, albedo, two_sided);
        let normal = if hit.front_face(ray.dir) {
            hit.shading_n
        } else if two_sided {
            -hit.shading_n
        } else {
            return point_lights; // the back of a one-sided surface is black
        };
        let mut irradiance = Vec3::ZERO;
        for light in self.lights {
            let points = self.options.points(sampler);
            // The sum of the terms, in f64 so that many samples lose no digits.
            let mut sum = DVec3::ZERO;
            for &u in &points {
                let Some(sample) = light.sample(hit.p, u, self.options.sampling) else {
                    continue; // a light without area
                };
                // The term in the measure the point was chosen in: by its direction,
                // `L cos θ / p_ω` (no cos θ′ / d² to divide by at the silhouette); by area,
                // `L cos θ cos θ′ / (d² p_A)`.
                let term = match sample.pdf_solid_angle {
                    Some(pdf_solid_angle) => {
                        let wi = (sample.p - hit.p).normalize();
                        let cos_theta = normal.dot(wi).max(0.0);
                        light.emitted(sample.n, -wi) * (cos_theta / pdf_solid_angle)
                    }
                    None => area_light_contribution(light, hit.p, normal, &sample),
                };
                // NaN (d = 0) and infinity (d² underflowing) come only from a point within a
                // float or so of the receiver: a set of measure zero. A term of 0 (the back
                // of the light, or below the horizon) needs no shadow ray.
                if !term.is_finite() || term == Vec3::ZERO {
                    continue;
                }
                // Offset at both ends, it stops short of the light, which is in the world.
                if !world.occluded(&sample.shadow_ray(hit, ray.time)) {
                    sum += term.as_dvec3();
                }
            }
            irradiance += (sum / points.len() as f64).as_vec3();
        }
        // A matte surface reflects ρ / π of its irradiance in every direction.
        point_lights + albedo * std::f32::consts::FRAC_1_PI * irradiance
        // END SOLUTION
    }
    // ANCHOR_END: matte
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::{polygon_irradiance, sphere_irradiance};
    use ch05_motion_blur::MotionScene;
    use common::geometry::{Parallelogram, Shape, Sphere};
    use common::render::counting_rays;
    use common::sampler::IndependentSampler;
    use common::scene::{Camera, CameraFrame, FilmSettings, Material, SceneBuilder};
    use glam::UVec2;
    use std::f64::consts::PI;

    const ALBEDO: f32 = 0.5;
    /// Where the receiver is looked at from: off to the side, clear of the lights.
    const EYE: Vec3 = Vec3::new(2.0, 1.0, 0.3);
    /// The point of the floor looked at, off the scene's origin (so that a term that forgets
    /// where the receiver is shows).
    const RECEIVER: Vec3 = Vec3::new(0.3, 0.0, -0.2);

    /// A matte floor (y = 0, facing up, 20 wide, albedo 0.5) and one light of radiance 1 of
    /// `shape`, with a black surface.
    fn scene_with(shape: Shape) -> MotionScene {
        scene_with_lights(&[shape])
    }

    /// The floor of [`scene_with`] under a light of radiance 1 of each of `shapes`.
    fn scene_with_lights(shapes: &[Shape]) -> MotionScene {
        let floor =
            Parallelogram::new(Vec3::new(-10.0, 0.0, -10.0), 20.0 * Vec3::Z, 20.0 * Vec3::X);
        let frame = CameraFrame::look_at(EYE, Vec3::ZERO, Vec3::Y).unwrap();
        let builder = SceneBuilder::new().shape(
            Shape::Parallelogram(floor),
            Material::diffuse(Vec3::splat(ALBEDO)),
        );
        let scene = shapes
            .iter()
            .fold(builder, |b, &shape| {
                b.area_light(shape, Material::diffuse(Vec3::ZERO), Vec3::ONE)
            })
            .build(Camera::pinhole(frame, 40.0), FilmSettings::new(16, 16), 2);
        MotionScene::still(scene)
    }

    /// The mean and standard error over `calls` of the radiance `matte` reflects from the
    /// floor's point `RECEIVER` towards `EYE`, with `samples` shadow rays per light; and the shadow
    /// rays traced.
    fn reflected(world: &MotionScene, samples: u32, calls: u64) -> (f64, f64, u64) {
        let area_lights = AreaLights::of(&world.scene);
        let lighting = area_lights.lighting(LightOptions::with_samples(samples));
        let ray = Ray::new(EYE, (RECEIVER - EYE).normalize());
        let hit = world.intersect(&ray).expect("the ray reaches the floor");
        assert!((hit.p - RECEIVER).length() < 1e-5, "the receiver: {hit:?}");
        let mut sampler = IndependentSampler::new(7);
        let (mut sum, mut sum2, mut shadow_rays) = (0.0f64, 0.0f64, 0);
        for i in 0..calls {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            let (l, rays) = counting_rays(|| {
                lighting.matte(world, &ray, &hit, Vec3::splat(ALBEDO), false, &mut sampler)
            });
            shadow_rays += rays;
            assert!(
                l.is_finite() && l.cmpge(Vec3::ZERO).all(),
                "matte: a matte floor under one light reflected {l}: never negative, NaN or \
                 infinite"
            );
            let x = f64::from(l.y);
            (sum, sum2) = (sum + x, sum2 + x * x);
        }
        let mean = sum / calls as f64;
        let variance = (sum2 / calls as f64 - mean * mean).max(0.0);
        (mean, (variance / calls as f64).sqrt(), shadow_rays)
    }

    /// Panics with what `mean` shows against `reference`, trying the usual slips `slips`
    /// (each a ratio to the reference and what it means) before the general `why`.
    fn judge(what: &str, mean: f64, se: f64, reference: f64, slips: &[(f64, &str)], why: &str) {
        let tolerance = 5.0 * se + 1e-3 * reference;
        if (mean - reference).abs() < tolerance {
            return;
        }
        let seen = slips
            .iter()
            .find(|(ratio, _)| (mean - ratio * reference).abs() < tolerance.max(0.02 * reference))
            .map_or(why, |(_, slip)| slip);
        panic!(
            "matte: {what} should reflect {reference:.5}; yours averaged {mean:.5} ± {se:.5} \
             ({:.3} times as much): {seen}",
            mean / reference
        );
    }

    const BLOCKED: &str = "no light arrived although nothing stands between the floor and \
        the light: the shadow ray was blocked by the light itself (the light is a shape of the \
        world, so its shadow ray must stop short of the light, offset at both ends)";
    const NO_PI: &str = "π times too bright: a matte surface reflects albedo / π of its \
        irradiance in every direction";

    #[test]
    fn exercise_matte_estimates_a_panel_light() {
        // A 1 x 1 panel facing down, 1 above the floor, off-centre: sampled by area.
        let quad = Parallelogram::new(Vec3::new(-0.2, 1.0, -0.7), Vec3::X, Vec3::Z);
        let vertices = [
            quad.corner(),
            quad.corner() + quad.e1(),
            quad.corner() + quad.e1() + quad.e2(),
            quad.corner() + quad.e2(),
        ];
        let irradiance = polygon_irradiance(RECEIVER, Vec3::Y, &vertices, Vec3::ONE).y;
        let reference = f64::from(ALBEDO) * f64::from(irradiance) / PI;
        let world = scene_with(Shape::Parallelogram(quad));
        for (samples, calls) in [(1, 4000), (4, 1000)] {
            let (mean, se, rays) = reflected(&world, samples, calls);
            assert!(
                rays <= u64::from(samples) * calls,
                "matte: {rays} shadow rays for {calls} hits with {samples} point(s) on the \
                 light each: one shadow ray per point at most"
            );
            let samples_f = f64::from(samples);
            let mut slips = vec![(0.0, BLOCKED), (std::f64::consts::PI, NO_PI)];
            let not_divided = format!(
                "{samples} times too bright with {samples} shadow rays: the terms of one light \
                 are averaged, not divided by the number of shadow rays and summed"
            );
            if samples > 1 {
                slips.insert(1, (samples_f, not_divided.as_str()));
            }
            judge(
                &format!("a floor of albedo 0.5 under a panel light, {samples} shadow ray(s)"),
                mean,
                se,
                reference,
                &slips,
                "is each point's term the light it sends, turned from a patch of the light's \
                 area into light arriving at the receiver and divided by the density it was \
                 chosen with, averaged over the shadow rays that reach the light?",
            );
        }
    }

    #[test]
    fn exercise_matte_estimates_a_sphere_light_by_its_cone() {
        // A sphere of radius 0.5 off to the side: sampled by the cone it covers.
        let center = Vec3::new(1.0, 1.5, 0.0);
        let d = f64::from((center - RECEIVER).length());
        let cos = f64::from(center.y - RECEIVER.y) / d;
        let irradiance = f64::from(sphere_irradiance(Vec3::ONE, 0.5, d as f32, cos as f32).y);
        let reference = f64::from(ALBEDO) * irradiance / PI;
        // Without the receiver's cosine the estimate is L times the cone's solid angle.
        // The cone's solid angle, from chapter 07's own cone.
        let cone = crate::solid_angle::sphere_cone(&Sphere::new(center, 0.5), RECEIVER)
            .expect("the receiver is outside the sphere");
        let solid_angle = 2.0 * PI * f64::from(cone.one_minus_cos_theta_max);
        let no_cos = solid_angle / irradiance;
        // The directions to the points taken from the scene's origin instead of the receiver.
        let light = AreaLight::new(Sphere::new(center, 0.5), Vec3::ONE);
        let points = crate::test_support::uniform_points(20_000, 5);
        let from_origin = points
            .iter()
            .filter_map(|&u| light.sample(RECEIVER, u, crate::LightSampling::solid_angle()))
            .map(|sample| {
                let wi = sample.p.normalize();
                let term = light.emitted(sample.n, -wi).y * wi.y.max(0.0)
                    / sample.pdf_solid_angle.unwrap_or(f32::NAN);
                f64::from(term)
            })
            .sum::<f64>()
            / points.len() as f64
            / irradiance;
        let world = scene_with(Shape::Sphere(Sphere::new(center, 0.5)));
        for (samples, calls) in [(1, 4000), (4, 1000)] {
            let (mean, se, _) = reflected(&world, samples, calls);
            let too_bright = "too bright: a point chosen by its direction has a density per unit \
                solid angle, and its term is L cos θ / p_ω; divided by the density per unit \
                area instead, it lacks the conversion d² / |cos θ′|";
            judge(
                &format!(
                    "a floor of albedo 0.5 under a sphere light, sampled by its cone, \
                     {samples} shadow ray(s)"
                ),
                mean,
                se,
                reference,
                &[
                    (0.0, BLOCKED),
                    (
                        no_cos,
                        "the receiver's cosine is missing: light arriving at angle θ to the \
                         floor's normal spreads over 1 / cos θ as much area",
                    ),
                    (std::f64::consts::PI, NO_PI),
                    (
                        f64::from(samples).max(2.0),
                        "not divided by the number of shadow rays",
                    ),
                    (
                        from_origin,
                        "the direction to the light's point was taken from the scene's origin: \
                         it goes from the receiver, hit.p, to the point",
                    ),
                ],
                if mean > reference {
                    too_bright
                } else {
                    "too dark: part of the light is lost"
                },
            );
        }
    }

    #[test]
    fn exercise_matte_adds_every_light() {
        // The panel of the check above, and a sphere light off to the other side, where
        // neither hides the other from the receiver.
        let quad = Parallelogram::new(Vec3::new(-0.2, 1.0, -0.7), Vec3::X, Vec3::Z);
        let vertices = [
            quad.corner(),
            quad.corner() + quad.e1(),
            quad.corner() + quad.e1() + quad.e2(),
            quad.corner() + quad.e2(),
        ];
        let center = Vec3::new(-1.5, 1.5, 1.2);
        let d = (center - RECEIVER).length();
        let panel = f64::from(polygon_irradiance(RECEIVER, Vec3::Y, &vertices, Vec3::ONE).y);
        let sphere = f64::from(sphere_irradiance(Vec3::ONE, 0.5, d, (center - RECEIVER).y / d).y);
        let to_radiance = f64::from(ALBEDO) / PI;
        let world = scene_with_lights(&[
            Shape::Parallelogram(quad),
            Shape::Sphere(Sphere::new(center, 0.5)),
        ]);
        let (mean, se, _) = reflected(&world, 4, 1000);
        let reference = to_radiance * (panel + sphere);
        let halves = "half of it: the estimates of the two lights are added, each the mean of \
            its own shadow rays (the number of lights divides nothing)";
        judge(
            "a floor of albedo 0.5 under a panel light and a sphere light, 4 shadow rays each",
            mean,
            se,
            reference,
            &[
                (0.5, halves),
                (
                    panel / (panel + sphere),
                    "only the first light came through: every light is estimated",
                ),
                (
                    sphere / (panel + sphere),
                    "only the last light came through: every light's estimate is added",
                ),
            ],
            "the two lights together give the sum of what each gives alone (the checks of a \
             panel and of a sphere light alone say more)",
        );
    }

    #[test]
    fn exercise_matte_leaves_the_back_of_a_one_sided_surface_black() {
        // The floor seen from below, lit from below: a one-sided matte surface's back is black.
        let world = scene_with(Shape::Sphere(Sphere::new(Vec3::new(0.5, -1.5, 0.0), 0.5)));
        let area_lights = AreaLights::of(&world.scene);
        let lighting = area_lights.lighting(LightOptions::with_samples(4));
        let from_below = Vec3::new(2.0, -1.0, 0.3);
        let ray = Ray::new(from_below, (Vec3::ZERO - from_below).normalize());
        let hit = world.intersect(&ray).expect("the ray reaches the floor");
        let mut sampler = IndependentSampler::new(3);
        for two_sided in [false, true] {
            let mut total = Vec3::ZERO;
            for i in 0..64 {
                sampler.start_pixel_sample(UVec2::ZERO, i);
                total += lighting.matte(
                    &world,
                    &ray,
                    &hit,
                    Vec3::splat(ALBEDO),
                    two_sided,
                    &mut sampler,
                );
            }
            if two_sided {
                assert!(
                    total.y > 0.0,
                    "matte: a two-sided matte floor seen from below, with a light below it, is \
                     lit on that side: its normal is turned to face the ray"
                );
            } else {
                assert!(
                    total == Vec3::ZERO,
                    "matte: a one-sided matte floor seen from behind reflects nothing, but \
                     yours reflected {total} over 64 calls"
                );
            }
        }
    }
}
