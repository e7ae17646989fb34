//! Chapter 02's warp explorer: a warp's points, its histogram against its density and the
//! chi-square verdict, all from the chapter's own [`Warp`] and [`chi2_tables`].
//!
//! The points are the ones the test counts: the same generator, seed and order. Both the
//! points and the bins are given in the test's grid coordinates scaled to the unit square
//! (`x` right, `y` up): the plane's bounding rectangle, or `(φ / 2π, (cos θ + 1) / 2)` for
//! directions, where equal areas are equal solid angles.

use ch02_monte_carlo::chi2::chi2_tables;
use ch02_monte_carlo::warps::{Domain, Warp, WarpPoint};
use common::sampler::unit_f32;
use glam::{Vec2, Vec3};
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;

use crate::{buffers, outcome};

/// The warp at `index` of [`Warp::NAMES`], with `exponent` for the lobe; `None` for an index
/// out of range or an exponent the lobe refuses.
fn warp(index: u32, exponent: f32) -> Option<Warp> {
    let name = Warp::NAMES.get(index as usize)?;
    let exponent = (*name == "cos-lobe").then_some(exponent);
    Warp::from_name(name, exponent).ok()
}

/// `point` in the unit square of the test's grid over `domain`.
fn on_grid(domain: Domain, point: WarpPoint) -> Vec2 {
    match (domain, point) {
        (Domain::Plane { min, max }, WarpPoint::Plane(p)) => (p - min) / (max - min),
        (_, WarpPoint::Direction(d)) => unit_square_of_direction(d),
        (Domain::Sphere, WarpPoint::Plane(p)) => p,
    }
}

/// `(φ / 2π, (cos θ + 1) / 2)` of a unit direction.
fn unit_square_of_direction(d: Vec3) -> Vec2 {
    let phi = d.y.atan2(d.x).rem_euclid(std::f32::consts::TAU);
    Vec2::new(
        phi / std::f32::consts::TAU,
        (d.z.clamp(-1.0, 1.0) + 1.0) / 2.0,
    )
}

/// How many warps there are.
#[unsafe(no_mangle)]
pub extern "C" fn warp_count() -> u32 {
    Warp::NAMES.len() as u32
}

/// Puts the name of warp `index` in the text buffer; gives its length (0 out of range).
#[unsafe(no_mangle)]
pub extern "C" fn warp_name(index: u32) -> u32 {
    let name = Warp::NAMES.get(index as usize).copied().unwrap_or("");
    buffers::set_text(name)
}

/// Whether warp `index` gives directions (drawn over `(φ, cos θ)`) rather than points.
#[unsafe(no_mangle)]
pub extern "C" fn warp_gives_directions(index: u32) -> u32 {
    warp(index, 1.0).is_some_and(|w| matches!(w.domain(), Domain::Sphere)) as u32
}

/// Puts the first `count` points of warp `index` (seeded by `seed`) in the number buffer as
/// `x, y` pairs on the unit square; gives the number of points, or `u32::MAX` if the warp does
/// not exist or a panic stopped it (its message is then the text).
#[unsafe(no_mangle)]
pub extern "C" fn warp_points(index: u32, exponent: f32, count: u32, seed: u32) -> u32 {
    outcome::run(|| {
        let Some(warp) = warp(index, exponent) else {
            buffers::set_text("no such warp, or an exponent the lobe refuses");
            return u32::MAX;
        };
        let domain = warp.domain();
        let mut rng = Pcg32::seed_from_u64(u64::from(seed));
        let mut numbers = Vec::with_capacity(2 * count as usize);
        for _ in 0..count {
            let u = Vec2::new(unit_f32(rng.next_u32()), unit_f32(rng.next_u32()));
            let p = on_grid(domain, warp.sample(u));
            numbers.extend([f64::from(p.x), f64::from(p.y)]);
        }
        buffers::set_numbers(numbers);
        count
    })
}

/// Runs the chi-square test of warp `index` with `count` samples on `columns x rows` bins and
/// puts in the number buffer: the statistic, the degrees of freedom, the p-value, the
/// impossible samples, then the observed and the expected count of every bin, row by row from
/// the bottom. Gives the number of values, or `u32::MAX` as [`warp_points`] does.
#[unsafe(no_mangle)]
pub extern "C" fn warp_chi2(
    index: u32,
    exponent: f32,
    count: u32,
    seed: u32,
    columns: u32,
    rows: u32,
) -> u32 {
    outcome::run(|| {
        let Some(warp) = warp(index, exponent) else {
            buffers::set_text("no such warp, or an exponent the lobe refuses");
            return u32::MAX;
        };
        let tables = chi2_tables(
            warp.domain(),
            count as usize,
            u64::from(seed),
            (columns.max(1) as usize, rows.max(1) as usize),
            |u| warp.sample(u),
            |point| warp.pdf(point),
        );
        let result = tables.result;
        let mut numbers = vec![
            result.statistic,
            result.dof as f64,
            result.p_value,
            result.impossible_samples as f64,
        ];
        numbers.extend(tables.observed.iter().map(|&o| o as f64));
        numbers.extend(&tables.expected);
        buffers::set_numbers(numbers)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn index_of(name: &str) -> u32 {
        Warp::NAMES.iter().position(|n| *n == name).unwrap() as u32
    }

    #[test]
    fn the_naive_disc_fails_and_the_polar_disc_passes() {
        let p_value = |name| {
            let values = warp_chi2(index_of(name), 1.0, 50_000, 7, 16, 16);
            assert_eq!(values as usize, 4 + 2 * 256);
            buffers::numbers()[2]
        };
        assert!(p_value("disc-naive") < 1e-6);
        assert!(p_value("disc-polar") > 1e-3);
    }

    #[test]
    fn points_land_in_the_unit_square_and_names_come_back() {
        for index in 0..warp_count() {
            assert_eq!(warp_points(index, 4.0, 100, 1), 100);
            assert!(buffers::numbers().iter().all(|&x| (0.0..=1.0).contains(&x)));
            let length = warp_name(index);
            assert_eq!(buffers::text(), Warp::NAMES[index as usize]);
            assert_eq!(length as usize, buffers::text().len());
        }
        assert_eq!(warp_points(99, 1.0, 10, 1), u32::MAX);
        assert_eq!(warp_points(index_of("cos-lobe"), -1.0, 10, 1), u32::MAX);
    }

    #[test]
    fn the_observed_counts_are_the_points_drawn() {
        let index = index_of("triangle");
        warp_chi2(index, 1.0, 1000, 3, 4, 4);
        let observed: f64 = buffers::numbers()[4..4 + 16].iter().sum();
        assert_eq!(observed, 1000.0);
    }
}
