//! `<transform>`: a list of elementary transforms composed into one `Mat4`.
//!
//! Mitsuba 3 applies each element *after* the ones before it, so the matrix is built as
//! `M = T_new * M`: `<rotate .../><translate .../>` first rotates, then translates. Every
//! element must be invertible (a zero scale or a camera looking at itself is a mistake in the
//! file, not a shape worth rendering), so each is checked where it is written.

use super::element::Element;
use glam::{Mat4, Vec3, Vec4};

use super::error::SceneError;
use super::reader::Reader;
use super::values::{parse_float, parse_floats, parse_vec3};

/// The composed matrix of a `<transform>` element.
pub(super) fn read_transform(reader: &Reader, node: &Element) -> Result<Mat4, SceneError> {
    let mut matrix = Mat4::IDENTITY;
    for child in node.children() {
        let step = match child.name() {
            "lookat" => look_at(reader, child)?,
            "translate" => Mat4::from_translation(reader.xyz(child)?),
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
fn look_at(reader: &Reader, node: &Element) -> Result<Mat4, SceneError> {
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
///
/// The axis is used as written, as Mitsuba 3 uses it: Rodrigues' formula with an axis that is
/// not of unit length also stretches along the axis and shears across it (Mitsuba's own
/// "hello" teapot turns about `(0, 1, 1)`), and a file written for Mitsuba is shaped by that
/// matrix. A unit axis gives the plain rotation.
fn rotate(reader: &Reader, node: &Element) -> Result<Mat4, SceneError> {
    let axis = match reader.parsed_attribute(node, "axis", parse_vec3)? {
        Some(axis) => axis,
        None => reader.xyz(node)?,
    };
    let angle = reader
        .parsed_attribute(node, "angle", parse_float)?
        .ok_or_else(|| reader.error(node, "<rotate> needs an \"angle\" attribute in degrees"))?;
    if axis == Vec3::ZERO || !axis.is_finite() {
        return Err(reader.error(node, "<rotate> needs a non-zero axis (x, y, z or \"axis\")"));
    }
    Ok(rotation(axis, angle))
}

/// A scale: `value` (one number for all axes, or three) or `x`, `y`, `z` (default 1).
fn scale(reader: &Reader, node: &Element) -> Result<Mat4, SceneError> {
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
fn matrix_element(reader: &Reader, node: &Element) -> Result<Mat4, SceneError> {
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

/// The rotation by `degrees` about the unit `axis` (Rodrigues' formula).
///
/// Quarter turns are exact: `sin` and `cos` of 90 degrees computed in floating point are not
/// (cos(π/2) comes out as -4.4e-8), which would tilt a wall of a box by that much and open
/// hairline gaps, or overlaps, along the edges where walls meet.
fn rotation(axis: Vec3, degrees: f32) -> Mat4 {
    let quarter_turns = degrees / 90.0;
    let (sin, cos) = if quarter_turns == quarter_turns.round() {
        match (quarter_turns.round() as i64).rem_euclid(4) {
            0 => (0.0, 1.0),
            1 => (1.0, 0.0),
            2 => (0.0, -1.0),
            _ => (-1.0, 0.0),
        }
    } else {
        degrees.to_radians().sin_cos()
    };
    let k = axis;
    let outer = |a: f32, b: f32| a * b * (1.0 - cos);
    Mat4::from_cols(
        Vec4::new(
            cos + outer(k.x, k.x),
            outer(k.y, k.x) + sin * k.z,
            outer(k.z, k.x) - sin * k.y,
            0.0,
        ),
        Vec4::new(
            outer(k.x, k.y) - sin * k.z,
            cos + outer(k.y, k.y),
            outer(k.z, k.y) + sin * k.x,
            0.0,
        ),
        Vec4::new(
            outer(k.x, k.z) + sin * k.y,
            outer(k.y, k.z) - sin * k.x,
            cos + outer(k.z, k.z),
            0.0,
        ),
        Vec4::W,
    )
}

#[cfg(test)]
mod rotation_tests {
    use super::rotation;
    use glam::{Mat4, Vec3};

    #[test]
    fn rotations_agree_with_glam_and_quarter_turns_are_exact() {
        let axis = Vec3::new(1.0, 2.0, -0.5).normalize();
        for degrees in [13.0f32, -70.0, 200.0] {
            let ours = rotation(axis, degrees);
            let glam = Mat4::from_axis_angle(axis, degrees.to_radians());
            assert!(ours.abs_diff_eq(glam, 1e-6), "{degrees}: {ours} vs {glam}");
        }
        assert_eq!(rotation(Vec3::X, -90.0).transform_vector3(Vec3::Z), Vec3::Y);
        assert_eq!(rotation(Vec3::Y, 90.0).transform_vector3(Vec3::Z), Vec3::X);
        assert_eq!(
            rotation(Vec3::Z, 180.0).transform_vector3(Vec3::X),
            -Vec3::X
        );
        assert_eq!(rotation(Vec3::Z, 450.0).transform_vector3(Vec3::X), Vec3::Y);
    }

    #[test]
    fn an_axis_not_of_unit_length_is_used_as_written_as_mitsuba_does() {
        // Mitsuba 3.9.1's ScalarTransform4f().rotate([0, 1, 1], 15), row by row.
        let mitsuba = [
            [0.965926, -0.258819, 0.258819],
            [0.258819, 1.0, 0.0340742],
            [-0.258819, 0.0340742, 1.0],
        ];
        let ours = rotation(Vec3::new(0.0, 1.0, 1.0), 15.0);
        for (row, expected) in mitsuba.iter().enumerate() {
            for (column, &value) in expected.iter().enumerate() {
                let got = ours.col(column)[row];
                assert!(
                    (got - value).abs() < 1e-6,
                    "({row}, {column}): {got} vs {value}"
                );
            }
        }
    }
}
