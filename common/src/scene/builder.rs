//! Building a scene in code: the chapters' built-in scenes, and the tests'.

use super::{
    AnimatedShape, AreaEmitter, Bitmap, BitmapId, Camera, DirectionalLight, EnvironmentMap,
    FilmSettings, Integrator, Material, Origins, PointLight, SamplerSettings, Scene, Surface,
};
use crate::geometry::{Geometry, Shape, TriangleMesh};
use glam::{Mat4, Vec3};

/// Collects shapes with their surfaces, and the lights; [`build`](Self::build) makes the BVH.
#[derive(Default)]
pub struct SceneBuilder {
    shapes: Vec<Shape>,
    surfaces: Vec<Surface>,
    moving: Vec<(AnimatedShape, Surface)>,
    point_lights: Vec<PointLight>,
    directional_lights: Vec<DirectionalLight>,
    environment: Vec3,
    environment_map: Option<EnvironmentMap>,
    bitmaps: Vec<Bitmap>,
}

impl SceneBuilder {
    /// An empty scene without an environment.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a still shape, in world space, with its surface.
    pub fn surface(mut self, shape: Shape, surface: Surface) -> Self {
        self.shapes.push(shape);
        self.surfaces.push(surface);
        self
    }

    /// Adds a still shape made of `material`.
    pub fn shape(self, shape: Shape, material: Material) -> Self {
        self.surface(shape, plain(material))
    }

    /// Adds a still shape made of `material` that glows with `radiance` on its front side:
    /// an area light (chapter 07).
    pub fn area_light(self, shape: Shape, material: Material, radiance: Vec3) -> Self {
        let surface = Surface {
            emitter: Some(AreaEmitter::uniform(radiance)),
            ..plain(material)
        };
        self.surface(shape, surface)
    }

    /// Adds every triangle of a mesh, all made of `material`.
    pub fn mesh(mut self, mesh: &TriangleMesh, material: Material) -> Self {
        for triangle in mesh.triangles() {
            self = self.shape(Shape::Triangle(triangle), material.clone());
        }
        self
    }

    /// Adds a moving shape, given in its own space, with its surface.
    pub fn moving_surface(mut self, shape: AnimatedShape, surface: Surface) -> Self {
        self.moving.push((shape, surface));
        self
    }

    /// Adds a shape made of `material` that moves: `keyframes` are `(time, object to world)`
    /// pairs (chapter 05).
    pub fn moving(self, shape: Shape, keyframes: Vec<(f32, Mat4)>, material: Material) -> Self {
        self.moving_surface(AnimatedShape { shape, keyframes }, plain(material))
    }

    /// Adds a point light.
    pub fn light(mut self, light: PointLight) -> Self {
        self.point_lights.push(light);
        self
    }

    /// Adds a light infinitely far away that shines one way.
    pub fn directional_light(mut self, light: DirectionalLight) -> Self {
        self.directional_lights.push(light);
        self
    }

    /// Sets the radiance seen where rays leave the scene.
    pub fn environment(mut self, radiance: Vec3) -> Self {
        self.environment = radiance;
        self
    }

    /// Sets the image of light around the scene (chapter 08), added to the environment.
    pub fn environment_map(mut self, map: EnvironmentMap) -> Self {
        self.environment_map = Some(map);
        self
    }

    /// Adds an image for [`Texture::Bitmap`](super::Texture) to read, returning its number.
    pub fn bitmap(&mut self, bitmap: Bitmap) -> BitmapId {
        self.bitmaps.push(bitmap);
        BitmapId(self.bitmaps.len() as u32 - 1)
    }

    /// Builds the BVH and the scene, seen by `camera` on `film`, with Mitsuba's `path`
    /// integrator limited to `max_depth` segments and its default sampler.
    pub fn build(self, camera: Camera, film: FilmSettings, max_depth: u32) -> Scene {
        let (moving, moving_surfaces): (Vec<AnimatedShape>, Vec<Surface>) =
            self.moving.into_iter().unzip();
        let mut surfaces = self.surfaces;
        surfaces.extend(moving_surfaces);
        Scene {
            geometry: Geometry::new(self.shapes),
            moving,
            surfaces,
            bitmaps: self.bitmaps,
            point_lights: self.point_lights,
            directional_lights: self.directional_lights,
            environment: self.environment,
            environment_map: self.environment_map,
            camera,
            film,
            sampler: SamplerSettings::default(),
            integrator: Integrator::Path { rr_depth: 5 },
            max_depth,
            hide_emitters: false,
            origins: Origins::default(),
            emission_grids: Default::default(),
        }
    }
}

/// A surface of `material` that does not glow, written nowhere.
fn plain(material: Material) -> Surface {
    Surface {
        material,
        emitter: None,
        origin: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Sphere;
    use crate::scene::CameraFrame;

    #[test]
    fn moving_shapes_are_numbered_after_the_still_ones() {
        let frame = CameraFrame::look_at(Vec3::Z, Vec3::ZERO, Vec3::Y).unwrap();
        let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0));
        let keyframes = vec![
            (0.0, Mat4::IDENTITY),
            (1.0, Mat4::from_translation(Vec3::X)),
        ];
        let scene = SceneBuilder::new()
            .moving(sphere, keyframes, Material::mirror())
            .shape(sphere, Material::glass(1.5))
            .area_light(sphere, Material::diffuse(Vec3::ONE), Vec3::splat(2.0))
            .build(Camera::pinhole(frame, 40.0), FilmSettings::new(8, 8), 4);
        assert_eq!(scene.geometry.shapes().len(), 2);
        assert_eq!(scene.shape_count(), 3);
        assert_eq!(scene.surface(0).material, Material::glass(1.5));
        assert_eq!(
            scene.surface(1).emitter,
            Some(AreaEmitter::uniform(Vec3::splat(2.0)))
        );
        assert_eq!(scene.surface(2).material, Material::mirror());
        assert_eq!(scene.moving.len(), 1);
    }

    #[test]
    fn the_materials_lent_without_reading_are_those_read_at_lends() {
        // `material_at` lends five kinds of material without asking `read_at`: each must be
        // one that `read_at` would lend as it is, or a texture added to it later is skipped.
        let frame = CameraFrame::look_at(Vec3::Z, Vec3::ZERO, Vec3::Y).unwrap();
        let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0));
        let plain = [
            Material::diffuse(Vec3::ONE),
            Material::mirror(),
            Material::glass(1.5),
            Material::ThinDielectric {
                int_ior: 1.5,
                ext_ior: 1.0,
            },
            Material::glossy(Vec3::ONE, 10.0),
        ];
        let mut builder = SceneBuilder::new();
        for material in &plain {
            builder = builder.shape(sphere, material.clone());
        }
        let scene = builder.build(Camera::pinhole(frame, 40.0), FilmSettings::new(8, 8), 4);
        for (shape, material) in plain.iter().enumerate() {
            let read = scene.read_at(material, shape as u32, glam::Vec2::splat(0.5));
            assert!(
                matches!(read, std::borrow::Cow::Borrowed(_)),
                "read_at reads something of {material:?}: material_at must not lend it unread"
            );
            assert_eq!(
                scene
                    .material_at(shape as u32, glam::Vec2::splat(0.5))
                    .as_ref(),
                material
            );
        }
    }
}
