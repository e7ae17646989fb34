//! `<animation name="to_world">`: a transform that changes over the shutter interval.
//!
//! Mitsuba 3 has no animated transforms, so this is the workbook's own extension of the
//! format, written in the syntax of Mitsuba 0.6, which had it:
//!
//! ```xml
//! <animation name="to_world">
//!     <transform time="0"> <translate x="-1"/> </transform>
//!     <transform time="1"> <translate x="1"/> </transform>
//! </animation>
//! ```
//!
//! Each `<transform>` is an ordinary one (lookat, translate, rotate, scale, matrix, composed as
//! usual) with a `time` attribute. The reader only checks what makes keyframes meaningful: at
//! least two, finite times in strictly increasing order, each matrix invertible. How a
//! transform *between* keyframes is found (from the keyframes' parts, each interpolated in its
//! own way) is chapter 05's business, not the reader's.

use super::element::Element;
use glam::Mat4;

use super::error::SceneError;
use super::reader::Reader;
use super::transform::read_transform;
use super::values::parse_float;

/// The keyframes of an `<animation>` element: `(time, matrix)` pairs with increasing times.
pub(super) fn read_animation(
    reader: &Reader,
    node: &Element,
) -> Result<Vec<(f32, Mat4)>, SceneError> {
    let mut keyframes: Vec<(f32, Mat4)> = Vec::new();
    for child in node.children() {
        let tag = child.name();
        if tag != "transform" {
            return Err(reader.error(
                child,
                format!("<{tag}> is not allowed in an <animation>: it holds <transform time=\"...\"> keyframes"),
            ));
        }
        let time = reader
            .parsed_attribute(child, "time", parse_float)?
            .ok_or_else(|| {
                reader.error(
                    child,
                    "a keyframe <transform> of an <animation> needs a \"time\" attribute",
                )
            })?;
        if let Some(&(previous, _)) = keyframes.last()
            && time <= previous
        {
            return Err(reader.error(
                child,
                format!("keyframe times must increase: time {time} follows time {previous}"),
            ));
        }
        keyframes.push((time, read_transform(reader, child)?));
    }
    if keyframes.len() < 2 {
        let found = keyframes.len();
        return Err(reader.error(
            node,
            format!(
                "an <animation> needs at least two <transform time=\"...\"> keyframes, found {found}; \
                 a transform that does not move is a plain <transform>"
            ),
        ));
    }
    Ok(keyframes)
}
