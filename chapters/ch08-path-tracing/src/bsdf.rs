//! The BSDF of every material, as the path tracer needs it: *sample* a direction,
//! *evaluate* `f cos θ` for a direction the light sample chose, and the *density* with which
//! sampling would have chosen it (for multiple importance sampling).
//!
//! Each material keeps the three in one small module. Directions point away from the surface:
//! `wo` towards where the path came from, `wi` towards where the light comes from. A
//! [`BsdfSample`]'s `weight` is `f cos θ / pdf`, which for the lecture's materials is a
//! constant (the albedo, the reflectance, 1 or the refraction's `eta²`): each is sampled by
//! exactly the lobe it is made of. Chapter 08's own (metals, thin glass, plastic) follow
//! Mitsuba 3's: a metal's weight is its Fresnel reflectance, plastic's varies with `wi`.
//!
//! A file's rough metals, rough plastics and rough glass (`roughness` or `stands_in_for`
//! given) are Mitsuba's microfacet models ([`microfacet`], through [`crate::microfacet`]);
//! chapter 06's own glossy and frosted materials keep their `cos^n` lobes.
//!
//! Random numbers, in this order: a choice at glass, a thin pane, plastic and every microfacet
//! material (1), a direction (2) for diffuse, glossy, frosted and plastic surfaces and every
//! microfacet material; a mirror, a smooth metal and smooth glass's chosen branch take no
//! direction numbers. A mask ([`mask`]) draws one number for its choice, then, when the ray
//! meets the surface, the nested material's.

pub mod conductor;
pub mod dielectric;
pub mod diffuse;
pub mod glossy;
pub mod mask;
pub mod microfacet;
pub mod mirror;
pub mod plastic;
pub mod rough_glass;
pub mod thin_dielectric;

use crate::microfacet::coating::Coatings;
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

/// A material at a hit point, ready to scatter: the material with its texture read at the hit
/// (`Scene::material_at`), the hit and the lobe family.
#[derive(Clone, Copy, Debug)]
pub struct Bsdf<'a> {
    /// The material, its texture read at the hit by `Scene::material_at` (a
    /// `TexturedDiffuse` that has not been read reflects nothing).
    pub material: &'a Material,
    /// The surface point.
    pub hit: &'a SurfaceHit,
    /// How fuzzy lobes spread (chapter 06's `cos^n` lobe or the empirical disc).
    pub fuzz: FuzzMethod,
    /// The rough plastics' coatings, tabulated before the render.
    pub coatings: &'a Coatings,
}

impl Bsdf<'_> {
    /// Whether every direction the material scatters to is a delta: no light sample can
    /// help it, so the path tracer sends none.
    pub fn is_delta(&self) -> bool {
        match self.material {
            Material::Mirror { .. } | Material::Dielectric { .. } => true,
            Material::Diffuse { .. } | Material::TexturedDiffuse { .. } => false,
            Material::Glossy(g) => !g.exponent.is_finite(),
            Material::RoughGlass(g) => g.stands_in_for.is_none() && !g.exponent.is_finite(),
            // A microfacet metal is never a delta: its roughness is at least `MIN_ALPHA`.
            Material::Conductor(c) => c.roughness.is_none(),
            Material::ThinDielectric { .. } => true,
            Material::Plastic(_) => false,
            Material::TintedGlass(g) => g.roughness.is_none(),
            // Passing through is a delta, but the nested material may want a light sample.
            Material::Mask(mask) => self.nested(&mask.nested).is_delta(),
        }
    }

    /// The BSDF of a mask's `nested` material at the same hit.
    fn nested<'b>(&'b self, nested: &'b Material) -> Bsdf<'b> {
        Bsdf {
            material: nested,
            ..*self
        }
    }

    /// Samples `wi` for the outgoing `wo`, drawing the material's numbers from `sampler`;
    /// `None` when the path ends here (a one-sided surface seen from behind, a lobe direction
    /// below the surface, a branch that carries nothing).
    pub fn sample<S: Sampler>(&self, wo: Vec3, sampler: &mut S) -> Option<BsdfSample> {
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
                if let Some(roughness) = g.stands_in_for {
                    let u = sampler.get_2d();
                    return microfacet::rough_dielectric(hit, &g, roughness).sample(wo, choice, u);
                }
                let u = if g.exponent.is_finite() {
                    sampler.get_2d()
                } else {
                    glam::Vec2::ZERO
                };
                rough_glass::sample(hit, wo, &g, self.fuzz, choice, u)
            }
            Material::Conductor(c) => match c.roughness {
                None => conductor::sample(hit, wo, &c),
                Some(roughness) => {
                    let (choice, u) = (sampler.get_1d(), sampler.get_2d());
                    microfacet::rough_conductor(hit, wo, &c, roughness)?.sample(wo, choice, u)
                }
            },
            Material::ThinDielectric { int_ior, ext_ior } => Some(thin_dielectric::sample(
                hit,
                wo,
                int_ior,
                ext_ior,
                sampler.get_1d(),
            )),
            Material::TintedGlass(g) => {
                let choice = sampler.get_1d();
                match g.roughness {
                    None => dielectric::sample_tinted(hit, wo, &g, choice),
                    Some(roughness) => microfacet::tinted_rough_dielectric(hit, &g, roughness)
                        .sample(wo, choice, sampler.get_2d()),
                }
            }
            Material::Plastic(p) => {
                let choice = sampler.get_1d();
                let u = sampler.get_2d();
                match p.roughness {
                    None => plastic::sample(hit, wo, &p, choice, u),
                    Some(roughness) => {
                        microfacet::rough_plastic(hit, wo, &p, roughness, self.coatings)?
                            .sample(wo, choice, u)
                    }
                }
            }
            Material::Mask(ref m) => mask::sample(
                mask::opacity(m.opacity),
                &self.nested(&m.nested),
                wo,
                sampler,
            ),
        }
    }

    /// `f(wo, wi) cos θ_i` without the delta parts (0 for a mirror, a smooth metal, smooth or
    /// thin glass; plastic's base without its smooth coat).
    pub fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        let hit = self.hit;
        match *self.material {
            Material::Diffuse { albedo, two_sided } => {
                diffuse::eval(hit, wo, wi, albedo, two_sided)
            }
            Material::TexturedDiffuse { .. } => Vec3::ZERO, // see `sample`
            Material::Mirror { .. } | Material::Dielectric { .. } => Vec3::ZERO,
            Material::Glossy(g) => glossy::eval(hit, wo, wi, &g, self.fuzz),
            Material::RoughGlass(g) => match g.stands_in_for {
                None => rough_glass::eval(hit, wo, wi, &g, self.fuzz),
                Some(roughness) => microfacet::rough_dielectric(hit, &g, roughness).eval(wo, wi),
            },
            Material::Conductor(c) => match c.roughness {
                None => Vec3::ZERO,
                Some(roughness) => microfacet::rough_conductor(hit, wo, &c, roughness)
                    .map_or(Vec3::ZERO, |bsdf| bsdf.eval(wo, wi)),
            },
            Material::ThinDielectric { .. } => Vec3::ZERO,
            Material::TintedGlass(g) => match g.roughness {
                None => Vec3::ZERO,
                Some(roughness) => {
                    microfacet::tinted_rough_dielectric(hit, &g, roughness).eval(wo, wi)
                }
            },
            Material::Plastic(p) => match p.roughness {
                None => plastic::eval(hit, wo, wi, &p),
                Some(roughness) => microfacet::rough_plastic(hit, wo, &p, roughness, self.coatings)
                    .map_or(Vec3::ZERO, |bsdf| bsdf.eval(wo, wi)),
            },
            Material::Mask(ref m) => {
                mask::eval(mask::opacity(m.opacity), &self.nested(&m.nested), wo, wi)
            }
        }
    }

    /// The density per unit solid angle with which [`sample`](Self::sample) picks `wi`
    /// (its delta parts left out: 0 for a mirror or smooth glass).
    pub fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        let hit = self.hit;
        match *self.material {
            Material::Diffuse { two_sided, .. } | Material::TexturedDiffuse { two_sided, .. } => {
                diffuse::pdf(hit, wo, wi, two_sided)
            }
            Material::Mirror { .. } | Material::Dielectric { .. } => 0.0,
            Material::Glossy(g) => glossy::pdf(hit, wo, wi, &g, self.fuzz),
            Material::RoughGlass(g) => match g.stands_in_for {
                None => rough_glass::pdf(hit, wo, wi, &g, self.fuzz),
                Some(roughness) => microfacet::rough_dielectric(hit, &g, roughness).pdf(wo, wi),
            },
            Material::Conductor(c) => match c.roughness {
                None => 0.0,
                Some(roughness) => microfacet::rough_conductor(hit, wo, &c, roughness)
                    .map_or(0.0, |bsdf| bsdf.pdf(wo, wi)),
            },
            Material::ThinDielectric { .. } => 0.0,
            Material::TintedGlass(g) => match g.roughness {
                None => 0.0,
                Some(roughness) => {
                    microfacet::tinted_rough_dielectric(hit, &g, roughness).pdf(wo, wi)
                }
            },
            Material::Plastic(p) => match p.roughness {
                None => plastic::pdf(hit, wo, wi, &p),
                Some(roughness) => microfacet::rough_plastic(hit, wo, &p, roughness, self.coatings)
                    .map_or(0.0, |bsdf| bsdf.pdf(wo, wi)),
            },
            Material::Mask(ref m) => {
                mask::pdf(mask::opacity(m.opacity), &self.nested(&m.nested), wo, wi)
            }
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

/// `local` (z along `normal`) in world space, through any frame around the unit `normal`.
pub fn to_world(normal: Vec3, local: Vec3) -> Vec3 {
    let (a, b) = normal.any_orthonormal_pair();
    local.x * a + local.y * b + local.z * normal
}

#[cfg(test)]
pub(crate) mod test_support;

#[cfg(test)]
mod tests {
    use super::test_support::check_consistent;
    use super::{Bsdf, test_support};
    use ch06_fuzzy_reflections::FuzzMethod;
    use common::geometry::SurfaceHit;
    use common::scene::Material as Smooth;
    use common::scene::{Conductor, Material, Microfacet, MicrofacetDistribution, Plastic};
    use glam::Vec3;

    #[test]
    fn sampling_eval_and_pdf_describe_the_same_material() {
        let materials = [
            Smooth::diffuse(Vec3::splat(0.8)),
            Smooth::two_sided_diffuse(Vec3::splat(0.5)),
            Material::glossy(Vec3::splat(0.9), 0.0),
            Material::glossy(Vec3::splat(0.9), 50.0),
            Material::rough_glass(1.5, 10.0),
            Material::rough_glass(1.5, 1000.0),
            Material::Plastic(plastic(None, false)),
            Material::Plastic(plastic(None, true)),
            Material::Plastic(plastic(Some(0.2), false)),
            Material::Plastic(Plastic {
                nonlinear: true,
                ..plastic(Some(0.05), true)
            }),
            Material::Conductor(Conductor {
                roughness: Some(beckmann(0.3)),
                ..gold()
            }),
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
            coatings: &crate::microfacet::coating::Coatings::default(),
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

    fn beckmann(alpha: f32) -> Microfacet {
        Microfacet::isotropic(MicrofacetDistribution::Beckmann, alpha)
    }

    fn plastic(alpha: Option<f32>, two_sided: bool) -> Plastic {
        Plastic {
            diffuse_reflectance: Vec3::new(0.9, 0.5, 0.1),
            specular_reflectance: Vec3::ONE,
            diffuse_texture: None,
            specular_texture: None,
            int_ior: 1.49,
            ext_ior: 1.000277,
            nonlinear: false,
            two_sided,
            roughness: alpha.map(beckmann),
        }
    }

    fn gold() -> Conductor {
        let (eta, k) = workbench::scene_file::named_metal("Au").unwrap();
        Conductor {
            eta,
            k,
            specular_reflectance: Vec3::ONE,
            specular_texture: None,
            two_sided: false,
            roughness: None,
        }
    }

    #[test]
    fn a_smooth_metal_reflects_its_fresnel_share_into_the_mirror_direction() {
        let wo = Vec3::new(0.6, 0.8, 0.0);
        let (weight, deltas) = check_consistent(&Material::Conductor(gold()), wo, 10);
        assert_eq!(deltas, 1.0);
        let fresnel = super::conductor::fresnel_conductor_rgb(0.8, gold().eta, gold().k);
        assert!((weight - fresnel).abs().max_element() < 1e-6, "{weight}");
        // Black from behind, unless two-sided.
        let behind = Vec3::new(0.6, -0.8, 0.0);
        let (weight, _) = check_consistent(&Material::Conductor(gold()), behind, 10);
        assert_eq!(weight, Vec3::ZERO);
        let two_sided = Material::Conductor(Conductor {
            two_sided: true,
            ..gold()
        });
        assert!(check_consistent(&two_sided, behind, 10).0.x > 0.9);
    }

    #[test]
    fn a_thin_pane_reflects_r_prime_and_lets_the_rest_through_unbent() {
        let pane = Material::ThinDielectric {
            int_ior: 1.5,
            ext_ior: 1.0,
        };
        let wo = Vec3::new(0.0, 0.8, 0.6);
        let r = super::thin_dielectric::reflectance(0.8, 1.5);
        let hit = super::test_support::floor_hit();
        let bsdf = Bsdf {
            material: &pane,
            hit: &hit,
            fuzz: ch06_fuzzy_reflections::FuzzMethod::Lobe,
            coatings: &crate::microfacet::coating::Coatings::default(),
        };
        assert!(bsdf.is_delta());
        let mut sampler = common::sampler::IndependentSampler::new(1);
        let n = 100_000;
        let mut reflected = 0;
        for i in 0..n {
            use common::sampler::Sampler;
            sampler.start_pixel_sample(glam::UVec2::ZERO, i);
            let s = bsdf.sample(wo, &mut sampler).unwrap();
            assert_eq!((s.weight, s.eta_scale), (Vec3::ONE, 1.0));
            if s.wi.y > 0.0 {
                reflected += 1;
                assert!((s.wi - Vec3::new(0.0, 0.8, -0.6)).length() < 1e-6);
            } else {
                assert_eq!(s.wi, -wo);
            }
        }
        // Binomial: within five standard errors of R'.
        let share = reflected as f32 / n as f32;
        let se = (r * (1.0 - r) / n as f32).sqrt();
        assert!((share - r).abs() < 5.0 * se, "{share} vs {r}");
        // From the other side the pane is the same.
        let below = check_consistent(&pane, -wo, 100).0;
        assert_eq!(below, Vec3::ONE);
    }

    #[test]
    fn plastic_reflects_what_mitsubas_model_adds_up_to() {
        // Square on, the coat reflects F = 0.04 of glass 1.5 as a delta; the base sends back
        // the albedo / (1 - F_dr) times (1 - F_i) ∫ (1 - F_o) cos / π dω / eta², which a
        // quadrature over the hemisphere gives here.
        let material = Plastic {
            int_ior: 1.5,
            ext_ior: 1.0,
            ..plastic(None, false)
        };
        let f_i = 0.04;
        let fdr = super::plastic::diffuse_fresnel_reflectance(1.0 / 1.5);
        let steps = 20_000;
        let mut transmitted = 0.0;
        for j in 0..steps {
            let cos = (j as f32 + 0.5) / steps as f32;
            let f_o = ch01_whitted::optics::fresnel_dielectric(cos, 1.0 / 1.5);
            // ∫ (1 - F) cos/π dω = ∫ (1 - F) 2 cos dcos.
            transmitted += (1.0 - f_o) * 2.0 * cos / steps as f32;
        }
        let expected = Vec3::splat(f_i)
            + material.diffuse_reflectance / (1.0 - fdr) * (1.0 - f_i) * transmitted / 2.25;
        let (albedo, deltas) = check_consistent(&Material::Plastic(material), Vec3::Y, 200_000);
        // The estimator's standard deviation is below 0.5 per sample here: 200 000 samples
        // give a standard error below 1.2e-3; five of them.
        assert!(
            (albedo - expected).abs().max_element() < 6e-3,
            "{albedo} vs {expected}"
        );
        // The coat is picked with F w / (F w + (1 - F)(1 - w)), w = 1 / (1 + 0.5).
        let w = 1.0 / 1.5;
        let picked = f_i * w / (f_i * w + (1.0 - f_i) * (1.0 - w));
        let se = (picked * (1.0 - picked) / 200_000.0f32).sqrt();
        assert!((deltas - picked).abs() < 5.0 * se, "{deltas} vs {picked}");
        // Black from behind, one-sided.
        let (behind, _) = check_consistent(&Material::Plastic(material), -Vec3::Y, 100);
        assert_eq!(behind, Vec3::ZERO);
    }

    #[test]
    fn smooth_glass_splits_by_fresnel() {
        // Normal incidence on glass of 1.5: F = 0.04.
        let (_, deltas) = check_consistent(&Smooth::glass(1.5), Vec3::Y, 20_000);
        assert_eq!(deltas, 1.0);
        let (weight, _) = check_consistent(&Smooth::glass(1.5), Vec3::Y, 20_000);
        // E[weight] = F + (1 - F) / 1.5² = 0.04 + 0.96 / 2.25.
        let expected = 0.04 + 0.96 / 2.25;
        assert!((weight.x - expected).abs() < 0.01, "{weight} vs {expected}");
    }
}
