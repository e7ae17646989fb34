//! The top level of a scene: `<scene>` with the files it includes, and the objects in it.

use std::path::Path;

use super::LoadedDescription;
use super::camera::read_sensor;
use super::description::SceneDescription;
use super::element::{Element, read_tree};
use super::error::{SceneError, TextPosition};
use super::integrator::{default_integrator, read_integrator};
use super::lights::{Emitter, read_emitter};
use super::materials::read_bsdf;
use super::reader::Reader;
use super::shapes::read_shape;

/// Objects that may stand at the top level only to be referenced from inside another object
/// (`<sensor>` refers to a `<sampler>`, a `<shape>` to an area `<emitter>`).
const REFERENCED_ONLY: &[&str] = &["sampler", "rfilter", "film", "texture"];

/// Parses the text of a scene file; see [`super::parse_scene`].
pub(super) fn parse_document(
    text: &str,
    file: &Path,
    overrides: &[(String, String)],
) -> Result<LoadedDescription, SceneError> {
    let tree = read_tree(text, file, overrides)?;
    let mut reader = Reader::new(file, &tree)?;

    let mut integrator = None;
    let mut hide_emitters = false;
    let mut integrator_position = None;
    let mut sensor = None;
    let mut shapes = Vec::new();
    let mut emitters = Vec::new();
    let mut set_apart: Vec<&Element> = Vec::new();
    for child in tree.root.children() {
        let tag = child.name();
        match tag {
            "default" => {}
            "integrator" if integrator.is_none() => {
                let (read, hide) = read_integrator(&mut reader, child)?;
                integrator = Some(read);
                hide_emitters = hide;
                integrator_position = Some(reader.position(child));
            }
            "sensor" if sensor.is_none() => sensor = Some(read_sensor(&mut reader, child)?),
            "integrator" | "sensor" => {
                return Err(reader.error(child, format!("the scene has more than one <{tag}>")));
            }
            "shape" => shapes.push(read_shape(&mut reader, child)?),
            "bsdf" => {
                read_bsdf(&mut reader, child)?;
                if child.attribute("id").is_none() {
                    reader.warn_at(
                        reader.position(child),
                        "a top-level <bsdf> without an id cannot be used: give it an id and \
                         <ref> it from a shape",
                    );
                }
            }
            "emitter" => match read_emitter(&mut reader, child)? {
                Emitter::Standalone(emitter) => emitters.push(emitter),
                // An area emitter declared apart is read again where a shape refers to it.
                Emitter::Area(_) if child.attribute("id").is_some() => set_apart.push(child),
                Emitter::Area(_) => {
                    return Err(reader.error(
                        child,
                        "an area emitter must be inside the <shape> that emits, or have an id \
                         that a shape's <ref> names",
                    ));
                }
            },
            _ if REFERENCED_ONLY.contains(&tag) => set_apart.push(child),
            _ => {
                return Err(reader.error(
                    child,
                    format!(
                        "unknown element <{tag}> in <scene>: expected default, path, include, \
                         integrator, sensor, shape, bsdf, emitter, or a sampler, rfilter, film \
                         or texture with an id"
                    ),
                ));
            }
        }
    }
    for element in set_apart {
        let used = element
            .attribute("id")
            .is_some_and(|id| reader.referenced.contains(id));
        if !used {
            let tag = element.name();
            reader.warn_at(
                reader.position(element),
                format!("this <{tag}> is never referenced by a <ref id=\"...\"/>, so it is unused"),
            );
        }
    }
    let sensor = sensor.ok_or_else(|| {
        reader.error_at(
            TextPosition::default(),
            "the scene has no <sensor>: add <sensor type=\"perspective\"> with a fov",
        )
    })?;
    Ok(LoadedDescription {
        scene: SceneDescription {
            integrator: integrator.unwrap_or_else(default_integrator),
            integrator_position,
            hide_emitters,
            sensor,
            shapes,
            emitters,
            bitmaps: reader.bitmaps,
        },
        warnings: reader.warnings,
    })
}
