//! Lights as data: point lights (chapter 01) and the area emitters of glowing shapes
//! (chapter 07). The environment is a colour on the scene itself.

use super::Texture;
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

/// What a glowing shape emits (Mitsuba 3's `area` emitter): the radiance `radiance` from
/// every point of its front side, the side its normal points to, times its texture's colour
/// at the point if it has one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaEmitter {
    /// Emitted radiance, per colour channel.
    pub radiance: Vec3,
    /// A texture that multiplies `radiance` point by point, read at the surface parameters
    /// `uv` of the point ([`Scene::emitted_at`](super::Scene::emitted_at)); a scene file's
    /// `<texture name="radiance">`.
    pub texture: Option<Texture>,
}

impl AreaEmitter {
    /// The same radiance `radiance` from every point.
    pub fn uniform(radiance: Vec3) -> Self {
        Self {
            radiance,
            texture: None,
        }
    }
}
