//! The named properties of one plugin element (`<float name="radius" value="1"/>` and friends),
//! read with their kind checked, and the nested objects (`<bsdf>`, `<film>`, ...) set aside for
//! the plugin to handle.
//!
//! Every property the plugin does not ask for becomes a warning when it is `finish`ed: a typo
//! in a property name is then visible instead of silently ignored.

use super::element::Element;
use glam::{Mat4, Vec3};

use super::animation::read_animation;
use super::description::PropertyValue;
use super::error::{SceneError, TextPosition};
use super::reader::Reader;
use super::spectrum::{SpectrumRole, read_spectrum};
use super::transform::read_transform;
use super::values::{parse_boolean, parse_float, parse_integer, parse_rgb};

/// `(time, matrix)` keyframes of an `<animation>`.
type Keyframes = Vec<(f32, Mat4)>;

/// Elements that are objects rather than properties.
const OBJECT_TAGS: &[&str] = &[
    "bsdf",
    "emitter",
    "film",
    "sampler",
    "rfilter",
    "ref",
    "shape",
    "sensor",
    "integrator",
    "texture",
];

struct Property {
    name: String,
    value: PropertyValue,
    position: TextPosition,
    used: bool,
}

/// The properties and nested objects of one plugin element.
pub(super) struct Properties<'a> {
    /// How messages name the plugin, such as "sphere shape".
    plugin: String,
    list: Vec<Property>,
    /// Nested objects, in file order.
    pub objects: Vec<&'a Element>,
    /// Warnings found while reading values (a spectrum clamped into the sRGB gamut), given to
    /// the reader when the plugin is `finish`ed.
    warnings: Vec<(TextPosition, String)>,
}

impl<'a> Properties<'a> {
    /// Reads every child element of `node`; `plugin` names it in messages ("sphere shape").
    pub fn read(reader: &Reader, node: &'a Element, plugin: String) -> Result<Self, SceneError> {
        let mut properties = Properties {
            plugin,
            list: Vec::new(),
            objects: Vec::new(),
            warnings: Vec::new(),
        };
        for child in node.children() {
            let tag = child.name();
            if OBJECT_TAGS.contains(&tag) {
                properties.objects.push(child);
                continue;
            }
            let value = read_value(reader, child)?;
            let name = reader.required_attribute(child, "name")?;
            if properties.list.iter().any(|p| p.name == name) {
                let plugin = &properties.plugin;
                return Err(reader.error(
                    child,
                    format!("property \"{name}\" of the {plugin} is given twice"),
                ));
            }
            properties.list.push(Property {
                name,
                value,
                position: reader.position(child),
                used: false,
            });
        }
        Ok(properties)
    }

    /// Marks `name` as used and returns its value and position.
    fn take(&mut self, name: &str) -> Option<(&PropertyValue, TextPosition)> {
        let property = self.list.iter_mut().find(|p| p.name == name)?;
        property.used = true;
        Some((&property.value, property.position.clone()))
    }

    /// Where the property `name` is written, if it is.
    pub fn position_of(&self, name: &str) -> Option<TextPosition> {
        self.list
            .iter()
            .find(|p| p.name == name)
            .map(|p| p.position.clone())
    }

    /// Reads `name` with `convert`, which returns `None` for a value of the wrong kind.
    fn typed<T>(
        &mut self,
        reader: &Reader,
        name: &str,
        expected: &str,
        convert: impl Fn(&PropertyValue) -> Option<T>,
    ) -> Result<Option<T>, SceneError> {
        let plugin = self.plugin.clone();
        let Some((value, position)) = self.take(name) else {
            return Ok(None);
        };
        convert(value).map(Some).ok_or_else(|| {
            let found = kind_name(value);
            let message =
                format!("property \"{name}\" of the {plugin} must be {expected}, found {found}");
            reader.error_at(position, message)
        })
    }

    /// A `<float>` (an `<integer>` is accepted too).
    pub fn float(&mut self, reader: &Reader, name: &str) -> Result<Option<f32>, SceneError> {
        self.typed(reader, name, "a <float>", |value| match value {
            PropertyValue::Float(x) => Some(*x),
            PropertyValue::Integer(i) => Some(*i as f32),
            _ => None,
        })
    }

    /// An `<integer>`.
    pub fn integer(&mut self, reader: &Reader, name: &str) -> Result<Option<i64>, SceneError> {
        self.typed(reader, name, "an <integer>", |value| match value {
            PropertyValue::Integer(i) => Some(*i),
            _ => None,
        })
    }

    /// A `<boolean>`.
    pub fn boolean(&mut self, reader: &Reader, name: &str) -> Result<Option<bool>, SceneError> {
        self.typed(reader, name, "a <boolean>", |value| match value {
            PropertyValue::Boolean(b) => Some(*b),
            _ => None,
        })
    }

    /// A `<string>`.
    pub fn string(&mut self, reader: &Reader, name: &str) -> Result<Option<String>, SceneError> {
        self.typed(reader, name, "a <string>", |value| match value {
            PropertyValue::String(s) => Some(s.clone()),
            _ => None,
        })
    }

    /// A reflectance colour: `<rgb>`, a `<float>` meaning a grey, or a `<spectrum>` converted
    /// as Mitsuba's RGB variants convert a reflectance.
    pub fn rgb(&mut self, reader: &Reader, name: &str) -> Result<Option<Vec3>, SceneError> {
        self.colour(reader, name, SpectrumRole::Reflectance)
    }

    /// An emitter's colour (radiance, intensity): like [`Properties::rgb`], but a `<spectrum>`
    /// is converted as Mitsuba converts emission, which differs from a reflectance.
    pub fn emitted_rgb(&mut self, reader: &Reader, name: &str) -> Result<Option<Vec3>, SceneError> {
        self.colour(reader, name, SpectrumRole::Emission)
    }

    /// A colour with a `<spectrum>` read in `role`; a spectrum clamped into the sRGB gamut
    /// gives a warning, as in Mitsuba.
    fn colour(
        &mut self,
        reader: &Reader,
        name: &str,
        role: SpectrumRole,
    ) -> Result<Option<Vec3>, SceneError> {
        let expected = "an <rgb>, a <spectrum> or a <float>";
        let Some((colour, clamped_from)) =
            self.typed(reader, name, expected, |value| match value {
                PropertyValue::Rgb(c) => Some((*c, None)),
                PropertyValue::Float(x) => Some((Vec3::splat(*x), None)),
                PropertyValue::Integer(i) => Some((Vec3::splat(*i as f32), None)),
                PropertyValue::Spectrum(spectrum) => {
                    let converted = spectrum.to_linear_srgb(role);
                    Some((converted.rgb, converted.clamped_from))
                }
                _ => None,
            })?
        else {
            return Ok(None);
        };
        if let (Some(original), Some(position)) = (clamped_from, self.position_of(name)) {
            let plugin = &self.plugin;
            let allowed = match role {
                SpectrumRole::Reflectance => "a reflectance lies in [0, 1]",
                SpectrumRole::Emission => "light is not negative",
            };
            let message = format!(
                "the <spectrum> \"{name}\" of the {plugin} is the colour {original:.4} in linear \
                 sRGB, but {allowed}: clamped to {colour:.4}, as Mitsuba does"
            );
            self.warnings.push((position, message));
        }
        Ok(Some(colour))
    }

    /// A `<point>`.
    pub fn point(&mut self, reader: &Reader, name: &str) -> Result<Option<Vec3>, SceneError> {
        self.typed(reader, name, "a <point>", |value| match value {
            PropertyValue::Point(p) => Some(*p),
            _ => None,
        })
    }

    /// A `<vector>` (or a `<point>`: Mitsuba 3 keeps both as three numbers).
    pub fn vector(&mut self, reader: &Reader, name: &str) -> Result<Option<Vec3>, SceneError> {
        self.typed(reader, name, "a <vector>", |value| match value {
            PropertyValue::Vector(v) | PropertyValue::Point(v) => Some(*v),
            _ => None,
        })
    }

    /// A `<transform>`.
    pub fn transform(&mut self, reader: &Reader, name: &str) -> Result<Option<Mat4>, SceneError> {
        self.typed(reader, name, "a <transform>", |value| match value {
            PropertyValue::Transform(m) => Some(*m),
            _ => None,
        })
    }

    /// An `<animation>`: its keyframes.
    pub fn animation(
        &mut self,
        reader: &Reader,
        name: &str,
    ) -> Result<Option<Vec<(f32, Mat4)>>, SceneError> {
        self.typed(reader, name, "an <animation>", |value| match value {
            PropertyValue::Animation(keyframes) => Some(keyframes.clone()),
            _ => None,
        })
    }

    /// A transform that may move: a `<transform>` (no keyframes) or an `<animation>` (its
    /// first keyframe's matrix, and the keyframes).
    pub fn transform_or_animation(
        &mut self,
        reader: &Reader,
        name: &str,
    ) -> Result<(Option<Mat4>, Keyframes), SceneError> {
        let is_animation = self
            .list
            .iter()
            .any(|p| p.name == name && matches!(p.value, PropertyValue::Animation(_)));
        if is_animation && let Some(keyframes) = self.animation(reader, name)? {
            return Ok((Some(keyframes[0].1), keyframes));
        }
        Ok((self.transform(reader, name)?, Vec::new()))
    }

    /// The properties the plugin did not ask for.
    fn unused(&self) -> impl Iterator<Item = &Property> {
        self.list.iter().filter(|p| !p.used)
    }

    /// Refuses the first property the plugin did not ask for: for the workbook's own
    /// materials, whose look a misspelt property (`alhpa`) would silently change.
    pub fn finish_strict(mut self, reader: &mut Reader) -> Result<(), SceneError> {
        self.give_warnings(reader);
        match self.unused().next() {
            Some(property) => Err(reader.error_at(
                property.position.clone(),
                format!(
                    "the {} has no property `{}`: a misspelt property would silently change \
                     the material",
                    self.plugin, property.name
                ),
            )),
            None => Ok(()),
        }
    }

    /// Hands the warnings found while reading values to `reader`.
    fn give_warnings(&mut self, reader: &mut Reader) {
        for (position, message) in self.warnings.drain(..) {
            reader.warn_at(position, message);
        }
    }

    /// Warns about every property the plugin did not ask for.
    pub fn finish(mut self, reader: &mut Reader) {
        self.give_warnings(reader);
        for property in self.unused() {
            let (name, plugin) = (&property.name, &self.plugin);
            let message = format!("unknown property \"{name}\" of the {plugin}, ignored");
            reader.warn_at(property.position.clone(), message);
        }
    }
}

/// The value of one property element, such as `<rgb name="radiance" value="17, 12, 4"/>`.
fn read_value(reader: &Reader, node: &Element) -> Result<PropertyValue, SceneError> {
    let tag = node.name();
    let value = |parse: fn(&str) -> Result<PropertyValue, String>| {
        let text = reader.required_attribute(node, "value")?;
        parse(&text).map_err(|message| reader.error(node, format!("<{tag}>: {message}")))
    };
    match tag {
        "float" => value(|t| parse_float(t).map(PropertyValue::Float)),
        "integer" => value(|t| parse_integer(t).map(PropertyValue::Integer)),
        "boolean" => value(|t| parse_boolean(t).map(PropertyValue::Boolean)),
        "string" => Ok(PropertyValue::String(
            reader.required_attribute(node, "value")?,
        )),
        "rgb" => value(|t| parse_rgb(t).map(PropertyValue::Rgb)),
        "point" => reader.xyz(node).map(PropertyValue::Point),
        "vector" => reader.xyz(node).map(PropertyValue::Vector),
        "transform" => read_transform(reader, node).map(PropertyValue::Transform),
        "animation" => read_animation(reader, node).map(PropertyValue::Animation),
        "spectrum" => read_spectrum(reader, node).map(PropertyValue::Spectrum),
        _ => Err(reader.error(
            node,
            format!(
                "unknown element <{tag}>: expected a property (float, integer, boolean, string, \
                 rgb, spectrum, point, vector, transform, animation) or an object ({})",
                OBJECT_TAGS.join(", ")
            ),
        )),
    }
}

/// How messages name the kind of a value.
fn kind_name(value: &PropertyValue) -> &'static str {
    match value {
        PropertyValue::Float(_) => "a <float>",
        PropertyValue::Integer(_) => "an <integer>",
        PropertyValue::Boolean(_) => "a <boolean>",
        PropertyValue::String(_) => "a <string>",
        PropertyValue::Rgb(_) => "an <rgb>",
        PropertyValue::Point(_) => "a <point>",
        PropertyValue::Vector(_) => "a <vector>",
        PropertyValue::Transform(_) => "a <transform>",
        PropertyValue::Animation(_) => "an <animation>",
        PropertyValue::Spectrum(_) => "a <spectrum>",
    }
}
