use super::direction;
use crate::microfacet::albedo;
use crate::microfacet::coating::Coating;
use crate::microfacet::{
    LocalBsdf, NormalDistribution, RoughConductor, RoughDielectric, RoughPlastic,
    RoughPlasticParameters,
};
use common::sampler::{IndependentSampler, Sampler};
use common::scene::MicrofacetDistribution::{self, Beckmann, Ggx};
use glam::{DVec3, UVec2, Vec2, Vec3};

/// Gold, in Mitsuba's RGB (`eta`, `k`).
fn gold(kind: MicrofacetDistribution, au: f32, av: f32) -> RoughConductor {
    RoughConductor {
        distribution: NormalDistribution::new(kind, au, av),
        eta: Vec3::new(0.143, 0.374, 1.442),
        k: Vec3::new(3.983, 2.385, 1.603),
        specular_reflectance: Vec3::ONE,
    }
}

fn glass(kind: MicrofacetDistribution, alpha: f32) -> RoughDielectric {
    RoughDielectric::new(NormalDistribution::isotropic(kind, alpha), 1.5, 1.0)
}

fn plastic(kind: MicrofacetDistribution, alpha: f32, diffuse: Vec3) -> RoughPlastic<'static> {
    let parameters = RoughPlasticParameters {
        kind,
        alpha,
        eta: 1.49,
        diffuse_reflectance: diffuse,
        specular_reflectance: Vec3::ONE,
        nonlinear: false,
    };
    // Kept to the end of the test process: the plastic outlives this function.
    let coating: &'static Coating = Box::leak(Box::new(parameters.coating()));
    RoughPlastic::new(parameters, coating)
}

/// The mean weight of `n` samples from `wo` and its standard error, after checking that every
/// sample's pdf is `pdf(wi)` and its weight `eval / pdf`.
///
/// Glass is allowed a few pdfs a little off: at a facet near the critical angle the Fresnel
/// term's slope is unbounded, and the facet `pdf` recomputes from the `f32` direction differs
/// from the sampled one in the last bits. (`eval / pdf` has no Fresnel term, so the weights
/// agree everywhere.)
fn sampled_albedo(bsdf: &dyn LocalBsdf, wo: Vec3, n: u64, name: &str) -> (DVec3, DVec3) {
    let mut sampler = IndependentSampler::new(11);
    let (mut sum, mut sum2) = (DVec3::ZERO, DVec3::ZERO);
    let mut slightly_off = 0;
    for i in 0..n {
        sampler.start_pixel_sample(UVec2::ZERO, i);
        let choice = sampler.get_1d();
        let Some(s) = bsdf.sample(wo, choice, sampler.get_2d()) else {
            continue;
        };
        assert!(
            s.weight.is_finite() && s.wi.is_finite() && s.pdf.is_finite(),
            "{name}: {s:?}"
        );
        let pdf = bsdf.pdf(wo, s.wi);
        let off = (pdf - s.pdf).abs() / s.pdf;
        assert!(
            off <= 2e-2,
            "{name}: pdf {pdf} vs {} at {wo} -> {}",
            s.pdf,
            s.wi
        );
        if off > 1e-3 {
            slightly_off += 1;
        }
        let expected = bsdf.eval(wo, s.wi) / pdf;
        assert!(
            (expected - s.weight).abs().max_element() <= 1e-3 * s.weight.max_element() + 1e-6,
            "{name} from {wo}: weight {} vs eval/pdf {expected}",
            s.weight
        );
        let w = s.weight.as_dvec3();
        sum += w;
        sum2 += w * w;
    }
    assert!(
        slightly_off * 10_000 <= n,
        "{name}: {slightly_off} pdfs off by over 1e-3"
    );
    let mean = sum / n as f64;
    let variance = (sum2 / n as f64 - mean * mean).max(DVec3::ZERO);
    (mean, (variance / n as f64).sqrt())
}

/// `∫ f cos dω_i` by quadrature, reflection and (for glass) refraction.
fn quadrature_albedo(bsdf: &dyn LocalBsdf, wo: Vec3, scale: f32, eta: Option<f32>) -> DVec3 {
    let eval = |wi| bsdf.eval(wo, wi);
    let reflected = albedo::reflected(wo, scale, eval);
    match eta {
        Some(eta) => reflected + albedo::refracted(wo, scale, eta, eval),
        None => reflected,
    }
}

/// The mean weight must be the quadrature's albedo to within five standard errors and what
/// the quadrature itself may be off by.
fn assert_consistent(bsdf: &dyn LocalBsdf, wo: Vec3, scale: f32, eta: Option<f32>, name: &str) {
    let (mean, error) = sampled_albedo(bsdf, wo, 200_000, name);
    let exact = quadrature_albedo(bsdf, wo, scale, eta);
    let slack = 5.0 * error + DVec3::splat(2e-3);
    assert!(
        (mean - exact).abs().cmple(slack).all(),
        "{name} from {wo}: E[weight] {mean} ± {error} but ∫ f cos = {exact}"
    );
}

#[test]
fn rough_conductors_sample_what_they_evaluate() {
    for kind in [Beckmann, Ggx] {
        for (au, av) in [(0.05, 0.05), (0.3, 0.3), (1.0, 1.0), (0.1, 0.5)] {
            let bsdf = gold(kind, au, av);
            for wo in [
                direction(0.0, 0.0),
                direction(60.0, 30.0),
                direction(85.0, 100.0),
            ] {
                let name = format!("gold {kind:?} {au}/{av}");
                assert_consistent(&bsdf, wo, au.max(av), None, &name);
            }
        }
    }
}

#[test]
fn rough_glass_samples_what_it_evaluates_from_both_sides() {
    for kind in [Beckmann, Ggx] {
        for alpha in [0.05, 0.3, 0.8] {
            let bsdf = glass(kind, alpha);
            for wo in [
                direction(0.0, 0.0),
                direction(50.0, 0.0),
                direction(80.0, 0.0),
            ] {
                let name = format!("glass {kind:?} {alpha}");
                assert_consistent(&bsdf, wo, alpha, Some(1.5), &name);
                assert_consistent(&bsdf, -wo, alpha, Some(1.5), &format!("{name}, inside"));
            }
        }
    }
}

#[test]
fn rough_plastic_samples_what_it_evaluates() {
    for kind in [Beckmann, Ggx] {
        for alpha in [0.05, 0.3] {
            let bsdf = plastic(kind, alpha, Vec3::new(0.2, 0.5, 0.8));
            for wo in [
                direction(0.0, 0.0),
                direction(45.0, 0.0),
                direction(80.0, 0.0),
            ] {
                let name = format!("plastic {kind:?} {alpha}");
                assert_consistent(&bsdf, wo, alpha, None, &name);
            }
        }
    }
}

/// `f(wo, wi) = f(wi, wo)`: `eval` is `f cos θ_i`, so `eval(wo, wi) / cos θ_i` must be
/// `eval(wi, wo) / cos θ_o`.
fn assert_reciprocal(bsdf: &dyn LocalBsdf, name: &str) {
    let directions = [
        direction(0.0, 0.0),
        direction(30.0, 10.0),
        direction(60.0, 200.0),
        direction(75.0, 90.0),
        direction(88.0, 300.0),
    ];
    for a in directions {
        for b in directions {
            let ab = bsdf.eval(a, b) / b.z;
            let ba = bsdf.eval(b, a) / a.z;
            let scale = ab.abs().max(ba.abs()).max_element().max(1e-6);
            assert!(
                (ab - ba).abs().max_element() <= 1e-4 * scale,
                "{name}: {a} {b}: {ab} vs {ba}"
            );
        }
    }
}

#[test]
fn conductors_and_plastics_are_reciprocal() {
    for kind in [Beckmann, Ggx] {
        assert_reciprocal(&gold(kind, 0.3, 0.3), "gold");
        assert_reciprocal(&gold(kind, 0.1, 0.5), "anisotropic gold");
        assert_reciprocal(&plastic(kind, 0.2, Vec3::splat(0.5)), "plastic");
    }
}

#[test]
fn a_white_rough_mirror_keeps_at_most_all_the_light_and_nearly_all_when_smooth() {
    for kind in [Beckmann, Ggx] {
        for alpha in [0.01, 0.1, 0.5, 1.0] {
            let bsdf = RoughConductor::white(kind, alpha);
            for theta in [0.0, 45.0, 80.0] {
                let wo = direction(theta, 0.0);
                let albedo = albedo::reflected(wo, alpha, |wi| bsdf.eval(wo, wi)).x;
                assert!(
                    (0.0..=1.0 + 1e-3).contains(&albedo),
                    "{kind:?} {alpha} {theta}°: {albedo}"
                );
                if alpha <= 0.01 {
                    assert!(albedo > 0.99, "{kind:?} {alpha} {theta}°: {albedo}");
                }
            }
        }
    }
}

#[test]
fn rough_glass_loses_light_but_never_makes_it() {
    for kind in [Beckmann, Ggx] {
        for alpha in [0.01, 0.3, 1.0] {
            let bsdf = glass(kind, alpha);
            for wo in [direction(0.0, 0.0), direction(70.0, 0.0)] {
                for (wo, eta_t_over_i) in [(wo, 1.5f64), (-wo, 1.0 / 1.5)] {
                    let eval = |wi| bsdf.eval(wo, wi);
                    let reflected = albedo::reflected(wo, alpha, eval).x;
                    // Undo the radiance scaling `(n_i / n_t)²` to count energy.
                    let refracted =
                        albedo::refracted(wo, alpha, 1.5, eval).x * eta_t_over_i.powi(2);
                    let total = reflected + refracted;
                    assert!(total <= 1.0 + 2e-3, "{kind:?} {alpha} from {wo}: {total}");
                    if alpha <= 0.01 && wo.z > 0.0 {
                        assert!(total > 0.99, "{kind:?} {alpha} from {wo}: {total}");
                    }
                }
            }
        }
    }
}

#[test]
fn a_white_plastic_keeps_at_most_all_the_light() {
    for kind in [Beckmann, Ggx] {
        for alpha in [0.05, 0.5] {
            let bsdf = plastic(kind, alpha, Vec3::ONE);
            for theta in [0.0, 60.0, 85.0] {
                let wo = direction(theta, 0.0);
                let albedo = albedo::reflected(wo, alpha, |wi| bsdf.eval(wo, wi)).x;
                assert!(albedo <= 1.0 + 1e-2, "{kind:?} {alpha} {theta}°: {albedo}");
            }
        }
    }
}

#[test]
fn stiff_inputs_never_give_nan_or_infinity() {
    let sharp = 1e-4;
    let bsdfs: Vec<(String, Box<dyn LocalBsdf>)> = [Beckmann, Ggx]
        .into_iter()
        .flat_map(|kind| {
            let all: [(String, Box<dyn LocalBsdf>); 6] = [
                (
                    format!("gold {kind:?} sharp"),
                    Box::new(gold(kind, sharp, sharp)),
                ),
                (format!("gold {kind:?} 1"), Box::new(gold(kind, 1.0, 1.0))),
                (
                    format!("glass {kind:?} sharp"),
                    Box::new(glass(kind, sharp)),
                ),
                (format!("glass {kind:?} 1"), Box::new(glass(kind, 1.0))),
                (
                    format!("plastic {kind:?} sharp"),
                    Box::new(plastic(kind, sharp, Vec3::ONE)),
                ),
                (
                    format!("plastic {kind:?} 1"),
                    Box::new(plastic(kind, 1.0, Vec3::ZERO)),
                ),
            ];
            all
        })
        .collect();
    let directions = [
        Vec3::Z,
        -Vec3::Z,
        Vec3::new(1.0, 0.0, 1e-4).normalize(),
        Vec3::new(0.0, 1.0, -1e-6).normalize(),
        Vec3::X,
        direction(45.0, 0.0),
        direction(45.0, 180.0),
    ];
    let numbers = [0.0, 0.25, 0.5, 0.999_999_94];
    for (name, bsdf) in &bsdfs {
        for wo in directions {
            for wi in directions {
                let (f, p) = (bsdf.eval(wo, wi), bsdf.pdf(wo, wi));
                assert!(f.is_finite() && p.is_finite(), "{name}: {wo} {wi}: {f} {p}");
            }
            for &choice in &numbers {
                for &x in &numbers {
                    for &y in &numbers {
                        if let Some(s) = bsdf.sample(wo, choice, Vec2::new(x, y)) {
                            assert!(
                                s.wi.is_finite() && s.weight.is_finite() && s.pdf.is_finite(),
                                "{name} from {wo}: {s:?}"
                            );
                        }
                    }
                }
            }
        }
    }
}
