//! The shape of the aperture, and how a uniform point of it is drawn.
//!
//! A real lens stops light down with a diaphragm of a few curved blades. Wide open the hole is
//! a disc; stopped down, the blades leave a regular polygon. Every out-of-focus point of light
//! is spread over the image of that hole, which is why the blurred highlights of a photograph
//! (its *bokeh*) are discs or pentagons or hexagons: each is a picture of the aperture.
//!
//! Shapes here are of unit size: the unit disc, or the regular `n`-gon inscribed in it. The
//! [`crate::lens::Lens`] scales them by the aperture radius.
//!
//! Drawing a point of the disc is chapter 02's business (its warps are reused, not copied);
//! this module adds the polygon, in the same style: a warp of the unit square with its
//! density beside it.

use ch02_monte_carlo::warps::{
    disc_naive_pdf, sample_disc_naive, sample_uniform_disc_concentric, sample_uniform_disc_polar,
    uniform_disc_pdf,
};
use glam::Vec2;
use std::f32::consts::TAU;

/// The most blades a polygonal aperture may have: past a few dozen a polygon is a disc to the
/// eye, and the limit keeps the fan of triangles small.
pub const MAX_BLADES: u32 = 64;

/// The hole of the diaphragm, at unit size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Aperture {
    /// The unit disc: a lens wide open.
    Disc,
    /// The regular polygon with `blades` corners on the unit circle: a diaphragm stopped down.
    Polygon {
        /// Number of blades, and so of corners: at least 3, at most [`MAX_BLADES`].
        blades: u32,
        /// Angle of the first corner from the camera's +x axis, in radians.
        rotation: f32,
    },
}

impl Aperture {
    /// A polygonal aperture, or why there is none: fewer than 3 blades make no polygon.
    pub fn polygon(blades: u32, rotation: f32) -> Result<Self, String> {
        if !(3..=MAX_BLADES).contains(&blades) {
            return Err(format!(
                "an aperture polygon needs between 3 and {MAX_BLADES} blades, not {blades}"
            ));
        }
        if !rotation.is_finite() {
            return Err(format!(
                "the aperture's rotation must be a finite angle, not {rotation}"
            ));
        }
        Ok(Aperture::Polygon { blades, rotation })
    }

    /// The area of the unit-size shape: `π` for the disc, `(n/2) sin(2π/n)` for the polygon.
    pub fn area(&self) -> f32 {
        match *self {
            Aperture::Disc => std::f32::consts::PI,
            Aperture::Polygon { blades, .. } => regular_polygon_area(blades),
        }
    }
}

/// How a point of the unit disc is made from two uniform numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "lab", derive(clap::ValueEnum))]
pub enum LensWarp {
    /// Shirley and Chiu's concentric map: uniform, little distortion; Mitsuba's choice.
    Concentric,
    /// Polar coordinates with the radius that makes them uniform (chapter 02's exercise).
    Polar,
    /// Polar coordinates with `r = ξ2`: **not** uniform, too many points near the centre, so
    /// blurred highlights come out too bright in their middle. Kept to show the mistake.
    Naive,
}

impl LensWarp {
    /// Every warp, in the order of the enum.
    pub const ALL: [LensWarp; 3] = [LensWarp::Concentric, LensWarp::Polar, LensWarp::Naive];

    /// The name on the command line and in figures.
    pub fn name(self) -> &'static str {
        match self {
            LensWarp::Concentric => "concentric",
            LensWarp::Polar => "polar",
            LensWarp::Naive => "naive",
        }
    }

    /// The point of the unit disc this warp makes of `u`.
    pub fn sample(self, u: Vec2) -> Vec2 {
        match self {
            LensWarp::Concentric => sample_uniform_disc_concentric(u),
            LensWarp::Polar => sample_uniform_disc_polar(u),
            LensWarp::Naive => sample_disc_naive(u),
        }
    }

    /// The density, per unit area, of the points this warp makes, at `p`: `1/π` for the two
    /// uniform warps, `1 / (2π r)` for the naive one.
    pub fn pdf(self, p: Vec2) -> f32 {
        match self {
            LensWarp::Concentric | LensWarp::Polar => {
                if p.length_squared() <= 1.0 {
                    uniform_disc_pdf()
                } else {
                    0.0
                }
            }
            LensWarp::Naive => disc_naive_pdf(p),
        }
    }
}

/// Corner `k` of the regular `blades`-gon on the unit circle, turned by `rotation`.
pub fn polygon_corner(k: u32, blades: u32, rotation: f32) -> Vec2 {
    let angle = rotation + TAU * (k % blades) as f32 / blades as f32;
    let (sin, cos) = angle.sin_cos();
    Vec2::new(cos, sin)
}

/// The area of the regular `blades`-gon inscribed in the unit circle: `blades` triangles from
/// the centre, each with two sides of length 1 enclosing the angle `2π / blades`, so of area
/// `sin(2π / blades) / 2`.
pub fn regular_polygon_area(blades: u32) -> f32 {
    0.5 * blades as f32 * (TAU / blades as f32).sin()
}

// ANCHOR: polygon_density
/// The density of [`sample_uniform_regular_polygon`] per unit area, at `p`: the density of
/// points spread evenly over the regular `blades`-gon inscribed in the unit circle, its first
/// corner at angle `rotation`, and nothing outside it.
///
/// How large is the polygon (see [`regular_polygon_area`]), and how can you tell that a point
/// is inside a convex polygon from its edges, taken in the order of [`polygon_corner`]?
/// A point on an edge counts as inside, with a little room for rounding.
pub fn sample_uniform_regular_polygon_pdf(p: Vec2, blades: u32, rotation: f32) -> f32 {
    // BEGIN SOLUTION
    let inside = (0..blades).all(|k| {
        let a = polygon_corner(k, blades, rotation);
        let b = polygon_corner(k + 1, blades, rotation);
        // Corners run counter-clockwise, so the inside is to the left of each edge a -> b.
        (b - a).perp_dot(p - a) >= -1e-6
    });
    if inside {
        1.0 / regular_polygon_area(blades)
    } else {
        0.0
    }
    // END SOLUTION
}
// ANCHOR_END: polygon_density

// ANCHOR: polygon_aperture
/// A uniform point of the regular `blades`-gon inscribed in the unit circle, its first corner
/// at angle `rotation`; density [`sample_uniform_regular_polygon_pdf`].
///
/// The polygon is a fan of `blades` equal triangles around the centre. Choose a triangle with
/// `ξ1` (each has the same area, so each gets the same chance), then a uniform point inside
/// it with chapter 02's triangle warp. The choice uses only the integer part of
/// `blades * ξ1`; its fractional part is again uniform in `[0, 1)` and independent of the
/// choice, so it serves as the triangle's first number: one random number does two jobs.
pub fn sample_uniform_regular_polygon(u: Vec2, blades: u32, rotation: f32) -> Vec2 {
    // BEGIN SOLUTION
    let scaled = u.x * blades as f32;
    // `u.x < 1`, yet `blades * u.x` may round up to `blades`: keep the last triangle then.
    let k = (scaled as u32).min(blades - 1);
    let reused = (scaled - k as f32).clamp(0.0, 1.0);
    ch02_monte_carlo::warps::sample_triangle(
        Vec2::new(reused, u.y),
        Vec2::ZERO,
        polygon_corner(k, blades, rotation),
        polygon_corner(k + 1, blades, rotation),
    )
    // END SOLUTION
}
// ANCHOR_END: polygon_aperture

/// The density of the points of the unit-size `aperture` (a disc drawn through `warp`, a
/// polygon by its fan), per unit area.
pub fn sample_aperture_pdf(aperture: Aperture, warp: LensWarp, p: Vec2) -> f32 {
    match aperture {
        Aperture::Disc => warp.pdf(p),
        Aperture::Polygon { blades, rotation } => {
            sample_uniform_regular_polygon_pdf(p, blades, rotation)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use ch02_monte_carlo::chi2::{chi2_test_density, significance_level};
    use ch02_monte_carlo::warps::{Domain, WarpPoint};

    /// Points of the unit square on a grid, its edges included (up to just below 1).
    fn grid(n: usize) -> Vec<Vec2> {
        let below_one = 1.0 - f32::EPSILON / 2.0;
        let coordinate = |i: usize| (i as f32 / (n - 1) as f32).min(below_one);
        (0..n)
            .flat_map(|i| (0..n).map(move |j| Vec2::new(coordinate(i), coordinate(j))))
            .collect()
    }

    fn polygon_chi2(
        blades: u32,
        rotation: f32,
        sample: impl Fn(Vec2) -> Vec2,
    ) -> ch02_monte_carlo::chi2::Chi2Result {
        chi2_test_density(
            Domain::Plane {
                min: Vec2::splat(-1.0),
                max: Vec2::ONE,
            },
            200_000,
            4,
            (20, 20),
            |u| WarpPoint::Plane(sample(u)),
            |point| match point {
                WarpPoint::Plane(p) => sample_uniform_regular_polygon_pdf(p, blades, rotation),
                WarpPoint::Direction(_) => 0.0,
            },
        )
    }

    /// Whether `p` lies in the regular `blades`-gon turned by `rotation`, its edges included
    /// with room for rounding: where the density of the exercise before is not 0.
    fn inside_polygon(p: Vec2, blades: u32, rotation: f32) -> bool {
        sample_uniform_regular_polygon_pdf(p, blades, rotation) > 0.0
    }

    #[test]
    fn exercise_polygon_aperture_stays_inside_the_polygon() {
        for blades in [3, 5, 6, 9] {
            for u in grid(41) {
                let p = sample_uniform_regular_polygon(u, blades, 0.3);
                assert!(
                    p.is_finite() && inside_polygon(p, blades, 0.3),
                    "sample_uniform_regular_polygon: ξ = {u} with {blades} blades (rotation 0.3) \
                     gave {p}, which is outside the polygon: every point has to lie in one of \
                     the fan's triangles around the centre"
                );
            }
        }
    }

    #[test]
    fn exercise_polygon_aperture_is_uniform() {
        // Chi-square against the density 1/area inside the polygon: a triangle picked with the
        // wrong weight, or a non-uniform point inside it, shows as a huge statistic.
        for (blades, rotation) in [(3, 0.0), (5, 0.4), (6, 0.0)] {
            let sample = |u| sample_uniform_regular_polygon(u, blades, rotation);
            let result = polygon_chi2(blades, rotation, sample);
            if result.p_value > significance_level(3, 0.01) {
                continue;
            }
            let points: Vec<Vec2> = grid(300).into_iter().map(sample).collect();
            panic!(
                "{} ({blades} blades: does every triangle get the same share, and is the point \
                 inside it uniform?)",
                workbench::test_support::not_uniform(
                    "ch04-polygon-aperture",
                    "sample_uniform_regular_polygon",
                    "polygon",
                    result.p_value,
                    &points,
                    &|p| f64::from(sample_uniform_regular_polygon_pdf(p, blades, rotation)),
                    [Vec2::splat(-1.0), Vec2::splat(1.0)],
                )
            );
        }
    }

    #[test]
    fn exercise_polygon_aperture_reaches_every_corner() {
        // u.x just below (k + 1) / n and u.y near 1 folds to the far corner of triangle k.
        let blades = 5;
        for k in 0..blades {
            let corner = polygon_corner(k, blades, 0.0);
            let nearest = grid(101)
                .into_iter()
                .map(|u| sample_uniform_regular_polygon(u, blades, 0.0).distance(corner))
                .fold(f32::INFINITY, f32::min);
            assert!(
                nearest < 0.03,
                "sample_uniform_regular_polygon: with {blades} blades, no ξ of a fine grid comes \
                 near corner {k} at {corner} (the nearest point is {nearest:.3} away): the \
                 points do not fill the polygon"
            );
        }
    }

    /// The density inside the regular `blades`-gon, worked out beforehand from its area (see
    /// `regular_polygon_area`), to 7 digits.
    fn density_inside(blades: u32) -> f32 {
        match blades {
            3 => 0.7698004,
            4 => 0.5,
            5 => 0.4205849,
            6 => 0.3849002,
            8 => 0.3535534,
            _ => unreachable!("no density worked out for {blades} blades"),
        }
    }

    /// Where a point of the check lies: inside the polygon, on its edge or outside.
    #[derive(Clone, Copy, Debug, PartialEq)]
    enum Place {
        Inside,
        OnEdge,
        Outside,
    }

    /// What is wrong with `got = sample_uniform_regular_polygon_pdf(p, blades, rotation)`, in
    /// words; `None` if right. `place` says where `p` lies, by construction.
    fn polygon_density_mistake(
        p: Vec2,
        blades: u32,
        rotation: f32,
        place: Place,
        got: f32,
    ) -> Option<String> {
        let area = regular_polygon_area(blades);
        let inside = place != Place::Outside;
        let on_edge = place == Place::OnEdge;
        let expected = if inside { density_inside(blades) } else { 0.0 };
        if (got - expected).abs() <= 1e-5 * expected.max(1.0) {
            return None;
        }
        let near = |a: f32, b: f32| (a - b).abs() <= 1e-5 * b.abs().max(1.0);
        // The same point in the polygon not turned, by your own density.
        let unturned = sample_uniform_regular_polygon_pdf(p, blades, 0.0);
        let mistake = if !got.is_finite() {
            "the density is not a number".to_string()
        } else if inside && near(got, std::f32::consts::FRAC_1_PI) {
            "inside, the points spread over the polygon's area, not over the disc's".to_string()
        } else if inside && near(got, 1.0) {
            format!(
                "a density integrates to one over its shape, and this polygon's area is {area}, \
                 not 1"
            )
        } else if inside && got == 0.0 && on_edge {
            "a point on the polygon's edge counts as inside: the sampler's points reach the \
             edges and corners, and there the density is not 0 (leave a little room for \
             rounding)"
                .to_string()
        } else if rotation != 0.0 && (got > 0.0) != inside && got == unturned {
            format!(
                "the polygon is turned by the rotation {rotation}: its first corner is at that \
                 angle, and so is every other corner"
            )
        } else if inside && got == 0.0 {
            "a point inside the polygon gets density 0: which side of each edge is the inside, \
             when the corners run counter-clockwise?"
                .to_string()
        } else if !inside && got != 0.0 {
            "a point outside the polygon gets a density: it must be 0 outside, so every edge has \
             to be tested"
                .to_string()
        } else {
            format!(
                "inside, the density is the same everywhere and integrates to one over the \
                 polygon (of area {area})"
            )
        };
        Some(format!(
            "{mistake}.\n  sample_uniform_regular_polygon_pdf({p}, {blades} blades, rotation \
             {rotation}) gave {got}, expected {expected}"
        ))
    }

    #[test]
    fn exercise_polygon_density_inside_and_outside() {
        for (blades, rotation) in [(3, 0.0f32), (5, 0.4), (6, 0.0), (8, 1.0), (4, 0.3)] {
            let mut points: Vec<(Vec2, Place)> = vec![(Vec2::ZERO, Place::Inside)];
            for k in 0..blades {
                let corner = polygon_corner(k, blades, rotation);
                let middle = 0.5 * (corner + polygon_corner(k + 1, blades, rotation));
                points.extend([
                    (0.9 * corner, Place::Inside),
                    (0.98 * middle, Place::Inside),
                    (corner, Place::OnEdge),
                    (middle, Place::OnEdge),
                    (1.03 * middle, Place::Outside),
                    (1.1 * corner, Place::Outside),
                ]);
            }
            points.push((Vec2::new(3.0, -2.0), Place::Outside));
            for (p, place) in points {
                let got = sample_uniform_regular_polygon_pdf(p, blades, rotation);
                if let Some(mistake) = polygon_density_mistake(p, blades, rotation, place, got) {
                    panic!("sample_uniform_regular_polygon_pdf: {mistake}");
                }
            }
        }
    }

    #[test]
    fn exercise_polygon_density_integrates_to_one() {
        // Midpoint rule over [-1, 1]^2.
        let n = 400;
        let h = 2.0 / n as f32;
        for (blades, rotation) in [(6, 0.2), (3, 1.3)] {
            let mut sum = 0.0f64;
            for i in 0..n {
                for j in 0..n {
                    let p = Vec2::new(-1.0 + (i as f32 + 0.5) * h, -1.0 + (j as f32 + 0.5) * h);
                    sum +=
                        f64::from(sample_uniform_regular_polygon_pdf(p, blades, rotation) * h * h);
                }
            }
            assert!(
                (sum - 1.0).abs() < 5e-3,
                "sample_uniform_regular_polygon_pdf: a density integrates to one over the plane, \
                 but yours integrates to {sum:.4} for {blades} blades (rotation {rotation})"
            );
        }
    }

    #[test]
    fn the_polygons_area() {
        assert_relative_eq!(regular_polygon_area(4), 2.0, epsilon = 1e-6);
        assert_relative_eq!(
            regular_polygon_area(MAX_BLADES),
            std::f32::consts::PI,
            epsilon = 0.01
        );
    }

    #[test]
    fn a_wrong_polygon_sampler_fails_the_same_test() {
        // Good points pulled towards the centre, each by its own distance from it: they stay
        // inside the polygon but crowd its middle, and the test must see that.
        let blades = 6;
        let squeezed = |u: Vec2| {
            let p = sample_uniform_regular_polygon(u, blades, 0.0);
            p * p.length()
        };
        let result = polygon_chi2(blades, 0.0, squeezed);
        assert!(result.p_value < 1e-6, "{result:?}");
    }

    #[test]
    fn too_few_blades_are_refused() {
        assert!(Aperture::polygon(2, 0.0).is_err());
        assert!(Aperture::polygon(0, 0.0).is_err());
        assert!(Aperture::polygon(MAX_BLADES + 1, 0.0).is_err());
        assert!(Aperture::polygon(5, f32::NAN).is_err());
        assert!(Aperture::polygon(3, 0.0).is_ok());
    }

    #[test]
    fn disc_warps_report_their_densities() {
        assert_relative_eq!(
            LensWarp::Concentric.pdf(Vec2::new(0.3, 0.1)),
            std::f32::consts::FRAC_1_PI
        );
        assert_eq!(LensWarp::Polar.pdf(Vec2::new(0.9, 0.9)), 0.0);
        // The naive warp's density at radius 1/2 equals the uniform one; nearer, it is higher.
        assert_relative_eq!(
            LensWarp::Naive.pdf(Vec2::new(0.5, 0.0)),
            std::f32::consts::FRAC_1_PI,
            epsilon = 1e-6
        );
        assert!(LensWarp::Naive.pdf(Vec2::new(0.1, 0.0)) > 4.0 / std::f32::consts::PI);
    }
}
