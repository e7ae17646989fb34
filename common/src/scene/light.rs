//! Lights as data: point lights (chapter 01), the area emitters of glowing shapes (chapter 07)
//! and directional lights (chapter 08). The environment is a colour on the scene itself.

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

/// A light infinitely far away that shines one way, as the sun does (Mitsuba 3's
/// `directional`): every point it reaches receives the irradiance `irradiance` on a surface
/// that faces it, from the one direction `-direction`, wherever the point is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectionalLight {
    /// The unit direction the light travels in.
    pub direction: Vec3,
    /// Irradiance on a surface facing the light, per colour channel (watts per square metre).
    pub irradiance: Vec3,
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
    /// How often a light sample picks this emitter, relative to the others (Mitsuba 3's
    /// `sampling_weight`, 1 unless a scene file says otherwise). It changes the noise, never
    /// the mean.
    pub sampling_weight: f32,
}

impl AreaEmitter {
    /// The same radiance `radiance` from every point, with the usual sampling weight 1.
    pub fn uniform(radiance: Vec3) -> Self {
        Self {
            radiance,
            texture: None,
            sampling_weight: 1.0,
        }
    }
}
