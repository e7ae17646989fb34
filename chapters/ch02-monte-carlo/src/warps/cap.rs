//! The spherical cap: uniform directions within an angle `θ_max` of +z.
//!
//! Seen from a point, a spherical light covers a cap of directions; sampling the cap instead
//! of the whole sphere sends every shadow ray towards the light (chapter 07). pbrt-v4 calls
//! it a cone (`SampleUniformCone`).
//!
//! By the hat-box theorem of [`super::sphere`], a cap is a band of heights `z = cos θ` in
//! `[cos θ_max, 1]` with uniform `φ`, and its solid angle is the band's height times `2π`:
//! `Ω = 2π (1 - cos θ_max)`. A uniform direction has `z` uniform in that band:
//! `1 - z = ξ2 (1 - cos θ_max)`, so `ξ2 = 0` is the pole and `ξ2 → 1` the rim. With
//! `cos θ_max = -1` this is [`super::sample_uniform_sphere`] exactly.
//!
//! A small light far away makes a tiny cap, `1 - cos θ_max` of 10^-8 and below. Computing
//! `1 - z` directly, as above, keeps its digits; forming `z` first and then `sin θ` from it
//! would not (see the notes of [`super::lobe`]). The caller should likewise pass an accurate
//! `cos θ_max`; for the tiniest caps the API would better take `1 - cos θ_max` itself.

use std::f32::consts::TAU;

use glam::{Vec2, Vec3};

use super::disc::azimuth;
use super::sphere::{one_minus_cos_theta, spherical_direction};

/// A uniform direction of the cap of directions within `θ_max` of +z, for
/// `-1 ≤ cos_theta_max < 1`. Density [`spherical_cap_pdf`].
pub fn sample_spherical_cap(u: Vec2, cos_theta_max: f32) -> Vec3 {
    let one_minus_cos = u.y * (1.0 - cos_theta_max);
    let cos_theta = 1.0 - one_minus_cos;
    let sin_theta = (one_minus_cos * (2.0 - one_minus_cos)).max(0.0).sqrt();
    spherical_direction(sin_theta, cos_theta, TAU * u.x)
}

/// The density of [`sample_spherical_cap`] per unit solid angle: one over the cap's solid
/// angle `2π (1 - cos θ_max)`, for directions inside the cap.
pub fn spherical_cap_pdf(cos_theta_max: f32) -> f32 {
    1.0 / (TAU * (1.0 - cos_theta_max))
}

/// The `u` that [`sample_spherical_cap`] maps to `d`: `(φ / 2π, (1 - cos θ) / (1 - cos θ_max))`.
pub fn invert_spherical_cap(d: Vec3, cos_theta_max: f32) -> Vec2 {
    Vec2::new(
        azimuth(d.truncate()) / TAU,
        one_minus_cos_theta(d) / (1.0 - cos_theta_max),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::warps::sample_uniform_sphere;
    use crate::warps::test_support::{edge_points, integrate_over_sphere, interior_grid};
    use approx::assert_relative_eq;

    const CAPS: [f32; 5] = [-1.0, -0.5, 0.0, 0.8, 0.999_9];

    #[test]
    fn edge_values_stay_in_the_cap() {
        for cos_max in CAPS {
            for u in edge_points() {
                let d = sample_spherical_cap(u, cos_max);
                assert!(
                    d.is_finite() && (d.length() - 1.0).abs() < 1e-5,
                    "u = {u}: {d}"
                );
                assert!(
                    d.z >= cos_max - 1e-6,
                    "u = {u}: {d} leaves the cap {cos_max}"
                );
            }
        }
    }

    #[test]
    fn the_density_integrates_to_one() {
        for cos_max in [-0.5, 0.0, 0.8] {
            let integral = integrate_over_sphere(
                |d| {
                    if d.z >= cos_max {
                        spherical_cap_pdf(cos_max)
                    } else {
                        0.0
                    }
                },
                1000,
            );
            assert_relative_eq!(integral, 1.0, epsilon = 1e-3);
        }
    }

    #[test]
    fn the_whole_sphere_is_a_cap() {
        for u in interior_grid(10) {
            assert_eq!(sample_spherical_cap(u, -1.0), sample_uniform_sphere(u));
        }
    }

    #[test]
    fn inverse_round_trips() {
        for cos_max in CAPS {
            for u in interior_grid(20) {
                let d = sample_spherical_cap(u, cos_max);
                let back = invert_spherical_cap(d, cos_max);
                assert_relative_eq!(back, u, epsilon = 1e-4);
                assert_relative_eq!(sample_spherical_cap(back, cos_max), d, epsilon = 1e-5);
            }
        }
    }

    #[test]
    fn a_tiny_cap_keeps_its_shape() {
        // The smallest cap an f32 cos θ_max can describe: the largest float below 1, so that
        // 1 - cos θ_max = 6e-8. Its directions lie about 2.4e-4 radians from the pole, and
        // sin θ must come out right rather than rounded to 0 via cos θ.
        let cos_max = f32::from_bits(0x3f7f_ffff);
        let d = sample_spherical_cap(Vec2::new(0.0, 0.5), cos_max);
        let expected_sin = (2.0 * 0.5 * (1.0 - cos_max as f64)).sqrt() as f32;
        assert_relative_eq!(d.x, expected_sin, max_relative = 1e-5);
    }
}
