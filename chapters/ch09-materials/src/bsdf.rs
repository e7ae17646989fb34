//! The BSDF of every material a scene file may name, for chapter 08's path loop: the lecture's
//! materials as chapter 08 renders them ([`ch08_path_tracing::Bsdf`]), and Mitsuba 3's beyond
//! them, one small module each.
//!
//! A metal's weight `f cos θ / pdf` is its Fresnel reflectance, plastic's varies with `wi`; a
//! file's rough metals, rough plastics and rough glass (`roughness` or `stands_in_for` given)
//! are Mitsuba's microfacet models ([`microfacet`], through [`crate::microfacet`]) instead of
//! chapter 06's `cos^n` lobes, which the lecture's own glossy and frosted materials keep.
//!
//! Random numbers, in this order: a choice at a thin pane, plastic, tinted glass and every
//! microfacet material (1), a direction (2) for plastic and every microfacet material; a
//! smooth metal takes none. A mask ([`mask`]) draws one number for its choice, then, when the
//! ray meets the surface, the nested material's. The lecture's materials draw what chapter 08
//! draws for them.

pub mod conductor;
pub mod mask;
pub mod microfacet;
pub mod plastic;
pub mod thin_dielectric;
pub mod tinted_glass;

use crate::microfacet::coating::Coatings;
use ch06_fuzzy_reflections::FuzzMethod;
use ch08_path_tracing::bsdf::{Bsdf, BsdfSample, Materials, SurfaceBsdf};
use common::geometry::SurfaceHit;
use common::sampler::Sampler;
use common::scene::{Material, Scene};
use glam::Vec3;

/// Every material of a scene file: the lecture's, as chapter 08 renders them, and Mitsuba's
/// beyond them, with the tables they need made before the render.
#[derive(Clone, Debug)]
pub struct SceneMaterials {
    /// How the lecture's fuzzy lobes spread (chapter 06's `cos^n` lobe or the empirical disc).
    pub fuzz: FuzzMethod,
    /// The rough plastics' coatings, tabulated before the render.
    pub coatings: Coatings,
}

impl SceneMaterials {
    /// The materials of `scene`, its rough plastics' coatings tabulated now, before any ray
    /// is traced; lobes spread as `fuzz` says.
    pub fn of(scene: &Scene, fuzz: FuzzMethod) -> Self {
        Self {
            fuzz,
            coatings: Coatings::of(scene),
        }
    }
}

impl Materials for SceneMaterials {
    type Bsdf<'a> = SceneBsdf<'a>;

    fn bsdf<'a>(&'a self, material: &'a Material, hit: &'a SurfaceHit) -> SceneBsdf<'a> {
        SceneBsdf {
            material,
            hit,
            fuzz: self.fuzz,
            coatings: &self.coatings,
        }
    }
}

/// Any material at a hit point, ready to scatter: the material with its textures read at the
/// hit (`Scene::material_at`), the hit, the lobe family and the coatings.
#[derive(Clone, Copy, Debug)]
pub struct SceneBsdf<'a> {
    /// The material, its textures read at the hit by `Scene::material_at`.
    pub material: &'a Material,
    /// The surface point.
    pub hit: &'a SurfaceHit,
    /// How the lecture's fuzzy lobes spread.
    pub fuzz: FuzzMethod,
    /// The rough plastics' coatings, tabulated before the render.
    pub coatings: &'a Coatings,
}

impl SceneBsdf<'_> {
    /// The BSDF of a mask's `nested` material at the same hit.
    fn nested<'b>(&'b self, nested: &'b Material) -> SceneBsdf<'b> {
        SceneBsdf {
            material: nested,
            ..*self
        }
    }

    /// Chapter 08's BSDF of the same material: the lecture's materials are rendered as the
    /// lecture renders them, number for number.
    fn lecture(&self) -> Bsdf<'_> {
        Bsdf {
            material: self.material,
            hit: self.hit,
            fuzz: self.fuzz,
        }
    }
}

impl SurfaceBsdf for SceneBsdf<'_> {
    fn hit(&self) -> &SurfaceHit {
        self.hit
    }

    fn is_delta(&self) -> bool {
        match self.material {
            Material::RoughGlass(g) if g.stands_in_for.is_some() => false,
            // A microfacet metal is never a delta: its roughness is at least `MIN_ALPHA`.
            Material::Conductor(c) => c.roughness.is_none(),
            Material::ThinDielectric { .. } => true,
            Material::Plastic(_) => false,
            Material::TintedGlass(g) => g.roughness.is_none(),
            // Passing through is a delta, but the nested material may want a light sample.
            Material::Mask(mask) => self.nested(&mask.nested).is_delta(),
            _ => self.lecture().is_delta(),
        }
    }

    fn sample<S: Sampler>(&self, wo: Vec3, sampler: &mut S) -> Option<BsdfSample> {
        let hit = self.hit;
        match *self.material {
            Material::RoughGlass(g) if g.stands_in_for.is_some() => {
                let roughness = g.stands_in_for?;
                let (choice, u) = (sampler.get_1d(), sampler.get_2d());
                microfacet::rough_dielectric(hit, &g, roughness).sample(wo, choice, u)
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
                    None => tinted_glass::sample(hit, wo, &g, choice),
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
            _ => self.lecture().sample(wo, sampler),
        }
    }

    fn eval(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        let hit = self.hit;
        match *self.material {
            Material::RoughGlass(g) => match g.stands_in_for {
                None => self.lecture().eval(wo, wi),
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
            _ => self.lecture().eval(wo, wi),
        }
    }

    fn pdf(&self, wo: Vec3, wi: Vec3) -> f32 {
        let hit = self.hit;
        match *self.material {
            Material::RoughGlass(g) => match g.stands_in_for {
                None => self.lecture().pdf(wo, wi),
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
            _ => self.lecture().pdf(wo, wi),
        }
    }
}

#[cfg(test)]
pub(crate) mod test_support;

#[cfg(test)]
mod tests {
    use super::SceneBsdf;
    use super::test_support::check_consistent;
    use ch08_path_tracing::SurfaceBsdf;
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
        let bsdf = SceneBsdf {
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
}
