//! The triangle, by the lecture's method: sample the square, fold it in half.
//!
//! A triangle is half a parallelogram: `p0 + b1 (p1 - p0) + b2 (p2 - p0)` covers the
//! parallelogram for `(b1, b2)` in the unit square, and the triangle for the half where
//! `b1 + b2 ≤ 1`. Rejecting the other half would waste half the samples. Folding does not: a
//! map that sends the upper half exactly onto the lower half and preserves area (its Jacobian
//! has a determinant of size 1) leaves each point of the lower triangle the samples of two
//! equal patches, itself and its image, and the density stays uniform: twice that of the
//! square, `1 / area` after the affine map. Which map is that? The exercise asks.
//!
//! The fold is two-to-one, so unlike the other warps it has no inverse. (pbrt-v4 samples
//! triangles with a different, one-to-one map for that reason; the fold is simpler to see.)

use glam::Vec2;

use super::VectorSpace;

// ANCHOR: triangle_fold
/// Uniform barycentric coordinates `(b1, b2)` of a triangle, with `b1, b2 ≥ 0` and
/// `b1 + b2 ≤ 1`; the third is `b0 = 1 - b1 - b2`.
///
/// By folding the unit square: the half that already is the triangle stays as it is, and the
/// other half is mapped onto it by a map that preserves area, so both halves arrive with the
/// same, uniform density.
pub fn sample_triangle_barycentric(u: Vec2) -> Vec2 {
    // BEGIN SOLUTION
    if u.x + u.y > 1.0 {
        Vec2::new(1.0 - u.x, 1.0 - u.y)
    } else {
        u
    }
    // END SOLUTION
}
// ANCHOR_END: triangle_fold

/// A uniform point of the triangle `p0 p1 p2` (in the plane or in space):
/// `p0 + b1 (p1 - p0) + b2 (p2 - p0)` with `(b1, b2)` from [`sample_triangle_barycentric`].
/// Its density is [`triangle_pdf`].
pub fn sample_triangle<V: VectorSpace>(u: Vec2, p0: V, p1: V, p2: V) -> V {
    let b = sample_triangle_barycentric(u);
    p0 + (p1 - p0) * b.x + (p2 - p0) * b.y
}

/// The density of [`sample_triangle`] per unit area: `1 / area` inside, where
/// `area = |(p1 - p0) × (p2 - p0)| / 2`.
pub fn triangle_pdf(area: f32) -> f32 {
    1.0 / area
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chi2::{chi2_test, significance_level};
    use crate::warps::Warp;
    use crate::warps::test_support::{ONE_MINUS_EPSILON, edge_points, interior_grid};
    use glam::Vec3;

    fn inside_unit_triangle(b: Vec2) -> bool {
        b.x >= 0.0 && b.y >= 0.0 && b.x + b.y <= 1.0 + 1e-6
    }

    #[test]
    fn exercise_triangle_fold_stays_inside_the_triangle() {
        let mut grid = interior_grid(40);
        grid.extend(edge_points());
        grid.push(Vec2::new(ONE_MINUS_EPSILON, 1e-7));
        for u in grid {
            let b = sample_triangle_barycentric(u);
            assert!(
                b.is_finite() && inside_unit_triangle(b),
                "sample_triangle_barycentric: ξ = {u} gave {b}, which is not in the triangle \
                 b1 ≥ 0, b2 ≥ 0, b1 + b2 ≤ 1: every point of the square has to end up in the \
                 triangle, the upper half moved into the lower one"
            );
        }
    }

    #[test]
    fn exercise_triangle_fold_keeps_the_lower_half_as_it_is() {
        // The fold moves only what lies outside the triangle.
        for u in interior_grid(20).into_iter().filter(|u| u.x + u.y < 1.0) {
            let b = sample_triangle_barycentric(u);
            assert_eq!(
                b, u,
                "sample_triangle_barycentric: ξ = {u} lies in the lower half (ξ1 + ξ2 ≤ 1), \
                 so it is a point of the triangle already, and the fold leaves it where it is; \
                 yours moved it to {b}"
            );
        }
    }

    #[test]
    fn exercise_triangle_fold_is_uniform() {
        let result = chi2_test(&Warp::Triangle, 200_000, 1, (16, 16));
        if result.p_value > significance_level(1, 0.01) {
            return;
        }
        let points: Vec<Vec2> = interior_grid(300)
            .into_iter()
            .map(sample_triangle_barycentric)
            .collect();
        panic!(
            "{}",
            workbench::test_support::not_uniform(
                "ch02-triangle-fold",
                "sample_triangle_barycentric",
                "triangle",
                result.p_value,
                &points,
                &|b| if inside_unit_triangle(b) { 2.0 } else { 0.0 },
                [Vec2::ZERO, Vec2::ONE],
            )
        );
    }

    #[test]
    fn sample_triangle_hits_its_corners() {
        let (p0, p1, p2) = (Vec3::ZERO, Vec3::X, Vec3::Z);
        assert_eq!(sample_triangle(Vec2::ZERO, p0, p1, p2), p0);
        assert_eq!(sample_triangle(Vec2::new(1.0, 0.0), p0, p1, p2), p1);
        assert_eq!(sample_triangle(Vec2::new(0.0, 1.0), p0, p1, p2), p2);
        // Area 1/2: density 2.
        assert_eq!(triangle_pdf(0.5 * (p1 - p0).cross(p2 - p0).length()), 2.0);
    }
}
