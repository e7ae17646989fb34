//! `<sensor>` with its `<film>` and `<sampler>`, and the field-of-view conversion.

use super::element::Element;
use glam::Mat4;

use super::description::{FilmDescription, SamplerDescription, Sensor};
use super::error::SceneError;
use super::properties::Properties;
use super::reader::Reader;
use super::sample_counts::mitsuba_sample_count;
use super::values::parse_float;
use common::scene::{CameraModel, FilmFilter};

/// Reads a `perspective` or `thinlens` sensor.
pub(super) fn read_sensor<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
) -> Result<Sensor, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    if type_name != "perspective" && type_name != "thinlens" {
        return Err(reader.error(
            node,
            format!("unknown sensor type \"{type_name}\": expected perspective or thinlens"),
        ));
    }
    let mut properties = Properties::read(reader, node, format!("{type_name} sensor"))?;
    let mut film = None;
    let mut sampler = None;
    for &written in &properties.objects {
        // A `<ref>` names a film or sampler declared apart, at the top level.
        let object = reader.dereference(written)?;
        match object.name() {
            "film" if film.is_none() => film = Some(read_film(reader, object)?),
            "sampler" if sampler.is_none() => sampler = Some(read_sampler(reader, object)?),
            tag => {
                return Err(reader.error(
                    written,
                    format!(
                        "<{tag}> is not allowed here: a sensor holds one <film> and one <sampler>"
                    ),
                ));
            }
        }
    }
    let film = film.unwrap_or_else(default_film);
    let sampler = sampler.unwrap_or(SamplerDescription {
        type_name: "independent".to_string(),
        sample_count: 4,
        seed: 0,
    });

    let aspect = film.width as f32 / film.height as f32;
    let fov_x_degrees = field_of_view(reader, node, &mut properties, aspect)?;
    let mut offset = |name: &str| -> Result<f32, SceneError> {
        let offset = properties.float(reader, name)?.unwrap_or(0.0);
        if offset.is_finite() {
            Ok(offset)
        } else {
            let position = properties
                .position_of(name)
                .unwrap_or(reader.position(node));
            Err(reader.error_at(position, format!("{name} must be a finite number")))
        }
    };
    let principal_point_offset = glam::Vec2::new(
        offset("principal_point_offset_x")?,
        offset("principal_point_offset_y")?,
    );

    let near_clip = properties.float(reader, "near_clip")?.unwrap_or(0.01);
    let far_clip = properties.float(reader, "far_clip")?.unwrap_or(10_000.0);
    let model = if type_name == "thinlens" {
        let aperture_radius = properties
            .float(reader, "aperture_radius")?
            .ok_or_else(|| {
                reader.error(
                    node,
                    "a thinlens sensor needs <float name=\"aperture_radius\"> (Mitsuba 3 has no \
                 default for it either)",
                )
            })?;
        // Mitsuba 3 focuses a thin lens without a focus_distance at its far clip plane
        // (measured on Mitsuba 3.9.1: 10000 by default, the far_clip when one is given).
        let focus_distance = properties
            .float(reader, "focus_distance")?
            .unwrap_or(far_clip);
        CameraModel::ThinLens {
            aperture_radius,
            focus_distance,
        }
    } else {
        CameraModel::Pinhole
    };
    let (to_world, to_world_keyframes) = properties.transform_or_animation(reader, "to_world")?;
    let sensor = Sensor {
        position: reader.position(node),
        model,
        fov_x_degrees,
        principal_point_offset,
        near_clip,
        far_clip,
        shutter_open: properties.float(reader, "shutter_open")?.unwrap_or(0.0),
        shutter_close: properties.float(reader, "shutter_close")?.unwrap_or(0.0),
        to_world: to_world.unwrap_or(Mat4::IDENTITY),
        to_world_keyframes,
        film,
        sampler,
    };
    properties.finish(reader);
    Ok(sensor)
}

/// The horizontal field of view in degrees, from `fov` and `fov_axis`, or else from
/// `focal_length` (Mitsuba 3's default "50mm") as a lens on a 36 x 24 mm film: its diagonal
/// field of view `2 atan(sqrt(36² + 24²) / 2f)`, whatever the image's aspect ratio.
fn field_of_view(
    reader: &Reader,
    node: &Element,
    properties: &mut Properties,
    aspect: f32,
) -> Result<f32, SceneError> {
    let at = |properties: &Properties, name: &str| {
        properties
            .position_of(name)
            .unwrap_or(reader.position(node))
    };
    let has_fov = properties.position_of("fov").is_some();
    if has_fov && properties.position_of("focal_length").is_some() {
        return Err(reader.error_at(
            at(properties, "focal_length"),
            "the sensor gives both fov and focal_length: give one of them",
        ));
    }
    let (fov, fov_axis, axis_name) = if has_fov {
        let fov = properties.float(reader, "fov")?.unwrap_or_default();
        let axis = properties
            .string(reader, "fov_axis")?
            .unwrap_or_else(|| "x".to_string());
        (fov, axis, "fov")
    } else {
        let focal_length = match properties.position_of("focal_length") {
            None => 50.0,
            Some(position) => {
                let text = match properties.string(reader, "focal_length") {
                    Ok(text) => text.unwrap_or_default(),
                    Err(_) => properties
                        .float(reader, "focal_length")?
                        .unwrap_or_default()
                        .to_string(),
                };
                let number = text.trim().trim_end_matches("mm").trim();
                parse_float(number)
                    .ok()
                    .filter(|f| f.is_finite() && *f > 0.0)
                    .ok_or_else(|| {
                        reader.error_at(
                            position,
                            format!(
                                "focal_length must be a positive length in millimetres such as                                  \"50mm\", found \"{text}\""
                            ),
                        )
                    })?
            }
        };
        let diagonal_mm = (36.0f32 * 36.0 + 24.0 * 24.0).sqrt();
        let fov = 2.0 * (diagonal_mm / (2.0 * focal_length)).atan().to_degrees();
        (fov, "diagonal".to_string(), "focal_length")
    };
    if !(fov > 0.0 && fov < 180.0) {
        return Err(reader.error_at(
            at(properties, axis_name),
            format!("fov must be between 0 and 180 degrees, found {fov}"),
        ));
    }
    horizontal_fov(fov, &fov_axis, aspect).ok_or_else(|| {
        reader.error_at(
            at(properties, "fov_axis"),
            format!("unknown fov_axis \"{fov_axis}\": expected x, y, diagonal, smaller or larger"),
        )
    })
}

/// The horizontal field of view in degrees for `fov` degrees along `fov_axis`, as Mitsuba 3
/// converts it; `aspect` is width / height. `None` for an unknown axis name.
pub fn horizontal_fov(fov: f32, fov_axis: &str, aspect: f32) -> Option<f32> {
    let half_tan = (0.5 * fov.to_radians()).tan();
    let from_half_tan = |t: f32| 2.0 * t.atan().to_degrees();
    let axis = match fov_axis {
        "smaller" if aspect > 1.0 => "y",
        "smaller" => "x",
        "larger" if aspect > 1.0 => "x",
        "larger" => "y",
        other => other,
    };
    match axis {
        "x" => Some(fov),
        "y" => Some(from_half_tan(half_tan * aspect)),
        // tan(fov/2) is half the diagonal at distance 1; the width is diagonal * W / sqrt(W²+H²).
        "diagonal" => Some(from_half_tan(
            half_tan / (1.0 + 1.0 / (aspect * aspect)).sqrt(),
        )),
        _ => None,
    }
}

/// Mitsuba 3's `hdrfilm` defaults.
fn default_film() -> FilmDescription {
    FilmDescription {
        width: 768,
        height: 576,
        filter: FilmFilter::Gaussian { stddev: 0.5 },
        filter_position: None,
        pixel_format: "rgb".to_string(),
        component_format: "float16".to_string(),
    }
}

/// Reads an `hdrfilm` with its optional `rfilter`.
fn read_film<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
) -> Result<FilmDescription, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    if type_name != "hdrfilm" {
        return Err(reader.error(
            node,
            format!("unknown film type \"{type_name}\": expected hdrfilm"),
        ));
    }
    let mut properties = Properties::read(reader, node, "hdrfilm".to_string())?;
    let mut film = default_film();
    for name in ["width", "height"] {
        if let Some(size) = properties.integer(reader, name)? {
            let position = properties
                .position_of(name)
                .unwrap_or(reader.position(node));
            let size = u32::try_from(size)
                .ok()
                .filter(|&size| size > 0)
                .ok_or_else(|| {
                    reader.error_at(
                        position,
                        format!("film {name} must be a positive integer, found {size}"),
                    )
                })?;
            *(if name == "width" {
                &mut film.width
            } else {
                &mut film.height
            }) = size;
        }
    }
    if let Some(format) = properties.string(reader, "pixel_format")? {
        film.pixel_format = format;
    }
    if let Some(format) = properties.string(reader, "component_format")? {
        film.component_format = format;
    }
    for &written in &properties.objects {
        let object = reader.dereference(written)?;
        if object.name() != "rfilter" {
            let tag = object.name();
            return Err(reader.error(written, format!("<{tag}> is not allowed inside <film>")));
        }
        film.filter = read_filter(reader, object)?;
        film.filter_position = Some(reader.position(object));
    }
    properties.finish(reader);
    Ok(film)
}

/// Reads an `rfilter`: box, tent, gaussian, mitchell or catmullrom.
fn read_filter(reader: &mut Reader, node: &Element) -> Result<FilmFilter, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    let mut properties = Properties::read(reader, node, format!("{type_name} rfilter"))?;
    let filter = match type_name.as_str() {
        "box" => FilmFilter::Box,
        "tent" => FilmFilter::Tent {
            radius: properties.float(reader, "radius")?.unwrap_or(1.0),
        },
        "gaussian" => FilmFilter::Gaussian {
            stddev: properties.float(reader, "stddev")?.unwrap_or(0.5),
        },
        "mitchell" => FilmFilter::Mitchell {
            b: properties.float(reader, "B")?.unwrap_or(1.0 / 3.0),
            c: properties.float(reader, "C")?.unwrap_or(1.0 / 3.0),
        },
        "catmullrom" => FilmFilter::Mitchell { b: 0.0, c: 0.5 },
        _ => {
            return Err(reader.error(
                node,
                format!(
                    "unknown rfilter type \"{type_name}\": expected box, tent, gaussian, mitchell \
                     or catmullrom"
                ),
            ));
        }
    };
    if let Some(object) = properties.objects.first() {
        return Err(reader.error(object, "an rfilter cannot contain objects"));
    }
    properties.finish(reader);
    Ok(filter)
}

/// Reads a sampler of any type: only `sample_count` (rounded as Mitsuba 3 rounds it for its
/// type) and `seed` are interpreted.
fn read_sampler(reader: &mut Reader, node: &Element) -> Result<SamplerDescription, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    let mut properties = Properties::read(reader, node, format!("{type_name} sampler"))?;
    let mut count_or_seed = |name: &str, default: u32, minimum: u32| {
        let Some(value) = properties.integer(reader, name)? else {
            return Ok(default);
        };
        let position = properties
            .position_of(name)
            .unwrap_or(reader.position(node));
        u32::try_from(value)
            .ok()
            .filter(|&value| value >= minimum)
            .ok_or_else(|| {
                reader.error_at(
                    position,
                    format!("{name} must be an integer of at least {minimum}, found {value}"),
                )
            })
    };
    let asked = count_or_seed("sample_count", 4, 1)?;
    let seed = count_or_seed("seed", 0, 0)?;
    // Mitsuba's structured samplers round the count up to one they can lay out; so do we.
    let sample_count = mitsuba_sample_count(&type_name, asked).ok_or_else(|| {
        reader.error(
            node,
            format!("a {type_name} sampler cannot lay out {asked} samples per pixel"),
        )
    })?;
    if sample_count != asked {
        reader.warn_at(
            reader.position(node),
            format!(
                "the {type_name} sampler takes {sample_count} samples per pixel where the file \
                 asks for {asked}, as Mitsuba 3 rounds them"
            ),
        );
    }
    let sampler = SamplerDescription {
        sample_count,
        seed,
        type_name,
    };
    if let Some(object) = properties.objects.first() {
        return Err(reader.error(object, "a sampler cannot contain objects"));
    }
    properties.finish(reader);
    Ok(sampler)
}
