//! The chapter's capstone: an integral a renderer meets at every matte surface, estimated with
//! the chapter's warps, their densities and the estimator, and reported with its error.
//!
//! The irradiance at a point under a sky of radiance `L(ω)` is `E = ∫ L(ω) cos θ dω` over the
//! hemisphere around the normal (+z here). Under a uniform sky, cosine-weighted directions are
//! perfect (every term is the same). A small, bright sun changes that: nearly all of `E` comes
//! from a tiny cap of directions that cosine-weighted sampling rarely visits. Sampling the
//! sun's cap finds it every time but never sees the rest of the sky, and an estimator must
//! never give zero density to a direction the integrand needs. The way out is a *mixture*: with
//! some probability a direction of the sun's cap, otherwise a cosine-weighted one.
//!
//! An estimate alone says little: it comes with its *standard error*, the typical distance
//! between such an estimate and the true value, measured from the same samples.

use std::f64::consts::PI;

use glam::{Vec2, Vec3};

/// A sky of uniform radiance with a sun at the zenith: every direction within `θ_max` of +z
/// has the sun's radiance, every other direction the sky's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SunAndSky {
    /// The radiance of the sky.
    pub sky: f64,
    /// The radiance of the sun's disc.
    pub sun: f64,
    /// `cos θ_max`: the sun covers the cap of directions within `θ_max` of +z.
    pub sun_cos_theta_max: f32,
}

impl SunAndSky {
    /// The radiance arriving from direction `d`.
    pub fn radiance(&self, d: Vec3) -> f64 {
        if d.z >= self.sun_cos_theta_max {
            self.sun
        } else {
            self.sky
        }
    }

    /// The exact irradiance under this sky, `π L_sky + (L_sun - L_sky) π sin² θ_max`: the cap
    /// of the sun receives `∫ cos θ dω = π sin² θ_max` of the cosine's weight.
    pub fn irradiance(&self) -> f64 {
        let cos = f64::from(self.sun_cos_theta_max);
        PI * self.sky + (self.sun - self.sky) * PI * (1.0 - cos * cos)
    }
}

/// How the directions of an estimate over the hemisphere around +z are drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DirectionSampling {
    /// Uniform directions of the hemisphere.
    Uniform,
    /// Cosine-weighted directions.
    Cosine,
    /// With probability `sun_probability`, a uniform direction of the cap within `θ_max` of +z
    /// (where the sun is); otherwise a cosine-weighted direction.
    SunOrSky {
        /// `cos θ_max` of the cap.
        cos_theta_max: f32,
        /// The chance of drawing from the cap, in `(0, 1)`.
        sun_probability: f32,
    },
}

/// A Monte Carlo estimate with its standard error.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// The estimate itself.
    pub mean: f64,
    /// Its standard error: the standard deviation of such estimates, measured from the
    /// samples of this one.
    pub standard_error: f64,
}

// ANCHOR: sun_and_sky
/// Estimates the irradiance `∫ L(ω) cos θ dω` over the hemisphere around +z under the sky
/// `radiance`, from `n` directions drawn with `sampling`, each made from one `u` of `next_u`,
/// and reports the estimate with its standard error. A uniform direction is the chapter's
/// `sample_uniform_hemisphere(u)`, a cosine-weighted one `sample_cosine_hemisphere(u)`.
///
/// Which density does each direction have, and what does the estimator do with it? With
/// [`DirectionSampling::SunOrSky`] the warp that makes a direction is itself picked at random,
/// and both warps can make the same direction: how likely is it, then? The chapter's warps and
/// their densities, and [`super::sample_mean_and_variance`], are there to be called.
///
/// A direction of density 0 (on the horizon, where the cosine's density vanishes) contributes
/// nothing. With `n = 0` there is nothing to average: both numbers are `NaN`. The standard
/// error needs at least two directions to mean anything.
pub fn estimate_irradiance(
    radiance: impl Fn(Vec3) -> f64,
    sampling: DirectionSampling,
    n: usize,
    next_u: &mut impl FnMut() -> Vec2,
) -> Estimate {
    // BEGIN SOLUTION
    use super::sample_mean_and_variance;
    use crate::warps::{
        cosine_hemisphere_pdf, sample_cosine_hemisphere, sample_spherical_cap,
        sample_uniform_hemisphere, spherical_cap_pdf, uniform_hemisphere_pdf,
    };

    let mut terms = Vec::with_capacity(n);
    for _ in 0..n {
        let u = next_u();
        let (direction, pdf) = match sampling {
            DirectionSampling::Uniform => (sample_uniform_hemisphere(u), uniform_hemisphere_pdf()),
            DirectionSampling::Cosine => {
                let d = sample_cosine_hemisphere(u);
                (d, cosine_hemisphere_pdf(d.z))
            }
            DirectionSampling::SunOrSky {
                cos_theta_max,
                sun_probability: p,
            } => {
                // ξ1 picks the warp and, stretched back over [0, 1), drives it.
                let d = if u.x < p {
                    sample_spherical_cap(Vec2::new(u.x / p, u.y), cos_theta_max)
                } else {
                    sample_cosine_hemisphere(Vec2::new((u.x - p) / (1.0 - p), u.y))
                };
                // Either warp can make d: its density is the mixture of both densities.
                let cap = if d.z >= cos_theta_max {
                    spherical_cap_pdf(cos_theta_max)
                } else {
                    0.0
                };
                (d, p * cap + (1.0 - p) * cosine_hemisphere_pdf(d.z))
            }
        };
        let f = radiance(direction) * f64::from(direction.z.max(0.0));
        let pdf = f64::from(pdf);
        terms.push(if pdf > 0.0 { f / pdf } else { 0.0 });
    }
    let (mean, variance) = sample_mean_and_variance(&terms);
    Estimate {
        mean,
        standard_error: (variance / n as f64).sqrt(),
    }
    // END SOLUTION
}
// ANCHOR_END: sun_and_sky

#[cfg(test)]
mod tests;
