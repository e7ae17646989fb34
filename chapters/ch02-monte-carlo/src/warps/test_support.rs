//! What the warps' tests share: awkward inputs and plain numerical integrals.
//!
//! The integrals here are deliberately simple (fine midpoint rules), and independent of the
//! adaptive integration inside the chi-square test, so that the two check each other.

use std::f64::consts::TAU;

use glam::{Vec2, Vec3};

use super::sphere::spherical_direction;

/// The largest `f32` below 1: the most a sampler's `[0, 1)` number can be.
pub const ONE_MINUS_EPSILON: f32 = f32::from_bits(0x3f7f_ffff);

/// Every `u` whose components are 0, 1/2 or the largest float below 1: the corners, edge
/// midpoints and centre of the square, where formulas divide by zero or take `ln 0`.
pub fn edge_points() -> Vec<Vec2> {
    let values = [0.0, 0.5, ONE_MINUS_EPSILON];
    values
        .iter()
        .flat_map(|&x| values.iter().map(move |&y| Vec2::new(x, y)))
        .collect()
}

/// An `n x n` grid of `u` strictly inside the square, away from the seams where an inverse
/// may legitimately answer 0 instead of 1 (the azimuth `0 = 2π`).
pub fn interior_grid(n: usize) -> Vec<Vec2> {
    let at = |i: usize| (0.02 + 0.96 * (i as f64 + 0.5) / n as f64) as f32;
    (0..n)
        .flat_map(|i| (0..n).map(move |j| Vec2::new(at(i), at(j))))
        .collect()
}

/// The centres of an `n x n` grid of cells covering the whole square: a deterministic
/// stand-in for `n²` uniform samples when a test wants averages.
pub fn midpoint_grid(n: usize) -> Vec<Vec2> {
    let at = |i: usize| ((i as f64 + 0.5) / n as f64) as f32;
    (0..n)
        .flat_map(|i| (0..n).map(move |j| Vec2::new(at(i), at(j))))
        .collect()
}

/// The midpoint rule over the rectangle `[min, max]`, with `n` columns and `n + 1` rows.
///
/// A square grid would put a row of nodes exactly on the diagonal of the rectangle, where the
/// triangle's density jumps; with one row more, no node is ever on it (`(2i + 1) / 2n +
/// (2j + 1) / 2(n + 1)` has an odd numerator over an even denominator, so it is never 1).
pub fn integrate_over_rectangle(f: impl Fn(Vec2) -> f32, min: Vec2, max: Vec2, n: usize) -> f64 {
    let size = (max - min).as_dvec2() / glam::DVec2::new(n as f64, (n + 1) as f64);
    let mut sum = 0.0;
    for i in 0..n {
        for j in 0..=n {
            let x = min.x as f64 + (i as f64 + 0.5) * size.x;
            let y = min.y as f64 + (j as f64 + 0.5) * size.y;
            sum += f(Vec2::new(x as f32, y as f32)) as f64;
        }
    }
    sum * size.x * size.y
}

/// The midpoint rule over the whole sphere in the coordinates `(cos θ, φ)`, where the
/// solid-angle element is exactly `dcos θ dφ`; `n` nodes in `cos θ`, `n` in `φ`.
pub fn integrate_over_sphere(f: impl Fn(Vec3) -> f32, n: usize) -> f64 {
    let (dz, dphi) = (2.0 / n as f64, TAU / n as f64);
    let mut sum = 0.0;
    for i in 0..n {
        let z = -1.0 + (i as f64 + 0.5) * dz;
        let sin = ((1.0 - z) * (1.0 + z)).sqrt();
        for j in 0..n {
            let phi = (j as f64 + 0.5) * dphi;
            sum += f(spherical_direction(sin as f32, z as f32, phi as f32)) as f64;
        }
    }
    sum * dz * dphi
}

/// The integral over the upper hemisphere of a density that depends on `cos θ` alone,
/// `2π ∫_0^1 p(cos θ) dcos θ`, on a grid fine enough for lobes of any width.
///
/// A lobe `cos^n θ` is about `1 / n` wide in `cos θ`, so a uniform grid would need many more
/// than `n` nodes. Substituting `s = 1 - cos θ` and spacing the nodes uniformly in `ln s`
/// (from `s = 1e-15` to 1) puts the same number of nodes in every decade of `s`, so the peak is
/// resolved whether it is 1 or 1e-6 wide: `∫ g(s) ds = ∫ g(s) s d(ln s)`.
pub fn integrate_rotationally_symmetric(p: impl Fn(f32) -> f32) -> f64 {
    let (ln_min, nodes) = (-15.0 * std::f64::consts::LN_10, 200_000);
    let step = -ln_min / nodes as f64;
    let mut sum = 0.0;
    for k in 0..nodes {
        let s = (ln_min + (k as f64 + 0.5) * step).exp();
        sum += p((1.0 - s) as f32) as f64 * s;
    }
    TAU * sum * step
}
