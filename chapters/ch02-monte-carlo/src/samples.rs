//! `samples`: warped points as CSV, so that anyone can test a warp with their own tools.

use crate::warps::{Warp, WarpPoint};
use common::sampler::unit_f32;
use glam::Vec2;
use rand::{Rng, SeedableRng};
use rand_pcg::Pcg32;
use std::fmt::Write;

/// `n` points of `warp` from uniform numbers seeded by `seed`, one CSV row each: `x,y,pdf` for
/// points in the plane, `x,y,z,pdf` for directions (+z is the pole). `pdf` is the density the
/// warp claims at the point.
pub fn samples_csv(warp: &Warp, n: usize, seed: u64) -> String {
    let mut rng = Pcg32::seed_from_u64(seed);
    let mut csv = String::with_capacity(n * 40);
    let directions = matches!(warp.sample(Vec2::ZERO), WarpPoint::Direction(_));
    csv.push_str(if directions {
        "x,y,z,pdf\n"
    } else {
        "x,y,pdf\n"
    });
    for _ in 0..n {
        let u = Vec2::new(unit_f32(rng.next_u32()), unit_f32(rng.next_u32()));
        let point = warp.sample(u);
        let pdf = warp.pdf(point);
        // Writing to a String cannot fail.
        let _ = match point {
            WarpPoint::Plane(p) => writeln!(csv, "{},{},{pdf}", p.x, p.y),
            WarpPoint::Direction(d) => writeln!(csv, "{},{},{},{pdf}", d.x, d.y, d.z),
        };
    }
    csv
}
