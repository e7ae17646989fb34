//! Reading one `<spectrum>` element: `value="..."` or `filename="....spd"`, never both.

use super::super::element::Element;
use super::super::error::SceneError;
use super::super::reader::Reader;
use super::{Spectrum, parse_spectrum, read_spd_file};

/// The spectrum a `<spectrum name="..." value="..."/>` or
/// `<spectrum name="..." filename="..."/>` element gives; errors are placed at the element.
pub(in super::super) fn read_spectrum(
    reader: &Reader,
    node: &Element,
) -> Result<Spectrum, SceneError> {
    if let Some(plugin) = reader.attribute(node, "type")? {
        return Err(reader.error(
            node,
            format!(
                "<spectrum type=\"{plugin}\"> (a spectrum plugin) is not supported: write \
                 value=\"wavelength:value, ...\" or filename=\"file.spd\""
            ),
        ));
    }
    let value = reader.attribute(node, "value")?;
    let filename = reader.attribute(node, "filename")?;
    match (value, filename) {
        (Some(text), None) => parse_spectrum(&text)
            .map_err(|message| reader.error(node, format!("<spectrum>: {message}"))),
        (None, Some(name)) => {
            let path = reader.resolve_file(node, &name);
            read_spd_file(&path).map_err(|message| reader.error(node, message))
        }
        _ => Err(reader.error(
            node,
            "<spectrum> needs either a \"value\" or a \"filename\" attribute (not both)",
        )),
    }
}
