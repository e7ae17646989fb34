//! Sampling a sphere light by the directions it covers, and the change of measure.
//!
//! Seen from a receiver at `x`, a sphere of radius `R` at distance `d` covers the cone of
//! directions within `θ_max` of its centre ([`sphere_cone`], an exercise). Area sampling
//! wastes samples on it: half its surface faces away from `x` and, of the rest, the parts near
//! the silhouette are seen at a grazing angle and get as many samples as the parts facing `x`.
//! Sampling the cone uniformly instead (chapter 02's spherical cap, pbrt-v4's
//! `Sphere::Sample`) sends every shadow ray towards the light, with the constant density
//!
//! ```text
//! p_ω = 1 / (2π (1 - cos θ_max))   per steradian,
//! ```
//!
//! and the estimator becomes `L cos θ / p_ω`: the integrand's only varying factor left is the
//! receiver's `cos θ`, so for a small or distant sphere the variance all but disappears.
//!
//! Densities per area and per solid angle are related by the solid angle `dω = |cos θ′| dA / d²`
//! that a patch `dA` of the light, seen at angle `θ′` to its normal from distance `d`,
//! covers: `p_ω = p_A d² / |cos θ′|` ([`pdf_area_to_solid_angle`]).
//!
//! Numerics. A distant sphere makes a tiny cap: at `R / d = 10⁻⁴`, `1 - cos θ_max = 5·10⁻⁹` is
//! below the spacing of floats near 1, so `cos θ_max` itself rounds to 1 and `1 - cos θ_max`,
//! written as that subtraction, to 0. The cone therefore keeps `1 - cos θ_max` as a number of
//! its own, computed without the subtraction, and is sampled from it directly (chapter 02's
//! [`sample_spherical_cap`](ch02_monte_carlo::warps::sample_spherical_cap), whose
//! documentation recommends this for the tiniest caps, with its parameter passed without
//! rounding). A receiver on or inside the sphere has no cone around it: it falls back to area
//! sampling.

use std::f32::consts::TAU;

use common::geometry::{Sphere, gamma};
use glam::{Vec2, Vec3};

use crate::light_sample::LightSample;

/// The density per unit solid angle, seen from a receiver at distance `√distance_squared`, of
/// a point chosen with density `pdf_area` per unit area of a light whose normal makes the
/// angle `θ′` with the direction to the receiver: `p_ω = p_A d² / |cos θ′|`. Infinite for
/// a patch seen edge-on, which covers no solid angle.
pub fn pdf_area_to_solid_angle(pdf_area: f32, distance_squared: f32, cos_theta_light: f32) -> f32 {
    pdf_area * distance_squared / cos_theta_light.abs()
}

/// The inverse of [`pdf_area_to_solid_angle`]: `p_A = p_ω |cos θ′| / d²`.
pub fn pdf_solid_angle_to_area(
    pdf_solid_angle: f32,
    distance_squared: f32,
    cos_theta_light: f32,
) -> f32 {
    pdf_solid_angle * cos_theta_light.abs() / distance_squared
}

/// The cone of directions a sphere covers, seen from a point outside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereCone {
    /// The unit direction from the point to the sphere's centre.
    pub axis: Vec3,
    /// The distance `d` from the point to the centre.
    pub distance: f32,
    /// `sin θ_max`, of the cone's half-angle.
    pub sin_theta_max: f32,
    /// `sin² θ_max`.
    pub sin2_theta_max: f32,
    /// `1 - cos θ_max`, computed so that it keeps its digits when the cone is tiny (which
    /// identity of `sin²` and `cos` avoids subtracting two numbers close to 1?).
    pub one_minus_cos_theta_max: f32,
}

// ANCHOR: sphere_cone
/// The cone `sphere` covers seen from `x` ([`SphereCone`]: its axis, the unit direction from `x`
/// to the centre, the distance `d` to the centre, `sin θ_max`, `sin² θ_max` and
/// `1 - cos θ_max`), or `None` when `x` is on or inside the sphere (or the sphere has no
/// radius, or is too far to compute with), where no cone describes it.
pub fn sphere_cone(sphere: &Sphere, x: Vec3) -> Option<SphereCone> {
    // BEGIN SOLUTION
    let r = sphere.radius;
    let to_center = sphere.center - x;
    let distance = to_center.length();
    let outside = r > 0.0 && distance > r && distance.is_finite();
    if !outside {
        return None;
    }
    let sin_theta_max = (r / distance).min(1.0);
    let sin2_theta_max = sin_theta_max * sin_theta_max;
    let cos_theta_max = ((1.0 - sin_theta_max) * (1.0 + sin_theta_max)).sqrt();
    Some(SphereCone {
        axis: to_center / distance,
        distance,
        sin_theta_max,
        sin2_theta_max,
        one_minus_cos_theta_max: sin2_theta_max / (1.0 + cos_theta_max),
    })
    // END SOLUTION
}
// ANCHOR_END: sphere_cone

/// The density per unit solid angle of a direction uniform in a cone whose half-angle has
/// `1 - cos θ_max` = `one_minus_cos_theta_max`: one over the cone's solid angle.
pub fn cone_pdf(one_minus_cos_theta_max: f32) -> f32 {
    1.0 / (TAU * one_minus_cos_theta_max)
}

// ANCHOR: sample_sphere_solid_angle
/// A point of the sphere light seen from `x`, chosen by a direction uniform in the cone the
/// sphere covers (pbrt-v4's `Sphere::Sample(ctx, u)`); by area
/// ([`sample_sphere_area`](crate::area_sampling::sample_sphere_area)) when `x` is on or inside
/// the sphere. `None`
/// if the sphere has no area or its cone is too small for `f32` (`R / d` below about 10⁻¹⁹:
/// its light is then far below anything an `f32` image can show).
///
/// Which share of the cone's solid angle lies within `θ` of its axis, and what `θ` makes that
/// share `ξ2`? [`point_seen_along`] finds the point of the sphere a direction meets. The
/// sample carries its density per unit area and, since it was chosen by direction, per unit
/// solid angle too: how are the two related at that point?
pub fn sample_sphere_solid_angle(sphere: &Sphere, x: Vec3, u: Vec2) -> Option<LightSample> {
    // BEGIN SOLUTION
    use crate::area_sampling::sample_sphere_area;
    let Some(cone) = sphere_cone(sphere, x) else {
        // On or inside the sphere (and not merely too far away to compute with).
        let inside = (sphere.center - x).length() <= sphere.radius;
        return if inside {
            sample_sphere_area(sphere, u)
        } else {
            None
        };
    };
    let pdf_solid_angle = cone_pdf(cone.one_minus_cos_theta_max);
    if !pdf_solid_angle.is_finite() {
        return None;
    }
    // 1 - cos θ uniform in [0, 1 - cos θ_max): uniform in solid angle (the hat-box theorem).
    let one_minus_cos = u.y * cone.one_minus_cos_theta_max;
    let sin2_theta = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0);
    let (cos_theta, phi) = (1.0 - one_minus_cos, TAU * u.x);
    let (p, p_error, n) = point_seen_along(sphere, x, &cone, cos_theta, sin2_theta, phi);
    let to_light = p - x;
    let distance_squared = to_light.length_squared();
    let cos_theta_light = n.dot(-to_light) / distance_squared.sqrt();
    Some(LightSample {
        p,
        p_error,
        n,
        pdf: pdf_solid_angle_to_area(pdf_solid_angle, distance_squared, cos_theta_light),
        pdf_solid_angle: Some(pdf_solid_angle),
    })
    // END SOLUTION
}
// ANCHOR_END: sample_sphere_solid_angle

/// The point of `sphere` that the direction from `x` at angle `θ` to the axis of `cone`
/// (`cos θ`, `sin² θ`), turned by `φ` about it, first meets, with its error bound and the
/// sphere's outward unit normal there: `(p, p_error, n)`. The axis is turned by `φ` in the
/// frame `cone.axis.any_orthonormal_pair()`.
///
/// The point is found in one of two ways so that it keeps its digits wherever the receiver is:
///
/// - a receiver farther than `2R` from the centre: intersecting the ray would lose the point's
///   digits (the ray travels `d ≫ R` and its rounding grows with `d`). Instead the point comes
///   from the angle `α` at the sphere's centre between the receiver and the point, by the law
///   of sines in the triangle of `x`, the centre and the point (as pbrt-v4 does):
///   `cos α = sin² θ / sin θ_max + cos θ √(1 - sin² θ / sin² θ_max)`;
/// - a receiver within `2R`: `α` is then tiny for most directions and `cos α` rounds to 1,
///   which would pile the samples onto the nearest point. The distance along the ray is
///   computed instead, without cancellation, as
///   `t = (d² - R²) / (d cos θ + √(R² - d² sin² θ))`.
///
/// Either way the point is then projected onto the sphere, `center + R n`, so its error bound
/// is that of the sphere's own hit points.
pub fn point_seen_along(
    sphere: &Sphere,
    x: Vec3,
    cone: &SphereCone,
    cos_theta: f32,
    sin2_theta: f32,
    phi: f32,
) -> (Vec3, Vec3, Vec3) {
    let r = sphere.radius;
    let sin_theta = sin2_theta.sqrt();
    let (t, b) = cone.axis.any_orthonormal_pair();
    let (sin_phi, cos_phi) = phi.sin_cos();
    let sideways = cos_phi * t + sin_phi * b;
    let n = if cone.sin2_theta_max < 0.25 {
        let ratio = sin2_theta / cone.sin2_theta_max;
        let cos_alpha = (sin2_theta / cone.sin_theta_max
            + cos_theta * (1.0 - ratio).max(0.0).sqrt())
        .clamp(-1.0, 1.0);
        let sin_alpha = ((1.0 - cos_alpha) * (1.0 + cos_alpha)).sqrt();
        // From the centre: back towards the receiver (-axis), swung out by α towards the side
        // the direction leans to.
        sin_alpha * sideways - cos_alpha * cone.axis
    } else {
        let d = cone.distance;
        let d_sin = d * sin_theta;
        let root = ((r - d_sin) * (r + d_sin)).max(0.0).sqrt();
        let t_hit = (d - r) * (d + r) / (d * cos_theta + root);
        let w = sin_theta * sideways + cos_theta * cone.axis;
        (x - sphere.center) + t_hit * w
    };
    let n = n.normalize();
    let local = r * n;
    let p = sphere.center + local;
    let p_error = gamma(5) * local.abs() + gamma(2) * p.abs();
    (p, p_error, n)
}

/// The density per unit solid angle with which [`sample_sphere_solid_angle`] picks the
/// direction `wi` (any length) from `x`: [`cone_pdf`] inside the cone, 0 outside it; `None`
/// when `x` is on or inside the sphere, where the sampler chooses by area instead.
pub fn sphere_solid_angle_pdf(sphere: &Sphere, x: Vec3, wi: Vec3) -> Option<f32> {
    let cone = sphere_cone(sphere, x)?;
    // 1 - cos θ = |w - axis|² / 2 for unit vectors: no digits lost near the axis.
    let one_minus_cos = (wi.normalize() - cone.axis).length_squared() / 2.0;
    Some(if one_minus_cos <= cone.one_minus_cos_theta_max {
        cone_pdf(cone.one_minus_cos_theta_max)
    } else {
        0.0
    })
}

#[cfg(test)]
mod tests;
