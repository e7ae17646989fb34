//! A scene for the fuzzy tracer: chapter 05's scene (geometry, moving shapes, lights, camera,
//! shutter) with this chapter's materials in place of chapter 01's.

use crate::material::Material;
use ch05_motion_blur::MotionScene;

/// Everything the fuzzy tracer needs to know about the world.
pub struct FuzzyScene {
    /// Shapes (still and moving), point lights, background, camera, shutter and depth limit.
    /// Its chapter 01 materials are not read by this chapter's tracer: see `materials`.
    pub world: MotionScene,
    /// One material per shape, indexed like the world's shapes (`SurfaceHit::shape`).
    pub materials: Vec<Material>,
}

impl FuzzyScene {
    /// `world` with `materials`, one per shape, or an error naming the mismatch.
    pub fn new(world: MotionScene, materials: Vec<Material>) -> Result<Self, String> {
        let shapes = world.scene.materials.len();
        if materials.len() != shapes {
            return Err(format!(
                "{} materials for {shapes} shapes: every shape needs exactly one",
                materials.len()
            ));
        }
        Ok(Self { world, materials })
    }

    /// `world` with its own chapter 01 materials: Whitted's scene, rendered by this chapter.
    pub fn smooth(world: MotionScene) -> Self {
        let materials = world
            .scene
            .materials
            .iter()
            .map(|&m| Material::from(m))
            .collect();
        Self { world, materials }
    }

    /// Whether any surface scatters with a lobe.
    pub fn has_fuzzy_materials(&self) -> bool {
        self.materials.iter().any(Material::is_fuzzy)
    }

    /// The same scene with every lobe's exponent set to `exponent`.
    pub fn with_exponent(mut self, exponent: f32) -> Self {
        for material in &mut self.materials {
            *material = material.with_exponent(exponent);
        }
        self
    }
}
