//! The chapter's diagrams: the geometry the page explains, drawn from the chapter's own
//! functions so that every direction in them is one the tracer would compute.
//!
//! - `fuzzy-lobe.svg`: a ray arrives at a grazing angle, chapter 01's `reflect` gives the
//!   mirror direction, and [`sample_lobe_around`] with fixed `ξ` spreads it; the lobe's
//!   density ([`lobe_around_pdf`]) is drawn as its outline, and the directions that fall below
//!   the surface are marked, with what [`BelowSurface::Drop`] (the default) does with them.
//! - `fuzzy-refraction.svg`: at glass, the reflection lobe around the mirror direction and the
//!   refraction lobe around chapter 01's refracted direction, whose exponent
//!   [`transmission_exponent`] makes narrower.
//!
//! Every sampled direction is drawn in the plane of incidence: `ξ1` (the turn about the lobe's
//! axis) is chosen so that the direction stays in that plane, and `ξ2` (how far from the axis)
//! is a fixed quantile. Only the scene is set by hand: the surface, the angle of incidence, the
//! exponents.

use std::f32::consts::TAU;
use std::path::Path;

use ch01_whitted::optics::{reflect, refract};
use common::sampler::{IndependentSampler, Sampler};
use glam::{UVec2, Vec2, Vec3};
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

use crate::below_surface::BelowSurface;
use crate::fuzz::{lobe_around_pdf, sample_lobe_around, to_world};
use crate::tracer::transmission_exponent;

/// The width of every diagram, in pixels.
const WIDTH: u32 = 720;

/// Writes the chapter's diagrams into `out_dir`, creating it.
pub fn write_all(out_dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)?;
    fuzzy_lobe(&LobeScene::new()).save(&out_dir.join("fuzzy-lobe.svg"))?;
    fuzzy_refraction(&RefractionScene::new()).save(&out_dir.join("fuzzy-refraction.svg"))?;
    Ok(())
}

/// The surface normal of both diagrams: the surface is the plane `y = 0`, the plane of
/// incidence the page's plane `z = 0`.
const NORMAL: Vec3 = Vec3::Y;

/// The unit direction travelling towards the surface at `degrees` from the normal, from the
/// upper left.
fn arriving_at(degrees: f32) -> Vec3 {
    let theta = degrees.to_radians();
    Vec3::new(theta.sin(), -theta.cos(), 0.0)
}

/// The `ξ` that makes [`sample_lobe_around`] return the direction at the lobe's quantile `xi2`
/// (its share of directions closer to the axis) on the side `towards` of the axis `center`,
/// in the plane spanned by the two: `ξ1` is the turn about the axis that points at `towards`.
fn xi_in_plane(center: Vec3, towards: Vec3, xi2: f32) -> Vec2 {
    // The frame's own axes, whichever frame the lobe is turned by.
    let (a, b) = (to_world(center, Vec3::X), to_world(center, Vec3::Y));
    let phi = towards.dot(b).atan2(towards.dot(a));
    Vec2::new((phi / TAU).rem_euclid(1.0), xi2)
}

/// The directions of the plane `z = 0` perpendicular to `d`: `d` turned by +90°.
fn turned_left(d: Vec3) -> Vec3 {
    Vec3::Z.cross(d)
}

fn point(d: Vec3, length: f32) -> Point {
    (f64::from(d.x * length), f64::from(d.y * length))
}

/// The outline of the lobe of `exponent` around `center` in the plane `z = 0`: at each
/// direction of the plane, a length proportional to the lobe's density there, `peak` along
/// the axis. Only the directions whose side of the surface `keep` accepts are kept, with the
/// surface point at both ends, so the outline closes.
fn lobe_outline(center: Vec3, exponent: f32, peak: f32, keep: impl Fn(Vec3) -> bool) -> Vec<Point> {
    let top = lobe_around_pdf(1.0, exponent);
    let mut outline = vec![(0.0, 0.0)];
    for i in 0..=720 {
        let angle = i as f32 / 720.0 * TAU;
        let d = Vec3::new(angle.cos(), angle.sin(), 0.0);
        if keep(d) {
            let length = peak * lobe_around_pdf(d.dot(center), exponent) / top;
            outline.push(point(d, length));
        }
    }
    outline.push((0.0, 0.0));
    outline
}

/// One direction drawn from a lobe with a fixed `ξ`.
#[derive(Clone, Copy, Debug)]
struct LobeSample {
    /// The `ξ` it was drawn from (read by the tests, which check the direction against it).
    #[cfg_attr(not(test), allow(dead_code))]
    xi: Vec2,
    /// The direction [`sample_lobe_around`] returned.
    direction: Vec3,
    /// What the default policy for stray directions, [`BelowSurface::Drop`], makes of it.
    kept: Option<Vec3>,
}

/// The fuzzy lobe's scene: a glossy surface, a grazing ray, its mirror direction and
/// directions drawn around it.
#[derive(Clone, Debug)]
struct LobeScene {
    /// The angle of incidence, in degrees from the normal.
    incidence: f32,
    /// The lobe's exponent.
    exponent: f32,
    /// The incoming direction.
    incoming: Vec3,
    /// The mirror direction, chapter 01's `reflect`.
    mirror: Vec3,
    /// Directions from the lobe at fixed `ξ`, on both sides of the mirror direction.
    samples: Vec<LobeSample>,
}

impl LobeScene {
    fn new() -> Self {
        let incidence = 70.0;
        let exponent = 10.0;
        let incoming = arriving_at(incidence);
        let mirror = reflect(incoming, NORMAL);
        let towards_normal = turned_left(mirror);
        let mut samples = Vec::new();
        for side in [towards_normal, -towards_normal] {
            for xi2 in [0.3, 0.6, 0.9] {
                let xi = xi_in_plane(mirror, side, xi2);
                let direction = sample_lobe_around(mirror, exponent, xi);
                samples.push(LobeSample {
                    xi,
                    direction,
                    kept: drop_policy(direction),
                });
            }
        }
        Self {
            incidence,
            exponent,
            incoming,
            mirror,
            samples,
        }
    }
}

/// What [`BelowSurface::Drop`] returns for a lobe that drew `direction`: the chapter's own
/// policy, asked with a `draw` that returns that direction.
fn drop_policy(direction: Vec3) -> Option<Vec3> {
    let mut sampler = IndependentSampler::new(0);
    sampler.start_pixel_sample(UVec2::ZERO, 0);
    BelowSurface::Drop.scatter(NORMAL, &mut sampler, |_| direction)
}

/// The lobe's description, also the page's alt text.
const LOBE_DESCRIPTION: &str = "A ray arrives at a glossy surface 70 degrees from the normal \
    and its mirror direction leaves 20 degrees above the surface. Around the mirror direction \
    the cos^n lobe (n = 10) is drawn as its density's outline, with six directions sampled from \
    it; the part of the lobe below the surface is shaded as lost, and the two sampled \
    directions that point into the surface are marked: the chapter drops them, so they carry \
    no light";

fn fuzzy_lobe(scene: &LobeScene) -> Diagram {
    let mut diagram = Diagram::new(LOBE_DESCRIPTION, (-1.25, 1.75), (-0.5, 1.1), WIDTH);
    let above = |d: Vec3| d.dot(NORMAL) >= 0.0;
    let (mirror, exponent) = (scene.mirror, scene.exponent);
    diagram
        .area(lobe_outline(mirror, exponent, 1.1, above), Ink::Ray, 0.12)
        .area(
            lobe_outline(mirror, exponent, 1.1, |d| !above(d)),
            Ink::Warning,
            0.25,
        )
        .line((-1.2, 0.0), (1.7, 0.0), Ink::Surface)
        .label((-1.2, -0.07), "surface", Anchor::Left, Ink::Surface)
        .arrow((0.0, 0.0), (0.0, 0.95), Ink::Normal)
        .label((0.0, 1.0), "n̂", Anchor::Below, Ink::Normal)
        .arrow(point(-scene.incoming, 1.1), (0.0, 0.0), Ink::Ray)
        .label(
            point(-scene.incoming, 1.15),
            "incoming ray",
            Anchor::Left,
            Ink::Ray,
        );
    // θᵢ on both sides of the normal: the mirror direction leaves at the angle the ray came in.
    // The right label sits between the normal and the steepest sampled direction.
    let theta = f64::from(scene.incidence.to_radians());
    let up = std::f64::consts::FRAC_PI_2;
    diagram
        .arc((0.0, 0.0), 0.3, up, up + theta, Ink::Guide)
        .arc((0.0, 0.0), 0.3, up - theta, up, Ink::Guide)
        .label(
            polar(0.38, up + theta / 2.0),
            "θᵢ",
            Anchor::Centre,
            Ink::Guide,
        )
        .label(polar(0.4, up - 0.28), "θᵢ", Anchor::Centre, Ink::Guide);
    for sample in &scene.samples {
        let ink = if sample.kept.is_some() {
            Ink::Ray
        } else {
            Ink::Warning
        };
        diagram.arrow((0.0, 0.0), point(sample.direction, 0.9), ink);
    }
    diagram
        .arrow((0.0, 0.0), point(mirror, 1.15), Ink::OtherRay)
        .label(
            point(mirror, 1.18),
            "mirror direction",
            Anchor::Left,
            Ink::OtherRay,
        );
    let lowest = scene
        .samples
        .iter()
        .map(|s| s.direction)
        .min_by(|a, b| a.y.total_cmp(&b.y))
        .expect("the lobe has samples");
    let (x, y) = point(lowest, 0.9);
    diagram.label(
        (x, y - 0.06),
        "below the surface: dropped",
        Anchor::Above,
        Ink::Warning,
    );
    diagram.label(
        (0.95, 0.75),
        &format!("cosⁿ lobe, n = {exponent}"),
        Anchor::Centre,
        Ink::Ray,
    );
    diagram
}

/// The point at `radius` and `angle` (radians from `+x`) around the origin.
fn polar(radius: f64, angle: f64) -> Point {
    (radius * angle.cos(), radius * angle.sin())
}

/// Frosted glass: a ray from air into glass, its reflection and refraction lobes.
#[derive(Clone, Debug)]
struct RefractionScene {
    /// The incoming direction.
    incoming: Vec3,
    /// The relative index as the code writes it, `η = η_i / η_t` (air over glass).
    eta: f32,
    /// The reflection lobe's exponent.
    exponent: f32,
    /// The mirror direction.
    mirror: Vec3,
    /// Chapter 01's refracted direction.
    refracted: Vec3,
    /// The refraction lobe's exponent, from [`transmission_exponent`].
    refraction_exponent: f32,
    /// The two directions at the lobe's median (`ξ2 = 1/2`) on either side of the mirror
    /// direction, and of the refracted one: half of each lobe's directions lie between them.
    reflection_median: [Vec3; 2],
    refraction_median: [Vec3; 2],
}

impl RefractionScene {
    fn new() -> Self {
        let incoming = arriving_at(40.0);
        let eta = 1.0 / 1.5;
        let exponent = 30.0;
        let mirror = reflect(incoming, NORMAL);
        let refracted = refract(incoming, NORMAL, eta).expect("air to glass always refracts");
        let refraction_exponent = transmission_exponent(exponent, eta);
        let median = |center: Vec3, exponent: f32| {
            let side = turned_left(center);
            [side, -side].map(|towards| {
                sample_lobe_around(center, exponent, xi_in_plane(center, towards, 0.5))
            })
        };
        Self {
            incoming,
            eta,
            exponent,
            mirror,
            refracted,
            refraction_exponent,
            reflection_median: median(mirror, exponent),
            refraction_median: median(refracted, refraction_exponent),
        }
    }
}

const REFRACTION_DESCRIPTION: &str = "A ray in air meets frosted glass 40 degrees from the \
    normal. Above the surface, the reflection lobe (n = 30) spreads around the mirror \
    direction; below it, the refraction lobe spreads around the refracted direction, bent \
    towards the normal by Snell's law. The refraction lobe's exponent is 36 times larger, so it \
    is about six times narrower: the two directions at each lobe's median, between which half \
    of its directions fall, are much closer together below the surface than above it";

fn fuzzy_refraction(scene: &RefractionScene) -> Diagram {
    let mut diagram = Diagram::new(REFRACTION_DESCRIPTION, (-1.3, 1.3), (-1.05, 1.2), WIDTH);
    diagram
        .area(
            vec![(-1.3, 0.0), (1.3, 0.0), (1.3, -1.05), (-1.3, -1.05)],
            Ink::Guide,
            0.08,
        )
        .area(
            lobe_outline(scene.mirror, scene.exponent, 1.0, |d| d.y >= 0.0),
            Ink::Ray,
            0.12,
        )
        .area(
            lobe_outline(scene.refracted, scene.refraction_exponent, 1.0, |d| {
                d.y <= 0.0
            }),
            Ink::Ray,
            0.12,
        )
        .line((-1.3, 0.0), (1.3, 0.0), Ink::Surface)
        .label((-1.25, 0.07), "air", Anchor::Left, Ink::Surface)
        .label((-1.25, -0.09), "glass", Anchor::Left, Ink::Surface)
        .line((0.0, 0.0), (0.0, -1.0), Ink::Guide)
        .arrow((0.0, 0.0), (0.0, 0.8), Ink::Normal)
        .label((0.0, 0.85), "n̂", Anchor::Below, Ink::Normal)
        .arrow(point(-scene.incoming, 1.1), (0.0, 0.0), Ink::Ray)
        .label(
            point(-scene.incoming, 1.12),
            "incoming ray",
            Anchor::Below,
            Ink::Ray,
        );
    for d in scene
        .reflection_median
        .iter()
        .chain(&scene.refraction_median)
    {
        diagram.arrow((0.0, 0.0), point(*d, 0.85), Ink::Ray);
    }
    diagram
        .arrow((0.0, 0.0), point(scene.mirror, 1.15), Ink::OtherRay)
        .arrow((0.0, 0.0), point(scene.refracted, 1.0), Ink::OtherRay)
        .label(
            (0.3, 1.1),
            &format!("reflection lobe, n = {}", scene.exponent),
            Anchor::Left,
            Ink::Ray,
        )
        .label(
            (0.45, -0.55),
            &format!("refraction lobe, n = {}", scene.refraction_exponent.round()),
            Anchor::Left,
            Ink::Ray,
        )
        .label(
            (0.45, -0.7),
            &format!("η = ηᵢ/ηₜ = 1/{}", 1.0 / scene.eta),
            Anchor::Left,
            Ink::Surface,
        );
    diagram
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use workbench::test_support::written_diagrams;

    /// The angle between two unit vectors, in radians.
    fn angle(a: Vec3, b: Vec3) -> f32 {
        a.dot(b).clamp(-1.0, 1.0).acos()
    }

    #[test]
    fn the_mirror_direction_leaves_at_the_angle_the_ray_came_in() {
        let scene = LobeScene::new();
        let theta_in = angle(-scene.incoming, NORMAL);
        let theta_out = angle(scene.mirror, NORMAL);
        assert_relative_eq!(theta_in, scene.incidence.to_radians(), epsilon = 1e-5);
        assert_relative_eq!(theta_out, theta_in, epsilon = 1e-5);
        // On the far side of the normal, in the plane of incidence.
        assert!(scene.mirror.x > 0.0 && scene.mirror.z.abs() < 1e-6);
    }

    #[test]
    fn the_drawn_directions_are_the_lobes_quantiles_in_the_page_plane() {
        let scene = LobeScene::new();
        for sample in &scene.samples {
            let d = sample.direction;
            assert!(d.z.abs() < 1e-5, "{d} is not in the page's plane");
            // The cos^n lobe puts the share ξ2 of its directions within α of its axis, where
            // cos α = (1 - ξ2)^(1/(n+1)).
            let expected = (1.0 - sample.xi.y).powf(1.0 / (scene.exponent + 1.0));
            assert_relative_eq!(d.dot(scene.mirror), expected, epsilon = 1e-5);
        }
    }

    #[test]
    fn exactly_the_directions_below_the_surface_are_dropped() {
        let scene = LobeScene::new();
        let below: Vec<_> = scene
            .samples
            .iter()
            .filter(|s| s.direction.y < 0.0)
            .collect();
        // The diagram has a point to make, and its description counts them: of six
        // directions, two point into the surface.
        assert_eq!((below.len(), scene.samples.len()), (2, 6));
        for sample in &scene.samples {
            match sample.kept {
                Some(d) => assert!(d.y > 0.0 && d == sample.direction),
                None => assert!(sample.direction.y < 0.0),
            }
            // Far enough from the surface to be told apart at the diagram's size (2°).
            assert!(sample.direction.y.abs() > 2f32.to_radians().sin());
        }
    }

    #[test]
    fn the_refracted_ray_obeys_snell_and_its_lobe_is_narrower() {
        let scene = RefractionScene::new();
        // Snell's law with the code's η = η_i / η_t: sin θ_t = η sin θ_i.
        let sin_i = angle(-scene.incoming, NORMAL).sin();
        let sin_t = angle(scene.refracted, -NORMAL).sin();
        assert_relative_eq!(sin_t, scene.eta * sin_i, epsilon = 1e-5);
        // Half of each lobe lies between its two median directions. A tilt δ of a facet turns
        // the reflected ray by 2δ and the refracted one by |1 - η| δ: the refraction lobe is
        // narrower by |1 - η| / 2 (a sixth for glass of 1.5), to first order in the angle.
        let width = |[a, b]: [Vec3; 2]| angle(a, b);
        // The description's "36 times larger".
        assert_relative_eq!(
            scene.refraction_exponent / scene.exponent,
            36.0,
            epsilon = 1e-3
        );
        let ratio = width(scene.refraction_median) / width(scene.reflection_median);
        assert_relative_eq!(ratio, (1.0 - scene.eta).abs() / 2.0, max_relative = 0.05);
        assert!(scene.refraction_median.iter().all(|d| d.y < 0.0));
        assert!(scene.reflection_median.iter().all(|d| d.y > 0.0));
    }

    #[test]
    fn write_all_writes_each_diagram_as_svg_with_its_description() {
        assert_eq!(
            written_diagrams(write_all, &["fuzzy-lobe.svg", "fuzzy-refraction.svg"]),
            [LOBE_DESCRIPTION, REFRACTION_DESCRIPTION]
        );
    }
}
