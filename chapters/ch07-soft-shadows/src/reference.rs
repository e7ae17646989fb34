//! Exact irradiance from uniform lights, for checking the estimators.
//!
//! Three closed forms, all for an unoccluded light of uniform radiance `L` entirely above the
//! receiver's horizon (a light that dips below the horizon needs its part above clipped
//! first, which none of the tests needs). They are computed in `f64`, so that they are more
//! accurate than anything they check.
//!
//! - A polygon: Lambert's formula (1760), `E = L/2 Σ_i β_i (n · γ̂_i)`, summed over the edges.
//!   `β_i` is the angle the edge `v_i v_{i+1}` subtends at the receiver and `γ̂_i` the unit
//!   normal of the plane through the receiver and the edge. (Stokes' theorem turns the
//!   integral of `cos θ` over the solid angle into one around its boundary.)
//! - A disc seen on its axis: `E = π L R² / (h² + R²)`, the disc covering a cone of
//!   `sin² θ_max = R² / (h² + R²)`.
//! - A sphere: `E = π L (R / d)² cos θ`, with `θ` the angle between the receiver's normal and
//!   the direction to the centre: a sphere is seen as a uniform disc of the same angular
//!   radius, and by symmetry that acts like a point of intensity `π L R²`.

use std::f64::consts::PI;

use glam::{DVec3, Vec3};

/// The irradiance at `x` (unit normal `n`) from the one-sided planar polygon `vertices` of
/// radiance `radiance`, by Lambert's formula; 0 when `x` is behind the polygon. The vertices
/// are in order (either way round); the front side is the one `(v1 - v0) × (v2 - v0)` points
/// to. Valid only when the whole polygon is above the receiver's horizon.
pub fn polygon_irradiance(x: Vec3, n: Vec3, vertices: &[Vec3], radiance: Vec3) -> Vec3 {
    let x = x.as_dvec3();
    let n = n.as_dvec3().normalize();
    let relative: Vec<DVec3> = vertices.iter().map(|v| v.as_dvec3() - x).collect();
    let [a, b, c, ..] = relative[..] else {
        return Vec3::ZERO;
    };
    let front_normal = (b - a).cross(c - a);
    // x is at the origin now: in front when the polygon's normal points towards it.
    if front_normal.dot(-a) <= 0.0 {
        return Vec3::ZERO;
    }
    let mut sum = 0.0;
    for (i, &v) in relative.iter().enumerate() {
        let w = relative[(i + 1) % relative.len()];
        let cross = v.cross(w);
        let beta = cross.length().atan2(v.dot(w));
        if cross.length() > 0.0 {
            sum += beta * n.dot(cross.normalize());
        }
    }
    // The vertex order defines the front (`(v1 - v0) × (v2 - v0)` points to it), so seen from
    // the receiver in front they run counter-clockwise, and every edge normal `v × w` then
    // points away from the light: the sum is negative, and its sign is the orientation's.
    let e = -0.5 * sum;
    radiance * e.max(0.0) as f32
}

/// The irradiance on the axis of a disc of radius `radius` and radiance `radiance`, at height
/// `height` in front of it, facing it: `π L R² / (h² + R²)`.
pub fn disc_on_axis_irradiance(radiance: Vec3, radius: f32, height: f32) -> Vec3 {
    let (r, h) = (radius as f64, height as f64);
    radiance * (PI * r * r / (h * h + r * r)) as f32
}

/// The irradiance from a sphere of radius `radius` and radiance `radiance` whose centre is at
/// distance `distance` in a direction at angle `θ` (given by `cos_theta`) from the receiver's
/// normal: `π L (R / d)² cos θ`. Valid when the whole sphere is above the horizon,
/// `cos θ ≥ R / d`.
pub fn sphere_irradiance(radiance: Vec3, radius: f32, distance: f32, cos_theta: f32) -> Vec3 {
    let s = radius as f64 / distance as f64;
    radiance * (PI * s * s * cos_theta as f64) as f32
}
