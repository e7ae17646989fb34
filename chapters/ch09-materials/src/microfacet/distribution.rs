//! The distribution of microfacet normals, `D(m)`, with Smith's shadowing and masking and the
//! two ways of sampling it, exactly as Mitsuba 3 writes them (`microfacet.h`), so that a
//! `roughconductor`, `roughdielectric` or `roughplastic` renders here as it does there.
//!
//! Everything is in the local frame: `z` is the macro-surface normal, `x` and `y` the tangent
//! and bitangent along which `alpha_u` and `alpha_v` stretch the distribution. `alpha` is
//! Mitsuba's: the root-mean-square slope of the microfacets for Beckmann, and the same
//! parameter in GGX's formula (Walter et al. 2007), which makes the two comparable.
//!
//! Sampling either draws a normal from `D(m) cos θ_m` (the plain way), or only the normals the
//! viewer can see, from `D_w(m) = G1(w, m) max(0, w·m) D(m) / cos θ_w` (Heitz and d'Eon 2014).
//! The second gives sample weights of at most 1, and is Mitsuba's default.

use super::visible_facets;
use common::scene::MicrofacetDistribution;
use glam::{Vec2, Vec3};
use std::f32::consts::{PI, TAU};

/// The smallest roughness: Mitsuba clamps `alpha` to it, because a narrower `D` no longer fits
/// in single precision (and is a smooth material, better rendered by the delta BSDF).
pub const MIN_ALPHA: f32 = 1e-4;

/// Beckmann's or GGX's distribution of normals with roughness `alpha_u` along `x` and
/// `alpha_v` along `y`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NormalDistribution {
    /// Beckmann or GGX.
    pub kind: MicrofacetDistribution,
    /// The roughness along the tangent `x`, at least [`MIN_ALPHA`].
    pub alpha_u: f32,
    /// The roughness along the bitangent `y`, at least [`MIN_ALPHA`].
    pub alpha_v: f32,
}

impl NormalDistribution {
    /// The distribution with its roughness clamped to at least [`MIN_ALPHA`] (a NaN becomes
    /// [`MIN_ALPHA`] too), as Mitsuba clamps it.
    pub fn new(kind: MicrofacetDistribution, alpha_u: f32, alpha_v: f32) -> Self {
        Self {
            kind,
            alpha_u: alpha_u.max(MIN_ALPHA),
            alpha_v: alpha_v.max(MIN_ALPHA),
        }
    }

    /// The same roughness in every direction.
    pub fn isotropic(kind: MicrofacetDistribution, alpha: f32) -> Self {
        Self::new(kind, alpha, alpha)
    }

    /// `D(m)`: the density of microfacet normals per unit solid angle, weighted so that their
    /// projected area is the macro-surface's, `∫ D(m) cos θ_m dm = 1`. 0 below the horizon and
    /// where the value is too small to matter (as Mitsuba: `D cos θ_m ≤ 10⁻²⁰`).
    pub fn d(&self, m: Vec3) -> f32 {
        let (au, av) = (self.alpha_u, self.alpha_v);
        let cos2 = m.z * m.z;
        let value = match self.kind {
            MicrofacetDistribution::Beckmann => {
                let tan2_over_alpha2 = ((m.x / au).powi(2) + (m.y / av).powi(2)) / cos2;
                (-tan2_over_alpha2).exp() / (PI * au * av * cos2 * cos2)
            }
            MicrofacetDistribution::Ggx => ggx_density(m, au, av),
        };
        // Also catches the 0/0 at the horizon.
        if value * m.z > 1e-20 { value } else { 0.0 }
    }

    // ANCHOR: smith_g1
    /// Smith's `G1(w, m)`: the share of microfacets of normal `m` that the direction `w` sees
    /// unshadowed, in `[0, 1]`. 0 when `w` would see the back of the facet (`w·m` and
    /// `cos θ_w` of opposite signs); 1 at normal incidence.
    ///
    /// For Beckmann this is Mitsuba's rational approximation (relative error below 0.35 %) of
    /// `2 / (1 + erf(a) + exp(-a²) / (a √π))`, `a = 1 / (alpha tan θ)`, kept so that the images
    /// agree; GGX's is exact.
    pub fn g1(&self, w: Vec3, m: Vec3) -> f32 {
        if w.dot(m) * w.z <= 0.0 {
            return 0.0;
        }
        let xy_alpha2 = (self.alpha_u * w.x).powi(2) + (self.alpha_v * w.y).powi(2);
        if xy_alpha2 == 0.0 {
            return 1.0;
        }
        // `alpha² tan² θ` along the azimuth of `w`: infinite at grazing, where G1 is 0.
        let tan2_alpha2 = xy_alpha2 / (w.z * w.z);
        match self.kind {
            MicrofacetDistribution::Beckmann => {
                let a = 1.0 / tan2_alpha2.sqrt();
                if a >= 1.6 {
                    1.0
                } else {
                    (3.535 * a + 2.181 * a * a) / (1.0 + 2.276 * a + 2.577 * a * a)
                }
            }
            MicrofacetDistribution::Ggx => 2.0 / (1.0 + (1.0 + tan2_alpha2).sqrt()),
        }
    }
    // ANCHOR_END: smith_g1

    /// Smith's separable `G(wi, wo, m) = G1(wi, m) G1(wo, m)`, Mitsuba's shadowing-masking
    /// term (it ignores the correlation between the two directions' shadows).
    pub fn g(&self, wi: Vec3, wo: Vec3, m: Vec3) -> f32 {
        self.g1(wi, m) * self.g1(wo, m)
    }

    // ANCHOR: sample_visible_normal
    /// A normal visible from `w` (above the surface), drawn from
    /// [`visible_normal_pdf`](Self::visible_normal_pdf), by Heitz and d'Eon's recipe: stretch the configuration so
    /// that the roughness is 1, draw the slope of a visible facet of the unit-roughness
    /// distribution seen from the stretched `w` (which only depends on its angle from the
    /// normal), turn it to `w`'s azimuth and stretch it back (a normal's tangential part
    /// scales with the roughness, as its slope does).
    pub fn sample_visible_normal(&self, w: Vec3, u: Vec2) -> Vec3 {
        let (au, av) = (self.alpha_u, self.alpha_v);
        let stretched = Vec3::new(au * w.x, av * w.y, w.z).normalize();
        let (sin_phi, cos_phi) = sin_cos_phi(stretched);
        let facet = match self.kind {
            MicrofacetDistribution::Beckmann => visible_facets::beckmann(stretched.z, u),
            MicrofacetDistribution::Ggx => visible_facets::ggx(stretched.z, u),
        };
        let turned = Vec2::new(
            cos_phi * facet.x - sin_phi * facet.y,
            sin_phi * facet.x + cos_phi * facet.y,
        );
        Vec3::new(turned.x * au, turned.y * av, facet.z).normalize()
    }
    // ANCHOR_END: sample_visible_normal

    /// The density per unit solid angle of [`sample_visible_normal`](Self::sample_visible_normal):
    /// `D_w(m) = G1(w, m) max(0, w·m) D(m) / cos θ_w`, the normals weighted by how much of
    /// them `w` sees. 0 for `w` on or below the horizon.
    pub fn visible_normal_pdf(&self, w: Vec3, m: Vec3) -> f32 {
        if w.z <= 0.0 {
            return 0.0;
        }
        self.g1(w, m) * w.dot(m).max(0.0) * self.d(m) / w.z
    }

    /// A normal drawn from `D(m) cos θ_m` (Mitsuba's `sample_visible = false`), by inverting
    /// the distribution of the azimuth, then of the slope along that azimuth.
    pub fn sample_normal(&self, u: Vec2) -> Vec3 {
        let (au, av) = (self.alpha_u, self.alpha_v);
        let (sin_phi, cos_phi, alpha2) = if au == av {
            let (sin, cos) = (TAU * u.y).sin_cos();
            (sin, cos, au * au)
        } else {
            // The azimuth of an elliptic distribution: `tan φ = (av / au) tan 2πξ`, with
            // `cos φ`'s sign chosen by the quadrant of `2πξ`.
            let tan = (av / au) * (TAU * u.y).tan();
            let cos = (1.0 / (tan * tan + 1.0).sqrt()).copysign((u.y - 0.5).abs() - 0.25);
            let sin = cos * tan;
            let alpha2 = 1.0 / ((cos / au).powi(2) + (sin / av).powi(2));
            (sin, cos, alpha2)
        };
        let tan2 = match self.kind {
            MicrofacetDistribution::Beckmann => -alpha2 * (-u.x).ln_1p(),
            MicrofacetDistribution::Ggx => alpha2 * u.x / (1.0 - u.x),
        };
        let cos_theta = 1.0 / (1.0 + tan2).sqrt();
        // Mitsuba's `sqrt(1 - cos²)` loses the digits of a small angle in single precision
        // (`cos² θ` rounds to a few parts in 10⁸ of 1); `tan θ cos θ` keeps them.
        let sin_theta = if tan2.is_finite() {
            tan2.sqrt() * cos_theta
        } else {
            1.0
        };
        Vec3::new(cos_phi * sin_theta, sin_phi * sin_theta, cos_theta)
    }

    /// The density per unit solid angle of [`sample_normal`](Self::sample_normal):
    /// `D(m) cos θ_m`.
    pub fn normal_pdf(&self, m: Vec3) -> f32 {
        self.d(m) * m.z.max(0.0)
    }
}

// ANCHOR: ggx_density
/// GGX's density of microfacet normals at the unit normal `m` (above the surface), for the
/// roughness `alpha_u` along `x` and `alpha_v` along `y`: Walter et al.'s
/// `D(m) = 1 / (π α_u α_v cos⁴ θ_m (1 + tan² θ_m (cos² φ / α_u² + sin² φ / α_v²))²)`,
/// written without the angles. Normalised so that `∫ D(m) cos θ_m dm = 1`: the facets'
/// projected area is the surface's.
pub fn ggx_density(m: Vec3, alpha_u: f32, alpha_v: f32) -> f32 {
    // BEGIN SOLUTION
    // `cos⁴ θ (1 + tan² θ ...)²` is `(cos² θ + sin² θ ...)²`: in the normal's coordinates,
    // `(x² / α_u² + y² / α_v² + z²)²`, with no angle to compute and nothing to divide by 0.
    let s = (m.x / alpha_u).powi(2) + (m.y / alpha_v).powi(2) + m.z * m.z;
    1.0 / (PI * alpha_u * alpha_v * s * s)
    // END SOLUTION
}
// ANCHOR_END: ggx_density

/// `(sin φ, cos φ)` of `v`'s azimuth, and `(0, 1)` for a `v` (almost) on the normal, where the
/// azimuth is undefined (as Mitsuba's `Frame3f::sincos_phi`).
fn sin_cos_phi(v: Vec3) -> (f32, f32) {
    let sin2_theta = v.x * v.x + v.y * v.y;
    // Mitsuba's threshold, four units of its epsilon `2^-24`.
    if sin2_theta <= 2.0 * f32::EPSILON {
        return (0.0, 1.0);
    }
    let inv = 1.0 / sin2_theta.sqrt();
    ((v.y * inv).clamp(-1.0, 1.0), (v.x * inv).clamp(-1.0, 1.0))
}
