//! The ray: a half-line with a shutter time.

use glam::Vec3;

/// A ray `origin + t * dir` for `t` in `(0, t_max)`, travelling at shutter time `time`.
///
/// `t` is always the ray parameter and `time` always the shutter time: motion blur (chapter 05)
/// gives every ray of a path the same `time`, and keeping the two names apart keeps that easy.
/// `dir` need not be unit length, but every ray the chapters build has a unit `dir`, so `t` is a
/// distance.
///
/// A ray that goes nowhere (an origin or a direction with a NaN or infinite component, or a
/// zero direction: what a wrong answer computes, `normalize` of a zero vector, say) hits
/// nothing and is occluded by nothing, and so is a ray whose `t_max` is NaN: every query
/// answers it, so that a chapter's check can say what is wrong with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts.
    pub origin: Vec3,
    /// Where it goes.
    pub dir: Vec3,
    /// Hits at `t >= t_max` are ignored: a shadow ray stops just before its light.
    pub t_max: f32,
    /// Shutter time at which the ray travels (0 for a static scene).
    pub time: f32,
}

impl Ray {
    /// A ray with no far limit, at shutter time 0.
    pub fn new(origin: Vec3, dir: Vec3) -> Self {
        Self {
            origin,
            dir,
            t_max: f32::INFINITY,
            time: 0.0,
        }
    }

    /// The same ray at shutter time `time`.
    #[inline]
    pub fn with_time(mut self, time: f32) -> Self {
        self.time = time;
        self
    }

    /// The point at parameter `t`.
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.dir
    }
}
