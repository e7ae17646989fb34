//! `<emitter>`: area lights attached to shapes, and point, directional, constant and
//! environment-map lights on their own.

use super::element::Element;
use glam::Vec3;

use super::description::EmitterDescription;
use super::environment_map::read_environment_map;
use super::error::SceneError;
use super::properties::Properties;
use super::reader::Reader;
use super::textures::{refuse_texture, take_textures};
use common::scene::AreaEmitter;

/// An `<emitter>` is either attached to a shape (area) or stands alone (point, constant,
/// envmap).
pub(super) enum Emitter {
    /// Must be inside a `<shape>`.
    Area(AreaEmitter),
    /// Must be at the top level.
    Standalone(EmitterDescription),
}

impl Emitter {
    /// The area emitter with the `sampling_weight` the element gives (Mitsuba 3 picks its
    /// emitters in proportion to it; 1 without), which must be positive and finite.
    fn with_sampling_weight(
        self,
        reader: &Reader,
        node: &Element,
        properties: &mut Properties,
    ) -> Result<Self, SceneError> {
        let Emitter::Area(mut area) = self else {
            return Ok(self);
        };
        if let Some(weight) = properties.float(reader, "sampling_weight")? {
            if !(weight > 0.0 && weight.is_finite()) {
                let position = properties
                    .position_of("sampling_weight")
                    .unwrap_or(reader.position(node));
                return Err(reader.error_at(
                    position,
                    format!("an emitter's sampling_weight must be positive, found {weight}"),
                ));
            }
            area.sampling_weight = weight;
        }
        Ok(Emitter::Area(area))
    }
}

/// Reads an `<emitter>` of type `area`, `point`, `constant` or `envmap`.
pub(super) fn read_emitter<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
) -> Result<Emitter, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    let mut properties = Properties::read(reader, node, format!("{type_name} emitter"))?;
    let mut textures = take_textures(reader, &mut properties.objects)?;
    // Only an area light's radiance may vary over its surface.
    let radiance_texture = match textures.iter().position(|t| t.name == "radiance") {
        Some(index) if type_name == "area" => Some(textures.remove(index)),
        _ => None,
    };
    if let Some(texture) = textures.first() {
        return Err(refuse_texture(
            reader,
            &format!("{type_name} emitter"),
            texture,
        ));
    }
    if let Some(object) = properties.objects.first() {
        let tag = object.name();
        return Err(reader.error(object, format!("<{tag}> is not allowed inside <emitter>")));
    }
    let emitter = match type_name.as_str() {
        "area" => Emitter::Area(match radiance_texture {
            None => AreaEmitter::uniform(emission(
                reader,
                node,
                &mut properties,
                "radiance",
                "an area light's",
            )?),
            Some(texture) => {
                if properties.position_of("radiance").is_some() {
                    return Err(reader.error(
                        texture.node,
                        "the area emitter's radiance is given twice: as a colour and as a \
                         texture",
                    ));
                }
                AreaEmitter {
                    radiance: Vec3::ONE,
                    texture: Some(texture.texture),
                    sampling_weight: 1.0,
                }
            }
        })
        .with_sampling_weight(reader, node, &mut properties)?,
        "constant" => Emitter::Standalone(EmitterDescription::Constant {
            radiance: emission(
                reader,
                node,
                &mut properties,
                "radiance",
                "a constant emitter's",
            )?,
            position: reader.position(node),
        }),
        "envmap" => Emitter::Standalone(read_environment_map(reader, node, &mut properties)?),
        "directional" => {
            // Mitsuba's: `direction`, or the `z` axis of `to_world` (+z without either).
            let names = ("directional", "direction");
            let direction = given_or_placed(reader, node, &mut properties, names, |m| {
                m.transform_vector3(Vec3::Z)
            })?;
            let Some(direction) = direction.try_normalize() else {
                let position = properties
                    .position_of("direction")
                    .unwrap_or(reader.position(node));
                return Err(reader.error_at(
                    position,
                    format!("a directional emitter needs a direction, found {direction}"),
                ));
            };
            Emitter::Standalone(EmitterDescription::Directional {
                direction,
                irradiance: emission(
                    reader,
                    node,
                    &mut properties,
                    "irradiance",
                    "a directional light's",
                )?,
                position: reader.position(node),
            })
        }
        "point" => {
            let names = ("point", "position");
            let position = given_or_placed(reader, node, &mut properties, names, |m| {
                m.transform_point3(Vec3::ZERO)
            })?;
            Emitter::Standalone(EmitterDescription::Point {
                position,
                intensity: emission(
                    reader,
                    node,
                    &mut properties,
                    "intensity",
                    "a point light's",
                )?,
            })
        }
        _ => {
            return Err(reader.error(
                node,
                format!(
                    "unknown emitter type \"{type_name}\": expected area, point, directional, \
                     constant or envmap"
                ),
            ));
        }
    };
    properties.finish(reader);
    Ok(emitter)
}

/// A light's position or direction, the property `given_name` (a `<point>` or a `<vector>`)
/// of a `type_name` emitter, or else what `from_to_world` makes of its `to_world` (the
/// identity when neither is given: the origin, or `+z`); both given is refused, as Mitsuba
/// refuses it.
fn given_or_placed(
    reader: &Reader,
    node: &Element,
    properties: &mut Properties,
    (type_name, given_name): (&str, &str),
    from_to_world: impl Fn(glam::Mat4) -> Vec3,
) -> Result<Vec3, SceneError> {
    let given = match given_name {
        "direction" => properties.vector(reader, given_name)?,
        _ => properties.point(reader, given_name)?,
    };
    let to_world = properties.transform(reader, "to_world")?;
    match (given, to_world) {
        (Some(_), Some(_)) => Err(reader.error(
            node,
            format!("a {type_name} emitter takes \"{given_name}\" or \"to_world\", not both"),
        )),
        (Some(given), None) => Ok(given),
        (None, to_world) => Ok(from_to_world(to_world.unwrap_or(glam::Mat4::IDENTITY))),
    }
}

/// An emitter's colour property `name` (1 if absent), refused unless every channel is finite
/// and not negative: a negative light would subtract light, which nothing physical does, and
/// would give negative pixels rather than an error.
fn emission(
    reader: &Reader,
    node: &Element,
    properties: &mut Properties,
    name: &str,
    whose: &str,
) -> Result<Vec3, SceneError> {
    let value = properties.emitted_rgb(reader, name)?.unwrap_or(Vec3::ONE);
    if value.is_finite() && value.cmpge(Vec3::ZERO).all() {
        return Ok(value);
    }
    let position = properties
        .position_of(name)
        .unwrap_or(reader.position(node));
    Err(reader.error_at(
        position,
        format!("{whose} {name} must be finite and not negative, found {value}"),
    ))
}
