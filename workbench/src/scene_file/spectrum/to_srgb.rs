//! A spectrum turned into linear sRGB, as Mitsuba 3's RGB variants (`scalar_rgb`) do when
//! they load a scene (`Properties::get_texture` and `spectrum_list_to_srgb` in v3.9.1).
//!
//! The workbook renders in RGB, so a scene written with spectra must be converted the same
//! way for its images to match Mitsuba's. What Mitsuba does, and so what this does:
//! - The spectrum is linearly interpolated between its samples and is **zero outside** its
//!   first and last wavelength.
//! - It is integrated against the CIE 1931 matching functions by a Riemann sum over 1000
//!   wavelengths evenly spread from 360 nm to 830 nm (both included), scaled so that a unit
//!   spectrum has a luminance of 1, then taken from XYZ to linear sRGB (Rec. 709 primaries).
//! - A **reflectance** is weighted by the D65 illuminant (normalised to a luminance of 1), so
//!   that a spectrum equal to 1 everywhere becomes white, (1, 1, 1) to 0.2 %. Its colour is
//!   clamped to [0, 1].
//! - An **emitter's** spectrum (radiance, intensity, irradiance) is integrated without D65:
//!   it is a power spectrum, and an equal-energy spectrum is not white in sRGB (whose white is
//!   D65) but a slightly purple (1.20, 0.95, 0.91). Negative channels are clamped to 0.
//! - A single number (`value="0.5"`) is that value in every channel for a reflectance, but
//!   the same purple times the value for an emitter (Mitsuba does this so that its RGB
//!   variants match its spectral ones).

use glam::{DVec3, Vec3};

use super::Spectrum;
use super::cie1931::{CIE_MAX, CIE_MIN, CIE_Y_NORMALIZATION, cie_d65, cie1931_xyz};

/// What a spectrum describes, which decides how Mitsuba converts it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpectrumRole {
    /// A fraction of light reflected (a BSDF's `reflectance`): weighted by D65, clamped to
    /// [0, 1].
    Reflectance,
    /// Light given off (an emitter's `radiance`, `intensity` or `irradiance`): not weighted by
    /// D65, unbounded above.
    Emission,
}

/// A spectrum's colour in linear sRGB.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LinearSrgb {
    /// The colour the renderer uses, clamped as Mitsuba clamps it.
    pub rgb: Vec3,
    /// The colour before clamping, when clamping changed it (the spectrum is out of the sRGB
    /// gamut, or a reflectance above 1); Mitsuba warns about these.
    pub clamped_from: Option<DVec3>,
}

/// How many wavelengths Mitsuba's Riemann sum evaluates.
const STEPS: u32 = 1000;

impl Spectrum {
    /// This spectrum's colour in linear sRGB, as Mitsuba 3's `scalar_rgb` variant computes it
    /// for a property in the given `role`.
    pub fn to_linear_srgb(&self, role: SpectrumRole) -> LinearSrgb {
        match (self, role) {
            (Spectrum::Uniform(value), SpectrumRole::Reflectance) => LinearSrgb {
                rgb: Vec3::splat(*value as f32),
                clamped_from: None,
            },
            (Spectrum::Uniform(value), SpectrumRole::Emission) => LinearSrgb {
                // Mitsuba multiplies in single precision here.
                rgb: xyz_to_srgb(DVec3::ONE).as_vec3() * *value as f32,
                clamped_from: None,
            },
            (Spectrum::Sampled(sampled), role) => {
                let (wavelengths, values) = (sampled.wavelengths(), sampled.values());
                let rgb = xyz_to_srgb(integrate_xyz(wavelengths, values, role));
                let clamped = match role {
                    SpectrumRole::Reflectance => rgb.clamp(DVec3::ZERO, DVec3::ONE),
                    SpectrumRole::Emission => rgb.max(DVec3::ZERO),
                };
                LinearSrgb {
                    rgb: clamped.as_vec3(),
                    clamped_from: (clamped != rgb).then_some(rgb),
                }
            }
        }
    }
}

/// The CIE XYZ of the piecewise linear spectrum through `(wavelengths[i], values[i])`, zero
/// outside, weighted by D65 for a reflectance; Mitsuba's Riemann sum, step for step.
fn integrate_xyz(wavelengths: &[f64], values: &[f64], role: SpectrumRole) -> DVec3 {
    let (first, last) = (wavelengths[0], wavelengths[wavelengths.len() - 1]);
    let mut xyz = DVec3::ZERO;
    for i in 0..STEPS {
        let wavelength = CIE_MIN + (f64::from(i) / f64::from(STEPS - 1)) * (CIE_MAX - CIE_MIN);
        if wavelength < first || wavelength > last {
            continue;
        }
        let value = interpolate(wavelengths, values, wavelength);
        let weight = match role {
            SpectrumRole::Reflectance => cie_d65(wavelength),
            SpectrumRole::Emission => 1.0,
        };
        xyz += DVec3::from_array(cie1931_xyz(wavelength)) * value * weight;
    }
    // The sum is over STEPS points but scaled by the width of STEPS intervals, as in Mitsuba.
    xyz * ((CIE_MAX - CIE_MIN) * CIE_Y_NORMALIZATION / f64::from(STEPS))
}

/// The spectrum at `wavelength`, which lies between the first and last sample: linear between
/// the two samples around it (the last interval for the last wavelength).
fn interpolate(wavelengths: &[f64], values: &[f64], wavelength: f64) -> f64 {
    // The last sample index i ≤ n - 2 with wavelengths[i] ≤ wavelength (Mitsuba's
    // `find_interval`): the number of inner samples at or before `wavelength`.
    let inner = &wavelengths[1..wavelengths.len() - 1];
    let i = inner.partition_point(|&w| w <= wavelength);
    let (w0, w1, v0, v1) = (wavelengths[i], wavelengths[i + 1], values[i], values[i + 1]);
    ((wavelength - w1) * v0 + (w0 - wavelength) * v1) / (w0 - w1)
}

/// CIE XYZ to linear sRGB (Rec. 709 primaries, D65 white), with Mitsuba's matrix, whose
/// entries are single-precision numbers.
fn xyz_to_srgb(xyz: DVec3) -> DVec3 {
    const ROWS: [[f32; 3]; 3] = [
        [3.240479, -1.53715, -0.498535],
        [-0.969256, 1.875991, 0.041556],
        [0.055648, -0.204043, 1.057311],
    ];
    let row = |r: [f32; 3]| DVec3::new(r[0].into(), r[1].into(), r[2].into()).dot(xyz);
    DVec3::new(row(ROWS[0]), row(ROWS[1]), row(ROWS[2]))
}
