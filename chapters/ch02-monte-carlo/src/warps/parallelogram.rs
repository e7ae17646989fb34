//! The parallelogram: the simplest warp, an affine map of the unit square.
//!
//! `p = p0 + ξ1 (p1 - p0) + ξ2 (p2 - p0)` moves along two edges by fractions `ξ1` and `ξ2`. An
//! affine map stretches every patch of the square by the same factor, the parallelogram's
//! area `A = |e1 × e2|` (with `e1 = p1 - p0`, `e2 = p2 - p0`), so the density is the constant
//! `1 / A`: uniform, with no derivation needed beyond "the Jacobian is constant". Area lights
//! and lens apertures shaped like rectangles are sampled this way.

use glam::Vec2;

use super::VectorSpace;

/// A uniform point of the parallelogram with corner `p0` and edges `p1 - p0` and `p2 - p0`;
/// works for `Vec2` and `Vec3` alike. Its density is [`parallelogram_pdf`].
pub fn sample_parallelogram<V: VectorSpace>(u: Vec2, p0: V, p1: V, p2: V) -> V {
    p0 + (p1 - p0) * u.x + (p2 - p0) * u.y
}

/// The density of [`sample_parallelogram`] per unit area: `1 / area` everywhere inside, where
/// `area = |(p1 - p0) × (p2 - p0)|`.
pub fn parallelogram_pdf(area: f32) -> f32 {
    1.0 / area
}

/// The `u` that [`sample_parallelogram`] maps to the plane point `p`: the coordinates of
/// `p - p0` along the two edges.
///
/// Solves the 2 x 2 system `ξ1 e1 + ξ2 e2 = p - p0` by Cramer's rule; `perp_dot` is the 2D
/// cross product, the determinant of two columns. A degenerate (flat) parallelogram has
/// determinant 0 and gives non-finite results, as it must: it has no inverse.
pub fn invert_parallelogram(p: Vec2, p0: Vec2, p1: Vec2, p2: Vec2) -> Vec2 {
    let (e1, e2, d) = (p1 - p0, p2 - p0, p - p0);
    let det = e1.perp_dot(e2);
    Vec2::new(d.perp_dot(e2) / det, e1.perp_dot(d) / det)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::warps::test_support::{edge_points, interior_grid};
    use approx::assert_relative_eq;
    use glam::Vec3;

    #[test]
    fn corners_of_the_square_go_to_the_corners() {
        let (p0, p1, p2) = (
            Vec2::new(1.0, 2.0),
            Vec2::new(4.0, 2.0),
            Vec2::new(2.0, 5.0),
        );
        assert_eq!(sample_parallelogram(Vec2::ZERO, p0, p1, p2), p0);
        assert_eq!(sample_parallelogram(Vec2::X, p0, p1, p2), p1);
        assert_eq!(sample_parallelogram(Vec2::Y, p0, p1, p2), p2);
        assert_eq!(sample_parallelogram(Vec2::ONE, p0, p1, p2), p1 + p2 - p0);
    }

    #[test]
    fn works_in_space_too() {
        let (p0, p1, p2) = (
            Vec3::ZERO,
            Vec3::new(2.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, 3.0),
        );
        let p = sample_parallelogram(Vec2::new(0.5, 0.25), p0, p1, p2);
        assert_eq!(p, Vec3::new(1.0, 0.0, 0.75));
        // A 2 x 3 rectangle has density 1/6.
        assert_relative_eq!(parallelogram_pdf(p1.cross(p2).length()), 1.0 / 6.0);
    }

    #[test]
    fn inverse_round_trips() {
        let (p0, p1, p2) = (
            Vec2::new(-1.0, 0.5),
            Vec2::new(2.0, 1.0),
            Vec2::new(0.0, 3.0),
        );
        for u in interior_grid(17) {
            let p = sample_parallelogram(u, p0, p1, p2);
            assert_relative_eq!(invert_parallelogram(p, p0, p1, p2), u, epsilon = 1e-5);
        }
        for p in [
            Vec2::new(0.0, 1.0),
            Vec2::new(1.5, 2.5),
            Vec2::new(-0.5, 1.5),
        ] {
            let u = invert_parallelogram(p, p0, p1, p2);
            assert_relative_eq!(sample_parallelogram(u, p0, p1, p2), p, epsilon = 1e-5);
        }
    }

    #[test]
    fn edge_values_stay_inside() {
        for u in edge_points() {
            let p = sample_parallelogram(u, Vec2::ZERO, Vec2::X, Vec2::Y);
            assert!(p.is_finite() && p.cmpge(Vec2::ZERO).all() && p.cmplt(Vec2::ONE).all());
        }
    }
}
