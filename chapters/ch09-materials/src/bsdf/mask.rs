//! A cut-out (Mitsuba 3's `mask`): where the surface has opacity `α`, a ray meets the nested
//! material with probability `α` and passes straight on otherwise.
//!
//! Passing on is a delta lobe (`wi = -wo`, weight 1, infinite density) that the choice picks
//! with probability `1 - α`, so light found beyond it is weighted 1, as after a mirror. The
//! nested material's lobes keep their weight `f cos θ / pdf` (its share `α` and the
//! probability `α` of choosing it cancel), while `eval` and `pdf` are the nested ones times
//! `α`: what a light sample at the surface sees, and the density of the whole mask.
//!
//! Two choices follow Mitsuba 3's `path` integrator. Passing through the surface counts as a
//! segment towards `max_depth` and the roulette. And a shadow ray is stopped by a masked
//! surface wherever it crosses it, however transparent the surface is there: light reaches a
//! point behind a cut-out only by paths that pass through it.
//!
//! Two things Mitsuba's `path` does are not copied, because they change the mean: its `mask`
//! reports the nested density without the factor `α` when it samples the nested material
//! (while its light samples use the density with it, as here, so the two MIS weights need
//! not add up to 1), and a path whose rays have all passed through masks and then left a
//! scene without an environment is set to black, the light sampled at those masks with it
//! (the `path` integrator keeps a path's radiance only once it has scattered off something:
//! `valid_ray`, meant for the image's alpha). Mitsuba's `volpath` gives what is computed here
//! for a card in front of nothing; the agreement scene has an environment.
//!
//! One number is drawn for the choice, before the nested material's own.

use super::SceneBsdf;
use ch08_path_tracing::{BsdfSample, SurfaceBsdf};
use common::sampler::Sampler;
use common::scene::Opacity;
use glam::Vec3;

/// The opacity of a mask whose texture [`Scene::material_at`](common::scene::Scene) has read:
/// in [0, 1]. A texture left unread (a material taken from the scene as it is) counts as
/// opaque: the nested material alone.
pub fn opacity(opacity: Opacity) -> f32 {
    match opacity {
        Opacity::Uniform(alpha) if alpha >= 0.0 => alpha.min(1.0),
        Opacity::Uniform(_) => 0.0, // negative or NaN: no surface
        Opacity::Texture(_) => 1.0,
    }
}

/// Passes on with probability `1 - alpha`, else samples `nested`.
pub fn sample<S: Sampler>(
    alpha: f32,
    nested: &SceneBsdf,
    wo: Vec3,
    sampler: &mut S,
) -> Option<BsdfSample> {
    if sampler.get_1d() >= alpha {
        return Some(BsdfSample {
            wi: -wo,
            weight: Vec3::ONE,
            pdf: f32::INFINITY,
            eta_scale: 1.0,
        });
    }
    let sample = nested.sample(wo, sampler)?;
    Some(BsdfSample {
        pdf: alpha * sample.pdf,
        ..sample
    })
}

/// `α f cos θ` of the nested material.
pub fn eval(alpha: f32, nested: &SceneBsdf, wo: Vec3, wi: Vec3) -> Vec3 {
    alpha * nested.eval(wo, wi)
}

/// `α pdf` of the nested material.
pub fn pdf(alpha: f32, nested: &SceneBsdf, wo: Vec3, wi: Vec3) -> f32 {
    alpha * nested.pdf(wo, wi)
}

#[cfg(test)]
mod tests {
    use super::super::test_support::check_consistent;
    use ch08_path_tracing::SurfaceBsdf;
    use common::scene::{Mask, Material, Opacity};
    use glam::Vec3;

    fn masked(opacity: f32, nested: Material) -> Material {
        Material::Mask(Mask {
            opacity: Opacity::Uniform(opacity),
            nested: Box::new(nested),
        })
    }

    #[test]
    fn a_mask_passes_on_one_minus_opacity_of_the_rays_and_scatters_the_rest_as_its_material() {
        let n = 20_000;
        let wo = Vec3::new(0.0, 0.8, 0.6);
        for opacity in [0.0, 0.3, 1.0] {
            // Matte: every sample weighs its albedo, passing on weighs 1; eval and pdf are
            // the matte ones times the opacity (checked sample by sample).
            let (weight, passed) =
                check_consistent(&masked(opacity, Material::diffuse(Vec3::splat(0.5))), wo, n);
            // The share passed on is binomial: 5 standard errors.
            let se = (opacity * (1.0 - opacity) / n as f32).sqrt();
            assert!(
                (passed - (1.0 - opacity)).abs() <= 5.0 * se + 1e-6,
                "{opacity}: {passed}"
            );
            let expected = passed + (1.0 - passed) * 0.5;
            assert!((weight.x - expected).abs() < 1e-4, "{opacity}: {weight}");
        }
    }

    #[test]
    fn the_opacity_scales_what_a_light_sample_sees() {
        let hit = super::super::test_support::floor_hit();
        let white = Material::diffuse(Vec3::ONE);
        let (wo, wi) = (Vec3::Y, Vec3::new(0.6, 0.8, 0.0));
        let bsdf = |material: Material| {
            let plain = super::super::SceneBsdf {
                material: &material,
                hit: &hit,
                fuzz: ch06_fuzzy_reflections::FuzzMethod::Lobe,
                coatings: &crate::microfacet::coating::Coatings::default(),
            };
            (plain.eval(wo, wi), plain.pdf(wo, wi), plain.is_delta())
        };
        let (f, pdf, delta) = bsdf(white.clone());
        assert!(!delta);
        let (f_masked, pdf_masked, delta_masked) = bsdf(masked(0.25, white));
        assert_eq!(
            (f_masked, pdf_masked, delta_masked),
            (0.25 * f, 0.25 * pdf, false)
        );
        // Around a mirror, both of its lobes are deltas: no light sample.
        assert!(bsdf(masked(0.25, Material::mirror())).2);
        // A texture left unread is opaque; a NaN opacity is no surface.
        assert_eq!(super::opacity(Opacity::Uniform(f32::NAN)), 0.0);
        assert_eq!(super::opacity(Opacity::Uniform(3.0)), 1.0);
    }
}
