//! `∫ f cos θ_i dω_i`, the share of light a BSDF scatters from `wo`, by quadrature over the
//! microfacet normals rather than over `wi`: a lobe of roughness `10⁻³` is a point to any grid
//! of directions, but spreads over a grid of slopes scaled by the roughness.
//!
//! A facet `m` turns `wo` into one reflected and one refracted direction, and each direction on
//! `wo`'s side (or the other) comes from exactly one facet seen from `wo`, so the integral over
//! directions is one over facets times the Jacobian `dω_i / dm`. The facets are laid out by
//! their slopes `tan θ_m (cos φ, sin φ)`, with `tan θ_m = s t / (1 - t)` for `t` in `[0, 1)`:
//! the midpoint rule in `t` and `φ` then puts half of the nodes within the slope `s`.

use super::fresnel;
use glam::{DVec3, Vec3};
use std::f64::consts::TAU;

/// Nodes along `t`.
const ALONG: usize = 2048;
/// Nodes around the azimuth.
const AROUND: usize = 256;

/// `∫ g(m) dm` over the normals of the upper hemisphere, nodes spread at the slope `scale`.
/// The rows of nodes along `t` are summed side by side, then added in order, so the sum is
/// the same whatever the thread count.
pub fn over_normals(scale: f32, g: impl Fn(Vec3) -> DVec3 + Sync) -> DVec3 {
    use rayon::prelude::*;
    let scale = f64::from(scale);
    let rows: Vec<DVec3> = (0..ALONG)
        .into_par_iter()
        .map(|i| {
            let t = (i as f64 + 0.5) / ALONG as f64;
            let r = scale * t / (1.0 - t);
            let dr_dt = scale / (1.0 - t).powi(2);
            // `dm = cos³ θ_m d²(slope)`, `d²(slope) = r dr dφ`.
            let cos = 1.0 / (1.0 + r * r).sqrt();
            let weight = cos.powi(3) * r * dr_dt / (ALONG * AROUND) as f64 * TAU;
            let mut row = DVec3::ZERO;
            for j in 0..AROUND {
                let phi = (j as f64 + 0.5) / AROUND as f64 * TAU;
                let m = DVec3::new(-r * phi.cos(), -r * phi.sin(), 1.0).normalize();
                row += weight * g(m.as_vec3());
            }
            row
        })
        .collect();
    rows.iter().fold(DVec3::ZERO, |sum, row| sum + *row)
}

/// `∫ eval(wi) dω_i` over the directions `wi` reflected from `wo` (above or below the
/// surface) about a facet it sees: `dω_i = 4 |wo·m| dm`.
pub fn reflected(wo: Vec3, scale: f32, eval: impl Fn(Vec3) -> Vec3 + Sync) -> DVec3 {
    over_normals(scale, |m| {
        let om = wo.dot(m);
        let wi = fresnel::reflect_away(wo, m);
        if om * wo.z <= 0.0 || wi.z * wo.z <= 0.0 {
            return DVec3::ZERO;
        }
        eval(wi).as_dvec3() * 4.0 * f64::from(om.abs())
    })
}

/// `∫ eval(wi) dω_i` over the directions `wi` refracted from `wo` into a medium of relative
/// index `eta` (`n_inside / n_outside`, `z` pointing outside) through a facet it sees:
/// `dω_i = (wo·m + η wi·m)² / (η² |wi·m|) dm`, `η = n_t / n_i`.
pub fn refracted(wo: Vec3, scale: f32, eta: f32, eval: impl Fn(Vec3) -> Vec3 + Sync) -> DVec3 {
    over_normals(scale, |m| {
        let om = wo.dot(m);
        if om * wo.z <= 0.0 {
            return DVec3::ZERO;
        }
        let f = fresnel::DielectricFresnel::new(om, eta);
        if f.reflectance >= 1.0 {
            return DVec3::ZERO;
        }
        let wi = fresnel::refract_away(wo, m, &f);
        if wi.z * wo.z >= 0.0 {
            return DVec3::ZERO;
        }
        let im = f64::from(wi.dot(m));
        let e = f64::from(f.eta_it);
        let jacobian = (f64::from(om) + e * im).powi(2) / (e * e * im.abs());
        eval(wi).as_dvec3() * jacobian
    })
}
