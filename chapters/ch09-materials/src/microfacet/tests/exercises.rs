//! The checks of the chapter's microfacet exercises: GGX's density of normals, and the rough
//! metal's sample by its visible normals. Each names the usual slip when it sees one.

use crate::microfacet::albedo::over_normals;
use crate::microfacet::distribution::ggx_density;
use crate::microfacet::fresnel::reflect_away;
use crate::microfacet::{NormalDistribution, RoughConductor};
use common::scene::MicrofacetDistribution::{Beckmann, Ggx};
use glam::{DVec3, Vec2, Vec3};
use std::f64::consts::PI;

/// GGX written with the angles, in double precision: the formula as papers print it.
fn ggx_by_angles(m: Vec3, alpha_u: f32, alpha_v: f32) -> f64 {
    let m = m.as_dvec3().normalize();
    let (au, av) = (f64::from(alpha_u), f64::from(alpha_v));
    let cos2 = m.z * m.z;
    let sin2 = 1.0 - cos2;
    let tan2 = sin2 / cos2;
    let phi = m.y.atan2(m.x);
    let stretch = phi.cos().powi(2) / (au * au) + phi.sin().powi(2) / (av * av);
    1.0 / (PI * au * av * cos2 * cos2 * (1.0 + tan2 * stretch).powi(2))
}

/// Names the slip that turns the right density `expected` into `got`, if it is one of the
/// usual ones. Each slip is recognised through the formula with the angles: a roughness
/// ignored, swapped or inverted is GGX of another roughness; a missing square or `1/π` shows
/// in how `got` relates to `expected`.
fn ggx_mistake(
    got: f64,
    expected: f64,
    m: Vec3,
    alpha_u: f32,
    alpha_v: f32,
) -> Option<&'static str> {
    let (au, av) = (f64::from(alpha_u), f64::from(alpha_v));
    let close = |value: f64| (got - value).abs() <= 1e-4 * value.abs().max(1e-12);
    let cos2 = f64::from(m.z).powi(2);
    let slopes2 = ((f64::from(m.x) / au).powi(2) + (f64::from(m.y) / av).powi(2)) / cos2;
    let candidates = [
        (
            PI * expected,
            "it is π times too large: the 1/π is missing, and without it the facets' projected \
             area is π times the surface's",
        ),
        (
            // Unsquared, the density's square times π α_u α_v is the right density.
            (expected / (PI * au * av)).sqrt(),
            "the sum in the denominator must be squared (the formula with the angles squares \
             its bracket, and multiplying cos⁴ θ_m in keeps a square)",
        ),
        (
            (-slopes2).exp() / (PI * au * av * cos2 * cos2),
            "that is Beckmann's distribution (a Gaussian in the slope); GGX's tail falls like a \
             power of tan θ, not an exponential",
        ),
        (
            ggx_by_angles(m, 1.0 / alpha_u, 1.0 / alpha_v) / (au * av).powi(2),
            "the tangential parts x and y are multiplied by the roughness; divide them by it (a \
             rougher surface spreads the normals wider)",
        ),
        (
            ggx_by_angles(m, alpha_u, alpha_u),
            "alpha_v is ignored: the roughness along y is alpha_v",
        ),
        (
            ggx_by_angles(m, alpha_v, alpha_u),
            "alpha_u and alpha_v are swapped: alpha_u is the roughness along x (the tangent), \
             alpha_v along y",
        ),
    ];
    candidates
        .into_iter()
        .find(|&(value, _)| close(value))
        .map(|(_, words)| words)
}

#[test]
fn exercise_ggx_density() {
    let normals = [
        Vec3::Z,
        Vec3::new(0.3, 0.0, 1.0).normalize(),
        Vec3::new(0.2, -0.4, 0.8).normalize(),
        Vec3::new(-0.9, 0.5, 0.2).normalize(),
    ];
    for (au, av) in [(0.5, 0.5), (0.2, 0.2), (1.0, 1.0), (0.1, 0.6)] {
        for m in normals {
            let got = f64::from(ggx_density(m, au, av));
            let expected = ggx_by_angles(m, au, av);
            if (got - expected).abs() <= 1e-4 * expected {
                continue;
            }
            let why = ggx_mistake(got, expected, m, au, av).unwrap_or(
                "the density differs from Walter et al.'s GGX, written with the angles in the \
                 function's documentation",
            );
            panic!(
                "ggx_density: {why}.\n  ggx_density(m = {m}, alpha_u = {au}, alpha_v = {av}) gave \
                 {got}, expected {expected}"
            );
        }
    }
    // On the horizon a facet stands on edge: its density is finite.
    let edge = ggx_density(Vec3::X, 0.3, 0.3);
    assert!(
        edge.is_finite() && edge >= 0.0,
        "ggx_density: a facet on edge (m = (1, 0, 0)) has a finite density, but got {edge}: \
         write it without dividing by cos θ_m"
    );
    for (au, av) in [(0.3f32, 0.3f32), (0.1, 0.6)] {
        let area = over_normals(au.max(av), |m| {
            DVec3::splat(f64::from(ggx_density(m, au, av) * m.z))
        })
        .x;
        assert!(
            (area - 1.0).abs() < 2e-3,
            "ggx_density: ∫ D(m) cos θ_m dm = {area:.4} for alpha ({au}, {av}), not 1: the \
             facets' projected area must be the surface's"
        );
    }
}

/// The metals of the check: copper-like, GGX and Beckmann, isotropic and not.
fn metals() -> Vec<RoughConductor> {
    [
        NormalDistribution::new(Ggx, 0.3, 0.3),
        NormalDistribution::new(Beckmann, 0.5, 0.5),
        NormalDistribution::new(Ggx, 0.1, 0.4),
    ]
    .into_iter()
    .map(|distribution| RoughConductor {
        distribution,
        eta: Vec3::new(0.27, 0.68, 1.3),
        k: Vec3::new(3.6, 2.6, 2.3),
        specular_reflectance: Vec3::ONE,
    })
    .collect()
}

/// Within a relative 1e-4; an infinity or a NaN is close to nothing (an infinite tolerance
/// would take anything).
fn close(a: f32, b: f32) -> bool {
    a.is_finite() && b.is_finite() && (a - b).abs() <= 1e-4 * a.abs().max(b.abs()).max(1e-6)
}

fn close3(a: Vec3, b: Vec3) -> bool {
    a.is_finite()
        && b.is_finite()
        && (a - b).abs().max_element() <= 1e-4 * a.abs().max(b.abs()).max_element().max(1e-6)
}

/// What the sample at `u` must be, and the words for what it is instead.
fn check_sample(metal: &RoughConductor, wo: Vec3, u: Vec2) -> Result<(), String> {
    let d = &metal.distribution;
    let got = metal.sample(wo, u);
    let m = d.sample_visible_normal(wo, u);
    let wi = reflect_away(wo, m);
    let call = format!("sample(wo = {wo}, u = {u}) with {d:?}");
    if wi.z <= 0.0 {
        return match got {
            None => Ok(()),
            Some(s) => Err(format!(
                "{call} gave {s:?}, but the visible normal m = {m} drawn with u mirrors wo below \
                 the surface: the path ends there (None)"
            )),
        };
    }
    let Some(s) = got else {
        return Err(format!(
            "{call} gave no direction, but the visible normal m = {m} drawn with u mirrors wo \
             to {wi}, above the surface (fresnel::reflect_away(wo, m) takes wo, which points away \
             from the surface; chapter 01's reflect(d, n) takes a direction d that points \
             towards it, so given wo it gives -wi)"
        ));
    };
    if !close3(s.wi, wi) {
        let plain = reflect_away(wo, d.sample_normal(u));
        let why = if close3(s.wi, plain) {
            "the normal is drawn from all the facets (sample_normal); draw it from those wo can \
             see (sample_visible_normal)"
        } else if close3(s.wi, m) {
            "wi is the facet normal itself: the light comes from wo mirrored about it"
        } else {
            "wi must be wo mirrored about the visible normal that u draws"
        };
        return Err(format!("{call}: {why}; wi = {}, expected {wi}", s.wi));
    }
    // The density must be the material's own (its `pdf`, which the renderer's MIS weighs
    // light samples by), and the weight its own `f cos θ_i` over that density.
    let pdf = metal.pdf(wo, wi);
    if !close(s.pdf, pdf) {
        let pdf_m = d.visible_normal_pdf(wo, m);
        let why = if close(s.pdf, pdf_m) {
            "that is the density of the normal m, not of the direction wi: how much solid angle \
             of mirrored directions does a small patch of normals around m make?"
        } else if close(s.pdf, 4.0 * pdf) {
            "it is 4 times too large: the density of wi is the density of the normal m divided \
             by how much larger a patch of mirrored directions is than its patch of normals"
        } else if close(s.pdf * pdf_m, pdf * d.normal_pdf(m)) {
            "that is the density of all the normals, D(m) cos θ_m, carried over to wi; the \
             normal was drawn among those wo can see"
        } else if !s.pdf.is_finite() {
            "a density is a finite number"
        } else {
            "the density of wi is the visible normal's density carried over from normals to \
             mirrored directions"
        };
        return Err(format!("{call}: {why}; pdf = {}, expected {pdf}", s.pdf));
    }
    let expected = metal.eval(wo, wi) / pdf;
    if !close3(s.weight, expected) {
        let (g1_wo, g1_wi) = (d.g1(wo, m), d.g1(wi, m));
        let why = if close3(s.weight, expected * g1_wo) {
            "G1(wo, m) is counted twice: the visible-normal density already holds it"
        } else if close3(s.weight * g1_wi, expected) {
            "G1(wi, m) is missing: the facet may be shadowed from the light's side"
        } else if close3(s.weight, metal.eval(wo, wi)) {
            "that is f cos θ_i itself; the weight is f cos θ_i / pdf"
        } else {
            "the weight is f cos θ_i / pdf: work out what is left of that quotient at the \
             sampled facet"
        };
        return Err(format!(
            "{call}: {why}; weight = {}, expected {expected}",
            s.weight
        ));
    }
    if s.eta_scale != 1.0 {
        return Err(format!(
            "{call}: a reflection does not scale radiance; eta_scale = {}, expected 1",
            s.eta_scale
        ));
    }
    Ok(())
}

#[test]
fn exercise_rough_conductor_sample() {
    for metal in metals() {
        let below = metal.sample(Vec3::new(0.3, 0.0, -0.95).normalize(), Vec2::splat(0.5));
        assert!(
            below.is_none(),
            "rough conductor sample: wo below the surface sees no facet of this one-sided \
             metal, so there is no direction (None), but got {below:?}"
        );
        for degrees in [0.0f32, 50.0, 80.0] {
            let (sin, cos) = degrees.to_radians().sin_cos();
            let wo = Vec3::new(sin * 0.866, sin * 0.5, cos);
            for i in 0..8 {
                for j in 0..8 {
                    let u = Vec2::new((i as f32 + 0.5) / 8.0, (j as f32 + 0.5) / 8.0);
                    if let Err(why) = check_sample(&metal, wo, u) {
                        panic!("rough conductor sample: {why}");
                    }
                }
            }
        }
    }
}
