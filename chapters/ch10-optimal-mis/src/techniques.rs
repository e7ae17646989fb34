//! The two techniques at the surface a camera ray meets, drawn once each, as chapter 08's
//! `direct` draws them, but kept apart instead of weighted on the spot.
//!
//! A heuristic weight needs the two densities of a sample and nothing else, so chapter 08
//! weighs each sample as soon as it is drawn. The optimal weights depend on every sample of
//! the pixel, so a sample must be kept as what it is: the integrand's value at its direction,
//! `f = L_e f_s cos θ` (visibility included, no weight, no density), and the density with which
//! *each* technique would draw that direction. Whatever cannot be drawn by both techniques
//! needs no combining and is kept apart, [`SurfaceDraws::certain`]: light the camera ray sees
//! itself, point lights (no BSDF sample can find them) and the directions of mirror and smooth
//! glass lobes (no light sample can draw them).

use ch01_whitted::world::World;
use ch08_path_tracing::{Materials, PathTracer, SurfaceBsdf};
use common::Ray;
use common::geometry::SurfaceHit;
use common::sampler::Sampler;
use glam::{Vec2, Vec3};

/// The light sample's index among the techniques.
pub const LIGHT: usize = 0;
/// The BSDF sample's index among the techniques.
pub const BSDF: usize = 1;

/// One technique's sample: the integrand at the direction it drew and both techniques'
/// densities there, per unit solid angle (`pdf[LIGHT]` includes the light's pick).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TechniqueSample {
    /// `L_e f_s cos θ`, visibility included: 0 where the light is blocked or behind the
    /// surface, or where a BSDF direction finds no light. Such a sample still counts.
    pub f: Vec3,
    /// The density of each technique at the sample's direction: `[LIGHT]`, `[BSDF]`.
    pub pdf: [f32; 2],
}

/// What one camera ray's sample gives at the surface it meets.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SurfaceDraws {
    /// What needs no combining, already an estimate: the light the camera ray sees itself,
    /// the point and directional lights, light found along a delta lobe's direction.
    pub certain: Vec3,
    /// The sample of each technique, `[LIGHT]` and `[BSDF]`; `None` when the technique drew
    /// nothing there (no surface, no light to pick, a direction below the surface, a delta
    /// lobe chosen): a failed sample, which counts as a sample of the technique all the same.
    pub drawn: [Option<TechniqueSample>; 2],
}

/// Traces `camera_ray` to the surface it meets and draws one light sample and one BSDF sample
/// there (in that order, as chapter 08's `direct` does), keeping each as a
/// [`TechniqueSample`].
pub fn draw_techniques<M: Materials, S: Sampler>(
    tracer: &PathTracer<'_, M>,
    camera_ray: &Ray,
    sampler: &mut S,
) -> SurfaceDraws {
    let lights = &tracer.lights;
    // With Mitsuba's `hide_emitters`, the camera sees through what glows, and not the sky.
    let camera_ray = &tracer.past_hidden_emitters(camera_ray);
    let shown = !tracer.options.hide_emitters;
    let Some(hit) = tracer.world.intersect(camera_ray) else {
        let sky = lights.environment.radiance(camera_ray.dir);
        return SurfaceDraws {
            certain: if shown { sky } else { Vec3::ZERO },
            drawn: [None, None],
        };
    };
    let mut draws = SurfaceDraws::default();
    if shown && let Some(light) = lights.area_light_of(hit.shape) {
        draws.certain += lights.emitted(light, hit.shape, hit.n, || Some(hit.uv), -camera_ray.dir);
    }
    let material = tracer.world.material_at(&hit);
    let bsdf = tracer.materials.bsdf(&material, &hit);
    let (wo, time) = (-camera_ray.dir, camera_ray.time);

    // The light sample: a light picked and a point on it, from one 2D number.
    if !bsdf.is_delta() {
        if lights.has_delta_lights() {
            draws.certain += tracer.delta_lights(&bsdf, wo, time);
        }
        if lights.can_be_hit() {
            draws.drawn[LIGHT] = light_technique(tracer, &bsdf, wo, time, sampler);
        }
    }

    // The BSDF sample: a direction from the material, traced to the light it finds.
    let Some(sample) = bsdf.sample(wo, sampler) else {
        return draws;
    };
    let ray = bsdf.hit().spawn_ray(sample.wi, time);
    let found = tracer.world.intersect(&ray);
    let (emitted, light_pdf) = light_found(tracer, bsdf.hit().p, sample.wi, found.as_ref());
    if sample.is_delta() {
        // A mirror direction: only this technique could draw it.
        let found = sample.weight * emitted;
        if found.is_finite() {
            draws.certain += found;
        }
        return draws;
    }
    let f = emitted * bsdf.eval(wo, sample.wi);
    draws.drawn[BSDF] = Some(TechniqueSample {
        f,
        pdf: [light_pdf, bsdf.pdf(wo, sample.wi)],
    });
    draws
}

/// The light technique's sample at the surface of `bsdf` seen from `wo`: a light picked and a
/// point on it, from one 2D number, with its shadow ray; `None` when no light could be picked
/// or no point drawn (a failed sample).
pub fn light_technique<M: Materials, S: Sampler>(
    tracer: &PathTracer<'_, M>,
    bsdf: &impl SurfaceBsdf,
    wo: Vec3,
    time: f32,
    sampler: &mut S,
) -> Option<TechniqueSample> {
    let lights = &tracer.lights;
    let u = sampler.get_2d();
    let (light, rest) = lights.pick_with_rest(u.x)?;
    let sample = lights.sample(light, bsdf.hit(), Vec2::new(rest, u.y))?;
    let f_cos = bsdf.eval(wo, sample.wi);
    let carries = sample.radiance != Vec3::ZERO && f_cos != Vec3::ZERO;
    let visible = carries && !tracer.world.occluded(&sample.shadow_ray(bsdf.hit(), time));
    let f = if visible {
        sample.radiance * f_cos
    } else {
        Vec3::ZERO
    };
    Some(TechniqueSample {
        f,
        pdf: [sample.pdf, bsdf.pdf(wo, sample.wi)],
    })
}

/// What a BSDF sample's ray from `origin` in direction `wi` finds of the lights: the radiance
/// that `found` (the surface it met, `None` for none) emits towards `origin`, or the
/// environment's, and the density with which the light technique would have drawn it (0 for
/// no light).
pub fn light_found<M: Materials>(
    tracer: &PathTracer<'_, M>,
    origin: Vec3,
    wi: Vec3,
    found: Option<&SurfaceHit>,
) -> (Vec3, f32) {
    let lights = &tracer.lights;
    match found {
        Some(found) => match lights.area_light_of(found.shape) {
            Some(light) => (
                lights.emitted(light, found.shape, found.n, || Some(found.uv), -wi),
                lights.area_pdf(light, origin, found.p, found.n),
            ),
            None => (Vec3::ZERO, 0.0),
        },
        None if lights.has_environment() => {
            (lights.environment.radiance(wi), lights.environment_pdf(wi))
        }
        None => (Vec3::ZERO, 0.0),
    }
}
