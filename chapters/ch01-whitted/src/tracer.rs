//! Whitted's recursive ray tracer.
//!
//! A camera ray finds the nearest surface. A matte surface is lit by every point light it can
//! see, asked through a shadow ray; a mirror sends one reflected ray; glass sends a reflected
//! and a refracted ray, weighted by the Fresnel equations. Reflected and refracted rays are
//! traced the same way, recursively, until the depth limit. Every ray is deterministic, so one
//! ray per pixel gives the final image, with every edge jagged and every shadow hard.

use crate::world::World;
use common::Ray;
use common::geometry::SurfaceHit;
use glam::Vec3;

// ANCHOR: trace
/// The radiance arriving along `ray`, which is segment number `depth` of its path (the camera
/// ray is segment 1; a path has at most the scene's `max_depth` segments, as in Mitsuba). A ray
/// that hits nothing brings back the scene's `environment`.
///
/// Every ray it spawns leaves by `hit.spawn_ray` and keeps the ray's shutter `time`. A
/// textured matte surface's albedo at the hit is `scene.albedo(texture, hit.uv)`. A mirror
/// reflects on its front side only, the side `hit.n` points to. Chapter 06's materials
/// (`Glossy`, `RoughGlass`) and those beyond the lecture, which `ch09-materials` renders
/// (`Conductor`, `ThinDielectric`, `Plastic`, `Mask`, `TintedGlass`), reflect nothing here: the
/// capability check refuses them or puts the lecture's stand-in in their place.
pub fn trace<W: World>(world: &W, ray: &Ray, depth: u32) -> Vec3 {
    // BEGIN SOLUTION
    use crate::optics::reflect;
    use common::scene::Material;

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
            direct_light(world, ray, &hit, albedo, two_sided)
        }
        Material::TexturedDiffuse { texture, two_sided } => {
            direct_light(world, ray, &hit, scene.albedo(texture, hit.uv), two_sided)
        }
        Material::Mirror { reflectance } => {
            if !hit.front_face(ray.dir) {
                return Vec3::ZERO; // mirrors reflect on their front side only, as in Mitsuba
            }
            let reflected = hit.spawn_ray(reflect(ray.dir, hit.n), ray.time);
            reflectance * trace(world, &reflected, depth + 1)
        }
        Material::Dielectric { int_ior, ext_ior } => {
            dielectric(ray, &hit, int_ior, ext_ior, &mut |next| {
                trace(world, next, depth + 1)
            })
        }
        // Chapter 06's materials and those beyond the lecture; the capability check keeps them
        // from this chapter (a metal arrives as the mirror that stands in for it).
        Material::Glossy(_)
        | Material::RoughGlass(_)
        | Material::Conductor(_)
        | Material::ThinDielectric { .. }
        | Material::Plastic(_)
        | Material::Mask(_)
        | Material::TintedGlass(_) => Vec3::ZERO,
    }
    // END SOLUTION
}
// ANCHOR_END: trace

// ANCHOR: direct_light
/// The radiance a matte surface of `albedo` reflects back along `ray` from the scene's point
/// lights: each light counts only where a shadow ray from `hit` reaches it unblocked
/// (`world.occluded`; only what lies between the point and the light can block it). The back
/// of a one-sided surface is black; a `two_sided` one is matte on both sides. The slant of the
/// light is measured from the shading normal `hit.shading_n`, turned to the side the ray
/// arrived on; which side that is, the geometric normal says (`hit.front_face`). A light
/// exactly at the lit point has no direction from it and lights nothing.
///
/// Every shadow ray leaves by `hit.spawn_ray_to` at the ray's shutter `time`, and none is traced
/// that could not change the answer. Public because the later chapters' tracers light their
/// matte surfaces the same way.
pub fn direct_light<W: World>(
    world: &W,
    ray: &Ray,
    hit: &SurfaceHit,
    albedo: Vec3,
    two_sided: bool,
) -> Vec3 {
    // BEGIN SOLUTION
    use std::f32::consts::FRAC_1_PI;

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
        if world.occluded(&hit.spawn_ray_to(light.position, ray.time)) {
            continue; // in shadow: hard-edged, since the light is a point
        }
        radiance += albedo * FRAC_1_PI * light.intensity * cos_theta / distance_squared;
    }
    radiance
    // END SOLUTION
}
// ANCHOR_END: direct_light

// ANCHOR: dielectric
/// Glass: the radiance arriving along `ray` from a smooth interface, brought back by the
/// reflected ray and, when there is one, the refracted ray, each with its share of the light.
/// (What happens to radiance that crosses into a medium of another index? The chapter's
/// section on glass says.)
///
/// `int_ior` is the index inside the glass (behind the normal `hit.n`), `ext_ior` the one
/// outside; the ray may arrive from either side. `trace_next` follows a ray one segment further
/// along the path and returns the radiance it brings back; a ray whose share is zero is not
/// traced. Every ray it spawns leaves by `hit.spawn_ray` and keeps the ray's shutter `time`.
/// Public so that a later tracer can reuse it.
pub fn dielectric(
    ray: &Ray,
    hit: &SurfaceHit,
    int_ior: f32,
    ext_ior: f32,
    trace_next: &mut impl FnMut(&Ray) -> Vec3,
) -> Vec3 {
    // BEGIN SOLUTION
    use crate::optics::{fresnel_dielectric, reflect, refract};

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
        radiance += reflectance * trace_next(&reflected);
    }
    if reflectance < 1.0
        && let Some(dir) = refract(ray.dir, normal, eta)
    {
        let refracted = hit.spawn_ray(dir, ray.time);
        radiance += (1.0 - reflectance) * eta * eta * trace_next(&refracted);
    }
    radiance
    // END SOLUTION
}
// ANCHOR_END: dielectric

#[cfg(test)]
mod tests;
