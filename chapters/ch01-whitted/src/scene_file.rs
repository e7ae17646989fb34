//! Scenes from Mitsuba 3 XML files, as far as Whitted's method can render them.
//!
//! The loader in `common::scene` reads the file; this module decides what chapter 01 can do
//! with it. What needs a later chapter (an area light, a lens with an aperture, a rough
//! material) is refused with the chapter that brings it. What Whitted's method renders but
//! leaves light out of (the indirect light that Mitsuba's `path` integrator adds) is rendered
//! with a note that says so.

use crate::camera::{CameraFrame, PinholeCamera};
use crate::light::PointLight;
use crate::material::Material;
use crate::scene::{Scene, SceneBuilder};
use common::scene::{
    Bsdf, CameraModel, EmitterDescription, Integrator, ReconstructionFilter, SceneDescription,
    world_shapes,
};
use glam::Vec3;

/// The recursion limit used for Mitsuba's "unlimited" (`max_depth = -1`): mirrors facing each
/// other would otherwise recurse without end.
pub const UNLIMITED_DEPTH: u32 = 100;

/// A scene ready for Whitted's tracer, and what the conversion had to say about it.
pub struct ConvertedScene {
    /// The scene.
    pub scene: Scene,
    /// Samples per pixel the file asks for.
    pub spp: u64,
    /// Light the method leaves out, and settings it ignores.
    pub notes: Vec<String>,
}

/// Converts a scene description for Whitted's tracer, or says which chapter it needs.
pub fn convert(description: &SceneDescription) -> Result<ConvertedScene, String> {
    let mut notes = Vec::new();
    let max_depth = match &description.integrator {
        Integrator::Path { max_depth, .. } => {
            notes.push(
                "Whitted's method leaves out indirect light (light that reaches a matte surface \
                 from other surfaces), which Mitsuba's path integrator includes; chapter 08 renders it"
                    .to_string(),
            );
            if *max_depth < 0 {
                UNLIMITED_DEPTH
            } else {
                (*max_depth).max(1) as u32
            }
        }
        Integrator::Direct => 2,
        Integrator::Other { type_name, .. } => {
            return Err(format!(
                "the integrator `{type_name}` is not one the workbook renders: it knows Mitsuba's `path` and `direct`"
            ));
        }
    };
    let sensor = &description.sensor;
    if let CameraModel::ThinLens {
        aperture_radius, ..
    } = sensor.model
        && aperture_radius > 0.0
    {
        return Err(format!(
            "the thinlens camera has an aperture of radius {aperture_radius}: depth of field needs a lens, which chapter 04 (ch04-depth-of-field) brings"
        ));
    }
    if !sensor.to_world_keyframes.is_empty() {
        return Err(
            "the sensor moves (an <animation> of its to_world): a moving camera blurs the image over the shutter interval, which chapter 05 (ch05-motion-blur) brings"
                .to_string(),
        );
    }
    if sensor.film.filter != ReconstructionFilter::Box {
        notes.push(format!(
            "the film's {:?} reconstruction filter belongs to chapter 03; chapter 01 averages each pixel's own samples (a box filter)",
            sensor.film.filter
        ));
    }
    let m = sensor.to_world;
    let frame = CameraFrame {
        origin: m.w_axis.truncate(),
        left: m.x_axis.truncate().normalize(),
        up: m.y_axis.truncate().normalize(),
        forward: m.z_axis.truncate().normalize(),
    };
    let mut camera = PinholeCamera::new(
        frame,
        sensor.fov_x_degrees,
        sensor.film.width,
        sensor.film.height,
    );
    camera.near_clip = sensor.near_clip;

    let mut builder = SceneBuilder::new();
    for (index, shape) in description.shapes.iter().enumerate() {
        if shape.emitter.is_some() {
            return Err(format!(
                "shape {} ({}) is an area light: lights with an area (and their soft shadows) come in chapter 07 (ch07-soft-shadows); chapter 01 knows point lights",
                index + 1,
                shape.position
            ));
        }
        if !shape.to_world_keyframes.is_empty() {
            return Err(format!(
                "shape {} ({}) moves (an <animation> of its to_world): moving objects and motion blur come in chapter 05 (ch05-motion-blur)",
                index + 1,
                shape.position
            ));
        }
        let name = format!("shape {} ({})", index + 1, shape.position);
        let material = material(&shape.bsdf).map_err(|e| format!("{name}: {e}"))?;
        for world_shape in world_shapes(shape).map_err(|e| format!("{name}: {e}"))? {
            builder = builder.shape(world_shape, material);
        }
    }
    let mut background = Vec3::ZERO;
    for emitter in &description.emitters {
        match *emitter {
            EmitterDescription::Point {
                position,
                intensity,
            } => {
                builder = builder.light(PointLight {
                    position,
                    intensity,
                })
            }
            EmitterDescription::Constant { radiance } => {
                background += radiance;
                notes.push(
                    "the constant environment is seen directly and in mirrors and glass, but it does not light matte surfaces: Whitted's method asks only point lights"
                        .to_string(),
                );
            }
        }
    }
    Ok(ConvertedScene {
        scene: builder.background(background).build(camera, max_depth),
        spp: u64::from(description.sensor.sampler.sample_count.max(1)),
        notes,
    })
}

/// The Whitted material of a BSDF, or why there is none.
fn material(bsdf: &Bsdf) -> Result<Material, String> {
    match bsdf {
        Bsdf::Diffuse { reflectance } => Ok(Material::diffuse(*reflectance)),
        Bsdf::TwoSided(inner) => match material(inner)? {
            Material::Diffuse { albedo, .. } => Ok(Material::two_sided_diffuse(albedo)),
            other => Ok(other),
        },
        Bsdf::Conductor {
            material,
            specular_reflectance,
        } => {
            if material == "none" {
                Ok(Material::Mirror {
                    reflectance: *specular_reflectance,
                })
            } else {
                Err(format!(
                    "the conductor `{material}` needs measured metal data; chapter 01 has the perfect mirror, material=\"none\""
                ))
            }
        }
        Bsdf::Dielectric { int_ior, ext_ior } => Ok(Material::Dielectric {
            int_ior: *int_ior,
            ext_ior: *ext_ior,
        }),
        Bsdf::Other { type_name, .. } => Err(format!(
            "the bsdf `{type_name}` is not one of Whitted's smooth materials; rough and glossy surfaces come in chapter 06 (ch06-fuzzy-reflections)"
        )),
    }
}
