//! `<bsdf>` and `<ref>`: materials, inline or named by `id` and referenced later.

use super::element::Element;
use glam::Vec3;

use super::error::SceneError;
use super::properties::Properties;
use super::reader::Reader;
use super::values::parse_float;
use crate::scene::{
    Glossy, Material, Microfacet, MicrofacetDistribution, RoughGlass, check_exponent,
};

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

/// The BSDF types the workbook renders, for messages.
const KNOWN_BSDFS: &str =
    "diffuse, conductor, dielectric, twosided, phong, roughconductor and roughdielectric";

/// Mitsuba 3's default `alpha` of its rough BSDFs.
const DEFAULT_ALPHA: f32 = 0.1;
/// Mitsuba 0.6's default Phong exponent.
const DEFAULT_PHONG_EXPONENT: f32 = 30.0;

/// Reads a `<bsdf>` element into the material it describes. One with an `id` is read once,
/// the first time it is met or referenced; every later `<ref>` gets the same material.
///
/// Mitsuba 3's rough BSDFs (`roughconductor`, `roughdielectric`) become `cos^n` lobes of about
/// the same width (see [`Microfacet`]), remembering the roughness they stand in for; the
/// workbook's `phong` (Mitsuba 0.6's name and exponent, a specular lobe only) is the glossy lobe
/// itself, normalised as chapter 06's density `(n + 1) / 2π cos^n` rather than as 0.6's Phong.
pub(super) fn read_bsdf<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
) -> Result<Material, SceneError> {
    let Some(id) = reader.attribute(node, "id")? else {
        return read_bsdf_element(reader, node);
    };
    if let Some(material) = reader.bsdfs_by_id.get(&id) {
        return Ok(*material);
    }
    reader.start_reading(node, &id)?;
    let material = read_bsdf_element(reader, node);
    reader.done_reading(&id);
    let material = material?;
    reader.bsdfs_by_id.insert(id, material);
    Ok(material)
}

/// Reads the `<bsdf>` element `node` itself, however often its id is referenced.
fn read_bsdf_element<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
) -> Result<Material, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    let mut properties = Properties::read(reader, node, format!("{type_name} bsdf"))?;
    if let (false, Some(object)) = (type_name == "twosided", properties.objects.first()) {
        let tag = object.name();
        return Err(reader.error(object, format!("a {type_name} bsdf cannot contain <{tag}>")));
    }
    let material = match type_name.as_str() {
        "diffuse" => Material::diffuse(
            properties
                .rgb(reader, "reflectance")?
                .unwrap_or(Vec3::splat(0.5)),
        ),
        "conductor" => {
            no_measured_metal(reader, node, &mut properties, "conductor")?;
            Material::Mirror {
                reflectance: properties
                    .rgb(reader, "specular_reflectance")?
                    .unwrap_or(Vec3::ONE),
            }
        }
        "dielectric" => Material::Dielectric {
            int_ior: ior(reader, &mut properties, "int_ior", BK7_IOR)?,
            ext_ior: ior(reader, &mut properties, "ext_ior", AIR_IOR)?,
        },
        "phong" => {
            let exponent = properties
                .float(reader, "exponent")?
                .unwrap_or(DEFAULT_PHONG_EXPONENT);
            let exponent = check_exponent(exponent).map_err(|message| {
                let position = properties
                    .position_of("exponent")
                    .unwrap_or(reader.position(node));
                reader.error_at(position, format!("phong: {message}"))
            })?;
            Material::Glossy(Glossy {
                reflectance: properties
                    .rgb(reader, "specular_reflectance")?
                    .unwrap_or(Vec3::ONE),
                exponent,
                two_sided: false,
                stands_in_for: None,
            })
        }
        "roughconductor" => {
            no_measured_metal(reader, node, &mut properties, "roughconductor")?;
            let microfacet = microfacet(reader, node, &mut properties)?;
            Material::Glossy(Glossy {
                reflectance: properties
                    .rgb(reader, "specular_reflectance")?
                    .unwrap_or(Vec3::ONE),
                exponent: microfacet.lobe_exponent(),
                two_sided: false,
                stands_in_for: Some(microfacet),
            })
        }
        "roughdielectric" => {
            let microfacet = microfacet(reader, node, &mut properties)?;
            Material::RoughGlass(RoughGlass {
                int_ior: ior(reader, &mut properties, "int_ior", BK7_IOR)?,
                ext_ior: ior(reader, &mut properties, "ext_ior", AIR_IOR)?,
                exponent: microfacet.lobe_exponent(),
                stands_in_for: Some(microfacet),
            })
        }
        "twosided" => {
            let nested = nested_bsdfs(reader, &properties.objects, node)?;
            match nested.as_slice() {
                [inner] => two_sided(*inner),
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
            return Err(reader.error(
                node,
                format!(
                    "the bsdf type \"{type_name}\" is not one the workbook renders: it knows \
                     {KNOWN_BSDFS}"
                ),
            ));
        }
    };
    if matches!(
        type_name.as_str(),
        "phong" | "roughconductor" | "roughdielectric"
    ) {
        properties.finish_strict(reader)?;
    } else {
        properties.finish(reader);
    }
    Ok(material)
}

/// The material `inner` reflecting on both sides. Matte and glossy surfaces get a back face;
/// mirrors and glass are what they were (a mirror reflects on its front side only, and glass
/// has two sides already).
fn two_sided(inner: Material) -> Material {
    match inner {
        Material::Diffuse { albedo, .. } => Material::two_sided_diffuse(albedo),
        Material::CheckeredDiffuse { checkerboard, .. } => Material::CheckeredDiffuse {
            checkerboard,
            two_sided: true,
        },
        Material::Glossy(glossy) => Material::Glossy(Glossy {
            two_sided: true,
            ..glossy
        }),
        other => other,
    }
}

/// Refuses a conductor made of a named metal: its colour needs measured spectral data the
/// workbook does not have; `material="none"` (the default) is a perfect mirror.
fn no_measured_metal(
    reader: &Reader,
    node: &Element,
    properties: &mut Properties,
    type_name: &str,
) -> Result<(), SceneError> {
    match properties.string(reader, "material")? {
        Some(metal) if metal != "none" => {
            let position = properties
                .position_of("material")
                .unwrap_or(reader.position(node));
            Err(reader.error_at(
                position,
                format!(
                    "the {type_name} `{metal}` needs measured metal data; the workbook has the \
                     perfect mirror, material=\"none\", with a specular_reflectance"
                ),
            ))
        }
        _ => Ok(()),
    }
}

/// The `distribution` and `alpha` of a rough BSDF.
fn microfacet(
    reader: &Reader,
    node: &Element,
    properties: &mut Properties,
) -> Result<Microfacet, SceneError> {
    let at = |properties: &Properties, name: &str| {
        properties
            .position_of(name)
            .unwrap_or(reader.position(node))
    };
    let distribution = match properties.string(reader, "distribution")?.as_deref() {
        None | Some("beckmann") => MicrofacetDistribution::Beckmann,
        Some("ggx") => MicrofacetDistribution::Ggx,
        Some(other) => {
            return Err(reader.error_at(
                at(properties, "distribution"),
                format!(
                    "unknown microfacet distribution `{other}` (Mitsuba 3 has beckmann and ggx)"
                ),
            ));
        }
    };
    if properties.position_of("alpha_u").is_some() || properties.position_of("alpha_v").is_some() {
        return Err(reader.error_at(
            at(properties, "alpha_u"),
            "alpha_u and alpha_v (an anisotropic roughness) are not rendered: give one alpha",
        ));
    }
    // Mitsuba's `sample_visible` says how it samples, not what the surface is.
    properties.boolean(reader, "sample_visible")?;
    let alpha = properties.float(reader, "alpha")?.unwrap_or(DEFAULT_ALPHA);
    if !(alpha.is_finite() && alpha > 0.0) {
        return Err(reader.error_at(
            at(properties, "alpha"),
            format!("alpha must be a positive number, found {alpha}"),
        ));
    }
    Ok(Microfacet {
        distribution,
        alpha,
    })
}

/// The BSDFs among `objects` (inline `<bsdf>` or `<ref>` to one); any other object is an error.
pub(super) fn nested_bsdfs<'a>(
    reader: &mut Reader<'a>,
    objects: &[&'a Element],
    parent: &Element,
) -> Result<Vec<Material>, SceneError> {
    let mut bsdfs = Vec::new();
    for &object in objects {
        let target = reader.dereference(object)?;
        match target.name() {
            "bsdf" => bsdfs.push(read_bsdf(reader, target)?),
            tag => {
                let parent_tag = parent.name();
                let what = if object.has_name("ref") {
                    format!("<ref> names a <{tag}>, which is not allowed inside <{parent_tag}>")
                } else {
                    format!("<{tag}> is not allowed inside <{parent_tag}>")
                };
                return Err(reader.error(object, what));
            }
        }
    }
    Ok(bsdfs)
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
