//! Scene files written for Mitsuba 0.5 and 0.6 (`<scene version="0.6.0">`), read as Mitsuba 3
//! reads them: it upgrades every file whose version is below 2.0 before it reads anything.
//!
//! The upgrade renames, and does nothing else:
//! - every property's name from camel case to snake case (`toWorld` to `to_world`, `maxDepth`
//!   to `max_depth`, `intIOR` to `int_ior`), nested objects' names too (a texture named
//!   `diffuseReflectance`);
//! - a `diffuse` material's `diffuse_reflectance` to `reflectance`;
//! - a texture's `uoffset`, `voffset`, `uscale` and `vscale` to a `to_uv` transform that
//!   moves, then scales.
//!
//! What else changed since 0.6 (`<lookAt>`, `ldrfilm`, spectra by wavelength) Mitsuba 3 does
//! not upgrade; such a file is refused as Mitsuba 3 refuses it. Each file of a scene keeps its
//! own version: a 0.6 file may include a 3.0 one.

use super::Element;

/// Whether a `<scene>`'s `version` attribute is below 2.0, so its file needs the upgrade;
/// `Err` with a sentence when it is not a version number.
pub(super) fn is_before_version_2(version: &str) -> Result<bool, String> {
    let parts: Vec<&str> = version.trim().split('.').collect();
    let numbers: Option<Vec<u32>> = parts.iter().map(|part| part.parse().ok()).collect();
    match numbers {
        Some(numbers) if !numbers.is_empty() && numbers.len() <= 3 => Ok(numbers[0] < 2),
        _ => Err(format!(
            "the scene's version \"{version}\" is not a version number such as 3.0.0"
        )),
    }
}

/// Upgrades the elements below `scene` (one file's, before its includes are read in).
pub(super) fn upgrade_from_version_1(scene: &mut Element) {
    for child in &mut scene.children {
        upgrade_element(child);
    }
}

/// Renames the properties of one element and everything below it.
fn upgrade_element(element: &mut Element) {
    // `<default name=...>` names a parameter, not a property; transform steps have no name.
    if element.name != "default" {
        for (key, value) in &mut element.attributes {
            if key == "name" {
                *value = camel_to_snake_case(value);
            }
        }
    }
    for child in &mut element.children {
        upgrade_element(child);
    }
    if element.attribute("type") == Some("diffuse") {
        for child in &mut element.children {
            if child.attribute("name") == Some("diffuse_reflectance") {
                set_attribute(child, "name", "reflectance");
            }
        }
    }
    texture_offsets_to_transform(element);
}

/// `uoffset`, `voffset`, `uscale` and `vscale` become `<transform name="to_uv">` with a
/// translate, then a scale (Mitsuba 3's `scale(s) * translate(o)`), written where the first
/// of them stood. Values stay as written (`$name`s are substituted when the transform is read).
fn texture_offsets_to_transform(element: &mut Element) {
    const NAMES: [&str; 4] = ["uoffset", "voffset", "uscale", "vscale"];
    let Some(first) = element.children.iter().position(|child| {
        NAMES
            .iter()
            .any(|name| child.attribute("name") == Some(name))
    }) else {
        return;
    };
    let position = element.children[first].position.clone();
    let value_of = |children: &[Element], name: &str, default: &str| {
        children
            .iter()
            .find(|child| child.attribute("name") == Some(name))
            .and_then(|child| child.attribute("value"))
            .unwrap_or(default)
            .to_string()
    };
    let step = |tag: &str, x: String, y: String| Element {
        name: tag.to_string(),
        attributes: vec![("x".to_string(), x), ("y".to_string(), y)],
        children: Vec::new(),
        position: position.clone(),
    };
    let translate = step(
        "translate",
        value_of(&element.children, "uoffset", "0"),
        value_of(&element.children, "voffset", "0"),
    );
    let scale = step(
        "scale",
        value_of(&element.children, "uscale", "1"),
        value_of(&element.children, "vscale", "1"),
    );
    let transform = Element {
        name: "transform".to_string(),
        attributes: vec![("name".to_string(), "to_uv".to_string())],
        children: vec![translate, scale],
        position: position.clone(),
    };
    element.children.retain(|child| {
        !NAMES
            .iter()
            .any(|name| child.attribute("name") == Some(name))
    });
    element
        .children
        .insert(first.min(element.children.len()), transform);
}

fn set_attribute(element: &mut Element, key: &str, value: &str) {
    for (name, old) in &mut element.attributes {
        if name == key {
            *old = value.to_string();
        }
    }
}

/// Mitsuba 3's conversion: an upper-case letter after a lower-case one starts a new word,
/// `_` and the letter in lower case, and the upper-case letters right after it are lowered
/// too (`intIOR` is `int_ior`); everything else is kept (`color0`, `to_world`, `UV`).
pub(super) fn camel_to_snake_case(name: &str) -> String {
    let characters: Vec<char> = name.chars().collect();
    let mut result = String::with_capacity(name.len() + 4);
    let mut i = 0;
    while i < characters.len() {
        let c = characters[i];
        if i > 0 && characters[i - 1].is_ascii_lowercase() && c.is_ascii_uppercase() {
            result.push('_');
            result.push(c.to_ascii_lowercase());
            while i + 1 < characters.len() && characters[i + 1].is_ascii_uppercase() {
                i += 1;
                result.push(characters[i].to_ascii_lowercase());
            }
        } else {
            result.push(c);
        }
        i += 1;
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_converted_as_mitsuba_3_converts_them() {
        for (old, new) in [
            ("toWorld", "to_world"),
            ("maxDepth", "max_depth"),
            ("sampleCount", "sample_count"),
            ("intIOR", "int_ior"),
            ("extIOR", "ext_ior"),
            ("specularReflectance", "specular_reflectance"),
            ("alphaU", "alpha_u"),
            ("fovAxis", "fov_axis"),
            ("color0", "color0"),
            ("to_world", "to_world"),
            ("UV", "UV"),
            ("radius", "radius"),
            ("", ""),
        ] {
            assert_eq!(camel_to_snake_case(old), new, "{old}");
        }
    }

    #[test]
    fn versions_below_2_are_upgraded() {
        assert_eq!(is_before_version_2("0.6.0"), Ok(true));
        assert_eq!(is_before_version_2("0.5"), Ok(true));
        assert_eq!(is_before_version_2("1.9.9"), Ok(true));
        assert_eq!(is_before_version_2("2.0.0"), Ok(false));
        assert_eq!(is_before_version_2("3.0.0"), Ok(false));
        for bad in ["three", "3.0.x", "", "1.2.3.4"] {
            assert!(is_before_version_2(bad).is_err(), "{bad}");
        }
    }
}
