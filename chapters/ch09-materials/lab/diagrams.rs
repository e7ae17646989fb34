//! The page's diagrams: the facets of a rough surface with the half vector, GGX's density of
//! normals for two roughnesses, and where GGX's visible normals fall seen from the viewer.
//!
//! Every point comes from the crate's code: the facets' slopes from
//! [`NormalDistribution::sample_normal`] with a fixed seed, the incoming direction from
//! [`reflect_away`], the density from [`NormalDistribution::d`], the visible normals from
//! [`visible_facets::ggx`]. The diagrams are cut through the plane `y = 0` of the local frame
//! (`z` the surface's normal), drawn with `x` to the right and `z` up.

use crate::microfacet::distribution::NormalDistribution;
use crate::microfacet::fresnel::reflect_away;
use crate::microfacet::visible_facets;
use common::scene::MicrofacetDistribution;
use glam::{UVec2, Vec2, Vec3};
use std::path::Path;
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

/// Writes every diagram of the page into `out` (the figures' `diagrams` folder).
pub fn write_all(out: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out)?;
    facets_and_half_vector().save(&out.join("facets-and-half-vector.svg"))?;
    ggx_density_polar().save(&out.join("ggx-density.svg"))?;
    visible_normals_projected().save(&out.join("visible-normals-projected.svg"))?;
    Ok(())
}

/// Uniform numbers from a fixed seed, for the diagrams' random facets and normals.
fn numbers(seed: u64) -> impl FnMut() -> Vec2 {
    use common::sampler::{IndependentSampler, Sampler};
    let mut sampler = IndependentSampler::new(seed);
    sampler.start_pixel_sample(UVec2::ZERO, 0);
    move || sampler.get_2d()
}

// ---------------------------------------------------------------------------------------
// The facets and the half vector
// ---------------------------------------------------------------------------------------

/// The roughness of the drawn surface.
const FACET_ALPHA: f32 = 0.3;
/// How many facets, and how wide each is.
const FACETS: usize = 14;
const FACET_WIDTH: f32 = 0.6;
/// The direction to the viewer.
const TO_VIEWER: Vec3 = Vec3::new(-0.8, 0.0, 0.6);

/// The rough surface's profile: `FACETS` facets side by side, each's normal drawn from
/// `D(m) cos θ_m` in the plane of the diagram (azimuth 0 or π), its height continuing from the
/// previous facet's end. Returns the profile's points and the facets' normals.
fn profile() -> (Vec<Vec3>, Vec<Vec3>) {
    let distribution = NormalDistribution::isotropic(MicrofacetDistribution::Ggx, FACET_ALPHA);
    let mut next = numbers(9);
    let mut points = vec![Vec3::new(-0.5 * FACETS as f32 * FACET_WIDTH, 0.0, 0.0)];
    let mut normals = Vec::new();
    for _ in 0..FACETS {
        let u = next();
        // The azimuth's number 0 or one half: a normal leaning along +x or -x.
        let m = distribution.sample_normal(Vec2::new(u.x, if u.y < 0.5 { 0.0 } else { 0.5 }));
        let m = Vec3::new(m.x, 0.0, m.z).normalize();
        // Along the facet, perpendicular to its normal.
        let along = Vec3::new(m.z, 0.0, -m.x);
        let last = *points.last().expect("a first point");
        points.push(last + along * (FACET_WIDTH / along.x));
        normals.push(m);
    }
    // Centre the profile's mean height on z = 0, the macro-surface.
    let mean = points.iter().map(|p| p.z).sum::<f32>() / points.len() as f32;
    for p in &mut points {
        p.z -= mean;
    }
    (points, normals)
}

/// What the facet diagram draws: the profile, the chosen facet's centre and normal, the two
/// directions, and the half vector computed from them.
struct HalfVector {
    points: Vec<Vec3>,
    chosen: usize,
    centre: Vec3,
    facet_normal: Vec3,
    wo: Vec3,
    wi: Vec3,
    h: Vec3,
}

fn half_vector() -> HalfVector {
    let (points, normals) = profile();
    // The facet drawn: among those tilted by more than 10°, the one whose mirror image of
    // the viewer's direction rises highest above the surface.
    let wo = TO_VIEWER.normalize();
    let chosen = (0..FACETS)
        .filter(|&i| normals[i].z < 10f32.to_radians().cos())
        .max_by(|&a, &b| {
            let rise = |i: usize| reflect_away(wo, normals[i]).z;
            rise(a).total_cmp(&rise(b))
        })
        .expect("a tilted facet");
    let m = normals[chosen];
    // The light the chosen facet mirrors towards the viewer.
    let wi = reflect_away(wo, m);
    let h = (wi + wo).normalize();
    HalfVector {
        centre: 0.5 * (points[chosen] + points[chosen + 1]),
        chosen,
        points,
        facet_normal: m,
        wo,
        wi,
        h,
    }
}

fn xz(p: Vec3) -> Point {
    (f64::from(p.x), f64::from(p.z))
}

fn facets_and_half_vector() -> Diagram {
    let v = half_vector();
    let mut d = Diagram::new(
        "A rough surface drawn as flat facets of random slopes. Light arriving from direction \
         omega i leaves towards omega o only from facets whose normal m is the half vector h, \
         the normalized sum of omega i and omega o; the highlighted facet is one of them, its \
         normal lies along h, and it mirrors one direction into the other. The macro-surface's \
         normal n points straight up.",
        (-4.6, 4.6),
        (-0.9, 2.5),
        720,
    );
    let profile: Vec<Point> = v.points.iter().map(|&p| xz(p)).collect();
    d.line((-4.4, 0.0), (4.4, 0.0), Ink::Guide);
    d.label((4.4, -0.15), "macro-surface", Anchor::Right, Ink::Guide)
        .polyline(profile, Ink::Surface);
    let (a, b) = (xz(v.points[v.chosen]), xz(v.points[v.chosen + 1]));
    d.area(
        vec![a, b, (b.0, b.1 - 0.12), (a.0, a.1 - 0.12)],
        Ink::Normal,
        0.5,
    );
    let c = v.centre;
    let reach = 2.0;
    d.arrow(xz(c), xz(c + reach * v.wi), Ink::Light);
    d.label(
        xz(c + (reach + 0.2) * v.wi),
        "ωᵢ",
        Anchor::Centre,
        Ink::Light,
    );
    d.arrow(xz(c), xz(c + reach * v.wo), Ink::Ray);
    d.label(xz(c + (reach + 0.2) * v.wo), "ωₒ", Anchor::Centre, Ink::Ray);
    // h, computed from the two directions, under the facet's own normal m.
    d.line(xz(c), xz(c + 1.7 * v.h), Ink::Guide);
    d.arrow(xz(c), xz(c + 1.3 * v.facet_normal), Ink::Normal);
    let tip = xz(c + 1.75 * v.h);
    d.label(tip, "m = h", Anchor::Below, Ink::Normal);
    d.label(
        (-4.4, 2.25),
        "h = (ωᵢ + ωₒ) / ‖ωᵢ + ωₒ‖",
        Anchor::Left,
        Ink::Normal,
    );
    let n_at = Vec3::new(3.4, 0.0, 0.0);
    d.arrow(xz(n_at), xz(n_at + Vec3::Z), Ink::Guide);
    d.label(xz(n_at + 1.1 * Vec3::Z), "n̂", Anchor::Below, Ink::Guide);
    d
}

// ---------------------------------------------------------------------------------------
// GGX's density of normals
// ---------------------------------------------------------------------------------------

/// The two roughnesses of the polar plot.
const POLAR_ALPHAS: [f32; 2] = [0.2, 0.5];

/// The curve of `D(θ) / D(0)` in the plane of incidence, as points `(θ, r)` from `-π/2` to
/// `π/2`, for GGX of roughness `alpha`.
fn polar_curve(alpha: f32) -> Vec<(f32, f32)> {
    let distribution = NormalDistribution::isotropic(MicrofacetDistribution::Ggx, alpha);
    let peak = distribution.d(Vec3::Z);
    (0..=180)
        .map(|i| {
            let theta = (i as f32 / 180.0 - 0.5) * std::f32::consts::PI;
            let m = Vec3::new(theta.sin(), 0.0, theta.cos());
            (theta, distribution.d(m) / peak)
        })
        .collect()
}

/// The angle at which `D` falls to half its peak, found by bisection on the crate's `d`.
fn half_maximum(alpha: f32) -> f32 {
    let distribution = NormalDistribution::isotropic(MicrofacetDistribution::Ggx, alpha);
    let peak = distribution.d(Vec3::Z);
    let (mut low, mut high) = (0.0f32, std::f32::consts::FRAC_PI_2);
    for _ in 0..40 {
        let mid = 0.5 * (low + high);
        let m = Vec3::new(mid.sin(), 0.0, mid.cos());
        if distribution.d(m) > 0.5 * peak {
            low = mid;
        } else {
            high = mid;
        }
    }
    0.5 * (low + high)
}

/// A point at angle `theta` from the normal (up) and distance `r` from the origin.
fn polar(theta: f32, r: f32) -> Point {
    (f64::from(r * theta.sin()), f64::from(r * theta.cos()))
}

fn ggx_density_polar() -> Diagram {
    let mut d = Diagram::new(
        "A polar plot of GGX's density of facet normals D against the angle from the surface's \
         normal, each curve divided by its value at the normal: for a roughness of one fifth a \
         narrow spike, for one half a wider lobe. The dashed rays mark where each falls to half \
         its peak; the rougher surface's normals spread further from the normal.",
        (-1.25, 1.25),
        (-0.2, 1.3),
        720,
    );
    d.line((-1.2, 0.0), (1.2, 0.0), Ink::Surface);
    d.arc((0.0, 0.0), 1.0, 0.0, std::f64::consts::PI, Ink::Guide);
    d.label((1.02, 0.05), "D(0)", Anchor::Left, Ink::Guide);
    for (alpha, ink, side) in [
        (POLAR_ALPHAS[0], Ink::Ray, -1.0f32),
        (POLAR_ALPHAS[1], Ink::OtherRay, 1.0),
    ] {
        let curve: Vec<Point> = polar_curve(alpha)
            .into_iter()
            .map(|(t, r)| polar(t, r))
            .collect();
        d.polyline(curve, ink);
        let half = side * half_maximum(alpha);
        d.line((0.0, 0.0), polar(half, 1.15), Ink::Guide);
        let (x, y) = polar(half, 1.18);
        let anchor = if side < 0.0 {
            Anchor::Right
        } else {
            Anchor::Left
        };
        d.label(
            (x, y),
            &format!("α = {alpha}: half at {:.0}°", half.abs().to_degrees()),
            anchor,
            ink,
        );
    }
    d.arrow((0.0, 0.0), (0.0, 1.25), Ink::Normal);
    d.label((0.04, 1.22), "n̂", Anchor::Left, Ink::Normal);
    d
}

// ---------------------------------------------------------------------------------------
// The visible normals, projected
// ---------------------------------------------------------------------------------------

/// The viewing angle from the normal, and how many normals are drawn.
const VIEW_DEGREES: f32 = 60.0;
const VISIBLE_DRAWN: usize = 400;

/// GGX's visible normals of roughness one seen from `VIEW_DEGREES`, each projected onto the
/// plane across the viewing direction: `(across, up)` with `up` towards the normal's side.
fn visible_points(count: usize, seed: u64) -> Vec<Vec2> {
    let cos_theta = VIEW_DEGREES.to_radians().cos();
    let sin_theta = VIEW_DEGREES.to_radians().sin();
    let mut next = numbers(seed);
    // The plane across w = (sin θ, 0, cos θ): `-y`, and the direction up the view.
    let up = Vec3::new(-cos_theta, 0.0, sin_theta);
    (0..count)
        .map(|_| {
            let m = visible_facets::ggx(cos_theta, next());
            Vec2::new(-m.y, m.dot(up))
        })
        .collect()
}

fn visible_normals_projected() -> Diagram {
    let cos_theta = f64::from(VIEW_DEGREES.to_radians().cos());
    let mut d = Diagram::new(
        "GGX's facets of roughness one form a hemisphere. Seen from 60 degrees off the normal, \
         the hemisphere projects onto a half-disc (its dome, above) and a half-ellipse as tall \
         as the cosine of 60 degrees (the near half of its base, below); the \
         visible normals the sampler draws, projected the same way, fill both halves \
         uniformly.",
        (-1.6, 1.6),
        (-0.85, 1.35),
        720,
    );
    let half_disc: Vec<Point> = (0..=90)
        .map(|i| {
            let a = std::f64::consts::PI * f64::from(i) / 90.0;
            (a.cos(), a.sin())
        })
        .collect();
    let half_ellipse: Vec<Point> = (0..=90)
        .map(|i| {
            let a = std::f64::consts::PI * f64::from(i) / 90.0;
            (a.cos(), -cos_theta * a.sin())
        })
        .collect();
    d.polyline(half_disc, Ink::Surface);
    d.polyline(half_ellipse, Ink::Surface);
    d.line((-1.0, 0.0), (1.0, 0.0), Ink::Guide);
    for p in visible_points(VISIBLE_DRAWN, 3) {
        d.dot((f64::from(p.x), f64::from(p.y)), Ink::Ray);
    }
    d.label(
        (0.0, 1.05),
        "half-disc: the dome",
        Anchor::Below,
        Ink::Surface,
    );
    d.label(
        (0.0, -cos_theta - 0.05),
        "half-ellipse: the base, cos θₒ tall",
        Anchor::Above,
        Ink::Surface,
    );
    d
}

#[cfg(test)]
mod tests {
    use super::*;
    use workbench::test_support::written_diagrams;

    #[test]
    fn the_half_vector_is_the_normal_of_the_facet_that_mirrors_one_direction_into_the_other() {
        let v = half_vector();
        assert!(
            (v.h - v.facet_normal).length() < 1e-5,
            "{:?} {:?}",
            v.h,
            v.facet_normal
        );
        assert!((reflect_away(v.wi, v.h) - v.wo).length() < 1e-5);
        assert!(v.wi.z > 0.0 && v.wo.z > 0.0, "both above the surface");
        // The facet is tilted: its normal is not the macro-surface's.
        assert!(v.facet_normal.z < 0.99);
        // The profile's points follow the facets' normals.
        let (points, normals) = profile();
        for (pair, m) in points.windows(2).zip(&normals) {
            assert!((pair[1] - pair[0]).normalize().dot(*m).abs() < 1e-5);
        }
    }

    #[test]
    fn the_rougher_density_is_wider_and_each_curve_is_d_over_its_peak() {
        let (sharp, rough) = (half_maximum(POLAR_ALPHAS[0]), half_maximum(POLAR_ALPHAS[1]));
        assert!(rough > 1.5 * sharp, "{sharp} {rough}");
        for alpha in POLAR_ALPHAS {
            let curve = polar_curve(alpha);
            let top = curve.iter().map(|c| c.1).fold(0.0, f32::max);
            assert!((top - 1.0).abs() < 1e-5, "the peak is at the normal");
            let half = half_maximum(alpha);
            let distribution = NormalDistribution::isotropic(MicrofacetDistribution::Ggx, alpha);
            let at = distribution.d(Vec3::new(half.sin(), 0.0, half.cos()));
            assert!((at / distribution.d(Vec3::Z) - 0.5).abs() < 1e-4);
        }
    }

    #[test]
    fn visible_normals_fill_the_half_disc_and_the_half_ellipse_uniformly() {
        let cos_theta = VIEW_DEGREES.to_radians().cos();
        let n = 20_000;
        let points = visible_points(n, 17);
        let mut below = 0;
        for p in &points {
            let inside = if p.y >= 0.0 {
                p.length() <= 1.0 + 1e-4
            } else {
                p.x * p.x + (p.y / cos_theta).powi(2) <= 1.0 + 1e-3
            };
            assert!(inside, "{p} lies outside the projected hemisphere");
            below += usize::from(p.y < 0.0);
        }
        // Uniform over both: the half-ellipse's share of the area, cos θ / (1 + cos θ).
        let share = below as f64 / n as f64;
        let expected = f64::from(cos_theta / (1.0 + cos_theta));
        let sigma = (expected * (1.0 - expected) / n as f64).sqrt();
        assert!(
            (share - expected).abs() < 5.0 * sigma,
            "{share} against {expected}"
        );
        // And not a whole disc: no point below the half-ellipse.
        assert!(points.iter().all(|p| p.y >= -cos_theta - 1e-4));
    }

    #[test]
    fn write_all_writes_each_diagram_as_svg_with_its_description() {
        written_diagrams(
            write_all,
            &[
                "facets-and-half-vector.svg",
                "ggx-density.svg",
                "visible-normals-projected.svg",
            ],
        );
    }
}
