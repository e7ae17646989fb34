//! `<bsdf>` and `<ref>`: materials, inline or named by `id` and referenced later.

use super::element::Element;
use glam::Vec3;

use super::error::SceneError;
use super::properties::Properties;
use super::reader::Reader;
use super::textures::{NamedTexture, refuse_texture, take_textures};
use super::values::parse_float;
use common::scene::{
    AlphaTexture, Conductor, Glossy, Mask, Material, Microfacet, MicrofacetDistribution, Opacity,
    Plastic, RoughGlass, Texture, TintedGlass, check_exponent,
};
use common::scene::{named_metal, named_metal_names};

/// Mitsuba's default interior index of refraction of glass, BK7.
const BK7_IOR: f32 = 1.5046;
/// Mitsuba's default exterior index of refraction, air.
const AIR_IOR: f32 = 1.000277;
/// Mitsuba's default interior index of refraction of plastic, polypropylene.
const POLYPROPYLENE_IOR: f32 = 1.49;

/// Indices of refraction that may be given by name instead of a number: Mitsuba 3's list
/// (`include/mitsuba/render/ior.h`, after Hecht's *Optics*: measured at about 589 nm between
/// 0 and 20 degrees Celsius), in its order and spelling.
const NAMED_IORS: &[(&str, f32)] = &[
    ("vacuum", 1.0),
    ("helium", 1.000036),
    ("hydrogen", 1.000132),
    ("air", AIR_IOR),
    ("carbon dioxide", 1.00045),
    ("water", 1.3330),
    ("acetone", 1.36),
    ("ethanol", 1.361),
    ("carbon tetrachloride", 1.461),
    ("glycerol", 1.4729),
    ("benzene", 1.501),
    ("silicone oil", 1.52045),
    ("bromine", 1.661),
    ("water ice", 1.31),
    ("fused quartz", 1.458),
    ("pyrex", 1.470),
    ("acrylic glass", 1.49),
    ("polypropylene", POLYPROPYLENE_IOR),
    ("bk7", BK7_IOR),
    ("sodium chloride", 1.544),
    ("amber", 1.55),
    ("pet", 1.5750),
    ("diamond", 2.419),
];

/// The index of refraction of a material Mitsuba knows by name (`bk7`, `water`, ...; in any
/// case, as Mitsuba compares them in lower case), also for chapters that read the properties
/// of a BSDF outside the subset.
pub fn named_ior(name: &str) -> Option<f32> {
    let name = name.to_lowercase();
    NAMED_IORS
        .iter()
        .find(|(material, _)| *material == name)
        .map(|&(_, ior)| ior)
}

/// The names [`named_ior`] knows, for error messages.
pub fn named_ior_names() -> Vec<&'static str> {
    NAMED_IORS.iter().map(|(material, _)| *material).collect()
}

/// The BSDF types the workbook renders.
const KNOWN_BSDF_TYPES: &[&str] = &[
    "diffuse",
    "conductor",
    "dielectric",
    "thindielectric",
    "plastic",
    "twosided",
    "phong",
    "roughconductor",
    "roughplastic",
    "roughdielectric",
    "mask",
];

/// The BSDF types the workbook renders, for messages.
const KNOWN_BSDFS: &str = "diffuse, conductor, dielectric, thindielectric, plastic, twosided, \
     phong, roughconductor, roughplastic, roughdielectric and mask";

/// Mitsuba 3's default `alpha` of its rough BSDFs.
const DEFAULT_ALPHA: f32 = 0.1;
/// Mitsuba 0.6's default Phong exponent.
const DEFAULT_PHONG_EXPONENT: f32 = 30.0;

/// Reads a `<bsdf>` element into the material it describes. One with an `id` is read once,
/// the first time it is met or referenced; every later `<ref>` gets the same material.
///
/// Mitsuba 3's rough BSDFs keep their microfacet roughness: `roughconductor` and
/// `roughplastic` as the `roughness` of a [`Conductor`] or [`Plastic`], `roughdielectric` as
/// a `cos^n` lobe of about the same width (see [`Microfacet`]) remembering the roughness it
/// stands in for; the workbook's `phong` (Mitsuba 0.6's name and exponent, a specular lobe
/// only) is the glossy lobe itself, normalised as chapter 06's density `(n + 1) / 2π cos^n`
/// rather than as 0.6's Phong.
pub(super) fn read_bsdf<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
) -> Result<Material, SceneError> {
    let Some(id) = reader.attribute(node, "id")? else {
        return read_bsdf_element(reader, node);
    };
    if let Some(material) = reader.bsdfs_by_id.get(&id) {
        return Ok(material.clone());
    }
    reader.start_reading(node, &id)?;
    let material = read_bsdf_element(reader, node);
    reader.done_reading(&id);
    let material = material?;
    reader.bsdfs_by_id.insert(id, material.clone());
    Ok(material)
}

/// Reads the `<bsdf>` element `node` itself, however often its id is referenced.
fn read_bsdf_element<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
) -> Result<Material, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    // Named first, before its contents: a nested <bsdf> or a texture says nothing.
    let unknown_type = |reader: &Reader| {
        reader.error(
            node,
            format!("unknown bsdf type \"{type_name}\": the workbook renders {KNOWN_BSDFS}"),
        )
    };
    if !KNOWN_BSDF_TYPES.contains(&type_name.as_str()) {
        return Err(unknown_type(reader));
    }
    let mut properties = Properties::read(reader, node, format!("{type_name} bsdf"))?;
    let mut textures = take_textures(reader, &mut properties.objects)?;
    let mut texture_of = |name: &str| {
        texturable_parameters(&type_name)
            .contains(&name)
            .then(|| take_named(&mut textures, name))
            .flatten()
    };
    let reflectance_texture = texture_of("reflectance");
    let diffuse_texture = texture_of("diffuse_reflectance");
    let specular_texture = texture_of("specular_reflectance");
    let transmittance_texture = texture_of("specular_transmittance");
    let opacity_texture = texture_of("opacity");
    let width_textures = ["alpha", "alpha_u", "alpha_v"].map(&mut texture_of);
    if let Some(texture) = textures.first() {
        return Err(refuse_texture(
            reader,
            &format!("{type_name} bsdf"),
            texture,
        ));
    }
    let wraps_bsdfs = matches!(type_name.as_str(), "twosided" | "mask");
    if let (false, Some(object)) = (wraps_bsdfs, properties.objects.first()) {
        let tag = object.name();
        return Err(reader.error(object, format!("a {type_name} bsdf cannot contain <{tag}>")));
    }
    let material = match type_name.as_str() {
        "diffuse" => diffuse(reader, &mut properties, reflectance_texture)?,
        "conductor" => conductor(reader, node, &mut properties, specular_texture, None)?,
        "dielectric" => glass(
            reader,
            &mut properties,
            [specular_texture, transmittance_texture],
            None,
        )?,
        "thindielectric" => {
            for unrendered in ["specular_reflectance", "specular_transmittance"] {
                if let Some(position) = properties.position_of(unrendered) {
                    return Err(reader.error_at(
                        position,
                        format!(
                            "thindielectric: `{unrendered}` (a factor against physics) is not \
                             rendered; leave it out"
                        ),
                    ));
                }
            }
            Material::ThinDielectric {
                int_ior: ior(reader, &mut properties, "int_ior", BK7_IOR)?,
                ext_ior: ior(reader, &mut properties, "ext_ior", AIR_IOR)?,
            }
        }
        "plastic" => plastic(
            reader,
            &mut properties,
            [diffuse_texture, specular_texture],
            None,
        )?,
        "roughplastic" => {
            let microfacet =
                microfacet(reader, node, &mut properties, Widths::One, width_textures)?;
            plastic(
                reader,
                &mut properties,
                [diffuse_texture, specular_texture],
                Some(microfacet),
            )?
        }
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
            let microfacet = microfacet(
                reader,
                node,
                &mut properties,
                Widths::OneOrTwo,
                width_textures,
            )?;
            conductor(
                reader,
                node,
                &mut properties,
                specular_texture,
                Some(microfacet),
            )?
        }
        "roughdielectric" => {
            let microfacet = microfacet(
                reader,
                node,
                &mut properties,
                Widths::OneOrTwo,
                width_textures,
            )?;
            glass(
                reader,
                &mut properties,
                [specular_texture, transmittance_texture],
                Some(microfacet),
            )?
        }
        "twosided" => {
            let nested = nested_bsdfs(reader, &properties.objects, node)?;
            match nested.as_slice() {
                [Material::Mask(_)] => {
                    return Err(reader.error(
                        node,
                        "a twosided bsdf cannot wrap a mask (Mitsuba 3 refuses a nested material \
                         that lets light through); put the twosided inside the mask instead",
                    ));
                }
                [inner] => two_sided(inner.clone()),
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
        "mask" => mask(reader, node, &mut properties, opacity_texture)?,
        _ => return Err(unknown_type(reader)),
    };
    if matches!(
        type_name.as_str(),
        "phong"
            | "roughconductor"
            | "roughdielectric"
            | "thindielectric"
            | "plastic"
            | "roughplastic"
            | "mask"
    ) {
        properties.finish_strict(reader)?;
    } else {
        properties.finish(reader);
    }
    Ok(material)
}

/// A `diffuse` bsdf: its reflectance a colour (0.5 when none is given, as in Mitsuba) or a
/// texture, not both.
fn diffuse(
    reader: &Reader,
    properties: &mut Properties,
    texture: Option<NamedTexture>,
) -> Result<Material, SceneError> {
    let reflectance = colour_or_texture(
        reader,
        properties,
        "reflectance",
        Vec3::splat(0.5),
        texture,
        "diffuse",
    )?;
    Ok(match reflectance {
        (_, Some(texture)) => Material::TexturedDiffuse {
            texture,
            two_sided: false,
        },
        (albedo, None) => Material::diffuse(albedo),
    })
}

/// The parameters of a BSDF type that may be textures: each then multiplies the parameter's
/// colour point by point, read at every hit by `Scene::material_at`.
fn texturable_parameters(type_name: &str) -> &'static [&'static str] {
    match type_name {
        "diffuse" => &["reflectance"],
        "conductor" => &["specular_reflectance"],
        "roughconductor" => &["specular_reflectance", "alpha", "alpha_u", "alpha_v"],
        "plastic" | "roughplastic" => &["diffuse_reflectance", "specular_reflectance"],
        "dielectric" => &["specular_reflectance", "specular_transmittance"],
        "roughdielectric" => &[
            "specular_reflectance",
            "specular_transmittance",
            "alpha",
            "alpha_u",
            "alpha_v",
        ],
        "mask" => &["opacity"],
        _ => &[],
    }
}

/// A colour parameter that may be a texture: the colour (`default` when absent) and the
/// texture, which then multiplies a colour of 1; both at once is an error, as in Mitsuba.
fn colour_or_texture(
    reader: &Reader,
    properties: &mut Properties,
    name: &str,
    default: Vec3,
    texture: Option<NamedTexture>,
    type_name: &str,
) -> Result<(Vec3, Option<Texture>), SceneError> {
    let colour = properties.rgb(reader, name)?;
    match (colour, texture) {
        (Some(_), Some(texture)) => Err(reader.error(
            texture.node,
            format!("the {type_name} bsdf's {name} is given twice: as a colour and as a texture"),
        )),
        (None, Some(texture)) => Ok((Vec3::ONE, Some(texture.texture))),
        (colour, None) => Ok((colour.unwrap_or(default), None)),
    }
}

/// A `mask` (Mitsuba 3's cut-out): one nested `<bsdf>` or `<ref>`, and its `opacity` a
/// number, a colour (read as its mean, as Mitsuba reads one value of a colour) or a texture,
/// 0.5 when none is given, as in Mitsuba.
fn mask<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
    properties: &mut Properties<'a>,
    texture: Option<NamedTexture>,
) -> Result<Material, SceneError> {
    let colour = properties.rgb(reader, "opacity")?;
    let opacity = match (colour, texture) {
        (None, Some(texture)) => Opacity::Texture(texture.texture),
        (Some(_), Some(texture)) => {
            return Err(reader.error(
                texture.node,
                "the mask's opacity is given twice: as a value and as a texture",
            ));
        }
        (colour, None) => Opacity::Uniform(colour.map_or(0.5, |c| c.element_sum() / 3.0)),
    };
    let nested = nested_bsdfs(reader, &properties.objects, node)?;
    let [nested] = <[Material; 1]>::try_from(nested).map_err(|nested| {
        reader.error(
            node,
            format!(
                "a mask bsdf wraps exactly one nested <bsdf> or <ref>, found {}",
                nested.len()
            ),
        )
    })?;
    Ok(Material::Mask(Mask {
        opacity,
        nested: Box::new(nested),
    }))
}

/// The texture given for `name`, taken out of `textures`.
fn take_named<'a>(textures: &mut Vec<NamedTexture<'a>>, name: &str) -> Option<NamedTexture<'a>> {
    let index = textures.iter().position(|t| t.name == name)?;
    Some(textures.remove(index))
}

/// The material `inner` reflecting on both sides. Matte, glossy, metal and plastic surfaces
/// get a back face; mirrors and glass are what they were (a mirror reflects on its front side
/// only, and glass has two sides already).
fn two_sided(inner: Material) -> Material {
    match inner {
        Material::Diffuse { albedo, .. } => Material::two_sided_diffuse(albedo),
        Material::TexturedDiffuse { texture, .. } => Material::TexturedDiffuse {
            texture,
            two_sided: true,
        },
        Material::Glossy(glossy) => Material::Glossy(Glossy {
            two_sided: true,
            ..glossy
        }),
        Material::Conductor(conductor) => Material::Conductor(Conductor {
            two_sided: true,
            ..conductor
        }),
        Material::Plastic(plastic) => Material::Plastic(Plastic {
            two_sided: true,
            ..plastic
        }),
        other => other,
    }
}

/// A `conductor` (`roughness` `None`) or `roughconductor`: its metal named by `material`
/// (Mitsuba's list, see [`named_metal`]) or given by `eta` and `k` (each an `<rgb>` or a
/// `<float>`; Mitsuba's defaults are `eta = 0` and `k = 1`, which reflect everything).
///
/// A smooth conductor of the default `material="none"` without `eta` or `k` is the perfect
/// mirror it is in Mitsuba, a [`Material::Mirror`] of `specular_reflectance`.
fn conductor(
    reader: &Reader,
    node: &Element,
    properties: &mut Properties,
    specular_texture: Option<NamedTexture>,
    roughness: Option<Microfacet>,
) -> Result<Material, SceneError> {
    let type_name = if roughness.is_some() {
        "roughconductor"
    } else {
        "conductor"
    };
    let at = |properties: &Properties, name: &str| {
        properties
            .position_of(name)
            .unwrap_or(reader.position(node))
    };
    let (specular_reflectance, specular_texture) = colour_or_texture(
        reader,
        properties,
        "specular_reflectance",
        Vec3::ONE,
        specular_texture,
        type_name,
    )?;
    let material = properties
        .string(reader, "material")?
        .unwrap_or_else(|| "none".to_string());
    let eta = properties.rgb(reader, "eta")?;
    let k = properties.rgb(reader, "k")?;
    let (eta, k) = if material == "none" {
        if roughness.is_none() && eta.is_none() && k.is_none() && specular_texture.is_none() {
            return Ok(Material::Mirror {
                reflectance: specular_reflectance,
            });
        }
        (eta.unwrap_or(Vec3::ZERO), k.unwrap_or(Vec3::ONE))
    } else {
        if eta.is_some() || k.is_some() {
            let given = if eta.is_some() { "eta" } else { "k" };
            return Err(reader.error_at(
                at(properties, given),
                format!(
                    "{type_name}: give either a named material or eta and k, not both \
                     (material is \"{material}\")"
                ),
            ));
        }
        named_metal(&material).ok_or_else(|| {
            reader.error_at(
                at(properties, "material"),
                format!(
                    "{type_name}: unknown material \"{material}\": Mitsuba 3 knows none (a \
                     perfect mirror) and {}",
                    named_metal_names().join(", ")
                ),
            )
        })?
    };
    for (name, value) in [("eta", eta), ("k", k)] {
        if !(value.is_finite() && value.min_element() >= 0.0) {
            return Err(reader.error_at(
                at(properties, name),
                format!("{type_name}: {name} must be finite and not negative, found {value}"),
            ));
        }
    }
    Ok(Material::Conductor(Conductor {
        eta,
        k,
        specular_reflectance,
        specular_texture,
        two_sided: false,
        roughness,
    }))
}

/// A `plastic` (`roughness` `None`) or `roughplastic` with Mitsuba 3's defaults: a base of
/// albedo 0.5 under a coat of polypropylene (1.49) in air, `specular_reflectance` 1,
/// `nonlinear` false.
fn plastic(
    reader: &Reader,
    properties: &mut Properties,
    [diffuse_texture, specular_texture]: [Option<NamedTexture>; 2],
    roughness: Option<Microfacet>,
) -> Result<Material, SceneError> {
    let type_name = if roughness.is_some() {
        "roughplastic"
    } else {
        "plastic"
    };
    let (diffuse_reflectance, diffuse_texture) = colour_or_texture(
        reader,
        properties,
        "diffuse_reflectance",
        Vec3::splat(0.5),
        diffuse_texture,
        type_name,
    )?;
    let (specular_reflectance, specular_texture) = colour_or_texture(
        reader,
        properties,
        "specular_reflectance",
        Vec3::ONE,
        specular_texture,
        type_name,
    )?;
    Ok(Material::Plastic(Plastic {
        diffuse_reflectance,
        specular_reflectance,
        diffuse_texture,
        specular_texture,
        int_ior: ior(reader, properties, "int_ior", POLYPROPYLENE_IOR)?,
        ext_ior: ior(reader, properties, "ext_ior", AIR_IOR)?,
        nonlinear: properties.boolean(reader, "nonlinear")?.unwrap_or(false),
        two_sided: false,
        roughness,
    }))
}

/// A `dielectric` (`roughness` `None`) or `roughdielectric`: plain glass, or, with a
/// `specular_reflectance` or `specular_transmittance` other than 1 (a colour or a texture), a
/// [`TintedGlass`]. Rough plain glass is a [`RoughGlass`] whose `cos^n` lobe (chapters 06
/// and 07) stands in for its roughness.
fn glass(
    reader: &Reader,
    properties: &mut Properties,
    [reflectance_texture, transmittance_texture]: [Option<NamedTexture>; 2],
    roughness: Option<Microfacet>,
) -> Result<Material, SceneError> {
    let type_name = if roughness.is_some() {
        "roughdielectric"
    } else {
        "dielectric"
    };
    let int_ior = ior(reader, properties, "int_ior", BK7_IOR)?;
    let ext_ior = ior(reader, properties, "ext_ior", AIR_IOR)?;
    let (specular_reflectance, reflectance_texture) = colour_or_texture(
        reader,
        properties,
        "specular_reflectance",
        Vec3::ONE,
        reflectance_texture,
        type_name,
    )?;
    let (specular_transmittance, transmittance_texture) = colour_or_texture(
        reader,
        properties,
        "specular_transmittance",
        Vec3::ONE,
        transmittance_texture,
        type_name,
    )?;
    let tinted = specular_reflectance != Vec3::ONE
        || specular_transmittance != Vec3::ONE
        || reflectance_texture.is_some()
        || transmittance_texture.is_some();
    Ok(match (tinted, roughness) {
        (true, roughness) => Material::TintedGlass(TintedGlass {
            int_ior,
            ext_ior,
            specular_reflectance,
            specular_transmittance,
            reflectance_texture,
            transmittance_texture,
            roughness,
        }),
        (false, None) => Material::Dielectric { int_ior, ext_ior },
        (false, Some(microfacet)) => Material::RoughGlass(RoughGlass {
            int_ior,
            ext_ior,
            exponent: microfacet.lobe_exponent(),
            stands_in_for: Some(microfacet),
        }),
    })
}

/// Whether a rough BSDF may have two widths: Mitsuba's `roughconductor` and
/// `roughdielectric` read `alpha_u` and `alpha_v`, its `roughplastic` only `alpha`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Widths {
    /// `alpha`, or `alpha_u` and `alpha_v` together.
    OneOrTwo,
    /// `alpha` only.
    One,
}

/// One width of a rough BSDF as the file gives it.
#[derive(Clone, Copy, Debug)]
enum Width {
    /// A number, the same everywhere.
    Number(f32),
    /// A texture, read at each hit.
    Texture(Texture),
}

/// The `distribution` and the width (`alpha`, or `alpha_u` and `alpha_v`, each a number or,
/// in `textures` in that order, a texture) of a rough BSDF.
fn microfacet(
    reader: &Reader,
    node: &Element,
    properties: &mut Properties,
    widths: Widths,
    textures: [Option<NamedTexture>; 3],
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
    // Mitsuba's `sample_visible` says how it samples, not what the surface is.
    properties.boolean(reader, "sample_visible")?;
    let width = |properties: &mut Properties, name: &str| -> Result<Option<f32>, SceneError> {
        let Some(alpha) = properties.float(reader, name)? else {
            return Ok(None);
        };
        if alpha.is_finite() && alpha > 0.0 {
            Ok(Some(alpha))
        } else {
            Err(reader.error_at(
                at(properties, name),
                format!("{name} must be a positive number, found {alpha}"),
            ))
        }
    };
    let [alpha_texture, alpha_u_texture, alpha_v_texture] = textures;
    let mut width_or_texture =
        |name: &str, texture: Option<NamedTexture>| -> Result<Option<Width>, SceneError> {
            match (width(properties, name)?, texture) {
                (Some(_), Some(texture)) => Err(reader.error(
                    texture.node,
                    format!("{name} is given twice: as a number and as a texture"),
                )),
                (Some(alpha), None) => Ok(Some(Width::Number(alpha))),
                (None, Some(texture)) => Ok(Some(Width::Texture(texture.texture))),
                (None, None) => Ok(None),
            }
        };
    let alpha = width_or_texture("alpha", alpha_texture)?;
    let alpha_u = width_or_texture("alpha_u", alpha_u_texture)?;
    let alpha_v = width_or_texture("alpha_v", alpha_v_texture)?;
    // A textured width keeps a number too, unused, so that the stand-ins of chapters before
    // 08 (which refuse textured widths) have one.
    let number = |width: Width| match width {
        Width::Number(alpha) => alpha,
        Width::Texture(_) => DEFAULT_ALPHA,
    };
    let texture = |width: Width| match width {
        Width::Number(_) => None,
        Width::Texture(texture) => Some(texture),
    };
    let with_textures = |microfacet: Microfacet, u: Width, v: Width| Microfacet {
        alpha_texture: (texture(u).is_some() || texture(v).is_some()).then_some(AlphaTexture {
            u: texture(u),
            v: texture(v),
        }),
        ..microfacet
    };
    let stretched = alpha_u.is_some() || alpha_v.is_some();
    if stretched && widths == Widths::One {
        let name = if alpha_u.is_some() {
            "alpha_u"
        } else {
            "alpha_v"
        };
        return Err(reader.error_at(
            at(properties, name),
            "roughplastic has one roughness in Mitsuba 3 (alpha), not alpha_u and alpha_v",
        ));
    }
    if stretched && alpha.is_some() {
        return Err(reader.error_at(
            at(properties, "alpha"),
            "give either alpha or alpha_u and alpha_v, not both (Mitsuba 3 would leave alpha_u \
             and alpha_v unused)",
        ));
    }
    match (alpha_u, alpha_v) {
        (Some(u), Some(v)) => Ok(with_textures(
            Microfacet::anisotropic(distribution, number(u), number(v)),
            u,
            v,
        )),
        (None, None) => {
            let alpha = alpha.unwrap_or(Width::Number(DEFAULT_ALPHA));
            Ok(with_textures(
                Microfacet::isotropic(distribution, number(alpha)),
                alpha,
                alpha,
            ))
        }
        (Some(_), None) | (None, Some(_)) => {
            let given = if alpha_u.is_some() {
                "alpha_u"
            } else {
                "alpha_v"
            };
            Err(reader.error_at(
                at(properties, given),
                "alpha_u and alpha_v go together: give both (an anisotropic roughness) or one \
                 alpha",
            ))
        }
    }
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
