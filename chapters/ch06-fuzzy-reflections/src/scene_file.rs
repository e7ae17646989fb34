//! Scenes from Mitsuba 3 XML files, with rough materials.
//!
//! Mitsuba 3 describes rough metal and rough glass with microfacet models (`roughconductor`,
//! `roughdielectric`): a surface of tiny mirror facets whose slopes are spread by a width
//! `alpha`. This chapter's lobes are Phong's `cos^n` instead. The two correspond for the
//! Beckmann distribution by `n = 2 / alpha² - 2` (Walter et al. 2007, "Microfacet models for
//! refraction through rough surfaces"), which gives lobes of about the same width; their
//! shapes, their brightness at grazing angles and their Fresnel colouring still differ, so
//! such a file renders *like* Mitsuba's, not *as* Mitsuba's, and the conversion says so.
//!
//! The workbook also reads `<bsdf type="phong">` (Mitsuba 0.6's name, its specular lobe
//! only): `exponent` (default 30) and `specular_reflectance` (default 1), exactly this
//! chapter's glossy material. Everything else goes through chapter 05's conversion: still and
//! moving shapes, the lens, the filter, the point lights; rough materials are stood in for
//! while it runs, then put in place, shape by shape in the order it lays them out.

use crate::material::{Glossy, Material, RoughGlass, check_exponent};
use crate::scene::FuzzyScene;
use ch03_anti_aliasing::{PixelSamplerKind, ReconstructionFilter};
use ch04_depth_of_field::Lens;
use common::scene::{
    Bsdf, PropertyValue, SceneDescription, ShapeDescription, named_ior, named_ior_names,
    world_shapes,
};
use glam::Vec3;

/// A scene ready for the fuzzy tracer, and what the conversion had to say about it.
pub struct ConvertedScene {
    /// The scene.
    pub scene: FuzzyScene,
    /// The lens of the file's sensor.
    pub lens: Lens,
    /// The film's reconstruction filter.
    pub filter: ReconstructionFilter,
    /// Samples per pixel the file asks for.
    pub spp: u64,
    /// The pixel sampler closest to the file's `<sampler>` type.
    pub sampler: PixelSamplerKind,
    /// Light the method leaves out, approximations, and settings it ignores.
    pub notes: Vec<String>,
}

/// Mitsuba 3's default `alpha` of its rough BSDFs.
const DEFAULT_ALPHA: f32 = 0.1;
/// Mitsuba 0.6's default Phong exponent.
const DEFAULT_PHONG_EXPONENT: f32 = 30.0;

// ANCHOR: convert
/// Converts a description with rough materials, or says why it cannot.
pub fn convert(description: &SceneDescription) -> Result<ConvertedScene, String> {
    let mut notes = Vec::new();
    // This chapter's material of each shape of the file; `None` where chapter 01's is used.
    let mut fuzzy = Vec::with_capacity(description.shapes.len());
    for (index, shape) in description.shapes.iter().enumerate() {
        let name = format!("shape {} ({})", index + 1, shape.position);
        fuzzy.push(fuzzy_material(&shape.bsdf, &mut notes).map_err(|e| format!("{name}: {e}"))?);
    }
    let mut smooth = description.clone();
    for (shape, material) in smooth.shapes.iter_mut().zip(&fuzzy) {
        if material.is_some() {
            shape.bsdf = Bsdf::mitsuba_default(); // a stand-in that chapter 01 converts
        }
    }
    let converted = ch05_motion_blur::scene_file::convert(&smooth)?;
    notes.extend(converted.notes);

    // Chapter 05 lays the shapes out as: the still shapes in file order, then the moving
    // ones in file order, each as many shapes as it has pieces (a cube six, a mesh one per
    // triangle). Chapter 01's materials are taken from its conversion, fuzzy ones put in.
    let still = |shape: &ShapeDescription| shape.to_world_keyframes.is_empty();
    let in_layout_order = description
        .shapes
        .iter()
        .zip(&fuzzy)
        .filter(|(shape, _)| still(shape))
        .chain(
            description
                .shapes
                .iter()
                .zip(&fuzzy)
                .filter(|(shape, _)| !still(shape)),
        );
    let smooth_materials = &converted.world.scene.materials;
    let mut materials = Vec::with_capacity(smooth_materials.len());
    for (shape, material) in in_layout_order {
        let pieces = world_shapes(shape)
            .map_err(|e| format!("shape at {}: {e}", shape.position))?
            .len();
        for _ in 0..pieces {
            let index = materials.len();
            let Some(&smooth) = smooth_materials.get(index) else {
                return Err(format!(
                    "internal error: chapter 05's conversion made {} shapes, fewer than the file's pieces",
                    smooth_materials.len()
                ));
            };
            materials.push(material.unwrap_or(Material::Smooth(smooth)));
        }
    }
    Ok(ConvertedScene {
        scene: FuzzyScene::new(converted.world, materials)?,
        lens: converted.lens,
        filter: converted.filter,
        spp: converted.spp,
        sampler: converted.sampler,
        notes,
    })
}
// ANCHOR_END: convert

/// This chapter's material for a rough BSDF; `None` for the smooth ones chapter 01 converts;
/// an error for what no chapter renders.
fn fuzzy_material(bsdf: &Bsdf, notes: &mut Vec<String>) -> Result<Option<Material>, String> {
    match bsdf {
        Bsdf::TwoSided(inner) => Ok(match fuzzy_material(inner, notes)? {
            Some(Material::Glossy(glossy)) => Some(Material::Glossy(Glossy {
                two_sided: true,
                ..glossy
            })),
            other => other,
        }),
        Bsdf::Other {
            type_name,
            properties,
        } => {
            let props = Props {
                type_name,
                properties,
            };
            match type_name.as_str() {
                "roughconductor" => {
                    props.only(&[
                        "alpha",
                        "distribution",
                        "material",
                        "specular_reflectance",
                        "sample_visible",
                    ])?;
                    if let Some(material) = props.string("material")?
                        && material != "none"
                    {
                        return Err(format!(
                            "the rough conductor `{material}` needs measured metal data; this chapter has material=\"none\" with a specular_reflectance"
                        ));
                    }
                    let exponent = exponent_of_alpha(&props, notes)?;
                    Ok(Some(Material::Glossy(Glossy {
                        reflectance: props.rgb("specular_reflectance")?.unwrap_or(Vec3::ONE),
                        exponent,
                        two_sided: false,
                    })))
                }
                "roughdielectric" => {
                    props.only(&[
                        "alpha",
                        "distribution",
                        "int_ior",
                        "ext_ior",
                        "sample_visible",
                    ])?;
                    let exponent = exponent_of_alpha(&props, notes)?;
                    Ok(Some(Material::RoughGlass(RoughGlass {
                        int_ior: props.ior("int_ior", 1.5046)?,
                        ext_ior: props.ior("ext_ior", 1.000277)?,
                        exponent,
                    })))
                }
                "phong" => {
                    props.only(&["exponent", "specular_reflectance"])?;
                    let exponent = props.float("exponent")?.unwrap_or(DEFAULT_PHONG_EXPONENT);
                    Ok(Some(Material::Glossy(Glossy {
                        reflectance: props.rgb("specular_reflectance")?.unwrap_or(Vec3::ONE),
                        exponent: check_exponent(exponent).map_err(|e| format!("phong: {e}"))?,
                        two_sided: false,
                    })))
                }
                _ => Err(format!(
                    "the bsdf `{type_name}` is not one this chapter renders: it knows Mitsuba 3's roughconductor and roughdielectric, and phong (the workbook's extension)"
                )),
            }
        }
        _ => Ok(None),
    }
}

/// The `cos^n` exponent equivalent to a Beckmann `alpha`, with a note of the approximation.
fn exponent_of_alpha(props: &Props, notes: &mut Vec<String>) -> Result<f32, String> {
    if let Some(distribution) = props.string("distribution")?
        && distribution != "beckmann"
        && distribution != "ggx"
    {
        return Err(format!(
            "{}: unknown microfacet distribution `{distribution}` (Mitsuba 3 has beckmann and ggx)",
            props.type_name
        ));
    }
    let alpha = props.float("alpha")?.unwrap_or(DEFAULT_ALPHA);
    if !(alpha.is_finite() && alpha > 0.0) {
        return Err(format!(
            "{}: alpha must be a positive number, found {alpha}",
            props.type_name
        ));
    }
    let exponent = beckmann_alpha_to_exponent(alpha);
    notes.push(format!(
        "{} with alpha {alpha} is rendered as a cos^n lobe of exponent {exponent:.1} (n = 2/alpha^2 - 2): about as wide as Mitsuba's microfacet lobe, not the same shape",
        props.type_name
    ));
    Ok(exponent)
}

/// The Phong exponent whose lobe is about as wide as a Beckmann distribution of roughness
/// `alpha`: `n = 2 / alpha² - 2`, never below 0 (alpha above 1 is rougher than any lobe).
pub fn beckmann_alpha_to_exponent(alpha: f32) -> f32 {
    (2.0 / (alpha * alpha) - 2.0).max(0.0)
}

/// The raw properties of a BSDF outside Mitsuba 3's subset, read with messages that name
/// the BSDF and the property.
struct Props<'a> {
    type_name: &'a str,
    properties: &'a [(String, PropertyValue)],
}

impl Props<'_> {
    fn get(&self, name: &str) -> Option<&PropertyValue> {
        self.properties
            .iter()
            .find(|(key, _)| key == name)
            .map(|(_, value)| value)
    }

    /// Refuses any property not in `known`: a typo must not silently change the material.
    fn only(&self, known: &[&str]) -> Result<(), String> {
        match self
            .properties
            .iter()
            .find(|(key, _)| !known.contains(&key.as_str()))
        {
            Some((key, _)) => Err(format!(
                "{} has no property `{key}` (it takes {})",
                self.type_name,
                known.join(", ")
            )),
            None => Ok(()),
        }
    }

    fn float(&self, name: &str) -> Result<Option<f32>, String> {
        match self.get(name) {
            None => Ok(None),
            Some(PropertyValue::Float(value)) => Ok(Some(*value)),
            Some(PropertyValue::Integer(value)) => Ok(Some(*value as f32)),
            Some(other) => Err(self.wrong_kind(name, "a <float>", other)),
        }
    }

    fn string(&self, name: &str) -> Result<Option<&str>, String> {
        match self.get(name) {
            None => Ok(None),
            Some(PropertyValue::String(value)) => Ok(Some(value)),
            Some(other) => Err(self.wrong_kind(name, "a <string>", other)),
        }
    }

    fn rgb(&self, name: &str) -> Result<Option<Vec3>, String> {
        match self.get(name) {
            None => Ok(None),
            Some(PropertyValue::Rgb(value)) => Ok(Some(*value)),
            Some(PropertyValue::Float(value)) => Ok(Some(Vec3::splat(*value))),
            Some(other) => Err(self.wrong_kind(name, "an <rgb>", other)),
        }
    }

    /// An index of refraction: a number, or a material Mitsuba knows by name.
    fn ior(&self, name: &str, default: f32) -> Result<f32, String> {
        let value = match self.get(name) {
            None => default,
            Some(PropertyValue::String(text)) => named_ior(text)
                .or_else(|| text.trim().parse().ok())
                .ok_or_else(|| {
                    format!(
                        "{}: unknown material \"{text}\" for {name}: give a number or one of {}",
                        self.type_name,
                        named_ior_names().join(", ")
                    )
                })?,
            Some(_) => self.float(name)?.unwrap_or(default),
        };
        if !(value.is_finite() && value > 0.0) {
            return Err(format!(
                "{}: {name} must be a positive number, found {value}",
                self.type_name
            ));
        }
        Ok(value)
    }

    fn wrong_kind(&self, name: &str, expected: &str, found: &PropertyValue) -> String {
        format!(
            "{}: `{name}` must be {expected}, found {found:?}",
            self.type_name
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn beckmann_roughness_maps_to_phong_exponents() {
        approx::assert_relative_eq!(beckmann_alpha_to_exponent(0.1), 198.0, max_relative = 1e-5);
        approx::assert_relative_eq!(
            beckmann_alpha_to_exponent(1e-3),
            2e6 - 2.0,
            max_relative = 1e-5
        );
        assert_eq!(beckmann_alpha_to_exponent(1.0), 0.0);
        assert_eq!(beckmann_alpha_to_exponent(3.0), 0.0);
    }
}
