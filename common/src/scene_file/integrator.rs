//! `<integrator>`: `path` and `direct`.

use super::element::Element;

use super::description::Integrator;
use super::error::SceneError;
use super::properties::Properties;
use super::reader::Reader;

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
        "path" => Integrator::Path {
            max_depth: depth(
                "max_depth",
                -1,
                "-1 (unlimited) or 1 or more (0 would render a black image)",
            )?,
            rr_depth: depth("rr_depth", 5, "1 or more")?,
        },
        "direct" => {
            // Mitsuba's `shading_samples` sets both counts; each may be given apart.
            let shading = properties.integer(reader, "shading_samples")?;
            for name in ["emitter_samples", "bsdf_samples"] {
                let count = properties.integer(reader, name)?.or(shading).unwrap_or(1);
                if count != 1 {
                    let position = properties
                        .position_of(name)
                        .or(properties.position_of("shading_samples"))
                        .unwrap_or(reader.position(node));
                    reader.warn_at(
                        position,
                        format!(
                            "{name} = {count} is rendered as 1 (one light and one BSDF sample \
                             per hit): the same image on average, with more noise than \
                             Mitsuba's at equal samples per pixel"
                        ),
                    );
                }
            }
            Integrator::Direct
        }
        _ => {
            return Err(reader.error(
                node,
                format!(
                    "the integrator type \"{type_name}\" is not one the workbook renders: it \
                     knows Mitsuba's path and direct"
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
