//! `<texture>`: Mitsuba 3's `checkerboard` and `bitmap`, inline in a `<bsdf>` as
//! `<texture name="reflectance" ...>` or declared apart with an id and named by
//! `<ref name="reflectance" id="..."/>`.

use glam::{Affine2, Mat2, Mat4, Vec3};

use super::bitmap::load_bitmap;
use super::element::Element;
use super::error::SceneError;
use super::properties::Properties;
use super::reader::Reader;
use common::scene::{Bitmap, BitmapFilter, BitmapId, Checkerboard, Texture, WrapMode};

/// Mitsuba's default colours of a checkerboard.
const CHECKERBOARD_COLOURS: (f32, f32) = (0.4, 0.2);

/// A texture given to a plugin for one of its parameters.
pub(super) struct NamedTexture<'a> {
    /// The parameter, such as "reflectance".
    pub name: String,
    /// The `<texture>` element or the `<ref>` that names it, for messages.
    pub node: &'a Element,
    /// The texture.
    pub texture: Texture,
}

/// Takes the textures out of a plugin's nested `objects` (inline, or `<ref>`s to a
/// `<texture>`) and reads them; the other objects stay.
pub(super) fn take_textures<'a>(
    reader: &mut Reader<'a>,
    objects: &mut Vec<&'a Element>,
) -> Result<Vec<NamedTexture<'a>>, SceneError> {
    let mut textures = Vec::new();
    let mut others = Vec::new();
    for &node in objects.iter() {
        let target = reader.dereference(node)?;
        if !target.has_name("texture") {
            others.push(node);
            continue;
        }
        let Some(name) = reader.attribute(node, "name")? else {
            return Err(reader.error(
                node,
                "a texture inside a plugin needs the name of the parameter it gives, such as \
                 name=\"reflectance\"",
            ));
        };
        let texture = read_texture(reader, target)?;
        textures.push(NamedTexture {
            name,
            node,
            texture,
        });
    }
    *objects = others;
    Ok(textures)
}

/// Reads a `<texture>` element. One with an `id` is read once, however often it is named.
fn read_texture<'a>(reader: &mut Reader<'a>, node: &'a Element) -> Result<Texture, SceneError> {
    let Some(id) = reader.attribute(node, "id")? else {
        return read_texture_element(reader, node);
    };
    if let Some(texture) = reader.textures_by_id.get(&id) {
        return Ok(*texture);
    }
    reader.start_reading(node, &id)?;
    let texture = read_texture_element(reader, node);
    reader.done_reading(&id);
    let texture = texture?;
    reader.textures_by_id.insert(id, texture);
    Ok(texture)
}

/// Reads the `<texture>` element `node` itself.
fn read_texture_element<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
) -> Result<Texture, SceneError> {
    let type_name = reader.required_attribute(node, "type")?;
    let mut properties = Properties::read(reader, node, format!("{type_name} texture"))?;
    if let Some(object) = properties.objects.first() {
        let tag = object.name();
        return Err(reader.error(
            object,
            format!("a {type_name} texture cannot contain <{tag}>: its colours must be plain"),
        ));
    }
    let to_uv = properties
        .transform(reader, "to_uv")?
        .map_or(Affine2::IDENTITY, uv_part);
    let texture = match type_name.as_str() {
        "checkerboard" => {
            let (default0, default1) = CHECKERBOARD_COLOURS;
            Texture::Checkerboard(Checkerboard {
                colour0: properties
                    .rgb(reader, "color0")?
                    .unwrap_or(Vec3::splat(default0)),
                colour1: properties
                    .rgb(reader, "color1")?
                    .unwrap_or(Vec3::splat(default1)),
                to_uv,
            })
        }
        "bitmap" => Texture::Bitmap(bitmap(reader, node, &mut properties, to_uv)?),
        _ => {
            return Err(reader.error(
                node,
                format!(
                    "the texture type \"{type_name}\" is not one the workbook renders: it knows \
                     checkerboard and bitmap"
                ),
            ));
        }
    };
    properties.finish_strict(reader)?;
    Ok(texture)
}

/// The map of surface parameters a `to_uv` transform stands for, as Mitsuba 3 takes it from
/// the 4 x 4 matrix: `u` and `v` are its `x` and `y`, so its first two rows and the columns
/// of `x`, `y` and the translation (a shift along `z` does nothing).
fn uv_part(matrix: Mat4) -> Affine2 {
    Affine2::from_mat2_translation(
        Mat2::from_cols(
            matrix.x_axis.truncate().truncate(),
            matrix.y_axis.truncate().truncate(),
        ),
        matrix.w_axis.truncate().truncate(),
    )
}

/// Reads a `bitmap` texture's properties and its image (decoded once per file and `raw`
/// setting), and adds the bitmap to the scene's images.
fn bitmap<'a>(
    reader: &mut Reader<'a>,
    node: &'a Element,
    properties: &mut Properties<'a>,
    to_uv: Affine2,
) -> Result<BitmapId, SceneError> {
    let Some(filename) = properties.string(reader, "filename")? else {
        return Err(reader.error(
            node,
            "a bitmap texture needs its image: <string name=\"filename\" value=\"wood.png\"/>",
        ));
    };
    let filter = match properties.string(reader, "filter_type")?.as_deref() {
        None | Some("bilinear") => BitmapFilter::Bilinear,
        Some("nearest") => BitmapFilter::Nearest,
        Some(other) => {
            return Err(option_error(
                reader,
                properties,
                node,
                "filter_type",
                other,
                "bilinear or nearest",
            ));
        }
    };
    let wrap = match properties.string(reader, "wrap_mode")?.as_deref() {
        None | Some("repeat") => WrapMode::Repeat,
        Some("mirror") => WrapMode::Mirror,
        Some("clamp") => WrapMode::Clamp,
        Some(other) => {
            return Err(option_error(
                reader,
                properties,
                node,
                "wrap_mode",
                other,
                "repeat, mirror or clamp",
            ));
        }
    };
    let raw = properties.boolean(reader, "raw")?.unwrap_or(false);
    let path = reader.resolve_file(node, &filename);
    let key = (path.clone(), raw);
    let image = match reader.images_by_file.get(&key) {
        Some(image) => image.clone(),
        None => {
            let position = properties
                .position_of("filename")
                .unwrap_or(reader.position(node));
            let image = load_bitmap(&path, raw).map_err(|e| reader.error_at(position, e))?;
            reader.images_by_file.insert(key, image.clone());
            image
        }
    };
    let mut bitmap = Bitmap::new(image.width, image.height, image.pixels)
        .ok_or_else(|| reader.error(node, format!("the image {} has no pixel", path.display())))?;
    bitmap.filter = filter;
    bitmap.wrap = wrap;
    bitmap.to_uv = to_uv;
    reader.bitmaps.push(bitmap);
    Ok(BitmapId(reader.bitmaps.len() as u32 - 1))
}

/// An error for a `<string>` option of a bitmap that is none of the values Mitsuba knows.
fn option_error(
    reader: &Reader,
    properties: &Properties,
    node: &Element,
    name: &str,
    value: &str,
    known: &str,
) -> SceneError {
    let position = properties
        .position_of(name)
        .unwrap_or(reader.position(node));
    reader.error_at(
        position,
        format!("the bitmap texture's {name} \"{value}\" is not one Mitsuba knows: {known}"),
    )
}

/// Refuses a texture given for a parameter that only takes a plain value so far.
pub(super) fn refuse_texture(reader: &Reader, plugin: &str, texture: &NamedTexture) -> SceneError {
    reader.error(
        texture.node,
        format!(
            "the {plugin}'s `{}` cannot be a texture yet: the workbook reads textures as a \
             diffuse bsdf's reflectance, plastic's and roughplastic's diffuse_reflectance and \
             specular_reflectance, a conductor's and roughconductor's specular_reflectance, \
             a dielectric's and roughdielectric's specular_reflectance and \
             specular_transmittance, and an area emitter's radiance; give a plain <rgb> or \
             <float>",
            texture.name
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec2;

    #[test]
    fn to_uv_keeps_x_y_and_the_translation() {
        let matrix = Mat4::from_translation(Vec3::new(0.5, 0.25, 7.0))
            * Mat4::from_scale(Vec3::new(2.0, 3.0, 4.0));
        let map = uv_part(matrix);
        assert_eq!(
            map.transform_point2(Vec2::new(1.0, 1.0)),
            Vec2::new(2.5, 3.25)
        );
    }
}
