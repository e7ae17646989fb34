//! A scene with area lights: chapter 06's scene, and which of its shapes glow.
//!
//! A light's geometry is not stored twice. The scene names a shape of the world and its
//! radiance, and the light's shape is read from the world's own geometry, so the surface the
//! camera sees and the surface the shadow rays aim at cannot disagree.

use crate::light::{AreaLight, LightShape};
use crate::light_options::LightOptions;
use crate::lighting::AreaLighting;
use ch06_fuzzy_reflections::FuzzyScene;
use common::geometry::Shape;
use glam::Vec3;

/// Chapter 06's scene with area lights.
pub struct SoftShadowScene {
    /// Shapes (the lights' among them), materials, point lights, camera, shutter.
    pub scene: FuzzyScene,
    /// The area lights, in the order the scene named them.
    pub lights: Vec<AreaLight>,
    /// For every shape of the world, the index of the light it is, if any.
    pub light_of_shape: Vec<Option<u32>>,
}

/// The light shape of a world shape: every shape of `common` has a surface to sample.
pub fn light_shape(shape: &Shape) -> LightShape {
    match *shape {
        Shape::Sphere(s) => LightShape::Sphere(s),
        Shape::Triangle(t) => LightShape::Triangle(t),
        Shape::Quad(q) => LightShape::Parallelogram(q),
        Shape::Disc(d) => LightShape::Disc(d),
    }
}

impl SoftShadowScene {
    /// `scene` in which the still shapes `emitters` (index into the world's shapes, radiance)
    /// glow, or an error naming a shape that does not exist, moves, glows twice, or has a
    /// radiance that is negative or not finite.
    pub fn new(scene: FuzzyScene, emitters: &[(usize, Vec3)]) -> Result<Self, String> {
        let still = scene.world.scene.geometry.shapes();
        let shapes = scene.materials.len();
        let mut light_of_shape = vec![None; shapes];
        let mut lights = Vec::with_capacity(emitters.len());
        for &(index, radiance) in emitters {
            if !(radiance.is_finite() && radiance.min_element() >= 0.0) {
                return Err(format!(
                    "shape {index}: an area light's radiance must be finite and not negative, found {radiance}"
                ));
            }
            let Some(shape) = still.get(index) else {
                return Err(if index < shapes {
                    format!("shape {index} moves: an area light must stand still")
                } else {
                    format!("shape {index} does not exist: the scene has {shapes} shapes")
                });
            };
            if light_of_shape[index].is_some() {
                return Err(format!("shape {index} is named as a light twice"));
            }
            light_of_shape[index] = Some(lights.len() as u32);
            lights.push(AreaLight::new(light_shape(shape), radiance));
        }
        Ok(Self {
            scene,
            lights,
            light_of_shape,
        })
    }

    /// A scene without area lights: chapter 06's.
    pub fn without_lights(scene: FuzzyScene) -> Self {
        Self::new(scene, &[]).expect("no lights, nothing to refuse")
    }

    /// The scene's lights for the tracer, sampled as `options` say.
    pub fn lighting(&self, options: LightOptions) -> AreaLighting<'_> {
        AreaLighting {
            lights: &self.lights,
            light_of_shape: &self.light_of_shape,
            options,
        }
    }

    /// The same scene with every lobe's exponent set to `exponent` (chapter 06's
    /// `--exponent`); the lights do not change.
    pub fn with_exponent(self, exponent: f32) -> Self {
        Self {
            scene: self.scene.with_exponent(exponent),
            ..self
        }
    }
}
