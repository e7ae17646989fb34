//! The light that arrives from outside the scene, as one light to pick: Mitsuba's `constant`
//! emitter (the same radiance from everywhere) plus its `envmap` (an image around the scene).
//!
//! A light sample of the environment goes where its light is: for the constant part
//! uniformly over the sphere, for the map by the map's own density
//! ([`EnvironmentSampling`](common::scene::EnvironmentSampling): bright cells more often).
//! With both, one of the two is chosen by its share of the power, with the same two numbers
//! (the first one, stretched back to `[0, 1)`), and the density is the mixture's: either
//! could have drawn any direction. With only the constant part every number and density is
//! what it was before maps existed, so those images stay bit for bit the same.

use ch02_monte_carlo::warps::{sample_uniform_sphere, uniform_sphere_pdf};
use common::scene::{EnvironmentMap, Scene, luminance};
use glam::{Vec2, Vec3};

/// The constant environment and the environment map of a scene, borrowed.
#[derive(Clone, Copy, Debug)]
pub struct EnvironmentLight<'a> {
    /// The radiance from every direction (black: none).
    constant: Vec3,
    /// The image, if it gives any light.
    map: Option<&'a EnvironmentMap>,
    /// The chance that a light sample is drawn for the constant part (1 without a map).
    constant_share: f32,
}

impl<'a> EnvironmentLight<'a> {
    /// The environment of `scene`. A map that is black everywhere offers nothing to sample and
    /// is left out.
    pub fn of(scene: &'a Scene) -> Self {
        let map = scene
            .environment_map
            .as_ref()
            .filter(|map| map.sampling().integral() > 0.0);
        let constant = scene.environment;
        let constant_share = match map {
            None => 1.0,
            Some(map) => {
                let constant_power = f64::from(luminance(constant)) * 4.0 * std::f64::consts::PI;
                (constant_power / (constant_power + map.sampling().integral())) as f32
            }
        };
        Self {
            constant,
            map,
            constant_share,
        }
    }

    /// Whether any light comes from outside the scene.
    pub fn is_black(&self) -> bool {
        self.constant == Vec3::ZERO && self.map.is_none()
    }

    /// The radiance arriving along `direction` (towards the sky) from outside the scene.
    pub fn radiance(&self, direction: Vec3) -> Vec3 {
        match self.map {
            None => self.constant,
            Some(map) => self.constant + map.radiance(direction),
        }
    }

    /// The density per unit solid angle with which [`sample`](Self::sample) draws
    /// `direction`.
    pub fn pdf(&self, direction: Vec3) -> f32 {
        match self.map {
            None => uniform_sphere_pdf(),
            Some(map) => {
                let share = self.constant_share;
                let from_map = map.sampling().pdf(map.to_local(direction));
                share * uniform_sphere_pdf() + (1.0 - share) * from_map
            }
        }
    }

    /// A direction towards the sky drawn with the numbers `u` in `[0, 1)²`, with its density
    /// per unit solid angle; `None` when there is no light to draw.
    pub fn sample(&self, u: Vec2) -> Option<(Vec3, f32)> {
        let Some(map) = self.map else {
            return (self.constant != Vec3::ZERO)
                .then(|| (sample_uniform_sphere(u), uniform_sphere_pdf()));
        };
        let share = self.constant_share;
        let direction = if u.x < share {
            sample_uniform_sphere(Vec2::new(u.x / share, u.y))
        } else {
            let stretched = ((u.x - share) / (1.0 - share)).min(1.0 - f32::EPSILON / 2.0);
            let (local, _) = map.sampling().sample(Vec2::new(stretched, u.y))?;
            map.to_world(local)
        };
        let pdf = self.pdf(direction);
        (pdf > 0.0 && pdf.is_finite()).then_some((direction, pdf))
    }
}
