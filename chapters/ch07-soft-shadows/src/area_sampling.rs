//! Points uniform by area on each kind of light.
//!
//! The lecture's recipe needs a *random sample point on the surface of the light source*: a
//! point chosen with a known density, here the simplest one, uniform by area, `p_A = 1 / A`.
//! Each shape gets its warp from chapter 02, used in the shape's own frame:
//!
//! - the parallelogram by the affine map of the square, whose Jacobian is its area;
//! - the triangle by folding the square in half;
//! - the disc by one of the disc warps of [`DiscWarp`] (the naive one on purpose wrong);
//! - the sphere by a uniform direction from its centre (Archimedes' hat box).
//!
//! Every sample also carries a bound on the rounding error of its point, computed the way the
//! shapes of `common` bound the error of their hit points: a point built as `o + a e1 + b e2`
//! lies on the exact plane up to the roundings of that sum, `γ(3) (|o| + |a e1| + |b e2|)`,
//! whatever the rounding of `a` and `b`. The shadow ray needs the bound to leave the light
//! without hitting it ([`crate::light_sample`]).

use ch02_monte_carlo::warps::{sample_triangle_barycentric, sample_uniform_sphere, triangle_pdf};
use common::geometry::{Disc, Parallelogram, Sphere, Triangle, gamma};
use glam::{Vec2, Vec3};

use crate::area_lights::LightShape;
use crate::disc_warp::DiscWarp;
use crate::light_sample::LightSample;

/// The error bound of the parallelogram point `corner + u.x e1 + u.y e2` (as `Parallelogram`'s hit
/// points): the sum is on the exact plane up to its own three roundings.
pub fn parallelogram_point_error(quad: &Parallelogram, u: Vec2) -> Vec3 {
    gamma(3) * (quad.corner().abs() + (u.x * quad.e1()).abs() + (u.y * quad.e2()).abs())
}

// ANCHOR: parallelogram_light_point
/// A point of the parallelogram light `quad`, uniform by area (`ξ1` along the first edge, `ξ2`
/// along the second, `ξ = (0, 0)` exactly the corner), with the light's normal and its density
/// per unit area, or `None` if the light has no area.
///
/// Far from the origin the order of the sums matters: `corner + e1` rounds, and the difference
/// `(corner + e1) - corner` is then no longer `e1`.
pub fn sample_parallelogram_light(quad: &Parallelogram, u: Vec2) -> Option<LightSample> {
    // BEGIN SOLUTION
    use ch02_monte_carlo::warps::{parallelogram_pdf, sample_parallelogram};
    let p = quad.corner() + sample_parallelogram(u, Vec3::ZERO, quad.e1(), quad.e2());
    let pdf = parallelogram_pdf(quad.area());
    LightSample::by_area(p, parallelogram_point_error(quad, u), quad.normal(), pdf)
    // END SOLUTION
}
// ANCHOR_END: parallelogram_light_point

/// A point of the triangle light, uniform by area with density `1 / area`, or `None` if it has
/// no area.
///
/// Chapter 02's fold gives uniform barycentric coordinates `(b1, b2)`; the point is
/// `b0 p0 + b1 p1 + b2 p2` with pbrt-v4's error bound for it, `γ(6) Σ |b_i p_i|` (rounding `b0`
/// included).
pub fn sample_triangle_light(triangle: &Triangle, u: Vec2) -> Option<LightSample> {
    let [p0, p1, p2] = triangle.p;
    let b = sample_triangle_barycentric(u);
    let b0 = (1.0 - b.x - b.y).max(0.0);
    let p = b0 * p0 + b.x * p1 + b.y * p2;
    let p_error = gamma(6) * ((b0 * p0).abs() + (b.x * p1).abs() + (b.y * p2).abs());
    let n = (p1 - p0).cross(p2 - p0).normalize_or_zero();
    LightSample::by_area(p, p_error, n, triangle_pdf(triangle.area()))
}

/// The point of the disc light at `offset` from its centre, in the disc's own coordinates
/// (along its [`tangent`](Disc::tangent) and [`bitangent`](Disc::bitangent), in scene units),
/// claimed uniform by area: density `1 / A`. `None` if the disc has no area.
///
/// Like `Disc`'s hit points, `center + a tangent + b bitangent` lies on the disc's exact plane
/// up to the roundings of the sum.
pub fn disc_light_sample_at(disc: &Disc, offset: Vec2) -> Option<LightSample> {
    let area = LightShape::Disc(*disc).area();
    let p = disc.point_at(offset.x, offset.y);
    let p_error = gamma(3)
        * (disc.center().abs()
            + (offset.x * disc.tangent()).abs()
            + (offset.y * disc.bitangent()).abs());
    LightSample::by_area(p, p_error, disc.normal(), 1.0 / area)
}

// ANCHOR: disc_light_point
/// A point of the disc light, uniform by area, by the lecture's corrected polar map (the angle
/// from `ξ1`, the radius from `ξ2`, as chapter 02's polar disc: the angle runs from the disc's
/// tangent, at `ξ1 = 0`, towards its bitangent); `None` if the disc has no area. An ellipse (a disc under a non-uniform scale) is the same map stretched along its
/// two semi-axes, [`Disc::radii`]: a linear map keeps a uniform density uniform.
pub fn sample_disc_light_polar(disc: &Disc, u: Vec2) -> Option<LightSample> {
    // BEGIN SOLUTION
    use std::f32::consts::TAU;
    let r = disc.radii() * u.y.sqrt();
    let (sin, cos) = (TAU * u.x).sin_cos();
    disc_light_sample_at(disc, Vec2::new(r.x * cos, r.y * sin))
    // END SOLUTION
}
// ANCHOR_END: disc_light_point

/// A point of the disc light by `warp`, *claimed* uniform by area (density `1 / A`):
/// true for [`DiscWarp::Concentric`] and [`DiscWarp::Polar`], false for [`DiscWarp::Naive`],
/// whose points crowd the centre. `None` if the disc has no area.
pub fn sample_disc_light(disc: &Disc, u: Vec2, warp: DiscWarp) -> Option<LightSample> {
    match warp {
        DiscWarp::Polar => sample_disc_light_polar(disc, u),
        DiscWarp::Concentric | DiscWarp::Naive => {
            disc_light_sample_at(disc, disc.radii() * warp.sample(u))
        }
    }
}

/// A point of the sphere light, uniform over its whole surface: `center + R d` for a uniform
/// direction `d`, density `1 / (4π R²)`; `None` if it has no area.
///
/// The error bound is that of `Sphere`'s hit points: `R d` is within `γ(5) |R d|` of the exact
/// sphere (the direction's rounding), and adding the centre costs `γ(2) |p|`.
pub fn sample_sphere_area(sphere: &Sphere, u: Vec2) -> Option<LightSample> {
    let n = sample_uniform_sphere(u);
    let local = sphere.radius * n;
    let p = sphere.center + local;
    let p_error = gamma(5) * local.abs() + gamma(2) * p.abs();
    let area = LightShape::Sphere(*sphere).area();
    LightSample::by_area(p, p_error, n, 1.0 / area)
}

impl LightShape {
    /// A point of the shape uniform by area (for discs: claimed uniform, by `disc_warp`), or
    /// `None` if the shape has no area.
    pub fn sample_area(&self, u: Vec2, disc_warp: DiscWarp) -> Option<LightSample> {
        match self {
            LightShape::Parallelogram(q) => sample_parallelogram_light(q, u),
            LightShape::Triangle(t) => sample_triangle_light(t, u),
            LightShape::Disc(d) => sample_disc_light(d, u, disc_warp),
            LightShape::Sphere(s) => sample_sphere_area(s, u),
        }
    }

    /// The density per unit area that [`sample_area`](Self::sample_area) claims: `1 / A` for
    /// every shape and every disc warp (0 for a shape without area).
    pub fn pdf_area(&self) -> f32 {
        let area = self.area();
        if area > 0.0 { 1.0 / area } else { 0.0 }
    }
}

#[cfg(test)]
mod tests;
