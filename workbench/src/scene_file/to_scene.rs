//! The last step of loading: a file's description made into the scene model.
//!
//! Shapes are placed in world space ([`world_shapes`]), a moving shape in its own space with
//! its keyframes; every piece of a shape (a cube's six faces, a mesh's triangles) shares the
//! shape's one surface; the still shapes come first, in file order, then the moving ones.
//! What the file asks that no chapter can render, or that makes no sense, is refused here,
//! pointing at the element.

use std::path::Path;

use super::description::{EmitterDescription, Integrator, SceneDescription, ShapeGeometry};
use super::error::{SceneError, TextPosition};
use super::to_geometry::world_shapes;
use common::scene::{
    AnimatedShape, Camera, CameraFrame, CameraModel, DirectionalLight, FilmSettings,
    Integrator as Transport, Origins, PointLight, SamplerSettings, Scene, SceneBuilder, Surface,
    UNLIMITED_DEPTH,
};
use glam::{Mat4, Vec3};

/// The scene model of `description`, read from `file`.
pub(super) fn to_scene(description: &SceneDescription, file: &Path) -> Result<Scene, SceneError> {
    let error = |position: TextPosition, message: String| SceneError::at(file, &position, message);
    let sensor = &description.sensor;
    if let CameraModel::ThinLens {
        aperture_radius,
        focus_distance,
    } = sensor.model
    {
        if !(aperture_radius.is_finite() && aperture_radius >= 0.0) {
            return Err(error(
                sensor.position.clone(),
                format!(
                    "the thinlens sensor's aperture_radius must be a finite number of at least 0, found {aperture_radius}"
                ),
            ));
        }
        if !(focus_distance.is_finite() && focus_distance > 0.0) {
            return Err(error(
                sensor.position.clone(),
                format!(
                    "the thinlens sensor's focus_distance must be a finite positive distance, found {focus_distance}"
                ),
            ));
        }
    }
    let (open, close) = (sensor.shutter_open, sensor.shutter_close);
    if !(open.is_finite() && close.is_finite() && (close - open).is_finite()) {
        return Err(error(
            sensor.position.clone(),
            format!("the sensor's shutter_open {open} and shutter_close {close} must be finite"),
        ));
    }
    if close < open {
        return Err(error(
            sensor.position.clone(),
            format!(
                "the sensor's shutter_close {close} is before its shutter_open {open}: the shutter must open before it closes"
            ),
        ));
    }

    let mut builder = SceneBuilder::new();
    for shape in &description.shapes {
        let position = shape.position.clone();
        let kind = match shape.geometry {
            ShapeGeometry::Sphere { .. } => "sphere",
            ShapeGeometry::Rectangle => "rectangle",
            ShapeGeometry::Disc => "disk",
            ShapeGeometry::Cube => "cube",
            ShapeGeometry::Obj { .. } => "obj",
            ShapeGeometry::Ply { .. } => "ply",
            ShapeGeometry::Serialized { .. } => "serialized",
        };
        let surface = Surface {
            material: shape.material.clone(),
            emitter: shape.emitter,
            origin: Some(position.clone()),
        };
        let keyframes = &shape.to_world_keyframes;
        let placed = if keyframes.is_empty() {
            shape.clone()
        } else {
            // In its own space: the keyframes place it.
            super::ShapeDescription {
                to_world: Mat4::IDENTITY,
                to_world_keyframes: Vec::new(),
                ..shape.clone()
            }
        };
        let pieces = world_shapes(&placed)
            .map_err(|message| error(position, format!("the {kind} shape: {message}")))?;
        builder = if keyframes.is_empty() {
            builder.shared_surface(pieces, surface)
        } else {
            let animated = pieces.into_iter().map(|piece| AnimatedShape {
                shape: piece,
                keyframes: keyframes.clone(),
            });
            builder.shared_moving_surface(animated, surface)
        };
    }
    let mut environment = Vec3::ZERO;
    let mut environment_position = None;
    let mut environment_map = None;
    let mut environment_map_position = None;
    let mut directional_position = None;
    for emitter in &description.emitters {
        match emitter {
            EmitterDescription::Point {
                position,
                intensity,
            } => {
                builder = builder.light(PointLight {
                    position: *position,
                    intensity: *intensity,
                });
            }
            EmitterDescription::Directional {
                direction,
                irradiance,
                position,
            } => {
                builder = builder.directional_light(DirectionalLight {
                    direction: *direction,
                    irradiance: *irradiance,
                });
                directional_position.get_or_insert(position.clone());
            }
            EmitterDescription::Constant { radiance, position } => {
                environment += *radiance;
                environment_position.get_or_insert(position.clone());
            }
            EmitterDescription::EnvironmentMap { map, position } => {
                if let Some(first) = &environment_map_position {
                    return Err(error(
                        position.clone(),
                        format!(
                            "a second envmap emitter: the workbook renders one, and the first \
                             is at {first}"
                        ),
                    ));
                }
                environment_map = Some(map.as_ref().clone());
                environment_map_position = Some(position.clone());
            }
        }
    }
    let (integrator, max_depth) = match description.integrator {
        Integrator::Path {
            max_depth,
            rr_depth,
        } => (
            Transport::Path {
                rr_depth: rr_depth.max(1) as u32,
            },
            if max_depth < 0 {
                UNLIMITED_DEPTH
            } else {
                max_depth.max(1) as u32
            },
        ),
        // Mitsuba's `direct`: the camera ray and one segment to the lights.
        Integrator::Direct(samples) => (Transport::Direct(samples), 2),
    };
    let camera = Camera {
        frame: CameraFrame::from_matrix(&sensor.to_world),
        fov_x_degrees: sensor.fov_x_degrees,
        principal_point_offset: sensor.principal_point_offset,
        near_clip: sensor.near_clip,
        model: sensor.model,
        shutter_open: open,
        shutter_close: close,
        keyframes: sensor.to_world_keyframes.clone(),
    };
    let film = FilmSettings {
        width: sensor.film.width,
        height: sensor.film.height,
        filter: sensor.film.filter,
    };
    // The bitmaps go in before the scene is built: the densities of textured lights read them.
    for bitmap in &description.bitmaps {
        builder.bitmap(bitmap.clone());
    }
    let scene = builder
        .environment(environment)
        .build(camera, film, max_depth);
    Ok(Scene {
        integrator,
        hide_emitters: description.hide_emitters,
        sampler: SamplerSettings {
            type_name: sensor.sampler.type_name.clone(),
            sample_count: sensor.sampler.sample_count,
            seed: sensor.sampler.seed,
        },
        origins: Origins {
            integrator: description.integrator_position.clone(),
            sensor: Some(sensor.position.clone()),
            filter: sensor.film.filter_position.clone(),
            environment: environment_position,
            environment_map: environment_map_position,
            directional_light: directional_position,
        },
        environment_map,
        ..scene
    })
}
