//! Uniform directions: the whole sphere and the hemisphere around +z.
//!
//! Write a direction by its polar angle `θ` from +z and its azimuth `φ`. The solid-angle
//! element is `dω = sin θ dθ dφ = dz dφ` with `z = cos θ`: in the coordinates `(z, φ)` the
//! sphere is a flat rectangle `[-1, 1] x [0, 2π)` with no distortion of area. This is
//! Archimedes' hat-box theorem (a sphere's zone between two heights has the area of the
//! cylinder's band between them), and it makes uniform directions easy: `z` uniform in
//! `[-1, 1]`, `φ` uniform in `[0, 2π)`. The chi-square test bins directions in the same
//! coordinates for the same reason.
//!
//! `sin θ` is computed as `√((1 - z)(1 + z))` rather than `√(1 - z²)`: near the poles `z²`
//! rounds to 1 and the second form loses all its digits, while `1 - z` is exact there.

use std::f32::consts::{FRAC_1_PI, TAU};

use glam::{Vec2, Vec3};

use super::disc::azimuth;

/// The unit direction with polar angle `θ` from +z and azimuth `φ` from +x, given by `sin θ`
/// and `cos θ` (pbrt-v4's `SphericalDirection`).
pub fn spherical_direction(sin_theta: f32, cos_theta: f32, phi: f32) -> Vec3 {
    let (sin_phi, cos_phi) = phi.sin_cos();
    Vec3::new(sin_theta * cos_phi, sin_theta * sin_phi, cos_theta)
}

/// `1 - cos θ` of the unit direction `d`, accurate also near +z.
///
/// Near the pole `d.z` rounds to 1 and `1 - d.z` to 0, but the sideways part `x² + y²` is still
/// known to full relative precision, and `1 - cos θ = sin² θ / (1 + cos θ)`. Below the equator
/// the plain `1 - d.z` is accurate. The inverses of narrow lobes and small caps need this.
pub fn one_minus_cos_theta(d: Vec3) -> f32 {
    if d.z > 0.0 {
        (d.x * d.x + d.y * d.y) / (1.0 + d.z)
    } else {
        1.0 - d.z
    }
}

/// A uniform direction on the unit sphere: `z = cos θ = 1 - 2 ξ2` uniform in `(-1, 1]` and
/// `φ = 2π ξ1`, by the hat-box theorem above. Density [`uniform_sphere_pdf`].
pub fn sample_uniform_sphere(u: Vec2) -> Vec3 {
    let one_minus_z = 2.0 * u.y;
    let z = 1.0 - one_minus_z;
    let sin_theta = (one_minus_z * (2.0 - one_minus_z)).max(0.0).sqrt();
    spherical_direction(sin_theta, z, TAU * u.x)
}

/// The density of a uniform direction per unit solid angle: one over the sphere's `4π`
/// steradians.
pub fn uniform_sphere_pdf() -> f32 {
    FRAC_1_PI / 4.0
}

/// The `u` that [`sample_uniform_sphere`] maps to `d`: `(φ / 2π, (1 - z) / 2)`.
pub fn invert_uniform_sphere(d: Vec3) -> Vec2 {
    Vec2::new(azimuth(d.truncate()) / TAU, one_minus_cos_theta(d) / 2.0)
}

/// A uniform direction of the hemisphere around +z: `z = cos θ = 1 - ξ2` uniform in `(0, 1]`
/// and `φ = 2π ξ1`. `z` never reaches the horizon, since `ξ2 < 1`. Density
/// [`uniform_hemisphere_pdf`].
pub fn sample_uniform_hemisphere(u: Vec2) -> Vec3 {
    let one_minus_z = u.y;
    let z = 1.0 - one_minus_z;
    let sin_theta = (one_minus_z * (2.0 - one_minus_z)).max(0.0).sqrt();
    spherical_direction(sin_theta, z, TAU * u.x)
}

/// The density of a uniform direction of a hemisphere per unit solid angle, `1 / 2π` (for
/// directions with `z ≥ 0`).
pub fn uniform_hemisphere_pdf() -> f32 {
    FRAC_1_PI / 2.0
}

/// The `u` that [`sample_uniform_hemisphere`] maps to `d`: `(φ / 2π, 1 - z)`.
pub fn invert_uniform_hemisphere(d: Vec3) -> Vec2 {
    Vec2::new(azimuth(d.truncate()) / TAU, one_minus_cos_theta(d))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::warps::test_support::{edge_points, integrate_over_sphere, interior_grid};
    use approx::assert_relative_eq;

    #[test]
    fn edge_values_give_unit_directions() {
        for u in edge_points() {
            let d = sample_uniform_sphere(u);
            assert!(
                d.is_finite() && (d.length() - 1.0).abs() < 1e-5,
                "u = {u}: {d}"
            );
            let h = sample_uniform_hemisphere(u);
            assert!(
                h.is_finite() && (h.length() - 1.0).abs() < 1e-5,
                "u = {u}: {h}"
            );
            assert!(h.z > 0.0, "u = {u}: {h} is not above the horizon");
        }
    }

    #[test]
    fn the_densities_integrate_to_one() {
        let sphere = integrate_over_sphere(|_| uniform_sphere_pdf(), 100);
        assert_relative_eq!(sphere, 1.0, epsilon = 1e-6);
        let hemisphere = integrate_over_sphere(
            |d| {
                if d.z >= 0.0 {
                    uniform_hemisphere_pdf()
                } else {
                    0.0
                }
            },
            100,
        );
        assert_relative_eq!(hemisphere, 1.0, epsilon = 1e-6);
    }

    #[test]
    fn inverses_round_trip() {
        for u in interior_grid(20) {
            let d = sample_uniform_sphere(u);
            assert_relative_eq!(invert_uniform_sphere(d), u, epsilon = 1e-5);
            assert_relative_eq!(
                sample_uniform_sphere(invert_uniform_sphere(d)),
                d,
                epsilon = 1e-5
            );
            let h = sample_uniform_hemisphere(u);
            assert_relative_eq!(invert_uniform_hemisphere(h), u, epsilon = 1e-5);
            assert_relative_eq!(
                sample_uniform_hemisphere(invert_uniform_hemisphere(h)),
                h,
                epsilon = 1e-5
            );
        }
    }

    #[test]
    fn one_minus_cos_theta_keeps_its_digits_at_the_pole() {
        // θ = 1e-4: 1 - cos θ = 5e-9, far below the spacing of floats near 1 (6e-8).
        let theta = 1e-4f32;
        let d = Vec3::new(theta.sin(), 0.0, theta.cos());
        assert_eq!(1.0 - d.z, 0.0);
        assert_relative_eq!(one_minus_cos_theta(d), 5e-9, max_relative = 1e-4);
    }
}
