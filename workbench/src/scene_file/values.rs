//! Turning attribute text into numbers, the way Mitsuba 3 reads it.
//!
//! These functions know nothing about positions in the file: they return a message, and the
//! caller attaches the file, line and column.

use std::collections::HashMap;

use glam::Vec3;

/// Replaces every `$name` in `text` by its value. A `$` followed by no name is kept as it is.
pub(super) fn substitute(
    text: &str,
    parameters: &HashMap<String, String>,
) -> Result<String, String> {
    let mut result = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(dollar) = rest.find('$') {
        result.push_str(&rest[..dollar]);
        let after = &rest[dollar + 1..];
        let name_length = after
            .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .unwrap_or(after.len());
        let name = &after[..name_length];
        if name.is_empty() {
            result.push('$');
        } else {
            match parameters.get(name) {
                Some(value) => result.push_str(value),
                None => {
                    return Err(format!(
                        "unknown parameter \"${name}\": declare it with \
                         <default name=\"{name}\" value=\"...\"/> or pass -D {name}=..."
                    ));
                }
            }
        }
        rest = &after[name_length..];
    }
    result.push_str(rest);
    Ok(result)
}

/// One finite number, such as `"0.35"`.
pub(super) fn parse_float(text: &str) -> Result<f32, String> {
    let trimmed = text.trim();
    match trimmed.parse::<f32>() {
        Ok(value) if value.is_finite() => Ok(value),
        _ => Err(format!("expected a finite number, found \"{trimmed}\"")),
    }
}

/// Numbers separated by commas and/or spaces, such as `"0, 1, 0"` or `"1 0 0 0 ..."`.
pub(super) fn parse_floats(text: &str) -> Result<Vec<f32>, String> {
    text.split(|c: char| c == ',' || c.is_whitespace())
        .filter(|piece| !piece.is_empty())
        .map(parse_float)
        .collect()
}

/// Three numbers (`"x, y, z"`).
pub(super) fn parse_vec3(text: &str) -> Result<Vec3, String> {
    match *parse_floats(text)?.as_slice() {
        [x, y, z] => Ok(Vec3::new(x, y, z)),
        _ => Err(format!(
            "expected three numbers \"x, y, z\", found \"{}\"",
            text.trim()
        )),
    }
}

/// An RGB colour: three numbers, or one number for a grey.
pub(super) fn parse_rgb(text: &str) -> Result<Vec3, String> {
    match *parse_floats(text)?.as_slice() {
        [grey] => Ok(Vec3::splat(grey)),
        [r, g, b] => Ok(Vec3::new(r, g, b)),
        _ => Err(format!(
            "expected a colour \"r, g, b\" or a single grey value, found \"{}\"",
            text.trim()
        )),
    }
}

/// A whole number, such as `"64"` or `"-1"`.
pub(super) fn parse_integer(text: &str) -> Result<i64, String> {
    let trimmed = text.trim();
    trimmed
        .parse::<i64>()
        .map_err(|_| format!("expected a whole number, found \"{trimmed}\""))
}

/// `"true"` or `"false"`.
pub(super) fn parse_boolean(text: &str) -> Result<bool, String> {
    match text.trim() {
        "true" => Ok(true),
        "false" => Ok(false),
        other => Err(format!("expected \"true\" or \"false\", found \"{other}\"")),
    }
}
