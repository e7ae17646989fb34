//! The scene model: one plain-data scene that every chapter renders.
//!
//! The lecture has one integral and a better estimator of it in each chapter; the workbook has
//! one scene and a method per chapter over it. A [`Scene`] says what is there, with every
//! parameter, and nothing about how to sample it: the shapes with their BVH, what each shape
//! is made of and whether it glows ([`Surface`]), the point lights and the environment, the
//! camera with its lens and shutter, the film and the sampler's settings, the depth limit.
//! The scene-file loader (`workbench::scene_file`) fills it from a Mitsuba 3 XML file, the
//! chapters' built-in scenes fill it with a [`SceneBuilder`], and each chapter adds the
//! functions that sample it and a tracer that reads it.
//!
//! Which chapter renders which of its features is not the model's business: the workbench's
//! `capabilities` holds that course map, and each chapter's workbench its declaration.
//!
//! Shapes are numbered as a hit reports them ([`SurfaceHit::shape`](crate::geometry::SurfaceHit)):
//! the still shapes of [`Scene::geometry`] first, then the [`Scene::moving`] ones, and
//! [`Scene::surfaces`] is indexed the same way.

mod builder;
mod camera;
mod emission_sampling;
mod environment_map;
mod environment_sampling;
mod grid_distribution;
mod lat_long;
mod light;
mod material;
mod metals;
mod settings;
mod texture;

pub use builder::SceneBuilder;
pub use camera::{Camera, CameraFrame, CameraModel};
pub use emission_sampling::{EMISSION_GRID, UNIFORM_SHARE};
pub use environment_map::{EnvironmentMap, EnvironmentMapError};
pub use environment_sampling::{EnvironmentSampling, luminance};
pub use grid_distribution::GridDistribution;
pub use lat_long::{direction_of, direction_to_uv};
pub use light::{AreaEmitter, DirectionalLight, PointLight};
pub use material::{
    AlphaTexture, Conductor, Glossy, Mask, Material, Microfacet, MicrofacetDistribution, Opacity,
    Plastic, RoughGlass, TintedGlass, check_exponent,
};
pub use metals::{named_metal, named_metal_names};
pub use settings::{
    DirectSamples, FilmFilter, FilmSettings, Integrator, Origins, SamplerSettings, TextPosition,
};
pub use texture::{Bitmap, BitmapFilter, BitmapId, Checkerboard, Texture, WrapMode};

use crate::geometry::{Geometry, Shape};
use glam::{Mat4, Vec2, Vec3};
use std::borrow::Cow;

/// The luminance of a linear sRGB colour, with the weights Mitsuba 3 uses (`luminance()`).
const LUMINANCE: Vec3 = Vec3::new(0.212671, 0.715160, 0.072169);

/// The smallest microfacet width Mitsuba 3 uses: a textured width below it is raised to it.
const MICROFACET_MIN_ALPHA: f32 = 1e-4;

/// The recursion limit used for Mitsuba's "unlimited" `max_depth` (-1): mirrors facing each
/// other would otherwise recurse without end.
pub const UNLIMITED_DEPTH: u32 = 100;

/// Everything a render needs to know about the world, as data.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The shapes that stand still, in world space, with their BVH.
    pub geometry: Geometry,
    /// The shapes that move, each in its own space with its keyframes; shape number
    /// `geometry.shapes().len() + j` is `moving[j]`.
    pub moving: Vec<AnimatedShape>,
    /// What the shapes are made of and whether they glow: one surface per shape of the scene
    /// file, so that the pieces of one (a mesh's triangles, a cube's faces) share it. In the
    /// order of the shapes that first use them (still shapes first, then moving ones), so that
    /// where every shape is a single piece, surface `i` is shape `i`'s.
    pub surfaces: Vec<Surface>,
    /// For each shape, still ones first, then moving ones: its surface's index in
    /// [`surfaces`](Self::surfaces). Four bytes per triangle of a mesh, where a surface of
    /// its own takes hundreds.
    pub surface_of_shape: Vec<u32>,
    /// The images the materials' textures read, each once ([`Texture::Bitmap`] holds its
    /// number here).
    pub bitmaps: Vec<Bitmap>,
    /// The point lights.
    pub point_lights: Vec<PointLight>,
    /// The lights infinitely far away that shine one way (chapter 08 only).
    pub directional_lights: Vec<DirectionalLight>,
    /// Radiance of every ray that leaves the scene (Mitsuba's `constant` emitter); black for a
    /// closed room or a scene without an environment.
    pub environment: Vec3,
    /// Light from an image around the scene (Mitsuba's `envmap`), added to `environment`;
    /// chapters before 08 refuse it.
    pub environment_map: Option<EnvironmentMap>,
    /// Where the camera is, its lens, its shutter and its motion.
    pub camera: Camera,
    /// The image the camera records.
    pub film: FilmSettings,
    /// Samples per pixel and the seed, as the file asks.
    pub sampler: SamplerSettings,
    /// The light transport the file asks for.
    pub integrator: Integrator,
    /// The longest path, counted in segments *including* the camera ray, as Mitsuba's
    /// `max_depth`: 1 sees only what the camera ray hits, 2 adds direct light (the shadow ray
    /// is the second segment), each further step one more bounce.
    pub max_depth: u32,
    /// Mitsuba's `hide_emitters`: camera rays see no light source and no environment (light
    /// still reaches what they see, and mirrors still show the lights).
    pub hide_emitters: bool,
    /// Where the scene's parts are written in its file, for messages; empty for built-in
    /// scenes.
    pub origins: Origins,
    /// The shapes whose light samples follow their radiance's texture, each with the density
    /// they are drawn with ([`Scene::emission_grid`]), worked out when the scene is built
    /// ([`Scene::prepare_emission_grids`]).
    pub emission_grids: Vec<(u32, GridDistribution)>,
}

/// What the surface of one shape is made of, whether it glows, and where it was written.
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    /// How it scatters light.
    pub material: Material,
    /// The light it emits from its front side, if it is an area light.
    pub emitter: Option<AreaEmitter>,
    /// Where the `<shape>` element starts in the scene file (`None` for built-in scenes).
    pub origin: Option<TextPosition>,
}

/// A shape that moves: `keyframes` map its own space to world space over time.
#[derive(Clone, Debug, PartialEq)]
pub struct AnimatedShape {
    /// The shape in its own space.
    pub shape: Shape,
    /// `(time, object to world)` pairs: at least two, strictly increasing times, each matrix
    /// invertible. How the transform goes between them is chapter 05's business.
    pub keyframes: Vec<(f32, Mat4)>,
}

impl Scene {
    /// How many shapes the scene has, still and moving.
    pub fn shape_count(&self) -> usize {
        self.surface_of_shape.len()
    }

    /// The radiance arriving along direction `direction` from outside the scene: the
    /// constant environment plus the environment map's light from there.
    pub fn background(&self, direction: Vec3) -> Vec3 {
        match &self.environment_map {
            Some(map) => self.environment + map.radiance(direction),
            None => self.environment,
        }
    }

    /// Still shape number `shape` itself (its geometry, as the BVH holds it); `None` for a
    /// moving shape or a number the scene does not have.
    pub fn still_shape(&self, shape: u32) -> Option<&Shape> {
        self.geometry.shapes().get(shape as usize)
    }

    /// The surface of shape number `shape`, as a hit reports it.
    #[inline]
    pub fn surface(&self, shape: u32) -> &Surface {
        &self.surfaces[self.surface_of_shape[shape as usize] as usize]
    }

    // ANCHOR: albedo
    /// The colour of `texture` at surface parameters `uv` (a hit's `uv`): the albedo of a
    /// textured matte surface there.
    pub fn albedo(&self, texture: Texture, uv: Vec2) -> Vec3 {
        match texture {
            Texture::Checkerboard(checkerboard) => checkerboard.eval(uv),
            // A number the scene does not hold (a scene put together by hand) reads as black.
            Texture::Bitmap(BitmapId(index)) => self
                .bitmaps
                .get(index as usize)
                .map_or(Vec3::ZERO, |bitmap| bitmap.eval(uv)),
        }
    }
    // ANCHOR_END: albedo

    /// The material of shape number `shape` with its texture read at `uv`: a textured matte
    /// surface becomes the plain matte surface of the albedo there; other materials are
    /// returned as they are. For code that wants one material per hit, such as chapter 08's
    /// BSDFs.
    ///
    /// The textures of plastic, metals and glass (a [`Plastic`]'s `diffuse_texture` and
    /// `specular_texture`, a [`Conductor`]'s `specular_texture`, a [`TintedGlass`]'s two) are
    /// read the same way: each
    /// multiplies its colour, and the material returned has no texture left. A rough
    /// material's textured widths are read too, and where its two widths differ it gets the
    /// shape's `dp/du` at `uv` ([`Microfacet::dp_du`]), the tangent they are measured along.
    ///
    /// A material with nothing to read is lent as it is, not copied: that is nearly every hit,
    /// and the test for the plainest of them is made where the hit is shaded.
    #[inline]
    pub fn material_at(&self, shape: u32, uv: Vec2) -> Cow<'_, Material> {
        let material = &self.surface(shape).material;
        match material {
            Material::Diffuse { .. }
            | Material::Mirror { .. }
            | Material::Dielectric { .. }
            | Material::ThinDielectric { .. }
            | Material::Glossy(_) => Cow::Borrowed(material),
            _ => self.read_at(material, shape, uv),
        }
    }

    /// `material` of shape number `shape` with its textures read at `uv` (a mask's opacity and
    /// nested material too).
    fn read_at<'a>(&'a self, material: &'a Material, shape: u32, uv: Vec2) -> Cow<'a, Material> {
        let factor = |texture: Option<Texture>| texture.map_or(Vec3::ONE, |t| self.albedo(t, uv));
        // Whether a roughness must be read at the hit: its widths' textures, or its tangent.
        let varies = |m: Option<Microfacet>| {
            m.is_some_and(|m| m.alpha_texture.is_some() || m.is_anisotropic())
        };
        let read = match material {
            &Material::TexturedDiffuse { texture, two_sided } => Material::Diffuse {
                albedo: self.albedo(texture, uv),
                two_sided,
            },
            &Material::Conductor(c) if c.specular_texture.is_some() || varies(c.roughness) => {
                Material::Conductor(Conductor {
                    specular_reflectance: c.specular_reflectance * factor(c.specular_texture),
                    specular_texture: None,
                    roughness: c.roughness.map(|m| self.microfacet_at(m, shape, uv)),
                    ..c
                })
            }
            &Material::RoughGlass(g) if varies(g.stands_in_for) => {
                Material::RoughGlass(RoughGlass {
                    stands_in_for: g.stands_in_for.map(|m| self.microfacet_at(m, shape, uv)),
                    ..g
                })
            }
            &Material::Plastic(p)
                if p.diffuse_texture.is_some() || p.specular_texture.is_some() =>
            {
                Material::Plastic(Plastic {
                    diffuse_reflectance: p.diffuse_reflectance * factor(p.diffuse_texture),
                    specular_reflectance: p.specular_reflectance * factor(p.specular_texture),
                    diffuse_texture: None,
                    specular_texture: None,
                    ..p
                })
            }
            &Material::TintedGlass(g)
                if g.reflectance_texture.is_some()
                    || g.transmittance_texture.is_some()
                    || varies(g.roughness) =>
            {
                Material::TintedGlass(TintedGlass {
                    roughness: g.roughness.map(|m| self.microfacet_at(m, shape, uv)),
                    specular_reflectance: g.specular_reflectance * factor(g.reflectance_texture),
                    specular_transmittance: g.specular_transmittance
                        * factor(g.transmittance_texture),
                    reflectance_texture: None,
                    transmittance_texture: None,
                    ..g
                })
            }
            Material::Mask(mask) => Material::Mask(Mask {
                opacity: Opacity::Uniform(self.opacity(mask.opacity, uv)),
                nested: Box::new(self.read_at(&mask.nested, shape, uv).into_owned()),
            }),
            // Nothing to read: the material is lent as it is.
            material => return Cow::Borrowed(material),
        };
        Cow::Owned(read)
    }

    /// A mask's opacity at `uv`, in [0, 1], read as Mitsuba 3 reads a texture for one value
    /// (`eval_1`): a checkerboard's colour by its mean, an image's by its luminance.
    ///
    /// Mitsuba's checkerboard puts its colours the other way round when read for one value:
    /// `color0` where the fractional parts of `u` and `v` are on *different* sides of 1/2,
    /// the squares its colour reading gives `color1`. Opacity follows it, so that a file's
    /// holes are where Mitsuba cuts them.
    pub fn opacity(&self, opacity: Opacity, uv: Vec2) -> f32 {
        let value = match opacity {
            Opacity::Uniform(value) => value,
            Opacity::Texture(texture) => self.texture_value(texture, uv),
        };
        // Also a NaN becomes 0 (no surface), not a NaN in the path's weight.
        if value >= 0.0 { value.min(1.0) } else { 0.0 }
    }

    /// The one number `texture` holds at `uv`, read as Mitsuba 3 reads a texture for a single
    /// value (`eval_1`: a mask's opacity, a rough surface's width): a checkerboard's colour
    /// by its mean, an image's by its luminance.
    ///
    /// Mitsuba's checkerboard puts its colours the other way round when read for one value:
    /// `color0` where the fractional parts of `u` and `v` are on *different* sides of 1/2,
    /// the squares its colour reading gives `color1`. This follows it.
    pub fn texture_value(&self, texture: Texture, uv: Vec2) -> f32 {
        match texture {
            Texture::Checkerboard(squares) => {
                let swapped = Checkerboard {
                    colour0: squares.colour1,
                    colour1: squares.colour0,
                    ..squares
                };
                swapped.eval(uv).element_sum() / 3.0
            }
            Texture::Bitmap(_) => self.albedo(texture, uv).dot(LUMINANCE),
        }
    }

    /// `microfacet` on shape number `shape` at `uv`: its textured widths read there, each at
    /// least `10⁻⁴` as Mitsuba keeps them (a width of 0 is a mirror no microfacet model
    /// describes), and, where the two widths differ, the shape's `dp/du` they run along.
    fn microfacet_at(&self, microfacet: Microfacet, shape: u32, uv: Vec2) -> Microfacet {
        let mut read = microfacet;
        if let Some(textures) = microfacet.alpha_texture {
            let width = |texture: Option<Texture>, number: f32| {
                let alpha = texture.map_or(number, |t| self.texture_value(t, uv));
                // `max` also turns a NaN into the smallest width.
                alpha.max(MICROFACET_MIN_ALPHA)
            };
            read.alpha_u = width(textures.u, microfacet.alpha_u);
            read.alpha_v = width(textures.v, microfacet.alpha_v);
            read.alpha_texture = None;
        }
        if read.is_anisotropic() {
            read.dp_du = self.dp_du(shape, uv);
        }
        read
    }

    /// The `dp/du` of shape number `shape` at surface parameters `uv`
    /// ([`Shape::dp_du`](crate::geometry::Shape::dp_du)); zero on a moving shape, whose
    /// surface runs in a direction that changes with the time (its rough material's frame is
    /// then built from the normal alone).
    pub fn dp_du(&self, shape: u32, uv: Vec2) -> Vec3 {
        self.geometry
            .shapes()
            .get(shape as usize)
            .map_or(Vec3::ZERO, |still| still.dp_du(uv))
    }

    /// The radiance the emitter of shape number `shape` sends from its front side at surface
    /// parameters `uv`: its radiance times its texture there; black for a shape that does
    /// not glow.
    pub fn emitted_at(&self, shape: u32, uv: Vec2) -> Vec3 {
        match self.surface(shape).emitter {
            Some(AreaEmitter {
                radiance,
                texture: Some(texture),
                ..
            }) => radiance * self.albedo(texture, uv),
            Some(AreaEmitter { radiance, .. }) => radiance,
            None => Vec3::ZERO,
        }
    }

    /// The same scene with every lobe's exponent set to `exponent` (smooth materials stay).
    pub fn with_exponent(mut self, exponent: f32) -> Self {
        for surface in &mut self.surfaces {
            surface.material = surface.material.clone().with_exponent(exponent);
        }
        self
    }
}
