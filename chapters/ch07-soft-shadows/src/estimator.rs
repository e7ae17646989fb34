//! The direct light an area light sends to a matte receiver, by Monte Carlo.
//!
//! The irradiance `E(x)` at a receiver point `x` with unit normal `n` from a light of
//! radiance `L` is the familiar `∫ L cos θ dω` over the directions in which the light is seen,
//! `θ` the angle between `n` and the direction. A sampler of the light picks points `y` on its
//! surface `A`, not directions, so the integral is rewritten over the light's area: each patch
//! `dA(y)` that `x` sees (the visibility `V(x, y)` is 1 if nothing blocks the segment, else 0)
//! covers a solid angle that depends on its distance from `x` and on the angle `θ′` between
//! the light's normal at `y` and the direction back to `x`. Working that change of measure
//! into the integrand is left to the exercise below.
//!
//! Draw `y` with density `p_A(y)` and the integral becomes the expectation of one sample's
//! term, the integrand at `y` over the density ([`area_light_contribution`], an exercise). For
//! a uniform point, `p_A = 1 / A`: "scale intensity by area and cosine", as the lecture puts
//! it. Averaging `N` such terms gives an unbiased
//! estimate whose error falls as `1 / √N`; the partly visible lights of a penumbra are exactly
//! where `V` varies and the samples disagree, which is why soft shadows are noisy.
//!
//! A matte (Lambertian) receiver of albedo `ρ` reflects `ρ / π · E` in every direction
//! ([`matte_reflected_radiance`]).
//!
//! The estimate is never NaN or infinite: a light of zero area, a sample point that coincides
//! with the receiver (`d = 0`), a receiver on the light's plane, a sample seen edge-on, all
//! contribute 0. These are sets of measure zero (or lights with no power), so dropping them
//! biases nothing.

use glam::{DVec3, Vec2, Vec3};

use crate::area_lights::AreaLight;
use crate::light_sample::LightSample;
use crate::strategy::LightSampling;

// ANCHOR: area_light_contribution
/// One sample's term of the area estimator, without visibility: for the point `sample` on
/// `light`, chosen with density `sample.pdf` per unit area, seen from the receiver `x` with
/// unit normal `n`: the light's [`emitted`](AreaLight::emitted) radiance towards `x` (0 when
/// `x` is behind it), turned from a patch of the light's area into light arriving at `x`, and
/// divided by the density. Light from below the receiver's horizon does not reach it. May be
/// NaN when the point is `x` itself; callers check.
pub fn area_light_contribution(light: &AreaLight, x: Vec3, n: Vec3, sample: &LightSample) -> Vec3 {
    // BEGIN SOLUTION
    let to_light = sample.p - x;
    let distance_squared = to_light.length_squared();
    let wi = to_light / distance_squared.sqrt();
    let cos_theta = n.dot(wi).max(0.0);
    let cos_theta_light = sample.n.dot(wi).abs();
    light.emitted(sample.n, -wi) * (cos_theta * cos_theta_light / (distance_squared * sample.pdf))
    // END SOLUTION
}
// ANCHOR_END: area_light_contribution

/// One sample's term when the point was chosen by its direction with density `pdf_solid_angle`
/// per steradian (a sphere's cone): `L cos θ / p_ω`, the integral `∫ L cos θ dω` sampled
/// directly. Mathematically the same as [`area_light_contribution`] with the density converted
/// to area, but the light's tilt towards `x` never enters, so nothing blows up at the
/// silhouette, where the light is seen edge-on. May be NaN when the point coincides with `x`;
/// callers check.
pub fn solid_angle_contribution(
    light: &AreaLight,
    x: Vec3,
    n: Vec3,
    sample: &LightSample,
    pdf_solid_angle: f32,
) -> Vec3 {
    let wi = (sample.p - x).normalize();
    light.emitted(sample.n, -wi) * (n.dot(wi).max(0.0) / pdf_solid_angle)
}

/// The term of one light sample from `u` for the receiver at `x` with unit normal `n`: the
/// light is sampled as `sampling` says, the term computed by the measure it was sampled in,
/// and `visible` asked about the sample only when the term is not zero (so no shadow ray is
/// traced towards the back of a light, or from below the horizon). Always finite.
pub fn light_sample_contribution(
    x: Vec3,
    n: Vec3,
    light: &AreaLight,
    u: Vec2,
    sampling: LightSampling,
    visible: &mut impl FnMut(&LightSample) -> bool,
) -> Vec3 {
    let Some(sample) = light.sample(x, u, sampling) else {
        return Vec3::ZERO;
    };
    let term = match sample.pdf_solid_angle {
        Some(pdf) => solid_angle_contribution(light, x, n, &sample, pdf),
        None => area_light_contribution(light, x, n, &sample),
    };
    // NaN (d = 0) and infinity (d² underflowing) come only from a sample within a float or so
    // of the receiver: a set of measure zero.
    let usable = term.is_finite() && term != Vec3::ZERO;
    if usable && visible(&sample) {
        term
    } else {
        Vec3::ZERO
    }
}

/// The estimate of the irradiance `E` at the receiver `x` (unit normal `n`) from `light`, per
/// colour channel: the mean of [`light_sample_contribution`] over the sample points `samples`
/// in `[0, 1)^2` (0 for none), with `visible` deciding whether a sample point is seen from `x`
/// (a shadow ray, [`LightSample::shadow_ray`]; `|_| true` for an unoccluded light).
///
/// The sum is kept in `f64`, so many samples lose no digits. A matte receiver then reflects
/// [`matte_reflected_radiance`]. This is the estimator without a world, for measuring it
/// against exact references; the renderer's, with its shadow rays, is the `matte` of
/// [`AreaLighting`](crate::lighting::AreaLighting).
pub fn estimate_irradiance(
    x: Vec3,
    n: Vec3,
    light: &AreaLight,
    samples: &[Vec2],
    sampling: LightSampling,
    mut visible: impl FnMut(&LightSample) -> bool,
) -> Vec3 {
    if samples.is_empty() {
        return Vec3::ZERO;
    }
    let sum: DVec3 = samples
        .iter()
        .map(|&u| light_sample_contribution(x, n, light, u, sampling, &mut visible).as_dvec3())
        .sum();
    (sum / samples.len() as f64).as_vec3()
}

/// The radiance a matte (Lambertian) surface of albedo `albedo` reflects, in every direction,
/// when it receives the irradiance `irradiance`: `ρ / π · E`.
pub fn matte_reflected_radiance(albedo: Vec3, irradiance: Vec3) -> Vec3 {
    albedo * std::f32::consts::FRAC_1_PI * irradiance
}

#[cfg(test)]
mod tests;
