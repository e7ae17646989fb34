//! `<integrator>`: `path` and `direct`; `volpath` and `volpathmis` are `path`.
//!
//! Mitsuba's volumetric path tracers differ from its `path` only inside participating media,
//! which the loader refuses (a `<medium>` is no element it reads): on surfaces alone they
//! sample lights, BSDFs, MIS and the roulette as `path` does, with the same `max_depth`,
//! `rr_depth` and `hide_emitters`, so a file that names one renders as with `path`.

use super::element::Element;

use super::description::Integrator;
use super::error::SceneError;
use super::properties::Properties;
use super::reader::Reader;
use common::scene::DirectSamples;

/// What Mitsuba 3 uses when the file names no integrator.
pub(super) fn default_integrator() -> Integrator {
    Integrator::Path {
        max_depth: -1,
        rr_depth: 5,
    }
}

/// Reads an `<integrator>`: the light transport, and whether camera rays hide the emitters.
pub(super) fn read_integrator(
    reader: &mut Reader,
    node: &Element,
) -> Result<(Integrator, bool), SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    if let Some(output) = not_radiance(&type_name) {
        return Err(reader.error(
            node,
            format!(
                "the {type_name} integrator writes {output}, not an image of radiance, which is \
                 all the workbook renders: use the path or direct integrator on its own"
            ),
        ));
    }
    let mut properties = Properties::read(reader, node, format!("{type_name} integrator"))?;
    if let Some(object) = properties.objects.first() {
        let tag = object.name();
        return Err(reader.error(
            object,
            format!("<{tag}> is not allowed inside <integrator>"),
        ));
    }
    // Depths the workbook renders: `max_depth` -1 (unlimited) or from 1 (0, which Mitsuba
    // renders black, is refused rather than changed), `rr_depth` from 1 (as Mitsuba demands).
    let mut depth = |name: &str, default: i32, allowed: &str| -> Result<i32, SceneError> {
        let Some(value) = properties.integer(reader, name)? else {
            return Ok(default);
        };
        let position = properties
            .position_of(name)
            .unwrap_or(reader.position(node));
        let unlimited_allowed = name == "max_depth";
        i32::try_from(value)
            .ok()
            .filter(|&depth| depth >= 1 || (unlimited_allowed && depth == -1))
            .ok_or_else(|| {
                reader.error_at(position, format!("{name} must be {allowed}, found {value}"))
            })
    };
    let integrator = match type_name.as_str() {
        "path" | "volpath" | "volpathmis" => Integrator::Path {
            max_depth: depth(
                "max_depth",
                -1,
                "-1 (unlimited) or 1 or more (0 would render a black image)",
            )?,
            rr_depth: depth("rr_depth", 5, "1 or more")?,
        },
        "direct" => Integrator::Direct(direct_samples(reader, node, &mut properties)?),
        _ => {
            return Err(reader.error(
                node,
                format!(
                    "the integrator type \"{type_name}\" is not one the workbook renders: it \
                     knows Mitsuba's path and direct (and volpath and volpathmis, which are path \
                     where there are no participating media)"
                ),
            ));
        }
    };
    let hide_emitters = properties
        .boolean(reader, "hide_emitters")?
        .unwrap_or(false);
    properties.finish(reader);
    Ok((integrator, hide_emitters))
}

/// The sample counts of a `direct` integrator, as Mitsuba reads them: `shading_samples` sets
/// both (it may not be given beside either), `emitter_samples` and `bsdf_samples` one each,
/// 1 by default; a count is a whole number from 0 up to [`MOST_DIRECT_SAMPLES`], and not both
/// may be 0.
fn direct_samples(
    reader: &Reader,
    node: &Element,
    properties: &mut Properties,
) -> Result<DirectSamples, SceneError> {
    let shading = properties.integer(reader, "shading_samples")?;
    let mut count = |name: &str| -> Result<u32, SceneError> {
        let given = properties.integer(reader, name)?;
        let position = properties
            .position_of(name)
            .or(properties.position_of("shading_samples"))
            .unwrap_or(reader.position(node));
        if given.is_some() && shading.is_some() {
            return Err(reader.error_at(
                position,
                format!("{name} cannot be given beside shading_samples, which sets it too"),
            ));
        }
        let value = given.or(shading).unwrap_or(1);
        u32::try_from(value)
            .ok()
            .filter(|&n| n <= MOST_DIRECT_SAMPLES)
            .ok_or_else(|| {
                reader.error_at(
                    position,
                    format!(
                        "{name} must be a whole number from 0 to {MOST_DIRECT_SAMPLES}, found \
                         {value}"
                    ),
                )
            })
    };
    let samples = DirectSamples {
        emitter: count("emitter_samples")?,
        bsdf: count("bsdf_samples")?,
    };
    if samples.emitter + samples.bsdf == 0 {
        return Err(reader.error(
            node,
            "a direct integrator needs at least one emitter or BSDF sample: emitter_samples \
             and bsdf_samples are both 0",
        ));
    }
    Ok(samples)
}

/// The most samples of one kind a `direct` integrator may ask for at each hit: every sample
/// of the film takes that many shadow rays, so more would only hide a typing mistake.
pub const MOST_DIRECT_SAMPLES: u32 = 4096;

/// What an integrator whose output is not an image of radiance writes instead; `None` for
/// every other type.
fn not_radiance(type_name: &str) -> Option<&'static str> {
    match type_name {
        "aov" => Some("extra channels (depth, normals, positions, ...) beside the image"),
        "moment" => Some("the moments of the samples beside the image"),
        "stokes" => Some("the polarisation of the light (Stokes vectors)"),
        "depth" => Some("the distance to the first hit"),
        _ => None,
    }
}
