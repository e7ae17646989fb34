//! `<transform>`: a list of elementary transforms composed into one `Mat4`.
//!
//! Mitsuba 3 applies each element *after* the ones before it, so the matrix is built as
//! `M = T_new * M`: `<rotate .../><translate .../>` first rotates, then translates. Every
//! element must be invertible (a zero scale or a camera looking at itself is a mistake in the
//! file, not a shape worth rendering), so each is checked where it is written.

use glam::{Mat4, Vec3};
use roxmltree::Node;

use super::error::SceneError;
use super::properties::read_xyz;
use super::reader::Reader;
use super::values::{parse_float, parse_floats, parse_vec3};

/// The composed matrix of a `<transform>` element.
pub(super) fn read_transform(reader: &Reader, node: Node) -> Result<Mat4, SceneError> {
    let mut matrix = Mat4::IDENTITY;
    for child in node.children().filter(Node::is_element) {
        let step = match child.tag_name().name() {
            "lookat" => look_at(reader, child)?,
            "translate" => Mat4::from_translation(read_xyz(reader, child)?),
            "rotate" => rotate(reader, child)?,
            "scale" => scale(reader, child)?,
            "matrix" => matrix_element(reader, child)?,
            other => {
                return Err(reader.error(
                    child,
                    format!(
                        "unknown transform <{other}>: expected lookat, translate, rotate, \
                         scale or matrix"
                    ),
                ));
            }
        };
        matrix = step * matrix;
    }
    let determinant = matrix.determinant();
    if !determinant.is_finite() || determinant == 0.0 {
        return Err(reader.error(node, "the transform is degenerate (not invertible)"));
    }
    Ok(matrix)
}

/// Mitsuba's camera-to-world frame: columns left, up, direction, origin. +x is the image's
/// **left**, because `left = up × direction` in a right-handed frame.
fn look_at(reader: &Reader, node: Node) -> Result<Mat4, SceneError> {
    let vector = |name| {
        reader
            .parsed_attribute(node, name, parse_vec3)?
            .ok_or_else(|| reader.error(node, format!("<lookat> needs a \"{name}\" attribute")))
    };
    let (origin, target, up) = (vector("origin")?, vector("target")?, vector("up")?);
    let direction = (target - origin).normalize_or_zero();
    if direction == Vec3::ZERO {
        return Err(reader.error(
            node,
            "<lookat> has origin equal to target: the camera must look somewhere else",
        ));
    }
    let left = up.cross(direction).normalize_or_zero();
    if left == Vec3::ZERO || up.cross(direction).length() < 1e-6 * up.length() {
        return Err(reader.error(
            node,
            "<lookat> has \"up\" parallel to the view direction (or zero): pick an up vector \
             across it",
        ));
    }
    let true_up = direction.cross(left);
    Ok(Mat4::from_cols(
        left.extend(0.0),
        true_up.extend(0.0),
        direction.extend(0.0),
        origin.extend(1.0),
    ))
}

/// A rotation by `angle` degrees about `axis` (or the `x`, `y`, `z` attributes), right-handed.
fn rotate(reader: &Reader, node: Node) -> Result<Mat4, SceneError> {
    let axis = match reader.parsed_attribute(node, "axis", parse_vec3)? {
        Some(axis) => axis,
        None => read_xyz(reader, node)?,
    };
    let angle = reader
        .parsed_attribute(node, "angle", parse_float)?
        .ok_or_else(|| reader.error(node, "<rotate> needs an \"angle\" attribute in degrees"))?;
    let unit_axis = axis.normalize_or_zero();
    if unit_axis == Vec3::ZERO {
        return Err(reader.error(node, "<rotate> needs a non-zero axis (x, y, z or \"axis\")"));
    }
    Ok(Mat4::from_axis_angle(unit_axis, angle.to_radians()))
}

/// A scale: `value` (one number for all axes, or three) or `x`, `y`, `z` (default 1).
fn scale(reader: &Reader, node: Node) -> Result<Mat4, SceneError> {
    let factors = match reader.parsed_attribute(node, "value", parse_floats)? {
        Some(values) => match *values.as_slice() {
            [uniform] => Vec3::splat(uniform),
            [x, y, z] => Vec3::new(x, y, z),
            _ => {
                return Err(reader.error(node, "<scale value=...> needs one number or three"));
            }
        },
        None => {
            let mut factors = Vec3::ONE;
            for (axis, name) in ["x", "y", "z"].into_iter().enumerate() {
                if let Some(factor) = reader.parsed_attribute(node, name, parse_float)? {
                    factors[axis] = factor;
                }
            }
            factors
        }
    };
    if factors.cmpeq(Vec3::ZERO).any() {
        return Err(reader.error(
            node,
            format!(
                "<scale> by zero ({factors}) flattens the shape: every factor must be non-zero"
            ),
        ));
    }
    Ok(Mat4::from_scale(factors))
}

/// A matrix written as 16 numbers, row by row.
fn matrix_element(reader: &Reader, node: Node) -> Result<Mat4, SceneError> {
    let values = reader
        .parsed_attribute(node, "value", parse_floats)?
        .ok_or_else(|| reader.error(node, "<matrix> needs a \"value\" attribute"))?;
    let Ok(rows) = <[f32; 16]>::try_from(values.as_slice()) else {
        let count = values.len();
        return Err(reader.error(
            node,
            format!("<matrix> needs 16 numbers, row by row; found {count}"),
        ));
    };
    let matrix = Mat4::from_cols_array(&rows).transpose();
    // Hadamard's inequality bounds |det| by the product of the row lengths, so this ratio is a
    // scale-free measure of how close to singular the matrix is.
    let row_lengths: f32 = (0..4).map(|i| matrix.row(i).length()).product();
    let determinant = matrix.determinant();
    if !determinant.is_finite() || determinant.abs() <= 1e-6 * row_lengths {
        return Err(reader.error(node, "<matrix> is not invertible"));
    }
    Ok(matrix)
}
