//! The latitude–longitude parametrisation of directions that an environment map is stored in.
//!
//! Both the map's lookup ([`EnvironmentMap`](super::EnvironmentMap)) and its sampling density
//! ([`EnvironmentSampling`](super::EnvironmentSampling)) go between directions and map
//! coordinates; the conversion sits below both so that neither has to reach into the other.
//! The conventions are Mitsuba 3's: in the map's frame `+y` is up, `u = 0` looks along `-z`
//! and `u` grows towards `+x`.

use glam::{Vec2, Vec3};
use std::f32::consts::{PI, TAU};

/// Map coordinates of direction `d` in the map's frame: `u = atan2(d.x, -d.z) / 2π` (in
/// `(-1/2, 1/2]`; the lookup wraps it) and `v = acos(d.y) / π`. `d` need not be unit.
pub fn direction_to_uv(d: Vec3) -> Vec2 {
    let cos_theta = d.y / d.length();
    Vec2::new(
        d.x.atan2(-d.z) / TAU,
        cos_theta.clamp(-1.0, 1.0).acos() / PI,
    )
}

/// The unit direction in the map's frame of azimuth `u` (as [`direction_to_uv`] gives it)
/// and height `cos_theta` (the direction's `y`).
pub fn direction_of(u: f32, cos_theta: f32) -> Vec3 {
    let cos_theta = cos_theta.clamp(-1.0, 1.0);
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let (sin_phi, cos_phi) = (TAU * u).sin_cos();
    Vec3::new(sin_phi * sin_theta, cos_theta, -cos_phi * sin_theta)
}
