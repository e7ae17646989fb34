//! The two techniques at every vertex of chapter 08's path, kept apart per depth.
//!
//! Beyond the first surface, the light a path finds at its `d`-th vertex is again a light
//! sample and a BSDF sample of the same integral, now scaled by what the path carries to the
//! camera from there. Kondapaneni et al. solve the optimal weights per pixel *and per depth*:
//! at each depth the integrand is a different function (the light seen after `d` bounces), and
//! the best combination for the floor lit directly is not the best for the floor lit through
//! the ceiling. So a path here is a sequence of [`SurfaceDraws`], one per vertex, each with the
//! throughput folded into its values, and the pixel keeps one set of sums per depth.
//!
//! The walk is chapter 08's: at each vertex a light sample, then a BSDF sample, whose ray both
//! finds the light the BSDF technique sees and carries the path on; Russian roulette from the
//! file's depth. The random numbers are drawn in chapter 08's order.

use crate::techniques::{BSDF, LIGHT, SurfaceDraws, TechniqueSample, light_found, light_technique};
use ch01_whitted::world::World;
use ch08_path_tracing::roulette::russian_roulette;
use ch08_path_tracing::{Materials, PathTracer, SurfaceBsdf};
use common::Ray;
use common::sampler::Sampler;
use glam::Vec3;

/// Traces a path from `camera_ray` and hands `at_depth` what each vertex draws: at depth 0,
/// what the camera ray sees glow (or the sky), with nothing to combine; at depth `d` ≥ 1, the
/// light sample and the BSDF sample taken at the `d`-th surface, their values times what the
/// path carries from there to the camera. A depth the path does not reach is not handed over:
/// for the pixel it is a sample that drew nothing there.
pub fn draw_path<M: Materials, S: Sampler>(
    tracer: &PathTracer<'_, M>,
    camera_ray: &Ray,
    sampler: &mut S,
    mut at_depth: impl FnMut(usize, SurfaceDraws),
) {
    let (lights, options) = (&tracer.lights, &tracer.options);
    let mut ray = tracer.past_hidden_emitters(camera_ray);
    let shown = !options.hide_emitters;
    let Some(mut hit) = tracer.world.intersect(&ray) else {
        let sky = lights.environment.radiance(ray.dir);
        let certain = if shown { sky } else { Vec3::ZERO };
        at_depth(
            0,
            SurfaceDraws {
                certain,
                drawn: [None, None],
            },
        );
        return;
    };
    let mut seen = SurfaceDraws::default();
    if shown && let Some(light) = lights.area_light_of(hit.shape) {
        seen.certain = lights.emitted(light, hit.shape, hit.n, || Some(hit.uv), -ray.dir);
    }
    at_depth(0, seen);

    // What the path carries to the camera, and the radiance scalings of refraction inside it.
    let (mut throughput, mut eta_scale) = (Vec3::ONE, 1.0_f32);
    for depth in 1.. {
        // The vertex's light would end a path of `depth + 1` segments.
        if depth >= options.max_depth {
            break;
        }
        // The vertex's BSDF lives for this block: the path then moves on to `found`.
        let (found, next) = {
            let material = tracer.world.material_at(&hit);
            let bsdf = tracer.materials.bsdf(&material, &hit);
            let (wo, time) = (-ray.dir, ray.time);
            let mut draws = SurfaceDraws::default();

            // The light sample, as at the first surface, its value times the throughput.
            if options.nee && !bsdf.is_delta() {
                if lights.has_delta_lights() {
                    draws.certain += throughput * tracer.delta_lights(&bsdf, wo, time);
                }
                if lights.can_be_hit() {
                    draws.drawn[LIGHT] =
                        light_technique(tracer, &bsdf, wo, time, sampler).map(|sample| {
                            TechniqueSample {
                                f: throughput * sample.f,
                                ..sample
                            }
                        });
                }
            }
            // Chapter 08 skips the last segment, numbers and all, when no ray can find light.
            if depth + 1 >= options.max_depth && !lights.can_be_hit() {
                at_depth(depth as usize, draws);
                break;
            }

            // The BSDF sample: what its ray finds of the lights is this depth's; where it lands,
            // the path goes on.
            let Some(sample) = bsdf.sample(wo, sampler) else {
                at_depth(depth as usize, draws);
                break;
            };
            let carried = throughput;
            throughput *= sample.weight;
            eta_scale *= sample.eta_scale;
            let next = bsdf.hit().spawn_ray(sample.wi, time);
            let found = tracer.world.intersect(&next);
            let (emitted, light_pdf) = light_found(tracer, bsdf.hit().p, sample.wi, found.as_ref());
            if sample.is_delta() {
                // A mirror direction: only this technique could draw it.
                let light = throughput * emitted;
                if light.is_finite() {
                    draws.certain += light;
                }
            } else {
                // Without NEE the light technique draws nothing, and its density takes no part.
                let light_pdf = if options.nee { light_pdf } else { 0.0 };
                draws.drawn[BSDF] = Some(TechniqueSample {
                    f: carried * emitted * bsdf.eval(wo, sample.wi),
                    pdf: [light_pdf, bsdf.pdf(wo, sample.wi)],
                });
            }
            at_depth(depth as usize, draws);
            (found, next)
        };

        let Some(next_hit) = found else {
            break;
        };
        if throughput == Vec3::ZERO {
            break;
        }
        (hit, ray) = (next_hit, next);

        // Russian roulette, as chapter 08 plays it.
        if let Some(rr_depth) = options.rr_depth
            && depth >= rr_depth
        {
            let throughput_max = throughput.max_element() / eta_scale;
            let Some(survivor) = russian_roulette(throughput_max, sampler.get_1d()) else {
                break;
            };
            throughput *= survivor;
        }
    }
}
