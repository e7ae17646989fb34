//! A Whitted scene: shapes with materials, point lights, a background and a camera.

use crate::camera::PinholeCamera;
use crate::light::PointLight;
use crate::material::Material;
use common::Ray;
use common::geometry::{Geometry, Shape, SurfaceHit, TriangleMesh};
use glam::Vec3;

/// Everything the tracer needs to know about the world.
pub struct Scene {
    /// The camera, with the image size the scene was made for.
    pub camera: PinholeCamera,
    /// The shapes and their BVH; shape `i` has material `materials[i]`.
    pub geometry: Geometry,
    /// One material per shape.
    pub materials: Vec<Material>,
    /// The point lights.
    pub lights: Vec<PointLight>,
    /// Radiance of every ray that leaves the scene (Mitsuba's `constant` emitter); black
    /// for a closed room.
    pub background: Vec3,
    /// The longest path, counted in segments *including* the camera ray, as Mitsuba's
    /// `max_depth`: 1 sees only the background, 2 adds direct light (the shadow ray is the
    /// second segment), each further step one more mirror or glass bounce.
    pub max_depth: u32,
}

// ANCHOR: world
/// What the tracer asks of the world: the nearest surface on a ray, and whether a shadow ray
/// is blocked. Materials, lights and the background come from [`World::scene`].
///
/// Chapter 01's [`Scene`] answers from its static geometry. A later chapter adds what it
/// needs behind the same two questions (chapter 05: objects that move with the ray's
/// `time`) and reuses the tracer as it is. A hit's `shape` indexes the scene's `materials`.
pub trait World: Sync {
    /// The materials, lights, background and depth limit.
    fn scene(&self) -> &Scene;
    /// The nearest hit with `0 < t < ray.t_max`.
    fn intersect(&self, ray: &Ray) -> Option<SurfaceHit>;
    /// Whether anything lies on the ray before `ray.t_max`.
    fn occluded(&self, ray: &Ray) -> bool;
}
// ANCHOR_END: world

impl World for Scene {
    fn scene(&self) -> &Scene {
        self
    }

    #[inline]
    fn intersect(&self, ray: &Ray) -> Option<SurfaceHit> {
        self.geometry.intersect(ray)
    }

    #[inline]
    fn occluded(&self, ray: &Ray) -> bool {
        self.geometry.occluded(ray)
    }
}

/// Collects shapes and materials in matching order.
#[derive(Default)]
pub struct SceneBuilder {
    shapes: Vec<Shape>,
    materials: Vec<Material>,
    lights: Vec<PointLight>,
    background: Vec3,
}

impl SceneBuilder {
    /// An empty scene with a black background.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a shape made of `material`.
    pub fn shape(mut self, shape: Shape, material: Material) -> Self {
        self.shapes.push(shape);
        self.materials.push(material);
        self
    }

    /// Adds every triangle of a mesh, all made of `material`.
    pub fn mesh(mut self, mesh: &TriangleMesh, material: Material) -> Self {
        for triangle in mesh.triangles() {
            self = self.shape(Shape::Triangle(triangle), material);
        }
        self
    }

    /// Adds a point light.
    pub fn light(mut self, light: PointLight) -> Self {
        self.lights.push(light);
        self
    }

    /// Sets the radiance seen where rays leave the scene.
    pub fn background(mut self, radiance: Vec3) -> Self {
        self.background = radiance;
        self
    }

    /// Builds the BVH and the scene.
    pub fn build(self, camera: PinholeCamera, max_depth: u32) -> Scene {
        Scene {
            camera,
            geometry: Geometry::new(self.shapes),
            materials: self.materials,
            lights: self.lights,
            background: self.background,
            max_depth,
        }
    }
}
