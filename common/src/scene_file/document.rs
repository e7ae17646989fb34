//! The top level of a scene file: `<scene>`, `<default>`s, and the objects in it.

use std::collections::HashMap;
use std::path::Path;

use roxmltree::{Document, Node};

use super::LoadedDescription;
use super::camera::read_sensor;
use super::description::SceneDescription;
use super::error::{SceneError, TextPosition};
use super::integrator::{default_integrator, read_integrator};
use super::lights::{Emitter, read_emitter};
use super::materials::read_bsdf;
use super::reader::Reader;
use super::shapes::read_shape;

/// Parses the text of a scene file; see [`super::parse_scene`].
pub(super) fn parse_document(
    text: &str,
    file: &Path,
    overrides: &[(String, String)],
) -> Result<LoadedDescription, SceneError> {
    let document = Document::parse(text).map_err(|error| {
        let position = error.pos();
        SceneError {
            file: file.to_path_buf(),
            line: position.row,
            column: position.col,
            message: format!("malformed XML: {error}"),
        }
    })?;
    let root = document.root_element();
    let parameters = collect_parameters(file, &document, root, overrides)?;
    let mut reader = Reader::new(file, &document, parameters);
    if root.tag_name().name() != "scene" {
        let tag = root.tag_name().name();
        return Err(reader.error(
            root,
            format!("expected <scene> as the outer element, found <{tag}>"),
        ));
    }

    let mut integrator = None;
    let mut integrator_position = None;
    let mut sensor = None;
    let mut shapes = Vec::new();
    let mut emitters = Vec::new();
    for child in root.children().filter(Node::is_element) {
        let tag = child.tag_name().name();
        match tag {
            "default" => {}
            "integrator" if integrator.is_none() => {
                integrator = Some(read_integrator(&mut reader, child)?);
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
                Emitter::Area(_) => {
                    return Err(reader.error(
                        child,
                        "an area emitter must be inside the <shape> that emits",
                    ));
                }
            },
            _ => {
                return Err(reader.error(
                    child,
                    format!(
                        "unknown element <{tag}> in <scene>: expected default, integrator, \
                         sensor, shape, bsdf or emitter"
                    ),
                ));
            }
        }
    }
    let sensor = sensor.ok_or_else(|| {
        reader.error_at(
            TextPosition { line: 0, column: 0 },
            "the scene has no <sensor>: add <sensor type=\"perspective\"> with a fov",
        )
    })?;
    Ok(LoadedDescription {
        scene: SceneDescription {
            integrator: integrator.unwrap_or_else(default_integrator),
            integrator_position,
            sensor,
            shapes,
            emitters,
        },
        warnings: reader.warnings,
    })
}

/// The `$name` parameters: every top-level `<default>`, then the caller's overrides on top.
fn collect_parameters(
    file: &Path,
    document: &Document,
    root: Node,
    overrides: &[(String, String)],
) -> Result<HashMap<String, String>, SceneError> {
    let reader = Reader::new(file, document, HashMap::new());
    let mut parameters = HashMap::new();
    for node in root.children().filter(|n| n.has_tag_name("default")) {
        let (Some(name), Some(value)) = (node.attribute("name"), node.attribute("value")) else {
            return Err(reader.error(node, "<default> needs \"name\" and \"value\" attributes"));
        };
        parameters.insert(name.to_string(), value.to_string());
    }
    for (name, value) in overrides {
        parameters.insert(name.clone(), value.clone());
    }
    Ok(parameters)
}
