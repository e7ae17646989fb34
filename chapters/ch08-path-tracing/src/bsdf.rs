//! The BSDF of each of the lecture's materials, as the path tracer needs it: *sample* a
//! direction, *evaluate* `f cos θ` for a direction the light sample chose, and the *density*
//! with which sampling would have chosen it (for multiple importance sampling).
//!
//! Each material keeps the three in one small module. Directions point away from the surface:
//! `wo` towards where the path came from, `wi` towards where the light comes from. A
//! [`BsdfSample`]'s `weight` is `f cos θ / pdf`, which for the lecture's materials is a
//! constant (the albedo, the reflectance, 1 or the refraction's `eta²`): each is sampled by
//! exactly the lobe it is made of.
//!
//! The path loop asks its questions through two traits, [`Materials`] (the BSDF of a material
//! at a hit) and [`SurfaceBsdf`] (the questions themselves), so that it takes its materials
//! from outside: this chapter's are [`LectureMaterials`]; Mitsuba's metals, plastic, masks
//! and microfacet models come after the lecture, over the same loop. A file's rough metal or
//! rough glass is rendered here as chapter 06 renders it, by the `cos^n` lobe that stands in
//! for its roughness.
//!
//! Random numbers, in this order: a choice at glass (1), a direction (2) for diffuse, glossy
//! and frosted surfaces; a mirror and smooth glass's chosen branch take no direction numbers.

pub mod dielectric;
pub mod diffuse;
pub mod glossy;
pub mod mirror;
pub mod rough_glass;

use ch06_fuzzy_reflections::FuzzMethod;
use common::geometry::SurfaceHit;
use common::sampler::Sampler;
use common::scene::Material;
use glam::Vec3;

/// A sampled direction and what it carries.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfSample {
    /// The unit direction the light comes from.
    pub wi: Vec3,
    /// `f cos θ / pdf`: what the path's throughput is multiplied by.
    pub weight: Vec3,
    /// The density per unit solid angle (of the whole BSDF, all lobes), `f32::INFINITY` for
    /// a delta lobe, which a light sample can never produce.
    pub pdf: f32,
    /// The radiance scaling `(eta_i / eta_t)²` included in `weight` (1 without refraction),
    /// so that Russian roulette can look at the throughput without it, as Mitsuba does.
    pub eta_scale: f32,
}

impl BsdfSample {
    /// Whether the direction was the only one possible (mirror, smooth glass).
    pub fn is_delta(&self) -> bool {
        self.pdf.is_infinite()
    }
}

/// What the path loop asks of the material at a hit: the three questions of the module's
/// opening, and whether a light sample can help at all. The loop, the light sample and the
/// BSDF step are written against this trait, so that they serve this chapter's materials
/// ([`Bsdf`]) and any set of materials a later crate brings, with the same code.
pub trait SurfaceBsdf {
    /// The surface point.
    fn hit(&self) -> &SurfaceHit;

    /// Whether every direction the material scatters to is a delta: no light sample can
    /// help it, so the path tracer sends none.
    fn is_delta(&self) -> bool;

    /// Samples `wi` for the outgoing `wo`, drawing the material's numbers from `sampler`;
    /// `None` when the path ends here (a one-sided surface seen from behind, a lobe direction
    /// below the surface, a branch that carries nothing).
    fn sample<S: Sampler>(&self, wo: Vec3, sampler: &mut S) -> Option<BsdfSample>;

    /// `f(wo, wi) cos θ_i` without the delta parts (0 for a mirror or smooth glass).
    fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3;

    /// The density per unit solid angle with which [`sample`](Self::sample) picks `wi`
    /// (its delta parts left out: 0 for a mirror or smooth glass).
    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32;
}

/// The materials a tracer knows: how it makes the BSDF of a surface at a hit. The path
/// tracer takes them from outside ([`PathTracer`](crate::PathTracer) is generic over them):
/// this chapter's [`LectureMaterials`] know the lecture's; a renderer of real scene files
/// brings Mitsuba's with the same loop.
pub trait Materials: Sync {
    /// The BSDF at one hit.
    type Bsdf<'a>: SurfaceBsdf
    where
        Self: 'a;

    /// The BSDF of `material` (its textures read at the hit, `Scene::material_at`) at `hit`.
    fn bsdf<'a>(&'a self, material: &'a Material, hit: &'a SurfaceHit) -> Self::Bsdf<'a>;
}

/// The lecture's materials: matte (its texture read), mirror, smooth glass, and chapter 06's
/// glossy and frosted `cos^n` lobes, spread as `fuzz` says.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LectureMaterials {
    /// How fuzzy lobes spread (chapter 06's `cos^n` lobe or the empirical disc).
    pub fuzz: FuzzMethod,
}

impl Default for LectureMaterials {
    /// The `cos^n` lobe, as Mitsuba's lobes would be written ([`Method::new`](crate::Method::new)).
    fn default() -> Self {
        Self {
            fuzz: FuzzMethod::Lobe,
        }
    }
}

impl Materials for LectureMaterials {
    type Bsdf<'a> = Bsdf<'a>;

    fn bsdf<'a>(&'a self, material: &'a Material, hit: &'a SurfaceHit) -> Bsdf<'a> {
        Bsdf {
            material,
            hit,
            fuzz: self.fuzz,
        }
    }
}

/// One of the lecture's materials at a hit point, ready to scatter: the material with its
/// texture read at the hit (`Scene::material_at`), the hit and the lobe family.
///
/// A material beyond the lecture's (a metal, plastic, a mask, a thin pane, tinted glass)
/// scatters nothing here: the chapter's capabilities put the lecture's stand-in in its place
/// or refuse the scene before a render, and a later crate renders them.
#[derive(Clone, Copy, Debug)]
pub struct Bsdf<'a> {
    /// The material, its texture read at the hit by `Scene::material_at` (a
    /// `TexturedDiffuse` that has not been read reflects nothing).
    pub material: &'a Material,
    /// The surface point.
    pub hit: &'a SurfaceHit,
    /// How fuzzy lobes spread (chapter 06's `cos^n` lobe or the empirical disc).
    pub fuzz: FuzzMethod,
}

impl SurfaceBsdf for Bsdf<'_> {
    fn hit(&self) -> &SurfaceHit {
        self.hit
    }

    fn is_delta(&self) -> bool {
        match self.material {
            Material::Mirror { .. } | Material::Dielectric { .. } => true,
            Material::Diffuse { .. } | Material::TexturedDiffuse { .. } => false,
            Material::Glossy(g) => !g.exponent.is_finite(),
            Material::RoughGlass(g) => !g.exponent.is_finite(),
            // Beyond the lecture: black here (see the type), so no light sample is spent.
            _ => true,
        }
    }

    fn sample<S: Sampler>(&self, wo: Vec3, sampler: &mut S) -> Option<BsdfSample> {
        let hit = self.hit;
        match *self.material {
            Material::Diffuse { albedo, two_sided } => {
                diffuse::sample(hit, wo, albedo, two_sided, sampler.get_2d())
            }
            // Read by `Scene::material_at` before a `Bsdf` is made: nothing left to sample.
            Material::TexturedDiffuse { .. } => None,
            Material::Mirror { reflectance } => mirror::sample(hit, wo, reflectance),
            Material::Dielectric { int_ior, ext_ior } => {
                dielectric::sample(hit, wo, int_ior, ext_ior, sampler.get_1d())
            }
            Material::Glossy(g) => {
                let u = if g.exponent.is_finite() {
                    sampler.get_2d()
                } else {
                    glam::Vec2::ZERO
                };
                glossy::sample(hit, wo, &g, self.fuzz, u)
            }
            Material::RoughGlass(g) => {
                let choice = sampler.get_1d();
                let u = if g.exponent.is_finite() {
                    sampler.get_2d()
                } else {
                    glam::Vec2::ZERO
                };
                rough_glass::sample(hit, wo, &g, self.fuzz, choice, u)
            }
            _ => None,
        }
    }

    fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        let hit = self.hit;
        match *self.material {
            Material::Diffuse { albedo, two_sided } => {
                diffuse::eval(hit, wo, wi, albedo, two_sided)
            }
            Material::Glossy(g) => glossy::eval(hit, wo, wi, &g, self.fuzz),
            Material::RoughGlass(g) => rough_glass::eval(hit, wo, wi, &g, self.fuzz),
            // A texture not read (see `sample`), a delta, or beyond the lecture.
            _ => Vec3::ZERO,
        }
    }

    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        let hit = self.hit;
        match *self.material {
            Material::Diffuse { two_sided, .. } | Material::TexturedDiffuse { two_sided, .. } => {
                diffuse::pdf(hit, wo, wi, two_sided)
            }
            Material::Glossy(g) => glossy::pdf(hit, wo, wi, &g, self.fuzz),
            Material::RoughGlass(g) => rough_glass::pdf(hit, wo, wi, &g, self.fuzz),
            _ => 0.0,
        }
    }
}

/// The shading normal turned to the side `wo` is on, or `None` for the back of a one-sided
/// surface (Mitsuba's `diffuse`, `conductor` and `roughconductor` are black from behind).
///
/// The side is the shading normal's, as in Mitsuba's shading frame: a mesh whose triangles
/// are wound every which way but whose vertex normals agree (many a PLY teapot) is lit by its
/// normals, not darkened wherever a triangle happens to face the other way.
pub fn facing_normal(hit: &SurfaceHit, wo: Vec3, two_sided: bool) -> Option<Vec3> {
    if wo.dot(hit.shading_n) > 0.0 {
        Some(hit.shading_n)
    } else if two_sided {
        Some(-hit.shading_n)
    } else {
        None
    }
}

/// A direction drawn around `+z` turned to be drawn around a unit normal: chapter 06's frame,
/// which turned its `cos^n` lobe to the mirror direction, turns the cosine-weighted hemisphere
/// here.
pub use ch06_fuzzy_reflections::fuzz::to_world;

#[cfg(test)]
pub(crate) mod test_support;

#[cfg(test)]
mod tests {
    use super::test_support::check_consistent;
    use super::{Bsdf, SurfaceBsdf, test_support};
    use ch06_fuzzy_reflections::FuzzMethod;
    use common::geometry::SurfaceHit;
    use common::scene::Material;
    use glam::Vec3;

    #[test]
    fn sampling_eval_and_pdf_describe_the_same_material() {
        let materials = [
            Material::diffuse(Vec3::splat(0.8)),
            Material::two_sided_diffuse(Vec3::splat(0.5)),
            Material::glossy(Vec3::splat(0.9), 0.0),
            Material::glossy(Vec3::splat(0.9), 50.0),
            Material::rough_glass(1.5, 10.0),
            Material::rough_glass(1.5, 1000.0),
        ];
        for wo in [
            Vec3::Y,
            Vec3::new(0.6, 0.8, 0.0),
            Vec3::new(0.0, -0.7, 0.714),
        ] {
            let wo = wo.normalize();
            for material in &materials {
                let (albedo, _) = check_consistent(material, wo, 2000);
                // Energy: a white material reflects at most what arrives, a glass transmits
                // at most eta² of it (radiance scaling).
                assert!(albedo.max_element() <= 2.3, "{material:?} {wo}: {albedo}");
            }
        }
    }

    #[test]
    fn a_surface_faces_where_its_shading_normal_points_as_in_mitsuba() {
        // A triangle wound the other way round than its vertex normals: its geometric normal
        // points down, the interpolated one up. Mitsuba decides the side in its shading
        // frame, so a one-sided matte surface seen from above reflects.
        let hit = SurfaceHit {
            n: -Vec3::Y,
            ..test_support::floor_hit()
        };
        let one_sided = Material::diffuse(Vec3::ONE);
        let bsdf = Bsdf {
            material: &one_sided,
            hit: &hit,
            fuzz: FuzzMethod::Lobe,
        };
        let f = bsdf.eval(Vec3::Y, Vec3::new(0.0, 0.8, 0.6));
        assert!(
            (f - Vec3::splat(0.8 / std::f32::consts::PI))
                .abs()
                .max_element()
                < 1e-6,
            "seen from its shading normal's side the surface is lit, got {f}"
        );
        assert_eq!(
            bsdf.eval(-Vec3::Y, -Vec3::Y),
            Vec3::ZERO,
            "and black from behind"
        );
    }

    #[test]
    fn a_material_beyond_the_lecture_scatters_nothing_and_takes_no_light_sample() {
        let hit = test_support::floor_hit();
        let pane = Material::ThinDielectric {
            int_ior: 1.5,
            ext_ior: 1.0,
        };
        let bsdf = Bsdf {
            material: &pane,
            hit: &hit,
            fuzz: FuzzMethod::Lobe,
        };
        assert!(bsdf.is_delta());
        let (weight, deltas) = check_consistent(&pane, Vec3::Y, 10);
        assert_eq!((weight, deltas), (Vec3::ZERO, 0.0));
        assert_eq!(bsdf.eval(Vec3::Y, Vec3::Y), Vec3::ZERO);
        assert_eq!(bsdf.pdf(Vec3::Y, Vec3::Y), 0.0);
    }

    #[test]
    fn smooth_glass_splits_by_fresnel() {
        // Normal incidence on glass of 1.5: F = 0.04.
        let (_, deltas) = check_consistent(&Material::glass(1.5), Vec3::Y, 20_000);
        assert_eq!(deltas, 1.0);
        let (weight, _) = check_consistent(&Material::glass(1.5), Vec3::Y, 20_000);
        // E[weight] = F + (1 - F) / 1.5² = 0.04 + 0.96 / 2.25.
        let expected = 0.04 + 0.96 / 2.25;
        assert!((weight.x - expected).abs() < 0.01, "{weight} vs {expected}");
    }
}
