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
    /// Every surface added, in the order added.
    surfaces: Vec<Surface>,
    /// For each still shape, its surface's index in `surfaces`.
    surface_of_shape: Vec<u32>,
    /// The moving shapes, each with its surface's index in `surfaces`.
    moving: Vec<(AnimatedShape, u32)>,
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
    pub fn surface(self, shape: Shape, surface: Surface) -> Self {
        self.shared_surface(std::iter::once(shape), surface)
    }

    /// Adds still shapes, in world space, that share one surface: the pieces of one shape of a
    /// scene file, such as a mesh's triangles.
    pub fn shared_surface(
        mut self,
        shapes: impl IntoIterator<Item = Shape>,
        surface: Surface,
    ) -> Self {
        let index = self.add(surface);
        for shape in shapes {
            self.shapes.push(shape);
            self.surface_of_shape.push(index);
        }
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
    pub fn mesh(self, mesh: &TriangleMesh, material: Material) -> Self {
        self.shared_surface(mesh.triangles().map(Shape::Triangle), plain(material))
    }

    /// Adds a moving shape, given in its own space, with its surface.
    pub fn moving_surface(self, shape: AnimatedShape, surface: Surface) -> Self {
        self.shared_moving_surface(std::iter::once(shape), surface)
    }

    /// Adds moving shapes, each given in its own space, that share one surface.
    pub fn shared_moving_surface(
        mut self,
        shapes: impl IntoIterator<Item = AnimatedShape>,
        surface: Surface,
    ) -> Self {
        let index = self.add(surface);
        self.moving
            .extend(shapes.into_iter().map(|shape| (shape, index)));
        self
    }

    /// Keeps `surface`; returns its index.
    fn add(&mut self, surface: Surface) -> u32 {
        self.surfaces.push(surface);
        u32::try_from(self.surfaces.len() - 1).expect("at most u32::MAX surfaces")
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
        let (moving, moving_surfaces): (Vec<AnimatedShape>, Vec<u32>) =
            self.moving.into_iter().unzip();
        let (surfaces, surface_of_shape) = in_order_of_use(
            self.surfaces,
            self.surface_of_shape.into_iter().chain(moving_surfaces),
        );
        let mut scene = Scene {
            geometry: Geometry::new(self.shapes),
            moving,
            surfaces,
            surface_of_shape,
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
            emission_grids: Vec::new(),
        };
        scene.prepare_emission_grids();
        scene
    }
}

/// The surfaces renumbered in the order of the shapes that first use them, and each shape's
/// new number, from each shape's old one (still shapes first, then moving ones). Without shared
/// surfaces, surface `i` is then shape `i`'s, whatever order the shapes were added in; a surface
/// no shape uses is dropped.
fn in_order_of_use(
    surfaces: Vec<Surface>,
    surface_of_shape: impl Iterator<Item = u32>,
) -> (Vec<Surface>, Vec<u32>) {
    let mut added: Vec<Option<Surface>> = surfaces.into_iter().map(Some).collect();
    let mut new_number = vec![None; added.len()];
    let mut in_order = Vec::new();
    let numbers = surface_of_shape
        .map(|old| {
            let old = old as usize;
            *new_number[old].get_or_insert_with(|| {
                in_order.push(added[old].take().expect("each surface is moved once"));
                (in_order.len() - 1) as u32
            })
        })
        .collect();
    (in_order, numbers)
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
    fn a_mesh_shares_one_surface_and_surfaces_follow_the_shapes() {
        let frame = CameraFrame::look_at(Vec3::Z, Vec3::ZERO, Vec3::Y).unwrap();
        let sphere = Shape::Sphere(Sphere::new(Vec3::ZERO, 1.0));
        let mesh = TriangleMesh::bumpy_sphere(100);
        let keyframes = vec![
            (0.0, Mat4::IDENTITY),
            (1.0, Mat4::from_translation(Vec3::X)),
        ];
        let scene = SceneBuilder::new()
            .moving(sphere, keyframes, Material::mirror())
            .mesh(&mesh, Material::diffuse(Vec3::splat(0.5)))
            .shape(sphere, Material::glass(1.5))
            .build(Camera::pinhole(frame, 40.0), FilmSettings::new(8, 8), 4);
        let triangles = mesh.indices.len();
        assert_eq!(scene.shape_count(), triangles + 2);
        // The mesh's surface, the sphere's, then the moving sphere's: the shapes' order.
        assert_eq!(scene.surfaces.len(), 3);
        assert!(scene.surface_of_shape[..triangles].iter().all(|&s| s == 0));
        assert_eq!(scene.surface_of_shape[triangles..], [1, 2]);
        assert_eq!(
            scene.surface(0).material,
            Material::diffuse(Vec3::splat(0.5))
        );
        assert_eq!(
            scene.surface(triangles as u32).material,
            Material::glass(1.5)
        );
        assert_eq!(
            scene.surface(triangles as u32 + 1).material,
            Material::mirror()
        );
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
