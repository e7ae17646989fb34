//! Every warp of the chapter by name, with the domain it lands in and the density it claims.
//!
//! Command-line tools pick a warp by name and write its samples with their densities; the
//! chi-square test takes a [`Warp`] and checks the samples against the density. The planar
//! warps are fixed to one shape each here: the parallelogram is the unit square and the
//! triangle its lower half, `(0, 0), (1, 0), (0, 1)`.

use glam::{Vec2, Vec3};

use super::{
    cos_lobe_pdf, cosine_hemisphere_pdf, parallelogram_pdf, sample_cos_lobe,
    sample_cosine_hemisphere, sample_disc_naive, sample_parallelogram, sample_spherical_cap,
    sample_triangle, sample_uniform_disc_concentric, sample_uniform_disc_polar,
    sample_uniform_hemisphere, sample_uniform_sphere, spherical_cap_pdf, triangle_pdf,
    uniform_disc_pdf, uniform_hemisphere_pdf, uniform_sphere_pdf,
};

/// The exponent of `cos-lobe` when none is given.
pub const DEFAULT_COS_LOBE_EXPONENT: f32 = 20.0;

/// `cos θ_max` of `spherical-cap`: a cap of about 37 degrees, a fifth of the hemisphere's
/// height, so the test sees both the cap and the empty sphere around it.
pub const DEFAULT_CAP_COS_THETA_MAX: f32 = 0.8;

/// One of the chapter's warps, with its parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Warp {
    /// The unit square, as the parallelogram `(0, 0), (1, 0), (0, 1)`.
    Parallelogram,
    /// The triangle `(0, 0), (1, 0), (0, 1)` by the fold.
    Triangle,
    /// The unit disc by `r = ξ2`: not uniform, yet claimed uniform (see [`Warp::pdf`]).
    DiscNaive,
    /// The unit disc by the corrected polar map, [`super::sample_uniform_disc_polar`].
    DiscPolar,
    /// The unit disc by Shirley and Chiu's concentric map.
    DiscConcentric,
    /// Uniform directions on the sphere.
    Sphere,
    /// Uniform directions on the hemisphere around +z.
    Hemisphere,
    /// Cosine-weighted directions around +z (Malley's method).
    CosineHemisphere,
    /// The lobe `cos^n θ` around +z.
    CosLobe {
        /// The exponent `n`, finite and at least 0.
        exponent: f32,
    },
    /// Uniform directions within `θ_max` of +z.
    SphericalCap {
        /// `cos θ_max`, in `[-1, 1)`.
        cos_theta_max: f32,
    },
}

/// Where a warp's samples land, and how the chi-square test lays its grid of bins over it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Domain {
    /// Points of the plane inside the rectangle `[min, max]`, binned on a grid over it.
    Plane {
        /// The lower left corner of the bounding rectangle.
        min: Vec2,
        /// The upper right corner.
        max: Vec2,
    },
    /// Unit directions, binned on a grid over `(φ, cos θ)` in `[0, 2π) x [-1, 1]`, where bins of
    /// equal size have equal solid angle.
    Sphere,
}

/// One sample of a warp: a point of the plane or a unit direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WarpPoint {
    /// A point of the plane.
    Plane(Vec2),
    /// A unit direction.
    Direction(Vec3),
}

impl Warp {
    /// The command-line names, in the order of the enum.
    pub const NAMES: [&'static str; 10] = [
        "parallelogram",
        "triangle",
        "disc-naive",
        "disc-polar",
        "disc-concentric",
        "sphere",
        "hemisphere",
        "cosine-hemisphere",
        "cos-lobe",
        "spherical-cap",
    ];

    /// The warp's command-line name, one of [`Warp::NAMES`].
    pub fn name(&self) -> &'static str {
        match self {
            Warp::Parallelogram => "parallelogram",
            Warp::Triangle => "triangle",
            Warp::DiscNaive => "disc-naive",
            Warp::DiscPolar => "disc-polar",
            Warp::DiscConcentric => "disc-concentric",
            Warp::Sphere => "sphere",
            Warp::Hemisphere => "hemisphere",
            Warp::CosineHemisphere => "cosine-hemisphere",
            Warp::CosLobe { .. } => "cos-lobe",
            Warp::SphericalCap { .. } => "spherical-cap",
        }
    }

    /// The warp called `name`. `exponent` is the exponent of `cos-lobe`
    /// ([`DEFAULT_COS_LOBE_EXPONENT`] when `None`) and must be finite and at least 0; no other
    /// warp takes one, so giving it for another warp is an error rather than silently ignored.
    /// `spherical-cap` uses [`DEFAULT_CAP_COS_THETA_MAX`].
    pub fn from_name(name: &str, exponent: Option<f32>) -> Result<Warp, String> {
        let warp = match name {
            "parallelogram" => Warp::Parallelogram,
            "triangle" => Warp::Triangle,
            "disc-naive" => Warp::DiscNaive,
            "disc-polar" => Warp::DiscPolar,
            "disc-concentric" => Warp::DiscConcentric,
            "sphere" => Warp::Sphere,
            "hemisphere" => Warp::Hemisphere,
            "cosine-hemisphere" => Warp::CosineHemisphere,
            "cos-lobe" => {
                let exponent = exponent.unwrap_or(DEFAULT_COS_LOBE_EXPONENT);
                if !(exponent.is_finite() && exponent >= 0.0) {
                    return Err(format!(
                        "cos-lobe needs a finite exponent of at least 0, not {exponent}"
                    ));
                }
                return Ok(Warp::CosLobe { exponent });
            }
            "spherical-cap" => Warp::SphericalCap {
                cos_theta_max: DEFAULT_CAP_COS_THETA_MAX,
            },
            _ => {
                return Err(format!(
                    "unknown warp `{name}`; the warps are: {}",
                    Warp::NAMES.join(", ")
                ));
            }
        };
        match exponent {
            Some(exponent) => Err(format!(
                "only cos-lobe takes an exponent, but {exponent} was given for {name}"
            )),
            None => Ok(warp),
        }
    }

    /// Every warp, for tests that run them all: the lobe at several exponents (the uniform
    /// hemisphere, the cosine, a broad and a narrow glossy lobe), the default cap and one
    /// larger than a hemisphere. Includes [`Warp::DiscNaive`], which fails its density; see
    /// [`Warp::delivers_claimed_density`].
    pub fn all_for_tests() -> Vec<Warp> {
        let mut warps = vec![
            Warp::Parallelogram,
            Warp::Triangle,
            Warp::DiscNaive,
            Warp::DiscPolar,
            Warp::DiscConcentric,
            Warp::Sphere,
            Warp::Hemisphere,
            Warp::CosineHemisphere,
        ];
        warps.extend([0.0, 1.0, 10.0, 100.0].map(|exponent| Warp::CosLobe { exponent }));
        warps.extend(
            [DEFAULT_CAP_COS_THETA_MAX, -0.5]
                .map(|cos_theta_max| Warp::SphericalCap { cos_theta_max }),
        );
        warps
    }

    /// Whether the warp's samples really have the density [`Warp::pdf`] claims: true for all
    /// but [`Warp::DiscNaive`].
    pub fn delivers_claimed_density(&self) -> bool {
        !matches!(self, Warp::DiscNaive)
    }

    /// Where the warp's samples land.
    pub fn domain(&self) -> Domain {
        match self {
            Warp::Parallelogram | Warp::Triangle => Domain::Plane {
                min: Vec2::ZERO,
                max: Vec2::ONE,
            },
            Warp::DiscNaive | Warp::DiscPolar | Warp::DiscConcentric => Domain::Plane {
                min: Vec2::splat(-1.0),
                max: Vec2::ONE,
            },
            Warp::Sphere
            | Warp::Hemisphere
            | Warp::CosineHemisphere
            | Warp::CosLobe { .. }
            | Warp::SphericalCap { .. } => Domain::Sphere,
        }
    }

    /// The sample the warp makes of `u` in `[0, 1)^2`.
    pub fn sample(&self, u: Vec2) -> WarpPoint {
        let (p0, p1, p2) = (Vec2::ZERO, Vec2::X, Vec2::Y);
        match *self {
            Warp::Parallelogram => WarpPoint::Plane(sample_parallelogram(u, p0, p1, p2)),
            Warp::Triangle => WarpPoint::Plane(sample_triangle(u, p0, p1, p2)),
            Warp::DiscNaive => WarpPoint::Plane(sample_disc_naive(u)),
            Warp::DiscPolar => WarpPoint::Plane(sample_uniform_disc_polar(u)),
            Warp::DiscConcentric => WarpPoint::Plane(sample_uniform_disc_concentric(u)),
            Warp::Sphere => WarpPoint::Direction(sample_uniform_sphere(u)),
            Warp::Hemisphere => WarpPoint::Direction(sample_uniform_hemisphere(u)),
            Warp::CosineHemisphere => WarpPoint::Direction(sample_cosine_hemisphere(u)),
            Warp::CosLobe { exponent } => WarpPoint::Direction(sample_cos_lobe(u, exponent)),
            Warp::SphericalCap { cos_theta_max } => {
                WarpPoint::Direction(sample_spherical_cap(u, cos_theta_max))
            }
        }
    }

    /// The density the warp *claims* at `point`, per unit area or solid angle, with 0 outside
    /// the shape it samples (and for a point of the wrong kind, a direction for a planar warp).
    ///
    /// For [`Warp::DiscNaive`] this is the uniform density `1 / π`, not its true density
    /// [`super::disc_naive_pdf`]: the naive warp is offered as a uniform disc, and the
    /// chi-square test holds it to that claim and rejects it. Its true density stays available
    /// for plots that show where the samples really go.
    pub fn pdf(&self, point: WarpPoint) -> f32 {
        match (*self, point) {
            (Warp::Parallelogram, WarpPoint::Plane(p)) if in_unit_square(p) => {
                parallelogram_pdf(1.0)
            }
            (Warp::Triangle, WarpPoint::Plane(p)) if in_unit_triangle(p) => triangle_pdf(0.5),
            (Warp::DiscNaive | Warp::DiscPolar | Warp::DiscConcentric, WarpPoint::Plane(p))
                if p.length_squared() <= 1.0 =>
            {
                uniform_disc_pdf()
            }
            (Warp::Sphere, WarpPoint::Direction(_)) => uniform_sphere_pdf(),
            (Warp::Hemisphere, WarpPoint::Direction(d)) if d.z >= 0.0 => uniform_hemisphere_pdf(),
            (Warp::CosineHemisphere, WarpPoint::Direction(d)) => cosine_hemisphere_pdf(d.z),
            (Warp::CosLobe { exponent }, WarpPoint::Direction(d)) => cos_lobe_pdf(d.z, exponent),
            (Warp::SphericalCap { cos_theta_max }, WarpPoint::Direction(d))
                if d.z >= cos_theta_max =>
            {
                spherical_cap_pdf(cos_theta_max)
            }
            // Outside the shape, or a point of the wrong kind.
            _ => 0.0,
        }
    }
}

/// Whether `p` lies in the unit square `[0, 1]^2`, edges included.
fn in_unit_square(p: Vec2) -> bool {
    p.cmpge(Vec2::ZERO).all() && p.cmple(Vec2::ONE).all()
}

/// Whether `p` lies in the triangle `(0, 0), (1, 0), (0, 1)`, edges included.
fn in_unit_triangle(p: Vec2) -> bool {
    p.x >= 0.0 && p.y >= 0.0 && p.x + p.y <= 1.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::warps::test_support::{
        edge_points, integrate_over_rectangle, integrate_over_sphere,
        integrate_rotationally_symmetric,
    };
    use approx::assert_relative_eq;

    #[test]
    fn names_round_trip() {
        for warp in Warp::all_for_tests() {
            let exponent = match warp {
                Warp::CosLobe { exponent } => Some(exponent),
                _ => None,
            };
            let parsed = Warp::from_name(warp.name(), exponent).unwrap();
            assert_eq!(parsed.name(), warp.name());
            assert!(Warp::NAMES.contains(&warp.name()));
        }
        assert_eq!(
            Warp::from_name("cos-lobe", None),
            Ok(Warp::CosLobe {
                exponent: DEFAULT_COS_LOBE_EXPONENT
            })
        );
    }

    #[test]
    fn bad_names_and_exponents_are_explained() {
        let unknown = Warp::from_name("disc", None).unwrap_err();
        assert!(
            unknown.contains("`disc`") && unknown.contains("disc-concentric"),
            "{unknown}"
        );
        for exponent in [-1.0, f32::NAN, f32::INFINITY] {
            let error = Warp::from_name("cos-lobe", Some(exponent)).unwrap_err();
            assert!(error.contains("exponent"), "{error}");
        }
        let misplaced = Warp::from_name("sphere", Some(3.0)).unwrap_err();
        assert!(misplaced.contains("only cos-lobe"), "{misplaced}");
    }

    #[test]
    fn every_claimed_density_integrates_to_one() {
        for warp in Warp::all_for_tests() {
            let integral = match (warp, warp.domain()) {
                // The narrow lobes need a grid that resolves their peak.
                (Warp::CosLobe { .. }, _) => integrate_rotationally_symmetric(|z| {
                    warp.pdf(WarpPoint::Direction(Vec3::new(0.0, 0.0, z)))
                }),
                (_, Domain::Plane { min, max }) => {
                    integrate_over_rectangle(|p| warp.pdf(WarpPoint::Plane(p)), min, max, 1000)
                }
                (_, Domain::Sphere) => {
                    integrate_over_sphere(|d| warp.pdf(WarpPoint::Direction(d)), 1000)
                }
            };
            assert_relative_eq!(integral, 1.0, epsilon = 2e-3);
        }
    }

    #[test]
    fn samples_of_the_edges_are_finite_and_possible() {
        for warp in Warp::all_for_tests() {
            for u in edge_points() {
                let point = warp.sample(u);
                let finite = match point {
                    WarpPoint::Plane(p) => p.is_finite(),
                    WarpPoint::Direction(d) => d.is_finite(),
                };
                assert!(finite, "{} at {u}: {point:?}", warp.name());
                // Malley's method may touch the horizon, where cos θ / π is 0.
                if warp != Warp::CosineHemisphere {
                    assert!(warp.pdf(point) > 0.0, "{} at {u}: {point:?}", warp.name());
                }
            }
        }
    }

    #[test]
    fn points_of_the_wrong_kind_have_no_density() {
        assert_eq!(Warp::Sphere.pdf(WarpPoint::Plane(Vec2::ZERO)), 0.0);
        assert_eq!(Warp::DiscPolar.pdf(WarpPoint::Direction(Vec3::Z)), 0.0);
    }
}
