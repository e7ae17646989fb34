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

use crate::estimator::{estimate_irradiance, matte_reflected_radiance};
use crate::light::AreaLight;
use crate::light_options::LightOptions;
use ch01_whitted::scene::World;
use ch01_whitted::tracer::direct_light;
use ch06_fuzzy_reflections::Lighting;
use common::Ray;
use common::geometry::SurfaceHit;
use common::render::SampleCounters;
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
    fn matte<W: World, S: Sampler>(
        &self,
        world: &W,
        ray: &Ray,
        hit: &SurfaceHit,
        albedo: Vec3,
        two_sided: bool,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        let point_lights = direct_light(world, ray, hit, albedo, two_sided, counters);
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
            irradiance += estimate_irradiance(
                hit.p,
                normal,
                light,
                &points,
                self.options.sampling,
                |sample| {
                    counters.rays += 1;
                    !world.occluded(&sample.shadow_ray(hit, ray.time))
                },
            );
        }
        point_lights + matte_reflected_radiance(albedo, irradiance)
    }
    // ANCHOR_END: matte
}
