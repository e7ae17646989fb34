//! Spreading a mirror (or refracted) direction: the lecture's two ways of making a surface
//! fuzzy.
//!
//! A real surface is never perfectly smooth, so the light it reflects comes not from one
//! mirror direction but from a small cone of directions around it. Both ways below take the
//! ideal direction `center` (the mirror or the refracted direction) and return a direction
//! near it:
//!
//! - **The empirical approach** ([`sample_disc_perturbation`]): move the tip of `center` by a
//!   random point of a disc of radius `R` lying across it. It is quick and looks plausible,
//!   but the directions it makes have no named distribution, and a renderer that uses it
//!   weights every ray by the surface's reflectance alone, so what it computes is whatever
//!   that distribution happens to be.
//! - **The `cos^n` lobe** ([`sample_lobe_around`]): directions with density
//!   `(n + 1) / 2π · cos^n α` per solid angle, `α` the angle from `center` (chapter 02's
//!   warp, turned to point along `center`). The exponent `n` is the roughness: `n = 0` spreads
//!   over a whole hemisphere, `n = 1e6` stays within about a milliradian, and `n → ∞` is the
//!   mirror.
//!
//! The chapter's glossy material *is* the `cos^n` lobe: a fuzzy mirror of reflectance `k`
//! sends the light arriving from direction `ω` towards the viewer in the proportion the lobe
//! around the mirror direction gives `ω`. What weight a ray sampled from that lobe carries,
//! its `f_r cos θ / pdf`, is for the chapter's glossy exercise to work out. The disc is then a
//! different, empirical lobe, which [`disc_radius_for_exponent`] sizes to spread as wide as
//! the `cos^n` one.

use glam::{Vec2, Vec3};

/// How a fuzzy surface spreads its directions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum FuzzMethod {
    /// The `cos^n` lobe around the ideal direction, with its proper weight.
    Lobe,
    /// The empirical approach: a disc point added to the ideal direction.
    Disc,
}

impl FuzzMethod {
    /// Both methods, lobe first.
    pub const ALL: [FuzzMethod; 2] = [FuzzMethod::Lobe, FuzzMethod::Disc];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            FuzzMethod::Lobe => "lobe",
            FuzzMethod::Disc => "disc",
        }
    }

    /// A direction near `center` spread as much as a `cos^n` lobe of `exponent`.
    pub fn sample(self, center: Vec3, exponent: f32, u: Vec2) -> Vec3 {
        match self {
            FuzzMethod::Lobe => sample_lobe_around(center, exponent, u),
            FuzzMethod::Disc => {
                sample_disc_perturbation(center, disc_radius_for_exponent(exponent), u)
            }
        }
    }

    /// The density per unit solid angle of [`sample`](Self::sample) at a direction at angle
    /// `α` from the centre (`cos_alpha = cos α`). An infinite exponent is a mirror, whose
    /// density is a delta with no finite value: 0 is returned, and light reaches a mirror
    /// only along its one direction.
    pub fn pdf(self, cos_alpha: f32, exponent: f32) -> f32 {
        if !exponent.is_finite() {
            return 0.0;
        }
        match self {
            FuzzMethod::Lobe => lobe_around_pdf(cos_alpha, exponent),
            FuzzMethod::Disc => {
                disc_perturbation_pdf(cos_alpha, disc_radius_for_exponent(exponent))
            }
        }
    }
}

// ANCHOR: lobe_around
/// The direction whose coordinates are `local` in a frame that has the unit vector `center`
/// as its `z` axis: a direction drawn around `+z` (by chapter 02's warps) turned to be drawn
/// around `center`, every angle between directions kept. [`sample_lobe_around`] turns the
/// `cos^n` lobe with it, and chapter 08 its cosine-weighted hemisphere around the normal.
///
/// What frame turns `+z` into the centre and keeps every angle between directions, is it
/// defined for every centre, and does it matter how it is turned about the centre?
pub fn to_world(center: Vec3, local: Vec3) -> Vec3 {
    // BEGIN SOLUTION
    let (a, b) = center.any_orthonormal_pair();
    local.x * a + local.y * b + local.z * center
    // END SOLUTION
}
// ANCHOR_END: lobe_around

/// A direction around the unit vector `center` with density `(n + 1) / 2π · cos^n α` per
/// unit solid angle, `α` the angle between the direction and `center`
/// ([`lobe_around_pdf`]): chapter 02's lobe around `+z`, turned by [`to_world`].
pub fn sample_lobe_around(center: Vec3, exponent: f32, u: Vec2) -> Vec3 {
    to_world(
        center,
        ch02_monte_carlo::warps::sample_cos_lobe(u, exponent),
    )
}

/// The density of [`sample_lobe_around`] per unit solid angle, from `cos α = d · center`.
pub fn lobe_around_pdf(cos_alpha: f32, exponent: f32) -> f32 {
    ch02_monte_carlo::warps::cos_lobe_pdf(cos_alpha, exponent)
}

// ANCHOR: disc_perturbation
/// The lecture's empirical fuzz: the unit `center` moved by a point drawn uniformly (by area)
/// from a disc of `radius`, whose centre is the tip of `center` (one unit from the surface
/// point); a unit direction.
///
/// How must the disc be turned so that every way of tilting the direction is equally likely,
/// and which of chapter 02's disc warps is uniform by area? The widest tilt is then
/// `atan(radius)`: the radius is a length on the disc, not an angle.
pub fn sample_disc_perturbation(center: Vec3, radius: f32, u: Vec2) -> Vec3 {
    // BEGIN SOLUTION
    use ch02_monte_carlo::warps::sample_uniform_disc_concentric;
    // A frame (a, b) perpendicular to the centre: the disc lies across the direction.
    let (a, b) = center.any_orthonormal_pair();
    let p = radius * sample_uniform_disc_concentric(u);
    (center + p.x * a + p.y * b).normalize()
    // END SOLUTION
}
// ANCHOR_END: disc_perturbation

/// The density per unit solid angle of [`sample_disc_perturbation`] at a direction at angle
/// `α` from the centre: `1 / (π R² cos³ α)` inside the cone `tan α ≤ R`, else 0.
///
/// The disc lies in the plane one unit along the centre. A patch `dA` of it, seen at angle
/// `α` and distance `1 / cos α`, subtends `dω = dA cos α / (1 / cos α)² = dA cos³ α`, and the
/// disc point is uniform with density `1 / (π R²)` per area.
pub fn disc_perturbation_pdf(cos_alpha: f32, radius: f32) -> f32 {
    if cos_alpha <= 0.0 || radius <= 0.0 {
        return 0.0;
    }
    let cos_alpha = cos_alpha.min(1.0);
    // tan² α = (1 - cos² α) / cos² α, compared as tan² α ≤ R² without dividing.
    let sin2 = (1.0 - cos_alpha) * (1.0 + cos_alpha);
    if sin2 > radius * radius * cos_alpha * cos_alpha {
        return 0.0;
    }
    1.0 / (std::f32::consts::PI * radius * radius * cos_alpha.powi(3))
}

/// The disc radius at which the empirical approach spreads directions as much as a `cos^n`
/// lobe of `exponent`: both then have the same mean `sin² α` to first order.
///
/// For the lobe, `E[cos² α] = (n + 1)/(n + 3)`, so `E[sin² α] = 2/(n + 3)`. For the disc,
/// `sin² α ≈ R² ρ²` for small angles, and `E[ρ²] = 1/2` over the unit disc: `R²/2`. Equal
/// when `R = 2 / √(n + 3)`: about 1.15 for `n = 0`, 0.2 for `n = 100`, 0.002 for `n = 1e6`.
pub fn disc_radius_for_exponent(exponent: f32) -> f32 {
    2.0 / (exponent + 3.0).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use ch02_monte_carlo::warps::sample_cos_lobe;
    use common::sampler::{IndependentSampler, Sampler};
    use glam::UVec2;

    const EXPONENTS: [f32; 7] = [0.0, 1.0, 10.0, 100.0, 1e3, 1e4, 1e6];

    /// Why a direction around `center` came out NaN or infinite: the usual cause.
    fn not_finite_why(center: Vec3) -> &'static str {
        if center.x.abs().max(center.y.abs()).max(center.z.abs()) > 1.0 - 1e-6 {
            "is the frame around the centre defined when the centre lies along a coordinate \
             axis? A cross product with a fixed axis vanishes for a centre along it, and \
             normalising zero gives NaN (glam's Vec3 can build a frame that works for every \
             unit vector)"
        } else {
            "is every vector that is normalised non-zero?"
        }
    }

    fn centres() -> [Vec3; 4] {
        [
            Vec3::Z,
            -Vec3::Z,
            Vec3::new(1.0, 2.0, -0.5).normalize(),
            Vec3::new(0.0, -1.0, 1e-7).normalize(),
        ]
    }

    fn uniforms(n: u64) -> impl Iterator<Item = Vec2> {
        let mut sampler = IndependentSampler::new(6);
        (0..n).map(move |i| {
            sampler.start_pixel_sample(UVec2::ZERO, i);
            sampler.get_2d()
        })
    }

    /// A unit vector perpendicular to the unit `center`: the coordinate axis least along it,
    /// with its part along `center` taken out.
    fn perpendicular(center: Vec3) -> Vec3 {
        let axis = if center.x.abs() < 0.6 {
            Vec3::X
        } else {
            Vec3::Y
        };
        (axis - axis.dot(center) * center).normalize()
    }

    /// How far `d` is turned about the unit `center`, as a fraction of a full turn in
    /// `[0, 1)`, counted from [`perpendicular`]`(center)`.
    fn turn_about(center: Vec3, d: Vec3) -> f32 {
        let reference = perpendicular(center);
        let sine = center.dot(reference.cross(d));
        let cosine = reference.dot(d);
        sine.atan2(cosine).rem_euclid(std::f32::consts::TAU) / std::f32::consts::TAU
    }

    /// A few unit directions given in the frame of the centre.
    const LOCAL: [Vec3; 5] = [
        Vec3::X,
        Vec3::Y,
        Vec3::new(0.6, 0.0, 0.8),
        Vec3::new(-0.48, 0.64, 0.6),
        Vec3::new(0.0, -0.28, -0.96),
    ];

    #[test]
    fn exercise_lobe_around_turns_z_to_the_centre_keeping_angles() {
        for center in centres() {
            let z = to_world(center, Vec3::Z);
            assert!(
                z.is_finite(),
                "to_world: around the centre {center}, +z gave {z}, which is not finite: {}",
                not_finite_why(center)
            );
            assert!(
                (z - center).length() < 1e-5,
                "to_world: +z, the lobe's own axis, has to land on the centre {center}, and \
                 lands on {z}{}",
                if (z - Vec3::Z).length() < 1e-6 {
                    ": it was not turned to the centre"
                } else {
                    ": is the lobe's own axis, its z, the one turned to the centre?"
                }
            );
            for (i, &p) in LOCAL.iter().enumerate() {
                let wp = to_world(center, p);
                assert!(
                    wp.is_finite() && (wp.length() - 1.0).abs() < 1e-5,
                    "to_world: around the centre {center}, the unit {p} became {wp}, of length \
                     {}: turning a unit vector with an orthonormal frame keeps it unit{}",
                    wp.length(),
                    if wp.is_finite() {
                        String::new()
                    } else {
                        format!(" ({})", not_finite_why(center))
                    }
                );
                for &q in &LOCAL[i + 1..] {
                    let wq = to_world(center, q);
                    assert!(
                        (wp.dot(wq) - p.dot(q)).abs() < 1e-5,
                        "to_world: around the centre {center}, {p} and {q} (cosine {:.3} \
                         between them) became {wp} and {wq} (cosine {:.3}): a turn keeps every \
                         angle between directions, so the frame's three axes have to be \
                         perpendicular to each other, the two sideways ones perpendicular to \
                         the centre",
                        p.dot(q),
                        wp.dot(wq)
                    );
                }
            }
        }
    }

    #[test]
    fn exercise_lobe_around_points_along_the_centre() {
        for center in centres() {
            for exponent in EXPONENTS {
                let mut mean = Vec3::ZERO;
                let n = 2000;
                for u in uniforms(n) {
                    let d = sample_lobe_around(center, exponent, u);
                    let problem = if !d.is_finite() {
                        format!("is not finite: {}", not_finite_why(center))
                    } else if (d.length() - 1.0).abs() > 1e-4 {
                        format!(
                            "has length {}: turning a unit vector with an orthonormal frame keeps \
                             it unit",
                            d.length()
                        )
                    } else if d.dot(center) <= 0.0 {
                        if (d - sample_cos_lobe(u, exponent)).length() < 1e-5 {
                            "is the lobe's direction around +z, not turned to the centre"
                                .to_string()
                        } else {
                            "points away from the centre: the lobe is a cap around it (is the \
                             lobe's own axis, its z, the one turned to the centre?)"
                                .to_string()
                        }
                    } else {
                        mean += d / n as f32;
                        continue;
                    };
                    panic!(
                        "sample_lobe_around: around the centre {center} with exponent \
                         {exponent}, ξ = {u} gave {d}, which {problem}"
                    );
                }
                // E[cos α] = (n + 1)/(n + 2) for the cos^n lobe; 6 standard errors of the
                // mean (Var cos α <= 1/12 for n = 0 and smaller for narrower lobes).
                let expected = (exponent + 1.0) / (exponent + 2.0);
                let tolerance = 6.0 * (1.0 / 12.0 / n as f32).sqrt();
                let mean_cos = mean.dot(center);
                assert!(
                    (mean_cos - expected).abs() < tolerance,
                    "sample_lobe_around: around {center} with exponent {exponent} the mean cosine \
                     to the centre is {mean_cos:.3}; the cos^n lobe gives (n + 1) / (n + 2) = \
                     {expected:.3}: is the lobe's own axis, its z, the one turned to the centre?"
                );
                // Symmetric about the axis: the sideways mean vanishes.
                let sideways = (mean - mean_cos * center).length();
                assert!(
                    sideways < tolerance,
                    "sample_lobe_around: around {center} with exponent {exponent} the directions \
                     lean to one side of the centre (mean sideways {sideways:.3}): the lobe is \
                     symmetric about its axis"
                );
            }
        }
    }

    #[test]
    fn exercise_lobe_around_has_the_lobes_distribution_of_angles() {
        // P(cos α >= c) = 1 - c^(n+1): a binomial count at three thresholds.
        let center = Vec3::new(0.3, -0.4, 0.8).normalize();
        for exponent in [0.0f32, 3.0, 50.0] {
            let n = 20_000;
            for p in [0.2f32, 0.6, 0.9] {
                // The threshold the lobe exceeds with probability p.
                let c = (1.0 - p).powf(1.0 / (exponent + 1.0));
                let hits = uniforms(n)
                    .filter(|&u| sample_lobe_around(center, exponent, u).dot(center) >= c)
                    .count() as f32;
                let sigma = (n as f32 * p * (1.0 - p)).sqrt();
                if (hits - n as f32 * p).abs() < 5.0 * sigma {
                    continue;
                }
                // The picture: each direction as (its turn about the centre, cos^(n+1) α),
                // which the cos^n lobe spreads evenly over the unit square.
                let points: Vec<Vec2> = uniforms(n)
                    .map(|u| {
                        let d = sample_lobe_around(center, exponent, u);
                        Vec2::new(
                            turn_about(center, d),
                            d.dot(center).max(0.0).powf(exponent + 1.0),
                        )
                    })
                    .collect();
                let picture = workbench::test_support::not_uniform(
                    "ch06-lobe-around",
                    "sample_lobe_around",
                    "lobe, drawn as (turn about the centre, cos^(n+1) α)",
                    0.0,
                    &points,
                    &|_| 1.0,
                    [Vec2::ZERO, Vec2::ONE],
                );
                let picture = picture.split("; see ").nth(1).unwrap_or("");
                panic!(
                    "sample_lobe_around: with exponent {exponent}, {:.1} % of the directions \
                     should lie within {:.1}° of the centre, and {:.1} % of yours do: the \
                     spread does not follow the cos^n lobe of that exponent; see {picture}, \
                     where the lobe's directions spread evenly",
                    100.0 * p,
                    c.acos().to_degrees(),
                    100.0 * hits / n as f32
                );
            }
        }
    }

    #[test]
    fn exercise_lobe_around_with_a_huge_exponent_is_the_centre() {
        for center in centres() {
            for u in uniforms(100) {
                let d = sample_lobe_around(center, 1e9, u);
                assert!(
                    d.dot(center) > 1.0 - 1e-6,
                    "sample_lobe_around: an exponent of 1e9 makes the lobe a mirror, every \
                     direction the centre {center} itself; ξ = {u} gave {d}{}",
                    if d.is_finite() {
                        String::new()
                    } else {
                        format!(": {}", not_finite_why(center))
                    }
                );
            }
        }
    }

    /// What is wrong with the directions `sample_disc_perturbation` makes around `center`
    /// with `radius` from `n` uniform pairs, in words; `None` if nothing is.
    fn disc_mistake(center: Vec3, radius: f32, n: u64) -> Option<String> {
        let samples: Vec<(Vec2, Vec3)> = uniforms(n)
            .map(|u| (u, sample_disc_perturbation(center, radius, u)))
            .collect();
        for &(u, d) in &samples {
            let length = d.length();
            if !d.is_finite() {
                return Some(format!(
                    "ξ = {u} gave {d}, which is not finite: {}",
                    not_finite_why(center)
                ));
            }
            if (length - 1.0).abs() > 1e-4 {
                return Some(format!(
                    "ξ = {u} gave {d}, of length {length}: a direction is a unit vector"
                ));
            }
        }
        // Every way of tilting equally likely: as much spread along every direction across the
        // centre. Measured along the coordinate axes' parts across it (those not nearly along
        // the centre).
        let spread = |axis: Vec3| -> f64 {
            samples
                .iter()
                .map(|&(_, d)| f64::from((d - d.dot(center) * center).dot(axis).powi(2)))
                .sum()
        };
        let (least, most) = [Vec3::X, Vec3::Y, Vec3::Z]
            .into_iter()
            .map(|axis| axis - axis.dot(center) * center)
            .filter(|across| across.length() > 0.3)
            .map(|across| spread(across.normalize()))
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            });
        let ratio = least / most.max(1e-30);
        if ratio < 0.8 {
            return Some(format!(
                "the directions spread {:.2} times as much one way as the other across the \
                 centre: the disc has to lie across the direction, perpendicular to it",
                1.0 / ratio.max(1e-9)
            ));
        }
        let tan = |d: Vec3| {
            let cos_alpha = d.dot(center);
            (1.0 - cos_alpha * cos_alpha).max(0.0).sqrt() / cos_alpha
        };
        for &(u, d) in &samples {
            let cos_alpha = d.dot(center);
            if cos_alpha <= 0.0 || tan(d) > radius * (1.0 + 1e-3) + 1e-5 {
                let alpha = cos_alpha.clamp(-1.0, 1.0).acos();
                let why = if alpha <= radius * (1.0 + 1e-3) {
                    "the radius was used as an angle; it is the disc's radius one unit along \
                     the centre, so the widest tilt is atan(radius)"
                } else {
                    "is the disc one unit along the centre, with the radius it is given?"
                };
                return Some(format!(
                    "ξ = {u} gave {d}, tilted {:.2}° from the centre, beyond the {:.2}° \
                     (atan {radius}) that a disc of radius {radius} allows: {why}",
                    alpha.to_degrees(),
                    radius.atan().to_degrees()
                ));
            }
        }
        // A uniform disc point: the share within a fraction s of the radius is s².
        for s in [0.3f32, 0.6, 0.9] {
            let count = samples
                .iter()
                .filter(|&&(_, d)| tan(d) <= radius * s)
                .count();
            let p = f64::from(s * s);
            let share = count as f64 / n as f64;
            let sigma = (p * (1.0 - p) / n as f64).sqrt();
            if (share - p).abs() > 5.0 * sigma {
                let why = if (share - f64::from(s)).abs() <= 5.0 * sigma {
                    "the disc point is not uniform by area: it crowds the centre as the polar \
                     warp with r = ξ does"
                } else {
                    "the disc point should be uniform by area over the disc of the given radius"
                };
                // The picture: each direction as (its turn about the centre, the square of
                // its disc point's distance from the centre in units of the radius), which a
                // point uniform over the disc spreads evenly over the unit square.
                let points: Vec<Vec2> = samples
                    .iter()
                    .map(|&(_, d)| {
                        Vec2::new(turn_about(center, d), (tan(d) / radius).powi(2).min(1.0))
                    })
                    .collect();
                let picture = workbench::test_support::not_uniform(
                    "ch06-disc-fuzz",
                    "sample_disc_perturbation",
                    "disc, drawn as (turn about the centre, (distance from the centre / radius)²)",
                    0.0,
                    &points,
                    &|_| 1.0,
                    [Vec2::ZERO, Vec2::ONE],
                );
                let picture = picture.split("; see ").nth(1).unwrap_or("");
                return Some(format!(
                    "{:.1} % of the directions should lie within {s} of the disc's radius from \
                     the centre, and {:.1} % of yours do: {why}; see {picture}, the disc points \
                     by turn and squared distance",
                    100.0 * p,
                    100.0 * share
                ));
            }
        }
        None
    }

    #[test]
    fn exercise_disc_perturbation_spreads_evenly_inside_its_cone() {
        for center in [Vec3::X, -Vec3::Z, Vec3::new(1.0, 2.0, -0.5).normalize()] {
            for radius in [0.05f32, 0.5, 1.5] {
                if let Some(mistake) = disc_mistake(center, radius, 20_000) {
                    panic!(
                        "sample_disc_perturbation: around the centre {center} with a disc of \
                         radius {radius}: {mistake}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_disc_stays_inside_its_cone() {
        for center in centres() {
            for exponent in EXPONENTS {
                let radius = disc_radius_for_exponent(exponent);
                let cos_max = 1.0 / (1.0 + radius * radius).sqrt();
                for u in uniforms(500) {
                    let d = sample_disc_perturbation(center, radius, u);
                    assert!(d.is_finite());
                    assert_relative_eq!(d.length(), 1.0, epsilon = 1e-5);
                    assert!(d.dot(center) >= cos_max - 1e-5, "{center} R={radius}: {d}");
                }
            }
        }
    }

    #[test]
    fn both_densities_integrate_to_one() {
        // Integrate over the sphere around +z in (cos α, φ), where dω = d(cos α) dφ; the
        // disc's cone is narrow, so the grid is fine near cos α = 1.
        for exponent in [0.0f32, 1.0, 10.0, 100.0, 1e3] {
            for method in FuzzMethod::ALL {
                let n = 200_000;
                let mut integral = 0.0f64;
                for i in 0..n {
                    // Points crowd towards the pole: cos α = 1 - s² (2), ds uniform.
                    let s = (i as f64 + 0.5) / n as f64 * 2f64.sqrt();
                    let cos_alpha = 1.0 - s * s;
                    let d_cos = 2.0 * s * 2f64.sqrt() / n as f64;
                    let p = f64::from(method.pdf(cos_alpha as f32, exponent));
                    integral += std::f64::consts::TAU * p * d_cos;
                }
                assert_relative_eq!(integral, 1.0, max_relative = 2e-3);
            }
        }
    }

    #[test]
    fn disc_and_lobe_spread_alike() {
        // The matching of `disc_radius_for_exponent`: equal mean sin^2 to within 10 % for
        // narrow lobes, where the first-order argument holds.
        let center = Vec3::new(0.2, 0.9, -0.1).normalize();
        for exponent in [100.0f32, 1e3, 1e4] {
            let n = 20_000;
            let mean_sin2 = |method: FuzzMethod| {
                uniforms(n)
                    .map(|u| {
                        let c = method.sample(center, exponent, u).dot(center);
                        f64::from(1.0 - c * c)
                    })
                    .sum::<f64>()
                    / n as f64
            };
            let lobe = mean_sin2(FuzzMethod::Lobe);
            let disc = mean_sin2(FuzzMethod::Disc);
            assert_relative_eq!(lobe, 2.0 / f64::from(exponent + 3.0), max_relative = 0.05);
            assert_relative_eq!(disc, lobe, max_relative = 0.1);
        }
    }
}
