//! Distribution ray tracing with every effect at once: Cook, Porter and Carpenter's tracer,
//! where each effect takes *several* samples at every hit and the ray tree branches.
//!
//! Chapters 03 to 07 each spent their samples on one dimension. Combined, a camera ray meets
//! a glossy plate that sends `k` rays into its lobe; each of those finds a matte wall that
//! sends `m` shadow rays to each light, or another glossy surface that sends `k` more. Every
//! depth multiplies the branches: the "exponential growth" of the lecture, and the reason
//! [`crate::path`] keeps a single branch. [`ray_tree`] counts the rays and measures how
//! little the deep ones carry.
//!
//! At each hit, what the tracer does:
//!
//! - **matte**: chapter 07's [`AreaLighting`]: `m` shadow rays per area light, one per point
//!   light. With [`DistributionOptions::indirect_diffuse`], also `k` cosine-distributed rays
//!   for the light reflected by other surfaces (Cook's 1984 method has none: it is the
//!   option that lets the chapter show how fast the tree then explodes). Those rays do not
//!   count the area lights they hit, which the shadow rays already counted;
//! - **glossy, frosted glass, smooth glass**: `k` directions drawn from the material
//!   ([`Bsdf::sample`]), each weighted `1/k`; at smooth glass these are `k` Fresnel choices
//!   between the reflected and the refracted ray. The point lights are added as highlights
//!   (they cannot be hit);
//! - **a mirror** or a lobe of infinite exponent: its one direction, once.
//!
//! Random numbers are drawn depth first, in the order the tree is walked: the camera's, then
//! at each hit the shadow rays' points (light by light), then each branch's material numbers
//! followed by everything below that branch. The order depends on nothing but the sample, so
//! a seed gives the same image on any number of threads.

pub mod ray_tree;

use crate::bsdf::{Bsdf, SurfaceBsdf};
use crate::lights::SceneLights;
use crate::nee::point_lights;
use ch01_whitted::world::World;
use ch04_depth_of_field::Lens;
use ch05_motion_blur::MotionScene;
use ch05_motion_blur::{CameraRays, TimeSampler};
use ch06_fuzzy_reflections::{FuzzMethod, Lighting};
use ch07_soft_shadows::{AreaLighting, AreaLights, LightOptions};
use common::Ray;
use common::film::Filter;
use common::render::{self, RenderOutput, RenderSettings};
use common::sampler::Sampler;
use common::scene::Material;
use glam::Vec3;

/// How many samples each effect takes at every hit, and how deep the tree may grow.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DistributionOptions {
    /// `k`: rays into the lobe of a glossy or frosted surface, Fresnel choices at glass, and
    /// (with `indirect_diffuse`) cosine rays at a matte surface. At least 1.
    pub material_samples: u32,
    /// `m`: shadow rays to each area light from a matte surface. At least 1.
    pub light_samples: u32,
    /// The longest chain of rays, counting the camera ray (chapter 06's `max_depth`).
    pub max_depth: u32,
    /// Whether matte surfaces also gather light from other surfaces (not in Cook 1984).
    pub indirect_diffuse: bool,
}

impl DistributionOptions {
    /// One sample per effect, no indirect diffuse light: chapter 07's tracer, in expectation.
    pub fn cook(max_depth: u32) -> Self {
        Self {
            material_samples: 1,
            light_samples: 1,
            max_depth,
            indirect_diffuse: false,
        }
    }

    /// `branching` samples for every effect.
    pub fn branching(branching: u32, max_depth: u32, indirect_diffuse: bool) -> Self {
        Self {
            material_samples: branching,
            light_samples: branching,
            max_depth,
            indirect_diffuse,
        }
    }
}

/// The branching tracer over a chapter 07 scene.
///
/// Its area lights are chapter 07's, whose radiance is the same at every point: a light whose
/// radiance is a texture is read by the path tracer only ([`crate::lights`]); this tracer
/// renders the chapter's own scenes, which have none.
#[derive(Clone)]
pub struct DistributionTracer<'a> {
    /// The scene.
    pub world: &'a MotionScene,
    /// Chapter 07's lights for matte surfaces, with `light_samples` rays per light.
    pub lighting: AreaLighting<'a>,
    /// The same lights as one list: the point lights' highlights on glossy surfaces.
    pub lights: SceneLights<'a>,
    /// How many samples, how deep.
    pub options: DistributionOptions,
    /// How fuzzy lobes spread.
    pub fuzz: FuzzMethod,
}

impl<'a> DistributionTracer<'a> {
    /// The tracer for `scene`, lights sampled as chapter 07's defaults (spheres by solid
    /// angle), lobes `cos^n`.
    pub fn new(
        world: &'a MotionScene,
        area_lights: &'a AreaLights,
        options: DistributionOptions,
    ) -> Self {
        let light_options = LightOptions::with_samples(options.light_samples.max(1));
        Self {
            world,
            lighting: area_lights.lighting(light_options),
            lights: SceneLights::of(world, area_lights, light_options.sampling),
            options,
            fuzz: FuzzMethod::Lobe,
        }
    }

    /// The radiance arriving along the camera ray `ray`.
    pub fn radiance<S: Sampler>(&self, ray: &Ray, sampler: &mut S) -> Vec3 {
        self.trace(ray, 1, true, sampler)
    }

    // ANCHOR: trace
    /// The radiance along `ray`, segment `depth` of its branch. `count_emission` is false
    /// for a ray that a matte surface sent: its shadow rays already counted the area lights.
    fn trace<S: Sampler>(
        &self,
        ray: &Ray,
        depth: u32,
        count_emission: bool,
        sampler: &mut S,
    ) -> Vec3 {
        let world = self.world;
        let Some(hit) = world.intersect(ray) else {
            return world.background(ray.dir);
        };
        let mut radiance = if count_emission {
            self.lighting.emitted(&hit, ray)
        } else {
            Vec3::ZERO
        };
        if depth >= self.options.max_depth {
            return radiance; // no segment left to carry reflected light
        }
        let bsdf = Bsdf {
            material: &self.world.material_at(&hit),
            hit: &hit,
            fuzz: self.fuzz,
        };
        let wo = -ray.dir.normalize();
        let k = self.options.material_samples.max(1);
        if let Some((albedo, two_sided)) = matte(&bsdf) {
            if albedo == Vec3::ZERO {
                return radiance; // a black surface (a light's back): nothing to gather
            }
            radiance += self
                .lighting
                .matte(world, ray, &hit, albedo, two_sided, sampler);
            if self.options.indirect_diffuse {
                radiance += self.branches(&bsdf, wo, ray.time, depth, k, false, sampler);
            }
        } else {
            radiance += self.highlights(&bsdf, wo, ray.time);
            let k = if single_direction(&bsdf) { 1 } else { k };
            radiance += self.branches(&bsdf, wo, ray.time, depth, k, true, sampler);
        }
        radiance
    }
    // ANCHOR_END: trace

    // ANCHOR: branches
    /// `k` directions drawn from the material, each traced and weighted `1/k`: the average
    /// of `k` one-sample estimates, so the mean does not depend on `k`, only the noise.
    #[allow(clippy::too_many_arguments)]
    fn branches<S: Sampler>(
        &self,
        bsdf: &Bsdf,
        wo: Vec3,
        time: f32,
        depth: u32,
        k: u32,
        count_emission: bool,
        sampler: &mut S,
    ) -> Vec3 {
        let mut sum = Vec3::ZERO;
        for _ in 0..k {
            let Some(sample) = bsdf.sample(wo, sampler) else {
                continue; // below the surface, or the back of a one-sided surface
            };
            let next = bsdf.hit.spawn_ray(sample.wi, time);
            sum += sample.weight * self.trace(&next, depth + 1, count_emission, sampler);
        }
        sum / k as f32
    }
    // ANCHOR_END: branches

    /// The point lights seen in a glossy or frosted surface: `f cos θ I / d²` through one
    /// shadow ray each (no random numbers), as the path tracer's next event counts them. A
    /// smooth surface has no highlight to show.
    fn highlights(&self, bsdf: &Bsdf, wo: Vec3, time: f32) -> Vec3 {
        if bsdf.is_delta() {
            return Vec3::ZERO;
        }
        point_lights(self.world, &self.lights, bsdf, wo, time)
    }
}

/// The albedo and sidedness of a matte material (its texture already read at the hit by
/// `Scene::material_at`).
fn matte(bsdf: &Bsdf) -> Option<(Vec3, bool)> {
    match *bsdf.material {
        Material::Diffuse { albedo, two_sided } => Some((albedo, two_sided)),
        _ => None,
    }
}

/// Whether the material has one direction only (a mirror, a smooth metal, a lobe of infinite
/// exponent that is not glass): `k` copies of it would trace the same ray `k` times.
fn single_direction(bsdf: &Bsdf) -> bool {
    match *bsdf.material {
        Material::Mirror { .. } => true,
        Material::Conductor(c) => c.roughness.is_none(),
        Material::Glossy(g) => !g.exponent.is_finite(),
        _ => false,
    }
}

// ANCHOR: render_distribution
/// Renders `world` through `lens` by distribution ray tracing. Each sample draws, in order:
/// the pixel position, the time and the lens point (each only when needed), then the tree's
/// numbers depth first.
pub fn render_distribution<S: TimeSampler>(
    world: &MotionScene,
    options: DistributionOptions,
    lens: &Lens,
    settings: &RenderSettings,
    sampler: &S,
    filter: &dyn Filter,
) -> RenderOutput {
    let camera_rays = CameraRays::new(world, lens, settings.width, settings.height);
    let area_lights = AreaLights::of(&world.scene);
    let tracer = DistributionTracer::new(world, &area_lights, options);
    render::render(settings, sampler, filter, |p_film, sampler| {
        let ray = camera_rays.generate(world, p_film, sampler);
        tracer.radiance(&ray, sampler)
    })
}
// ANCHOR_END: render_distribution
