//! A scene's area lights, found among its shapes.
//!
//! A light's geometry is not stored twice. The scene marks which shapes glow (a
//! [`Surface`](common::scene::Surface)'s emitter), and a light's shape is read from the
//! scene's own geometry, so the surface the camera sees and the surface the shadow rays aim
//! at cannot disagree.

use crate::light::{AreaLight, LightShape};
use crate::light_options::LightOptions;
use crate::lighting::AreaLighting;
use common::geometry::Shape;
use common::scene::Scene;

/// The area lights of a scene, and which shape each one is.
#[derive(Clone, Debug, Default)]
pub struct AreaLights {
    /// The area lights, in the order of their shapes.
    pub lights: Vec<AreaLight>,
    /// For every shape of the scene, the index of the light it is, if any.
    pub light_of_shape: Vec<Option<u32>>,
    /// For every light, the number of its shape: where its emitter (and a texture on its
    /// radiance, which chapter 08 reads) is found in the scene.
    pub shape_of_light: Vec<u32>,
}

/// The light shape of a world shape: every shape of `common` has a surface to sample.
pub fn light_shape(shape: &Shape) -> LightShape {
    match *shape {
        Shape::Sphere(s) => LightShape::Sphere(s),
        Shape::Triangle(t) => LightShape::Triangle(t),
        Shape::Parallelogram(q) => LightShape::Parallelogram(q),
        Shape::Disc(d) => LightShape::Disc(d),
    }
}

impl AreaLights {
    /// The lights of `scene`: every still shape that glows. (A glowing shape that moves is
    /// refused by every chapter's capability check before it gets here.)
    pub fn of(scene: &Scene) -> Self {
        let mut light_of_shape = vec![None; scene.shape_count()];
        let mut lights = Vec::new();
        let mut shape_of_light = Vec::new();
        for (index, shape) in scene.geometry.shapes().iter().enumerate() {
            if let Some(emitter) = scene.surface(index as u32).emitter {
                light_of_shape[index] = Some(lights.len() as u32);
                shape_of_light.push(index as u32);
                lights.push(AreaLight::new(light_shape(shape), emitter.radiance));
            }
        }
        Self {
            lights,
            light_of_shape,
            shape_of_light,
        }
    }

    /// The lights for chapter 06's tracer, sampled as `options` say.
    pub fn lighting(&self, options: LightOptions) -> AreaLighting<'_> {
        AreaLighting {
            lights: &self.lights,
            light_of_shape: &self.light_of_shape,
            options,
        }
    }
}
