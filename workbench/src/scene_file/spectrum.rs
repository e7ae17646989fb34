//! Mitsuba's `<spectrum>` property: a colour given as a function of wavelength, read from
//! `value="400:0.343, 404:0.445, ..."` (wavelength in nanometres, then value), from a single
//! number `value="0.5"`, or from a `.spd` file, and turned into the RGB the workbook renders
//! with ([`Spectrum::to_linear_srgb`]).
//!
//! Mitsuba's own Cornell boxes write every colour this way, so without it they cannot be read.

mod cie1931;
mod element;
mod to_srgb;

#[cfg(test)]
mod tests;

use super::bounded_read::{SPECTRUM_FILE_LIMIT, read_text};
use std::path::Path;

pub(super) use element::read_spectrum;
pub use to_srgb::{LinearSrgb, SpectrumRole};

/// The longest wavelength a spectrum may name, in nanometres (1 mm, far beyond the 830 nm where
/// the colour matching functions end).
pub const MAX_WAVELENGTH: f64 = 1e6;

/// The largest magnitude of a spectrum's value: no reflectance or light is near it, and the
/// colour of a larger one would not fit in an `f32`.
pub const MAX_VALUE: f64 = 1e30;

/// A spectrum as a scene file writes it.
#[derive(Clone, Debug, PartialEq)]
pub enum Spectrum {
    /// The same value at every wavelength: `value="0.5"`.
    Uniform(f64),
    /// Values at increasing wavelengths, linear in between and zero outside.
    Sampled(SampledSpectrum),
}

/// Values at two or more strictly increasing wavelengths, each above 0 and at most
/// [`MAX_WAVELENGTH`] nanometres, with values at most [`MAX_VALUE`] in magnitude. The bounds
/// keep every step of the conversion finite, so a colour is never NaN or infinite. The fields
/// are private so that no spectrum breaks these rules.
#[derive(Clone, Debug, PartialEq)]
pub struct SampledSpectrum {
    wavelengths: Vec<f64>,
    values: Vec<f64>,
}

impl SampledSpectrum {
    /// A spectrum through the `(wavelength, value)` pairs, or a message saying which rule they
    /// break.
    pub fn new(pairs: &[(f64, f64)]) -> Result<Self, String> {
        if pairs.len() < 2 {
            return Err(format!(
                "a spectrum needs at least two wavelength:value pairs, found {}",
                pairs.len()
            ));
        }
        let mut previous: Option<f64> = None;
        for &(wavelength, value) in pairs {
            if wavelength.is_nan() || wavelength <= 0.0 || wavelength > MAX_WAVELENGTH {
                return Err(format!(
                    "wavelength {wavelength} is not a positive number of nanometres up to \
                     {MAX_WAVELENGTH:e}"
                ));
            }
            if value.is_nan() || value.abs() > MAX_VALUE {
                return Err(format!(
                    "the value {value} at {wavelength} nm is not a number of magnitude at most \
                     {MAX_VALUE:e}"
                ));
            }
            if let Some(previous) = previous
                && wavelength <= previous
            {
                return Err(format!(
                    "wavelengths must increase, but {wavelength} nm comes after {previous} nm"
                ));
            }
            previous = Some(wavelength);
        }
        Ok(SampledSpectrum {
            wavelengths: pairs.iter().map(|&(w, _)| w).collect(),
            values: pairs.iter().map(|&(_, v)| v).collect(),
        })
    }

    /// The wavelengths, in nanometres, increasing.
    pub fn wavelengths(&self) -> &[f64] {
        &self.wavelengths
    }

    /// The value at each wavelength.
    pub fn values(&self) -> &[f64] {
        &self.values
    }
}

/// Reads a `value` attribute: one number, or `wavelength:value` pairs separated by commas
/// and/or whitespace, as in `"400:0, 500:8, 600:15.6, 700:18.4"`.
pub fn parse_spectrum(text: &str) -> Result<Spectrum, String> {
    let tokens: Vec<&str> = text
        .split(|c: char| c == ',' || c.is_whitespace())
        .filter(|token| !token.is_empty())
        .collect();
    match tokens.as_slice() {
        [] => Err("a spectrum needs a number or wavelength:value pairs, found nothing".into()),
        [single] if !single.contains(':') => parse_number(single, "a spectrum's value")
            .and_then(|value| {
                if value.abs() <= MAX_VALUE {
                    Ok(Spectrum::Uniform(value))
                } else {
                    Err(format!("a spectrum's value must be at most {MAX_VALUE:e} in magnitude, found {value}"))
                }
            })
            .map_err(|message| {
                format!("{message} (a spectrum is one number or wavelength:value pairs)")
            }),
        _ => {
            let pairs = tokens
                .iter()
                .map(|token| parse_pair(token))
                .collect::<Result<Vec<_>, _>>()?;
            SampledSpectrum::new(&pairs).map(Spectrum::Sampled)
        }
    }
}

/// One `wavelength:value` pair.
fn parse_pair(token: &str) -> Result<(f64, f64), String> {
    let Some((wavelength, value)) = token.split_once(':') else {
        return Err(format!(
            "\"{token}\" is not a wavelength:value pair (no colon); write pairs such as \
             \"400:0.5, 700:0.8\""
        ));
    };
    if value.contains(':') {
        return Err(format!(
            "\"{token}\" is not a wavelength:value pair (more than one colon)"
        ));
    }
    Ok((
        parse_number(wavelength, "a wavelength")?,
        parse_number(value, "a spectrum's value")?,
    ))
}

/// One finite number; `what` names it in the message.
fn parse_number(text: &str, what: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(number) if number.is_finite() => Ok(number),
        _ => Err(format!("{what} must be a finite number, found \"{text}\"")),
    }
}

/// Reads Mitsuba's `.spd` text: one `wavelength value` pair per line; `#` starts a comment
/// that runs to the end of the line; blank lines are skipped.
pub fn parse_spd(text: &str) -> Result<Spectrum, String> {
    let mut pairs = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let content = line.split('#').next().unwrap_or_default();
        let numbers: Vec<&str> = content
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|token| !token.is_empty())
            .collect();
        let line_number = index + 1;
        let pair = match numbers.as_slice() {
            [] => continue,
            [wavelength, value] => (
                parse_number(wavelength, "a wavelength"),
                parse_number(value, "a spectrum's value"),
            ),
            _ => {
                return Err(format!(
                    "line {line_number}: expected \"wavelength value\", found \"{}\"",
                    content.trim()
                ));
            }
        };
        match pair {
            (Ok(wavelength), Ok(value)) => pairs.push((wavelength, value)),
            (Err(message), _) | (_, Err(message)) => {
                return Err(format!("line {line_number}: {message}"));
            }
        }
    }
    SampledSpectrum::new(&pairs).map(Spectrum::Sampled)
}

/// Reads the `.spd` file at `path` (already resolved by the caller). The message names the
/// file, and the line when one is wrong.
pub fn read_spd_file(path: &Path) -> Result<Spectrum, String> {
    let shown = path.display();
    let text = read_text(path, "spectrum file", SPECTRUM_FILE_LIMIT)?;
    parse_spd(&text).map_err(|message| format!("spectrum file {shown}: {message}"))
}
