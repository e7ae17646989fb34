//! Directions as points of the unit square, so that a quadtree can split them.
//!
//! The map is the cylinder's: `u` is the height `cos θ = 2u - 1` of the direction along the
//! world's `z` axis, `v` its turn `φ = 2πv` around it. Archimedes' hat-box theorem makes it
//! preserve area: a region covering a fraction `a` of the square covers `4πa` steradians of
//! the sphere. So a density `p(u, v)` on the square is the density `p / 4π` per unit solid
//! angle, everywhere, and a quadtree cell that halves the square halves the sphere too.
//!
//! The directions are the world's, not a surface's own frame: one quadtree serves every
//! surface in its region of space, whatever way each one faces.

use glam::{Vec2, Vec3};
use std::f32::consts::{FRAC_1_PI, TAU};

/// The unit direction at `point` of the unit square.
pub fn direction_of(point: Vec2) -> Vec3 {
    let cos_theta = (2.0 * point.x - 1.0).clamp(-1.0, 1.0);
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let (sin_phi, cos_phi) = (TAU * point.y).sin_cos();
    Vec3::new(sin_theta * cos_phi, sin_theta * sin_phi, cos_theta)
}

/// The point of the unit square whose direction is the unit vector `w`: the inverse of
/// [`direction_of`], in `[0, 1]²` for any finite `w`.
pub fn point_of(w: Vec3) -> Vec2 {
    let u = ((w.z.clamp(-1.0, 1.0) + 1.0) * 0.5).clamp(0.0, 1.0);
    let turn = w.y.atan2(w.x) / TAU;
    let v = if turn < 0.0 { turn + 1.0 } else { turn };
    Vec2::new(u, v.clamp(0.0, 1.0))
}

/// The density per unit solid angle of a density `square_pdf` on the square: the map
/// preserves area, so it is the same at every point.
pub fn solid_angle_pdf(square_pdf: f32) -> f32 {
    square_pdf * (0.25 * FRAC_1_PI)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_square_and_the_sphere_map_back_and_forth() {
        for i in 0..64 {
            for j in 0..64 {
                let point = Vec2::new((i as f32 + 0.5) / 64.0, (j as f32 + 0.5) / 64.0);
                let w = direction_of(point);
                assert!((w.length() - 1.0).abs() < 1e-5, "{w} is not unit");
                let back = point_of(w);
                assert!(
                    (back - point).abs().max_element() < 1e-4,
                    "{point} went to {w} and came back as {back}"
                );
            }
        }
        assert_eq!(direction_of(Vec2::new(1.0, 0.3)), Vec3::Z);
        assert!(point_of(-Vec3::Z).x == 0.0);
    }

    #[test]
    fn equal_areas_of_the_square_are_equal_solid_angles() {
        // The band of heights [a, b] covers 2π(cos θ_a - cos θ_b): 4π times its share of the
        // square, whichever band.
        for (a, b) in [(0.0f32, 0.1f32), (0.45, 0.55), (0.9, 1.0)] {
            let (za, zb) = (
                direction_of(Vec2::new(a, 0.0)).z,
                direction_of(Vec2::new(b, 0.0)).z,
            );
            let solid_angle = TAU * (zb - za);
            let expected = 4.0 * std::f32::consts::PI * (b - a);
            assert!((solid_angle - expected).abs() < 1e-5, "band {a}..{b}");
        }
        assert!((solid_angle_pdf(1.0) * 4.0 * std::f32::consts::PI - 1.0).abs() < 1e-6);
    }
}
