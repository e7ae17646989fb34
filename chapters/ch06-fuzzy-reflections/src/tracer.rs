//! The fuzzy tracer: chapter 01's recursion, with random choices at mirrors and glass.
//!
//! A ray finds the nearest surface, as before. Matte surfaces are lit by the lights they see
//! (asked through [`Lighting`]); a perfect mirror sends its one reflected ray. What changes is
//! everything else:
//!
//! - glass follows both rays or one chosen at random, by the render's [`GlassStrategy`];
//! - a glossy surface sends one ray into its `cos^n` lobe around the mirror direction (or the
//!   empirical disc's spread), and shows the point lights as highlights;
//! - frosted glass does both: it picks reflection or refraction, then spreads the chosen ray;
//! - a spread ray that ends on the wrong side of the surface is handled by the render's
//!   [`BelowSurface`] policy.
//!
//! Random numbers are drawn per bounce, after the camera's: a choice at glass takes one, a
//! spread direction two (two more per resample). A smooth scene draws none, and renders as
//! chapter 05 does.

use crate::below_surface::BelowSurface;
use crate::fuzz::FuzzMethod;
use crate::glass_choice::{GlassStrategy, choose_fresnel, choose_half};
use crate::highlights::{Lobe, point_light_highlights};
use crate::lighting::Lighting;
use ch01_whitted::optics::{fresnel_dielectric, reflect, refract};
use ch01_whitted::scene::World;
use ch05_motion_blur::MotionScene;
use common::Ray;
use common::geometry::SurfaceHit;
use common::render::SampleCounters;
use common::sampler::Sampler;
use common::scene::{Glossy, Material};
use glam::Vec3;

/// The render's choices at mirrors and glass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TraceOptions {
    /// Which ray to trace at glass.
    pub glass: GlassStrategy,
    /// How fuzzy surfaces spread their directions.
    pub fuzz: FuzzMethod,
    /// What to do with a spread direction below the surface.
    pub below: BelowSurface,
}

impl Default for TraceOptions {
    /// One ray chosen by the Fresnel term, the `cos^n` lobe, stray rays dropped.
    fn default() -> Self {
        Self {
            glass: GlassStrategy::Fresnel,
            fuzz: FuzzMethod::Lobe,
            below: BelowSurface::Drop,
        }
    }
}

/// What one call of the tracer needs besides the ray: the scene, its lights, the options.
#[derive(Clone, Copy)]
pub struct Tracer<'a, L: Lighting> {
    /// The scene, with its motion.
    pub world: &'a MotionScene,
    /// How surfaces are lit directly.
    pub lighting: &'a L,
    /// Choices at mirrors and glass.
    pub options: TraceOptions,
}

impl<L: Lighting> Tracer<'_, L> {
    // ANCHOR: trace
    /// The radiance arriving along `ray`, segment number `depth` of its path (the camera ray
    /// is segment 1). Every ray it spawns keeps the ray's shutter `time`.
    pub fn trace<S: Sampler>(
        &self,
        ray: &Ray,
        depth: u32,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        counters.rays += 1;
        let world = self.world;
        let Some(hit) = world.intersect(ray) else {
            return world.scene.environment;
        };
        let emitted = self.lighting.emitted(&hit, ray);
        if depth >= world.scene.max_depth {
            return emitted; // no segment left to carry reflected light
        }
        let scattered = match world.scene.surface(hit.shape).material {
            Material::Diffuse { albedo, two_sided } => self
                .lighting
                .matte(world, ray, &hit, albedo, two_sided, sampler, counters),
            Material::CheckeredDiffuse {
                checkerboard,
                two_sided,
            } => self.lighting.matte(
                world,
                ray,
                &hit,
                checkerboard.eval(hit.uv),
                two_sided,
                sampler,
                counters,
            ),
            Material::Mirror { reflectance } => {
                if !hit.front_face(ray.dir) {
                    return emitted; // mirrors reflect on their front side only
                }
                let reflected = hit.spawn_ray(reflect(ray.dir, hit.n), ray.time);
                reflectance * self.trace(&reflected, depth + 1, sampler, counters)
            }
            Material::Dielectric { int_ior, ext_ior } => self.glass(
                ray,
                &hit,
                int_ior,
                ext_ior,
                f32::INFINITY,
                depth,
                sampler,
                counters,
            ),
            Material::Glossy(glossy) => self.glossy(ray, &hit, &glossy, depth, sampler, counters),
            Material::RoughGlass(glass) => self.glass(
                ray,
                &hit,
                glass.int_ior,
                glass.ext_ior,
                glass.exponent,
                depth,
                sampler,
                counters,
            ),
        };
        emitted + scattered
    }
    // ANCHOR_END: trace

    // ANCHOR: glossy
    /// A fuzzy mirror: the point lights' highlights, plus one ray into the lobe around the
    /// mirror direction, weighted by the reflectance alone (sampling the lobe the material is
    /// made of leaves nothing else to divide by).
    fn glossy<S: Sampler>(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        glossy: &Glossy,
        depth: u32,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        let normal = if hit.front_face(ray.dir) {
            hit.shading_n
        } else if glossy.two_sided {
            -hit.shading_n
        } else {
            return Vec3::ZERO; // the back of a one-sided surface is black
        };
        let lobe = Lobe {
            center: reflect(ray.dir, normal),
            exponent: glossy.exponent,
            side: normal,
            method: self.options.fuzz,
        };
        let highlights = point_light_highlights(self.world, hit, &lobe, ray.time, counters);
        let spread = self.spread(ray, hit, &lobe, depth, sampler, counters);
        glossy.reflectance * (highlights + spread)
    }
    // ANCHOR_END: glossy

    /// The radiance arriving along one direction drawn from `lobe`, handled by the render's
    /// below-surface policy; 0 when the policy drops it.
    fn spread<S: Sampler>(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        lobe: &Lobe,
        depth: u32,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        let direction = if lobe.exponent.is_finite() {
            self.options.below.scatter(lobe.side, sampler, |u| {
                lobe.method.sample(lobe.center, lobe.exponent, u)
            })
        } else {
            Some(lobe.center) // smooth: the ideal direction itself, no numbers drawn
        };
        match direction {
            Some(direction) => {
                let next = hit.spawn_ray(direction, ray.time);
                self.trace(&next, depth + 1, sampler, counters)
            }
            None => Vec3::ZERO,
        }
    }

    // ANCHOR: glass
    /// Glass, smooth (`exponent` infinite) or frosted: the Fresnel split into a reflected and
    /// a refracted ray, followed by the render's [`GlassStrategy`]. Radiance crossing into a
    /// denser medium is scaled by `(eta_i / eta_t)^2`, as in chapter 01.
    #[allow(clippy::too_many_arguments)]
    fn glass<S: Sampler>(
        &self,
        ray: &Ray,
        hit: &SurfaceHit,
        int_ior: f32,
        ext_ior: f32,
        exponent: f32,
        depth: u32,
        sampler: &mut S,
        counters: &mut SampleCounters,
    ) -> Vec3 {
        let (normal, eta) = if hit.front_face(ray.dir) {
            (hit.n, ext_ior / int_ior)
        } else {
            (-hit.n, int_ior / ext_ior)
        };
        let reflectance = fresnel_dielectric(-ray.dir.dot(normal), eta);
        let method = self.options.fuzz;
        let reflection = Lobe {
            center: reflect(ray.dir, normal),
            exponent,
            side: normal,
            method,
        };
        // `None` under total internal reflection, where the reflectance is 1.
        let refraction = refract(ray.dir, normal, eta).map(|center| Lobe {
            center,
            exponent: transmission_exponent(exponent, eta),
            side: -normal,
            method,
        });
        // The light of one branch, highlights of the point lights included.
        let branch = |lobe: &Lobe, sampler: &mut S, counters: &mut SampleCounters| {
            point_light_highlights(self.world, hit, lobe, ray.time, counters)
                + self.spread(ray, hit, lobe, depth, sampler, counters)
        };
        match self.options.glass {
            GlassStrategy::Both => {
                let mut radiance = Vec3::ZERO;
                if reflectance > 0.0 {
                    radiance += reflectance * branch(&reflection, sampler, counters);
                }
                if let Some(refraction) = refraction.filter(|_| reflectance < 1.0) {
                    // Written as chapter 01 writes it, so a smooth scene rounds the same way.
                    radiance +=
                        (1.0 - reflectance) * eta * eta * branch(&refraction, sampler, counters);
                }
                radiance
            }
            strategy => {
                let u = sampler.get_1d();
                let choice = if strategy == GlassStrategy::Half {
                    choose_half(u, reflectance)
                } else {
                    choose_fresnel(u, reflectance)
                };
                if choice.weight == 0.0 {
                    return Vec3::ZERO; // a branch that carries no light: nothing to trace
                }
                if choice.reflect {
                    choice.weight * branch(&reflection, sampler, counters)
                } else {
                    match refraction {
                        Some(refraction) => {
                            choice.weight * eta * eta * branch(&refraction, sampler, counters)
                        }
                        None => Vec3::ZERO, // unreachable: no refraction means F = 1
                    }
                }
            }
        }
    }
    // ANCHOR_END: glass
}

/// The exponent of frosted glass's refraction lobe, from the exponent of its reflection lobe
/// and the relative index `eta = eta_i / eta_t`.
///
/// Roughness is a tilt of the surface's tiny facets. Tilting a facet by a small angle `δ`
/// turns the reflected ray by `2δ`, but the refracted ray only by about `|1 - eta| δ` (at
/// normal incidence): refraction is the less sensitive, and at `eta = 1` a rough boundary
/// between equal media bends no ray at all, so glass of index 1 vanishes however frosted.
/// A lobe's width goes as `1/√n`, so the refraction lobe's exponent is the reflection's
/// times `(2 / |1 - eta|)²`: 36 times larger for glass of index 1.5 in air.
pub fn transmission_exponent(exponent: f32, eta: f32) -> f32 {
    let sensitivity = (1.0 - eta).abs() / 2.0;
    if sensitivity == 0.0 {
        return f32::INFINITY;
    }
    exponent / (sensitivity * sensitivity)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refraction_lobes_are_narrower_and_vanish_at_index_one() {
        assert_eq!(transmission_exponent(10.0, 1.0), f32::INFINITY);
        approx::assert_relative_eq!(
            transmission_exponent(10.0, 1.0 / 1.5),
            360.0,
            max_relative = 1e-5
        );
        approx::assert_relative_eq!(transmission_exponent(10.0, 1.5), 160.0, max_relative = 1e-5);
        assert_eq!(transmission_exponent(0.0, 1.5), 0.0);
    }
}
