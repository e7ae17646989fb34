//! Chapter 06's frosted glass: reflection with probability `F`, else refraction, each spread
//! by its lobe (the refraction's narrower, chapter 06's `transmission_exponent`).
//!
//! As a BSDF: `f cos θ_i = F · p_r(wi)` on `wo`'s side and `(1 - F) eta² · p_t(wi)` on the
//! other, and the density of the two-step sampling is `F · p_r` or `(1 - F) · p_t`. The sides
//! do not overlap, so each direction has one term, and the weight is 1 or `eta²`.

use super::BsdfSample;
use super::dielectric::side;
use ch01_whitted::optics::{fresnel_dielectric, reflect, refract};
use ch06_fuzzy_reflections::FuzzMethod;
use ch06_fuzzy_reflections::tracer::transmission_exponent;
use common::geometry::SurfaceHit;
use common::scene::RoughGlass;
use glam::{Vec2, Vec3};

/// The two lobes seen from `wo`.
struct Lobes {
    normal: Vec3,
    eta: f32,
    reflectance: f32,
    reflected: Vec3,
    /// `None` under total internal reflection.
    refracted: Option<Vec3>,
    exponent: f32,
    transmission_exponent: f32,
}

fn lobes(hit: &SurfaceHit, wo: Vec3, glass: &RoughGlass) -> Lobes {
    let (normal, eta) = side(hit, wo, glass.int_ior, glass.ext_ior);
    Lobes {
        normal,
        eta,
        reflectance: fresnel_dielectric(wo.dot(normal), eta),
        reflected: reflect(-wo, normal),
        refracted: refract(-wo, normal, eta),
        exponent: glass.exponent,
        transmission_exponent: transmission_exponent(glass.exponent, eta),
    }
}

/// A direction of the lobe chosen by `F` with `choice`, spread with `u`.
pub fn sample(
    hit: &SurfaceHit,
    wo: Vec3,
    glass: &RoughGlass,
    fuzz: FuzzMethod,
    choice: f32,
    u: Vec2,
) -> Option<BsdfSample> {
    let l = lobes(hit, wo, glass);
    let reflect = choice < l.reflectance;
    let (center, exponent, probability, scale, side) = if reflect {
        (l.reflected, l.exponent, l.reflectance, 1.0, l.normal)
    } else {
        let center = l.refracted?;
        let scale = l.eta * l.eta;
        (
            center,
            l.transmission_exponent,
            1.0 - l.reflectance,
            scale,
            -l.normal,
        )
    };
    if !exponent.is_finite() {
        return Some(BsdfSample {
            wi: center,
            weight: Vec3::splat(scale),
            pdf: f32::INFINITY,
            eta_scale: scale,
        });
    }
    let wi = fuzz.sample(center, exponent, u);
    let pdf = probability * fuzz.pdf(wi.dot(center), exponent);
    (wi.dot(side) > 0.0 && pdf > 0.0).then_some(BsdfSample {
        wi,
        weight: Vec3::splat(scale),
        pdf,
        eta_scale: scale,
    })
}

/// `(f cos θ_i, pdf)` at `wi`, delta lobes left out.
fn eval_pdf(
    hit: &SurfaceHit,
    wo: Vec3,
    wi: Vec3,
    glass: &RoughGlass,
    fuzz: FuzzMethod,
) -> (f32, f32) {
    let l = lobes(hit, wo, glass);
    if wi.dot(l.normal) > 0.0 {
        let pdf = l.reflectance * fuzz.pdf(wi.dot(l.reflected), l.exponent);
        (pdf, pdf)
    } else if let Some(refracted) = l.refracted {
        let pdf = (1.0 - l.reflectance) * fuzz.pdf(wi.dot(refracted), l.transmission_exponent);
        (l.eta * l.eta * pdf, pdf)
    } else {
        (0.0, 0.0)
    }
}

/// `f(wo, wi) cos θ_i`, both lobes.
pub fn eval(hit: &SurfaceHit, wo: Vec3, wi: Vec3, glass: &RoughGlass, fuzz: FuzzMethod) -> Vec3 {
    Vec3::splat(eval_pdf(hit, wo, wi, glass, fuzz).0)
}

/// The density of [`sample`] at `wi`.
pub fn pdf(hit: &SurfaceHit, wo: Vec3, wi: Vec3, glass: &RoughGlass, fuzz: FuzzMethod) -> f32 {
    eval_pdf(hit, wo, wi, glass, fuzz).1
}
