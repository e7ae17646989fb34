//! `<emitter type="envmap">`: light from an image around the scene, as Mitsuba 3 reads it.
//!
//! The image is read as textures read theirs ([`load_bitmap`]): PNG and JPEG as sRGB turned
//! linear, EXR and Radiance HDR (RGBE) as linear radiance; each file is decoded once.

use super::bitmap::load_bitmap;
use super::description::EmitterDescription;
use super::element::Element;
use super::error::SceneError;
use super::properties::Properties;
use super::reader::Reader;
use common::scene::{EnvironmentMap, EnvironmentMapError};
use glam::Mat3;

/// Reads an `envmap` emitter's `filename`, `scale` and `to_world` (and `mis_compensation`,
/// which changes only how Mitsuba samples the map, not the image, and is ignored).
pub(super) fn read_environment_map(
    reader: &mut Reader,
    node: &Element,
    properties: &mut Properties,
) -> Result<EmitterDescription, SceneError> {
    let Some(filename) = properties.string(reader, "filename")? else {
        return Err(reader.error(
            node,
            "an envmap emitter needs its image: <string name=\"filename\" value=\"sky.exr\"/>",
        ));
    };
    // Where each property is written (the element itself when it is not), for errors.
    let node_position = reader.position(node);
    let [filename_at, scale_at, to_world_at] = ["filename", "scale", "to_world"].map(|name| {
        properties
            .position_of(name)
            .unwrap_or(node_position.clone())
    });
    let scale = properties.float(reader, "scale")?.unwrap_or(1.0);
    if !scale.is_finite() || scale < 0.0 {
        return Err(reader.error_at(
            scale_at,
            format!("an envmap's scale must be finite and not negative, found {scale}"),
        ));
    }
    let to_world = properties.transform(reader, "to_world")?;
    let _ = properties.boolean(reader, "mis_compensation")?;
    let path = reader.resolve_file(node, &filename);
    let key = (path.clone(), false);
    let image = match reader.images_by_file.get(&key) {
        Some(image) => image.clone(),
        None => {
            let image =
                load_bitmap(&path, false).map_err(|e| reader.error_at(filename_at.clone(), e))?;
            reader.images_by_file.insert(key, image.clone());
            image
        }
    };
    let rotation = to_world.map_or(Mat3::IDENTITY, Mat3::from_mat4);
    let map = EnvironmentMap::new(image.width, image.height, &image.pixels, scale, rotation)
        .map_err(|error| {
            let (at, whose) = match error {
                EnvironmentMapError::NotRotation => (to_world_at, "the envmap's"),
                _ => (filename_at.clone(), "the envmap image's"),
            };
            reader.error_at(at, format!("{whose} {error} ({})", path.display()))
        })?;
    Ok(EmitterDescription::EnvironmentMap {
        map: Box::new(map),
        position: node_position,
    })
}
