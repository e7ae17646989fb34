//! The chapter's diagram: what the optimal combination does to an integrand, drawn from the
//! chapter's own sums.
//!
//! On `[0, 1]`, two techniques draw `x` with densities `p_1 = 1` (uniform) and `p_2 = 2x`
//! (linear). Their sums ([`OptimalSums`]) over many samples of both give `α`, and the diagram
//! shows the integrand `f`, the combination `α_1 p_1 + α_2 p_2` the densities cover exactly,
//! and what is left over, the only part the samples still estimate.

use crate::optimal::OptimalSums;
use crate::techniques::{SurfaceDraws, TechniqueSample};
use glam::Vec3;
use std::path::Path;
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

/// Writes every diagram of the chapter into `out` (the figures' `diagrams` folder).
pub fn write_all(out: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out)?;
    covered_and_left().save(&out.join("covered-and-left.svg"))?;
    Ok(())
}

/// The integrand of the diagram: light that rises across the domain, with a bump the
/// densities cannot follow.
fn integrand(x: f64) -> f64 {
    0.3 + 1.2 * x * x + 0.5 * (-((x - 0.35) / 0.08).powi(2)).exp()
}

/// The two densities at `x`: uniform, linear.
fn densities(x: f64) -> [f64; 2] {
    [1.0, 2.0 * x]
}

/// `α` from the chapter's sums over `n` stratified samples of each technique.
fn alpha(n: u32) -> [f64; 2] {
    let mut sums = OptimalSums::default();
    for k in 0..n {
        let u = (f64::from(k) + 0.5) / f64::from(n);
        // Inverting each technique's distribution: x = u, and x = sqrt(u).
        let drawn = [u, u.sqrt()].map(|x| {
            let p = densities(x);
            Some(TechniqueSample {
                f: Vec3::splat(integrand(x) as f32),
                pdf: [p[0] as f32, p[1] as f32],
            })
        });
        sums.add(&SurfaceDraws {
            certain: Vec3::ZERO,
            drawn,
        });
    }
    let solved = sums.solve().expect("two densities that differ");
    [solved[0].x, solved[1].x]
}

/// The integrand, the part the densities cover exactly, and the rest.
fn covered_and_left() -> Diagram {
    let a = alpha(4096);
    let mut d = Diagram::new(
        "Over the interval from 0 to 1, an integrand f (black) that rises with x and has a \
         narrow bump, and two sampling densities, uniform p1 and linear p2. The optimal \
         weights find the combination alpha1 p1 plus alpha2 p2 (green) closest to f in the \
         sense of the samples' variance; its integral, alpha1 plus alpha2, is known exactly, so \
         only what is left of f above or below it (shaded) is estimated from the samples. \
         Where f is such a combination, nothing is left and the estimate has no noise.",
        (-0.08, 1.5),
        (-0.12, 1.1),
        720,
    );
    // Values are drawn at half height, so that the plot is wider than tall.
    const Y: f64 = 0.5;
    let steps = 200;
    let xs: Vec<f64> = (0..=steps)
        .map(|i| f64::from(i) / f64::from(steps))
        .collect();
    let curve =
        |g: &dyn Fn(f64) -> f64| -> Vec<Point> { xs.iter().map(|&x| (x, Y * g(x))).collect() };
    let combination = |x: f64| {
        let p = densities(x);
        a[0] * p[0] + a[1] * p[1]
    };
    // What is left: between f and the combination.
    let mut left = curve(&integrand);
    left.extend(curve(&combination).into_iter().rev());
    d.area(left, Ink::Warning, 0.25);
    d.line((0.0, 0.0), (1.08, 0.0), Ink::Guide);
    d.line((0.0, 0.0), (0.0, 1.05), Ink::Guide);
    d.label((1.0, -0.02), "1", Anchor::Below, Ink::Guide);
    d.label((0.0, -0.02), "0", Anchor::Below, Ink::Guide);
    d.label((1.09, 0.0), "x", Anchor::Left, Ink::Guide);
    d.polyline(curve(&|x| densities(x)[0]), Ink::Ray);
    d.label((1.02, Y), "p1 (uniform)", Anchor::Left, Ink::Ray);
    d.polyline(curve(&|x| densities(x)[1]), Ink::OtherRay);
    d.label((1.02, 2.0 * Y), "p2 (linear)", Anchor::Left, Ink::OtherRay);
    d.polyline(curve(&combination), Ink::Normal);
    d.label(
        (1.02, Y * combination(1.0) - 0.04),
        "α1 p1 + α2 p2",
        Anchor::Left,
        Ink::Normal,
    );
    d.polyline(curve(&integrand), Ink::Surface);
    d.label(
        (1.02, Y * integrand(1.0) + 0.04),
        "f",
        Anchor::Left,
        Ink::Surface,
    );
    d.label(
        (0.66, 0.12),
        "shaded: left to the samples",
        Anchor::Centre,
        Ink::Warning,
    );
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The combination drawn is the one the sums solve for: its integral, `α_1 + α_2`, is the
    /// optimal estimate of `∫ f`, which stratified samples this many get right to a fraction of
    /// a per cent.
    #[test]
    fn the_combination_covers_most_of_the_integral() {
        let a = alpha(4096);
        // ∫ f = 0.3 + 0.4 + 0.5 · 0.08 √π (the bump lies well inside the interval).
        let integral = 0.7 + 0.5 * 0.08 * std::f64::consts::PI.sqrt();
        let covered = a[0] + a[1];
        assert!(
            (covered / integral - 1.0).abs() < 0.005,
            "{a:?}: {covered} against {integral}"
        );
        let svg = covered_and_left().to_svg();
        assert!(svg.contains("α1 p1 + α2 p2"));
    }
}
