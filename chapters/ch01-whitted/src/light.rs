//! Point lights: Whitted's only light sources, and the reason his shadows are hard.

use glam::Vec3;

/// A point that radiates `intensity` (watts per steradian, per colour channel) equally in
/// every direction. A surface at distance `r` facing it at angle `theta` receives the
/// irradiance `intensity * cos(theta) / r^2`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// Where the light is.
    pub position: Vec3,
    /// Radiant intensity in W/sr.
    pub intensity: Vec3,
}
