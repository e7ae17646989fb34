//! The normal of a microfacet visible from a direction at `θ` from the normal, for the
//! distributions of roughness 1, seen from the azimuth `φ = 0`. A facet of slope `(x̃, ỹ)` has
//! the normal `(-x̃, -ỹ, 1)`; both samplers return such a normal up to a positive factor, so
//! that a facet standing on edge (an infinite slope) stays finite.
//! [`NormalDistribution`](super::NormalDistribution) turns it to any azimuth and stretches it to any roughness.
//!
//! Both are Mitsuba 3's (`sample_visible_11`): GGX by Heitz's 2018 construction (a visible
//! GGX facet is a point of the projected hemisphere), Beckmann by Jakob's numerical inversion
//! of the slope's marginal distribution (Heitz and d'Eon 2014), computed here in double
//! precision.

use ch02_monte_carlo::warps::concentric::sample_uniform_disc_concentric;
use glam::{DVec2, Vec2, Vec3};
use statrs::function::erf::{erf, erf_inv};

/// GGX: a uniform point of the unit disc, squeezed into the part of the disc the hemisphere
/// seen from `θ` projects onto (the upper half shrinks towards the edge by `(1 + cos θ) / 2`),
/// lifted to the hemisphere and seen from `θ`. Mitsuba divides by the normal's `z` to get the
/// slope; here the normal is kept as it is.
pub fn ggx(cos_theta: f32, u: Vec2) -> Vec3 {
    let mut p = sample_uniform_disc_concentric(u);
    let s = 0.5 * (1.0 + cos_theta);
    let rim = (1.0 - p.x * p.x).max(0.0).sqrt();
    p.y = rim * (1.0 - s) + p.y * s;
    let z = (1.0 - p.length_squared()).max(0.0).sqrt();
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    // A point on the rim is a facet on edge, whose `z` may round below 0.
    Vec3::new(
        sin_theta * z - cos_theta * p.y,
        -p.x,
        (sin_theta * p.y + cos_theta * z).max(0.0),
    )
}

/// Beckmann: `ỹ` is a Gaussian slope (`erf⁻¹(2ξ₂ - 1)`), and `x̃` solves
/// `C(x̃) = ξ₁ C(∞)` for the marginal `C` of the visible slope along `φ = 0`, which written in
/// `x = erf(x̃)` is `1 + x + tan θ e^{-x̃²} / √π`: three Newton steps from the exact solution
/// at grazing incidence, the hardest case.
pub fn beckmann(cos_theta: f32, u: Vec2) -> Vec3 {
    let cos_theta = f64::from(cos_theta);
    // Mitsuba keeps the numbers off 0 and 1, where the inverse error function is infinite.
    let u = u
        .as_dvec2()
        .clamp(DVec2::splat(1e-6), DVec2::splat(1.0 - 1e-6));
    let tan_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt() / cos_theta;
    let cot_theta = 1.0 / tan_theta;
    let inv_sqrt_pi = 1.0 / std::f64::consts::PI.sqrt();
    // `C(∞)` in the erf domain.
    let max = erf(cot_theta);
    let mut x = max - (max + 1.0) * erf((-u.x.ln()).sqrt());
    let target = u.x * (1.0 + max + inv_sqrt_pi * tan_theta * (-cot_theta * cot_theta).exp());
    for _ in 0..3 {
        let slope = erf_inv(x);
        let value = 1.0 + x + inv_sqrt_pi * tan_theta * (-slope * slope).exp() - target;
        let derivative = 1.0 - slope * tan_theta;
        x -= value / derivative;
        // A step can overshoot the domain of erf⁻¹ near grazing incidence, where Mitsuba
        // would return NaN; the root lies inside.
        x = x.clamp(-1.0 + f64::EPSILON, 1.0 - f64::EPSILON);
    }
    Vec3::new(-erf_inv(x) as f32, -erf_inv(2.0 * u.y - 1.0) as f32, 1.0)
}
