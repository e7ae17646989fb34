//! Warps: turning uniform random numbers into points with a known density.
//!
//! Every sampler of the workbook hands out numbers `u = (ξ1, ξ2)` uniform in the unit square.
//! A renderer wants points on a lens, a light or a triangle, and directions around a normal. A
//! *warp* is a map `w` from the square onto such a domain, and it comes with a density: when
//! `u` is uniform, the point `x = w(u)` has the density
//!
//! ```text
//! p(x) = 1 / |det J_w(u)|        (J_w the Jacobian of w; the square has density 1)
//! ```
//!
//! because `w` stretches a small patch `du` of the square into a patch `|det J_w| du` of the
//! domain while the probability in it stays the same. A Monte Carlo estimator divides by this
//! `p(x)`, so a warp is only useful together with its density, and the density has to be
//! right: a wrong `p` biases every image silently. The chi-square test in
//! [`crate::chi2`] checks each warp against the density it claims.
//!
//! Two ways to build a warp appear here:
//! - *inverting a CDF*: write the target density in coordinates where it factors, draw each
//!   coordinate by solving `F(x) = ξ` for its cumulative distribution `F` (the disc's radius,
//!   the sphere's height, the lobe's and the cap's `cos θ`);
//! - *geometry*: a map whose Jacobian is constant by construction (the parallelogram's affine
//!   map, the triangle's fold, Shirley and Chiu's concentric squares), or a projection whose
//!   Jacobian is the density we want (Malley's cosine-weighted hemisphere).
//!
//! Conventions, the same in every file:
//! - Functions carry pbrt-v4's names (`SampleUniformDiskPolar` is [`sample_uniform_disc_polar`]),
//!   each with its density beside it and, where the warp is one-to-one, its inverse.
//! - In the polar and spherical warps `u.x = ξ1` drives the azimuth, `φ = 2π ξ1`, and
//!   `u.y = ξ2` the radius or the polar angle: the lecture's `Polar2Cartesian(R v, 2π u)` with
//!   `u = ξ1`, `v = ξ2`. (pbrt-v4 mostly has the two roles the other way round; the densities
//!   are the same.)
//! - On the sphere, `ξ2 = 0` is the pole `+z` and growing `ξ2` moves towards the rim, so the
//!   hemisphere, the cosine lobe and the spherical cap agree where they coincide.
//! - Densities of points are per unit area; densities of directions are per unit solid angle
//!   (steradian).
//!
//! The files, one warp each: [`parallelogram`], [`triangle`], [`disk`] (the naive and the polar
//! map), [`concentric`], [`sphere`] (sphere and hemisphere), [`cosine`], [`lobe`], [`cap`], and
//! [`catalogue`], which names them all for command-line tools and for the tests.

use std::ops::{Add, Mul, Sub};

pub mod cap;
pub mod catalogue;
pub mod concentric;
pub mod cosine;
pub mod disc;
pub mod lobe;
pub mod parallelogram;
pub mod sphere;
pub mod triangle;

#[cfg(test)]
pub(crate) mod test_support;

pub use cap::{sample_spherical_cap, spherical_cap_pdf};
pub use catalogue::{Domain, Warp, WarpPoint};
pub use concentric::{invert_uniform_disc_concentric, sample_uniform_disc_concentric};
pub use cosine::{cosine_hemisphere_pdf, invert_cosine_hemisphere, sample_cosine_hemisphere};
pub use disc::{
    disc_naive_pdf, invert_disc_naive, sample_disc_naive, sample_uniform_disc_polar,
    uniform_disc_pdf,
};
pub use lobe::{cos_lobe_pdf, invert_cos_lobe, sample_cos_lobe};
pub use parallelogram::{invert_parallelogram, parallelogram_pdf, sample_parallelogram};
pub use sphere::{
    invert_uniform_hemisphere, invert_uniform_sphere, sample_uniform_hemisphere,
    sample_uniform_sphere, uniform_hemisphere_pdf, uniform_sphere_pdf,
};
pub use triangle::{sample_triangle, sample_triangle_barycentric, triangle_pdf};

/// What a point type needs for affine combinations like `p0 + a (p1 - p0) + b (p2 - p0)`:
/// adding, subtracting and scaling by an `f32`. `Vec2` and `Vec3` both qualify, so the
/// parallelogram and the triangle are written once for the plane and for space.
pub trait VectorSpace:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<f32, Output = Self>
{
}

impl<V> VectorSpace for V where V: Copy + Add<Output = V> + Sub<Output = V> + Mul<f32, Output = V> {}
