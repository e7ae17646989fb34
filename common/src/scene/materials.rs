//! `<bsdf>` and `<ref>`: materials, inline or named by `id` and referenced later.

use glam::Vec3;
use roxmltree::Node;

use super::description::Bsdf;
use super::error::SceneError;
use super::properties::Properties;
use super::reader::Reader;
use super::values::parse_float;

/// Mitsuba's default interior index of refraction, BK7 glass.
const BK7_IOR: f32 = 1.5046;
/// Mitsuba's default exterior index of refraction, air.
const AIR_IOR: f32 = 1.000277;

/// Indices of refraction that may be given by name instead of a number.
const NAMED_IORS: &[(&str, f32)] = &[
    ("bk7", BK7_IOR),
    ("vacuum", 1.0),
    ("air", AIR_IOR),
    ("water", 1.3330),
    ("diamond", 2.419),
];

/// The index of refraction of a material Mitsuba knows by name (`bk7`, `water`, ...), also
/// for chapters that read the properties of a BSDF outside the subset; and the names known.
pub fn named_ior(name: &str) -> Option<f32> {
    NAMED_IORS
        .iter()
        .find(|(material, _)| *material == name)
        .map(|&(_, ior)| ior)
}

/// The names [`named_ior`] knows, for error messages.
pub fn named_ior_names() -> Vec<&'static str> {
    NAMED_IORS.iter().map(|(material, _)| *material).collect()
}

/// Reads a `<bsdf>` element and, when it has an `id`, registers it for later `<ref>`s.
pub(super) fn read_bsdf(reader: &mut Reader, node: Node) -> Result<Bsdf, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    let mut properties = Properties::read(reader, node, format!("{type_name} bsdf"))?;
    if let (false, Some(object)) = (type_name == "twosided", properties.objects.first()) {
        let tag = object.tag_name().name();
        return Err(reader.error(
            *object,
            format!("a {type_name} bsdf cannot contain <{tag}>"),
        ));
    }
    let bsdf = match type_name.as_str() {
        "diffuse" => Bsdf::Diffuse {
            reflectance: properties
                .rgb(reader, "reflectance")?
                .unwrap_or(Vec3::splat(0.5)),
        },
        "conductor" => Bsdf::Conductor {
            material: properties
                .string(reader, "material")?
                .unwrap_or_else(|| "none".to_string()),
            specular_reflectance: properties
                .rgb(reader, "specular_reflectance")?
                .unwrap_or(Vec3::ONE),
        },
        "dielectric" => Bsdf::Dielectric {
            int_ior: ior(reader, &mut properties, "int_ior", BK7_IOR)?,
            ext_ior: ior(reader, &mut properties, "ext_ior", AIR_IOR)?,
        },
        "twosided" => {
            let nested = nested_bsdfs(reader, &properties.objects, node)?;
            match nested.as_slice() {
                [inner] => Bsdf::TwoSided(Box::new(inner.clone())),
                _ => {
                    return Err(reader.error(
                        node,
                        format!(
                            "a twosided bsdf wraps exactly one nested <bsdf> or <ref>, found {}",
                            nested.len()
                        ),
                    ));
                }
            }
        }
        _ => {
            reader.warn_at(
                reader.position(node),
                format!(
                    "bsdf type \"{type_name}\" is not one of Mitsuba 3's (diffuse, conductor, \
                     dielectric, twosided): kept as is for a chapter that knows it"
                ),
            );
            Bsdf::Other {
                type_name: type_name.clone(),
                properties: properties.take_raw(),
            }
        }
    };
    properties.finish(reader);
    if let Some(id) = reader.attribute(node, "id")? {
        if reader.bsdfs_by_id.contains_key(&id) {
            return Err(reader.error(node, format!("a bsdf with id \"{id}\" is already defined")));
        }
        reader.bsdfs_by_id.insert(id, bsdf.clone());
    }
    Ok(bsdf)
}

/// The BSDFs among `objects` (inline `<bsdf>` or `<ref>`); any other object is an error.
pub(super) fn nested_bsdfs(
    reader: &mut Reader,
    objects: &[Node],
    parent: Node,
) -> Result<Vec<Bsdf>, SceneError> {
    let mut bsdfs = Vec::new();
    for &object in objects {
        match object.tag_name().name() {
            "bsdf" => bsdfs.push(read_bsdf(reader, object)?),
            "ref" => bsdfs.push(resolve_ref(reader, object)?),
            tag => {
                let parent_tag = parent.tag_name().name();
                return Err(reader.error(
                    object,
                    format!("<{tag}> is not allowed inside <{parent_tag}>"),
                ));
            }
        }
    }
    Ok(bsdfs)
}

/// The BSDF a `<ref id="..."/>` names; it must be defined earlier in the file.
pub(super) fn resolve_ref(reader: &Reader, node: Node) -> Result<Bsdf, SceneError> {
    let id = reader.required_attribute(node, "id")?;
    reader.bsdfs_by_id.get(&id).cloned().ok_or_else(|| {
        reader.error(
            node,
            format!(
                "<ref id=\"{id}\"> names no bsdf defined before it: define \
                 <bsdf type=\"...\" id=\"{id}\"> earlier in the file"
            ),
        )
    })
}

/// An index of refraction given as a `<float>` or as a `<string>` naming a material.
fn ior(
    reader: &Reader,
    properties: &mut Properties,
    name: &str,
    default: f32,
) -> Result<f32, SceneError> {
    let Some(position) = properties.position_of(name) else {
        return Ok(default);
    };
    let value = if let Ok(Some(named)) = properties.string(reader, name) {
        match (named_ior(&named), parse_float(&named)) {
            (Some(ior), _) => ior,
            (None, Ok(ior)) => ior,
            (None, Err(_)) => {
                let names = named_ior_names();
                return Err(reader.error_at(
                    position,
                    format!(
                        "unknown material \"{named}\" for {name}: give a number or one of {}",
                        names.join(", ")
                    ),
                ));
            }
        }
    } else {
        properties.float(reader, name)?.unwrap_or(default)
    };
    if value <= 0.0 {
        return Err(reader.error_at(position, format!("{name} must be positive, found {value}")));
    }
    Ok(value)
}
