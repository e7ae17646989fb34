//! The lights a surface sees directly: a hook for chapter 07.
//!
//! This chapter's tracer asks two questions of the lights, and only two: what a surface that
//! a ray hits emits itself, and what a matte surface reflects of the lights it sees. Here the
//! answers are chapter 01's: nothing glows, and a matte surface is lit by the point lights
//! through shadow rays ([`PointLights`]). Chapter 07 answers them for lights with an area and
//! reuses this tracer unchanged.

use ch01_whitted::tracer::direct_light;
use ch01_whitted::world::World;
use common::Ray;
use common::geometry::SurfaceHit;
use common::sampler::Sampler;
use glam::Vec3;

/// The light that arrives at a surface directly from the light sources.
pub trait Lighting: Sync {
    /// The radiance the surface at `hit` emits back along `ray` (an area light's surface).
    fn emitted(&self, hit: &SurfaceHit, ray: &Ray) -> Vec3;

    /// The radiance a matte surface of `albedo` at `hit` reflects back along `ray`, from every
    /// light it sees (a one-sided surface seen from behind reflects nothing).
    #[allow(clippy::too_many_arguments)]
    fn matte<W: World, S: Sampler>(
        &self,
        world: &W,
        ray: &Ray,
        hit: &SurfaceHit,
        albedo: Vec3,
        two_sided: bool,
        sampler: &mut S,
    ) -> Vec3;
}

/// Chapter 01's lights: the scene's point lights, and no surface that glows.
#[derive(Clone, Copy, Debug, Default)]
pub struct PointLights;

impl Lighting for PointLights {
    fn emitted(&self, _hit: &SurfaceHit, _ray: &Ray) -> Vec3 {
        Vec3::ZERO
    }

    fn matte<W: World, S: Sampler>(
        &self,
        world: &W,
        ray: &Ray,
        hit: &SurfaceHit,
        albedo: Vec3,
        two_sided: bool,
        _sampler: &mut S,
    ) -> Vec3 {
        direct_light(world, ray, hit, albedo, two_sided)
    }
}
