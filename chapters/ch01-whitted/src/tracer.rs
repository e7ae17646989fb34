//! Whitted's recursive ray tracer.
//!
//! A camera ray finds the nearest surface. A matte surface is lit by every point light it can
//! see, asked through a shadow ray; a mirror sends one reflected ray; glass sends a reflected
//! and a refracted ray, weighted by the Fresnel equations. Reflected and refracted rays are
//! traced the same way, recursively, until the depth limit. Every ray is deterministic, so one
//! ray per pixel gives the final image, with every edge jagged and every shadow hard.

use crate::optics::{fresnel_dielectric, reflect, refract};
use crate::scene::World;
use common::Ray;
use common::geometry::SurfaceHit;
use common::render::SampleCounters;
use common::scene::Material;
use glam::Vec3;
use std::f32::consts::FRAC_1_PI;

// ANCHOR: trace
/// The radiance arriving along `ray`, which is segment number `depth` of its path (the camera
/// ray is segment 1). Every ray it spawns keeps the ray's shutter `time`.
pub fn trace<W: World>(world: &W, ray: &Ray, depth: u32, counters: &mut SampleCounters) -> Vec3 {
    counters.rays += 1;
    let scene = world.scene();
    let Some(hit) = world.intersect(ray) else {
        return scene.environment;
    };
    if depth >= scene.max_depth {
        // No segment left to carry light here: surfaces do not glow by themselves.
        return Vec3::ZERO;
    }
    match scene.surface(hit.shape).material {
        Material::Diffuse { albedo, two_sided } => {
            direct_light(world, ray, &hit, albedo, two_sided, counters)
        }
        Material::CheckeredDiffuse {
            checkerboard,
            two_sided,
        } => direct_light(
            world,
            ray,
            &hit,
            checkerboard.eval(hit.uv),
            two_sided,
            counters,
        ),
        Material::Mirror { reflectance } => {
            if !hit.front_face(ray.dir) {
                return Vec3::ZERO; // mirrors reflect on their front side only, as in Mitsuba
            }
            let reflected = hit.spawn_ray(reflect(ray.dir, hit.n), ray.time);
            reflectance * trace(world, &reflected, depth + 1, counters)
        }
        Material::Dielectric { int_ior, ext_ior } => {
            dielectric(world, ray, &hit, int_ior, ext_ior, depth, counters)
        }
        // Chapter 06's materials; the capability check keeps them from this chapter.
        Material::Glossy(_) | Material::RoughGlass(_) => Vec3::ZERO,
    }
}
// ANCHOR_END: trace

// ANCHOR: direct_light
/// Light reflected by a matte surface from every point light it sees: `albedo / pi` times
/// the irradiance `I cos(theta) / r^2`, where a shadow ray finds nothing in the way.
///
/// Public because the later chapters' tracers light their matte surfaces the same way.
pub fn direct_light<W: World>(
    world: &W,
    ray: &Ray,
    hit: &SurfaceHit,
    albedo: Vec3,
    two_sided: bool,
    counters: &mut SampleCounters,
) -> Vec3 {
    let normal = if hit.front_face(ray.dir) {
        hit.shading_n
    } else if two_sided {
        -hit.shading_n
    } else {
        return Vec3::ZERO; // the back of a one-sided surface is black
    };
    let mut radiance = Vec3::ZERO;
    for light in &world.scene().point_lights {
        let to_light = light.position - hit.p;
        let distance_squared = to_light.length_squared();
        let cos_theta = normal.dot(to_light) / distance_squared.sqrt();
        // `<= 0` would let a NaN through (a light exactly on the surface); this does not.
        if cos_theta.is_nan() || cos_theta <= 0.0 {
            continue; // behind the surface, or the light sits on it
        }
        counters.rays += 1;
        if world.occluded(&hit.spawn_ray_to(light.position, ray.time)) {
            continue; // in shadow: hard-edged, since the light is a point
        }
        radiance += albedo * FRAC_1_PI * light.intensity * cos_theta / distance_squared;
    }
    radiance
}
// ANCHOR_END: direct_light

// ANCHOR: dielectric
/// Glass: a Fresnel-weighted sum of the reflected and the refracted ray. Radiance crossing
/// into a denser medium is squeezed into a narrower cone, so it is scaled by `(eta_i/eta_t)^2`.
fn dielectric<W: World>(
    world: &W,
    ray: &Ray,
    hit: &SurfaceHit,
    int_ior: f32,
    ext_ior: f32,
    depth: u32,
    counters: &mut SampleCounters,
) -> Vec3 {
    // Orient the normal against the ray; coming from inside, the indices swap.
    let (normal, eta) = if hit.front_face(ray.dir) {
        (hit.n, ext_ior / int_ior)
    } else {
        (-hit.n, int_ior / ext_ior)
    };
    let cos_i = -ray.dir.dot(normal);
    let reflectance = fresnel_dielectric(cos_i, eta);
    let mut radiance = Vec3::ZERO;
    if reflectance > 0.0 {
        let reflected = hit.spawn_ray(reflect(ray.dir, normal), ray.time);
        radiance += reflectance * trace(world, &reflected, depth + 1, counters);
    }
    if reflectance < 1.0
        && let Some(dir) = refract(ray.dir, normal, eta)
    {
        let refracted = hit.spawn_ray(dir, ray.time);
        radiance += (1.0 - reflectance) * eta * eta * trace(world, &refracted, depth + 1, counters);
    }
    radiance
}
// ANCHOR_END: dielectric
