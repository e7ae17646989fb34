//! Shirley and Chiu's concentric map: a uniform disc with little distortion.
//!
//! The polar map of [`super::disc`] is uniform but distorts badly: the bottom edge of the
//! square collapses into the centre and its left and right edges are glued along a seam, so a
//! nicely stratified set of `u` (chapter 03) arrives as long thin slivers. Shirley and Chiu
//! (1997) map concentric *squares* to concentric *circles* instead.
//!
//! Shift the square to `[-1, 1]^2` as `(a, b) = 2u - 1`. In the wedge where `|a| > |b|`, the
//! point goes to radius `r = a` and angle `θ = (π/4) (b / a)`: the square's ring at "radius"
//! `|a|` becomes the circle of radius `|a|`, and along that ring equal lengths become equal
//! arcs. The Jacobian is constant: `dr dθ = (π / 4a) da db`, and with the polar area element
//! `r dr dθ = a (π / 4a) da db = (π/4) da db`. The square of area 4 is spread evenly over
//! the disc of area π, so the density is uniform, `1 / π`. The wedges where `|b| ≥ |a|` are
//! the same with the roles of `a` and `b` swapped.

use std::f32::consts::{FRAC_PI_2, FRAC_PI_4, PI};

use glam::Vec2;

use super::disc::polar_to_cartesian;

// ANCHOR: disc_concentric
/// A uniform point of the unit disc by Shirley and Chiu's concentric map; density
/// [`super::uniform_disc_pdf`].
///
/// The centre of the square, `u = (1/2, 1/2)`, would divide 0 by 0 for its angle; it goes to
/// the centre of the disc explicitly.
pub fn sample_uniform_disc_concentric(u: Vec2) -> Vec2 {
    let offset = 2.0 * u - Vec2::ONE;
    if offset == Vec2::ZERO {
        return Vec2::ZERO;
    }
    let (r, theta) = if offset.x.abs() > offset.y.abs() {
        // The left and right wedges: the ring of half-width |a|, angle from the x axis.
        (offset.x, FRAC_PI_4 * (offset.y / offset.x))
    } else {
        // The top and bottom wedges: the same, measured from the y axis.
        (offset.y, FRAC_PI_2 - FRAC_PI_4 * (offset.x / offset.y))
    };
    // A negative r points the other way: it covers the left (or bottom) wedge.
    polar_to_cartesian(r, theta)
}
// ANCHOR_END: disc_concentric

/// The `u` that [`sample_uniform_disc_concentric`] maps to `p` (pbrt-v4's
/// `InvertUniformDiskConcentricSample`).
///
/// Find the wedge from which of `|x|`, `|y|` is larger, undo the sign trick of the forward map
/// (a point of the left wedge came from a negative `r` with an angle near 0, not near π), and
/// solve the linear angle formula for the other coordinate.
pub fn invert_uniform_disc_concentric(p: Vec2) -> Vec2 {
    let r = p.length();
    let phi = p.y.atan2(p.x); // in (-π, π]
    let offset = if p.x.abs() > p.y.abs() {
        let a = r.copysign(p.x);
        // The forward map's θ, measured from +x for the right wedge and from -x for the left.
        let theta = if p.x >= 0.0 {
            phi
        } else if phi >= 0.0 {
            phi - PI
        } else {
            phi + PI
        };
        Vec2::new(a, theta * a / FRAC_PI_4)
    } else {
        let b = r.copysign(p.y);
        // θ = π/2 - (π/4)(a/b); for the bottom wedge the point's angle is θ - π.
        let theta = if p.y >= 0.0 { phi } else { phi + PI };
        Vec2::new((FRAC_PI_2 - theta) * b / FRAC_PI_4, b)
    };
    (offset + Vec2::ONE) / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::warps::test_support::{edge_points, interior_grid};
    use approx::assert_relative_eq;

    #[test]
    fn the_centre_goes_to_the_centre_without_nan() {
        assert_eq!(sample_uniform_disc_concentric(Vec2::splat(0.5)), Vec2::ZERO);
        assert_eq!(invert_uniform_disc_concentric(Vec2::ZERO), Vec2::splat(0.5));
    }

    #[test]
    fn edge_values_stay_in_the_disc() {
        for u in edge_points() {
            let p = sample_uniform_disc_concentric(u);
            assert!(p.is_finite() && p.length() <= 1.0 + 1e-6, "u = {u}: {p}");
        }
    }

    #[test]
    fn squares_become_circles() {
        // Every point of the square's ring max(|a|, |b|) = 0.6 lands on the circle r = 0.6.
        for t in 0..40 {
            let s = -0.6 + 1.2 * t as f32 / 39.0;
            for offset in [
                Vec2::new(0.6, s),
                Vec2::new(-0.6, s),
                Vec2::new(s, 0.6),
                Vec2::new(s, -0.6),
            ] {
                let p = sample_uniform_disc_concentric((offset + Vec2::ONE) / 2.0);
                assert_relative_eq!(p.length(), 0.6, epsilon = 1e-6);
            }
        }
    }

    #[test]
    fn inverse_round_trips() {
        // The whole square, including the wedges' diagonals and the axes.
        for u in interior_grid(41) {
            let p = sample_uniform_disc_concentric(u);
            assert_relative_eq!(invert_uniform_disc_concentric(p), u, epsilon = 2e-5);
        }
        for p in [
            Vec2::new(0.3, -0.4),
            Vec2::new(-0.9, 0.1),
            Vec2::new(-0.2, -0.7),
            Vec2::new(0.0, 0.7),
        ] {
            let u = invert_uniform_disc_concentric(p);
            assert_relative_eq!(sample_uniform_disc_concentric(u), p, epsilon = 1e-6);
        }
    }
}
