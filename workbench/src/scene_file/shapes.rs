//! `<shape>`: geometry with its transform, material and optional area light.

use super::element::Element;
use std::path::PathBuf;

use glam::{Mat4, Vec3};

use super::description::{
    ShapeDescription, ShapeGeometry, mitsuba_default_emitter_material, mitsuba_default_material,
};
use super::error::SceneError;
use super::lights::{Emitter, read_emitter};
use super::materials::nested_bsdfs;
use super::properties::Properties;
use super::reader::Reader;

/// Reads a `sphere`, `rectangle`, `disk`, `cube` or `obj` shape.
pub(super) fn read_shape<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
) -> Result<ShapeDescription, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    let mut properties = Properties::read(reader, node, format!("{type_name} shape"))?;
    let geometry = match type_name.as_str() {
        "sphere" => {
            let radius = properties.float(reader, "radius")?.unwrap_or(1.0);
            if radius <= 0.0 {
                let position = properties
                    .position_of("radius")
                    .unwrap_or(reader.position(node));
                return Err(reader.error_at(
                    position,
                    format!("a sphere's radius must be positive, found {radius}"),
                ));
            }
            ShapeGeometry::Sphere {
                center: properties.point(reader, "center")?.unwrap_or(Vec3::ZERO),
                radius,
            }
        }
        "rectangle" => ShapeGeometry::Rectangle,
        "disk" => ShapeGeometry::Disc,
        "cube" => ShapeGeometry::Cube,
        "obj" => ShapeGeometry::Obj {
            filename: mesh_file(reader, &mut properties, node, "obj", "mesh.obj")?,
            face_normals: properties.boolean(reader, "face_normals")?.unwrap_or(false),
        },
        "ply" => ShapeGeometry::Ply {
            filename: mesh_file(reader, &mut properties, node, "ply", "mesh.ply")?,
            face_normals: properties.boolean(reader, "face_normals")?.unwrap_or(false),
            flip_tex_coords: properties
                .boolean(reader, "flip_tex_coords")?
                .unwrap_or(false),
        },
        "serialized" => {
            let filename = mesh_file(
                reader,
                &mut properties,
                node,
                "serialized",
                "mesh.serialized",
            )?;
            let shape_index = properties.integer(reader, "shape_index")?.unwrap_or(0);
            let shape_index = u32::try_from(shape_index).map_err(|_| {
                reader.error(
                    node,
                    format!("shape_index {shape_index} must be a non-negative integer"),
                )
            })?;
            ShapeGeometry::Serialized {
                filename,
                shape_index,
                face_normals: properties.boolean(reader, "face_normals")?.unwrap_or(false),
            }
        }
        _ => {
            return Err(reader.error(
                node,
                format!(
                    "unknown shape type \"{type_name}\": expected sphere, rectangle, disk, cube, \
                     obj, ply or serialized"
                ),
            ));
        }
    };
    let (to_world, to_world_keyframes) = properties.transform_or_animation(reader, "to_world")?;
    let to_world = to_world.unwrap_or(Mat4::IDENTITY);
    let flip_normals = properties.boolean(reader, "flip_normals")?.unwrap_or(false);

    // An object may be a `<ref>` to a BSDF or an area emitter declared elsewhere.
    let mut emitter_nodes = Vec::new();
    let mut bsdf_nodes = Vec::new();
    for &object in &properties.objects {
        let target = reader.dereference(object)?;
        if target.has_name("emitter") {
            emitter_nodes.push(target);
        } else {
            bsdf_nodes.push(object);
        }
    }
    let material = match nested_bsdfs(reader, &bsdf_nodes, node)?.as_slice() {
        [] if emitter_nodes.is_empty() => mitsuba_default_material(),
        [] => mitsuba_default_emitter_material(),
        [material] => material.clone(),
        [_, ..] => {
            return Err(reader.error(bsdf_nodes[1], "a shape has at most one bsdf"));
        }
    };
    let emitter = match emitter_nodes.as_slice() {
        [] => None,
        [emitter_node] => match read_emitter(reader, emitter_node)? {
            Emitter::Area(area) => Some(area),
            Emitter::Standalone(_) => {
                return Err(reader.error(
                    emitter_node,
                    "only an area emitter can be inside a shape; put point and constant \
                     emitters at the top level",
                ));
            }
        },
        [_, second, ..] => {
            return Err(reader.error(second, "a shape has at most one emitter"));
        }
    };
    properties.finish(reader);
    Ok(ShapeDescription {
        geometry,
        to_world,
        to_world_keyframes,
        material,
        emitter,
        flip_normals,
        position: reader.position(node),
    })
}

/// The mesh file a shape's `filename` names, looked up as Mitsuba does (see
/// [`Reader::resolve_file`]); `kind` and `example` name the shape and a file in the message
/// when it is missing.
fn mesh_file(
    reader: &Reader,
    properties: &mut Properties,
    node: &Element,
    kind: &str,
    example: &str,
) -> Result<PathBuf, SceneError> {
    let article = if kind.starts_with('o') { "an" } else { "a" };
    let filename = properties.string(reader, "filename")?.ok_or_else(|| {
        reader.error(
            node,
            format!("{article} {kind} shape needs <string name=\"filename\" value=\"{example}\"/>"),
        )
    })?;
    Ok(reader.resolve_file(node, &filename))
}
