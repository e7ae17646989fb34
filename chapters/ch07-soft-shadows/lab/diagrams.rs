//! The chapter's diagrams: the geometry the page explains, drawn from the chapter's own
//! samplers so that every point in them is one the estimator would use.
//!
//! - `area-to-solid-angle.svg`: a receiver under a tilted panel light, points on the panel
//!   from [`sample_parallelogram_light`], and one small patch `dA` of the panel with the cone
//!   of directions `dω` it covers from the receiver: the angles `θ` and `θ′` and the distance
//!   `r` that turn the one into the other.
//! - `sphere-cone.svg`: a receiver and a sphere light, the cone [`sphere_cone`] finds (its
//!   axis, its half-angle, the tangent lines touching the sphere), and directions drawn in it
//!   by [`sample_sphere_solid_angle`], each ending on the cap of the sphere the receiver sees.
//!
//! The drawing is a cross-section, the plane `z = 0`: the panel's second edge and the cone's
//! turn about its axis are chosen to keep the drawn points in it. Only the scene is set by
//! hand: the receiver, the light, the patch's size.

use std::f32::consts::TAU;
use std::path::Path;

use common::geometry::{Parallelogram, Sphere};
use glam::{Vec2, Vec3};
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

use crate::area_sampling::sample_parallelogram_light;
use crate::light_sample::LightSample;
use crate::solid_angle::{SphereCone, sample_sphere_solid_angle, sphere_cone};

/// The width of every diagram, in pixels.
const WIDTH: u32 = 720;

/// Writes the chapter's diagrams into `out_dir`, creating it.
pub fn write_all(out_dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)?;
    area_to_solid_angle(&PanelScene::new()).save(&out_dir.join("area-to-solid-angle.svg"))?;
    sphere_cone_diagram(&SphereScene::new()).save(&out_dir.join("sphere-cone.svg"))?;
    Ok(())
}

/// The receiver of both diagrams: a point of a floor `y = 0`, facing up.
const RECEIVER: Vec3 = Vec3::ZERO;
const RECEIVER_NORMAL: Vec3 = Vec3::Y;

fn point(p: Vec3) -> Point {
    (f64::from(p.x), f64::from(p.y))
}

/// The angle of `d` in the page's plane, in radians from `+x`.
fn heading(d: Vec3) -> f64 {
    f64::from(d.y.atan2(d.x))
}

/// The point at `radius` and `angle` (radians from `+x`) around `centre`.
fn polar(centre: Point, radius: f64, angle: f64) -> Point {
    (
        centre.0 + radius * angle.cos(),
        centre.1 + radius * angle.sin(),
    )
}

/// A panel light above the receiver, sampled along its middle.
#[derive(Clone, Debug)]
struct PanelScene {
    /// The light: its first edge in the page's plane, its second across it.
    quad: Parallelogram,
    /// Points on the panel along its middle (`ξ2 = 1/2`), stratified in `ξ1`.
    samples: Vec<LightSample>,
    /// The sample whose patch is drawn.
    chosen: LightSample,
    /// The patch: `ξ` within `PATCH / 2` of the chosen sample's, on both edges.
    patch_ends: [LightSample; 2],
    /// The chosen sample's `ξ` (read by the tests, which measure the patch around it).
    #[cfg_attr(not(test), allow(dead_code))]
    chosen_u: Vec2,
}

/// The patch's size in `ξ`, along each edge.
const PATCH: f32 = 0.14;

impl PanelScene {
    fn new() -> Self {
        let quad = Parallelogram::new(
            Vec3::new(0.3, 1.9, -0.5),
            Vec3::new(1.3, 0.45, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
        );
        let at = |u: Vec2| sample_parallelogram_light(&quad, u).expect("the panel has an area");
        let samples = (0..6)
            .map(|k| at(Vec2::new((k as f32 + 0.5) / 6.0, 0.5)))
            .collect();
        let chosen_u = Vec2::new(0.25, 0.5);
        let half = Vec2::new(PATCH / 2.0, 0.0);
        Self {
            quad,
            samples,
            chosen: at(chosen_u),
            patch_ends: [at(chosen_u - half), at(chosen_u + half)],
            chosen_u,
        }
    }

    /// The panel's two ends along its middle, from the sampler at `ξ1 = 0` and `ξ1 = 1`.
    fn ends(&self) -> [Vec3; 2] {
        [0.0, 1.0].map(|x| {
            sample_parallelogram_light(&self.quad, Vec2::new(x, 0.5))
                .expect("the panel has an area")
                .p
        })
    }
}

const PANEL_DESCRIPTION: &str = "A receiver point x on a floor, with its normal, under a \
    tilted panel light seen edge-on; dots mark points sampled on the panel. One small patch dA \
    of the panel, around the point y, is highlighted, with the thin cone of directions dω it \
    covers from the receiver, drawn where the cone crosses the unit circle around the \
    receiver. The patch is at distance r, the light's normal makes the angle θ′ with the \
    direction back to the receiver and the receiver's normal the angle θ with the direction \
    to the patch: the patch covers the solid angle dω = cos θ′ dA / r², smaller the farther \
    away or the more edge-on it is";

fn area_to_solid_angle(scene: &PanelScene) -> Diagram {
    let mut diagram = Diagram::new(PANEL_DESCRIPTION, (-1.3, 2.3), (-0.35, 2.75), WIDTH);
    let x = point(RECEIVER);
    let y = scene.chosen.p;
    let to_light = (y - RECEIVER).normalize();
    let [end_a, end_b] = scene.patch_ends.map(|s| point(s.p));
    // The cone dω: from the receiver to the patch, and its trace on the unit circle.
    let [dir_a, dir_b] = scene.patch_ends.map(|s| heading(s.p - RECEIVER));
    diagram
        .area(vec![x, end_a, end_b], Ink::Light, 0.35)
        .arc(x, 1.0, 0.0, std::f64::consts::PI, Ink::Guide)
        .arc(x, 1.0, dir_a.min(dir_b), dir_a.max(dir_b), Ink::OtherRay)
        .label(
            polar(x, 1.1, dir_a.min(dir_b) - 0.04),
            "dω",
            Anchor::Left,
            Ink::OtherRay,
        )
        .label((0.85, 0.25), "unit circle", Anchor::Left, Ink::Guide);
    let [start, end] = scene.ends().map(point);
    diagram
        .line((-1.3, 0.0), (2.3, 0.0), Ink::Surface)
        .line(start, end, Ink::Light)
        .label(
            (end.0 - 0.05, end.1 + 0.12),
            "area light",
            Anchor::Right,
            Ink::Light,
        )
        .line(end_a, end_b, Ink::OtherRay)
        .label(
            (end_a.0 - 0.02, end_a.1 + 0.16),
            "dA around y",
            Anchor::Right,
            Ink::OtherRay,
        );
    for sample in &scene.samples {
        diagram.dot(point(sample.p), Ink::Light);
    }
    // The receiver, its normal and the angle θ to the patch.
    diagram
        .dot(x, Ink::Surface)
        .label((0.0, -0.1), "receiver x", Anchor::Above, Ink::Surface)
        .arrow(x, point(RECEIVER + 0.7 * RECEIVER_NORMAL), Ink::Normal)
        .label((0.0, 0.75), "n̂", Anchor::Below, Ink::Normal)
        .arc(
            x,
            0.45,
            heading(to_light),
            heading(RECEIVER_NORMAL),
            Ink::Guide,
        )
        .label(
            polar(
                x,
                0.55,
                (heading(to_light) + heading(RECEIVER_NORMAL)) / 2.0,
            ),
            "θ",
            Anchor::Centre,
            Ink::Guide,
        );
    // The distance r and the patch's normal, with the angle θ′ to the way back.
    let yp = point(y);
    let mid = (0.3 * x.0 + 0.7 * yp.0, 0.3 * x.1 + 0.7 * yp.1);
    let normal_tip = point(y + 0.6 * scene.chosen.n);
    let back = heading(-to_light);
    let light_normal = heading(scene.chosen.n);
    diagram
        .line(x, yp, Ink::Ray)
        .label((mid.0 - 0.1, mid.1), "r", Anchor::Right, Ink::Ray)
        .arrow(yp, normal_tip, Ink::Normal)
        .label(
            (normal_tip.0 + 0.05, normal_tip.1 - 0.05),
            "light normal",
            Anchor::Left,
            Ink::Normal,
        )
        .arc(
            yp,
            0.35,
            back.min(light_normal),
            back.max(light_normal),
            Ink::Guide,
        )
        .label(
            polar(yp, 0.47, (back + light_normal) / 2.0),
            "θ′",
            Anchor::Centre,
            Ink::Guide,
        )
        .dot(yp, Ink::OtherRay)
        .label(
            (-1.2, 2.55),
            "dω = cos θ′ dA / r²",
            Anchor::Left,
            Ink::OtherRay,
        );
    diagram
}

/// A sphere light above the receiver, its cone and directions drawn in it.
#[derive(Clone, Debug)]
struct SphereScene {
    sphere: Sphere,
    cone: SphereCone,
    /// The two unit directions along the cone's rim in the page's plane.
    rims: [Vec3; 2],
    /// The points on the sphere that directions drawn in the cone meet, with the `ξ` each was
    /// drawn from.
    samples: Vec<(Vec2, LightSample)>,
}

impl SphereScene {
    fn new() -> Self {
        let sphere = Sphere::new(Vec3::new(1.0, 1.75, 0.0), 0.85);
        let cone = sphere_cone(&sphere, RECEIVER).expect("the receiver is outside the light");
        let across = Vec3::Z.cross(cone.axis);
        let cos_max = 1.0 - cone.one_minus_cos_theta_max;
        let rims = [1.0, -1.0].map(|side| cos_max * cone.axis + side * cone.sin_theta_max * across);
        // The cone's turn about its axis that points at `across` (or away): the directions
        // stay in the page's plane.
        let (t, b) = cone.axis.any_orthonormal_pair();
        let phi = across.dot(b).atan2(across.dot(t));
        let mut samples = Vec::new();
        for turn in [0.0, 0.5] {
            for xi2 in [0.15, 0.5, 0.9] {
                let u = Vec2::new((phi / TAU + turn).rem_euclid(1.0), xi2);
                let sample = sample_sphere_solid_angle(&sphere, RECEIVER, u)
                    .expect("a sphere seen from outside has a cone");
                samples.push((u, sample));
            }
        }
        Self {
            sphere,
            cone,
            rims,
            samples,
        }
    }

    /// Where each rim direction touches the sphere: at the distance `d cos θ_max`.
    fn tangent_points(&self) -> [Vec3; 2] {
        let cos_max = 1.0 - self.cone.one_minus_cos_theta_max;
        self.rims
            .map(|rim| RECEIVER + self.cone.distance * cos_max * rim)
    }
}

const SPHERE_DESCRIPTION: &str = "A receiver point on a floor and a sphere light above it. \
    From the receiver, two tangent lines touch the sphere; between them lies the cone of \
    directions in which the sphere is seen, of half-angle θ_max about the axis to the sphere's \
    centre, at distance d; R is the sphere's radius. Six directions sampled uniformly in the \
    cone end on the cap of the sphere that faces the receiver, between the two points of \
    tangency; the far side of the sphere gets none";

fn sphere_cone_diagram(scene: &SphereScene) -> Diagram {
    let mut diagram = Diagram::new(SPHERE_DESCRIPTION, (-1.0, 2.4), (-0.35, 2.85), WIDTH);
    let x = point(RECEIVER);
    let c = point(scene.sphere.center);
    let r = f64::from(scene.sphere.radius);
    let [touch_a, touch_b] = scene.tangent_points().map(point);
    // The cap the receiver sees: from one point of tangency to the other, the side facing x.
    let angle_at_centre = |p: Point| (p.1 - c.1).atan2(p.0 - c.0);
    let (from, mut to) = (angle_at_centre(touch_a), angle_at_centre(touch_b));
    let towards_x = (x.1 - c.1).atan2(x.0 - c.0);
    // Go the way round that passes the direction towards x.
    let between = |a: f64, b: f64, t: f64| {
        let turn = |v: f64| (v - a).rem_euclid(std::f64::consts::TAU);
        turn(t) < turn(b)
    };
    if !between(from, to, towards_x) {
        to -= std::f64::consts::TAU;
    } else if to < from {
        to += std::f64::consts::TAU;
    }
    diagram
        .area(
            (0..=128)
                .map(|i| polar(c, r, i as f64 / 128.0 * std::f64::consts::TAU))
                .collect(),
            Ink::Light,
            0.25,
        )
        .circle(c, r, Ink::Light)
        .arc(c, r, from, to, Ink::Surface)
        .line((-1.0, 0.0), (2.4, 0.0), Ink::Surface)
        .dot(x, Ink::Surface)
        .label((0.0, -0.1), "receiver", Anchor::Above, Ink::Surface);
    let extend = |p: Point| (p.0 * 1.12, p.1 * 1.12);
    diagram
        .line(x, extend(touch_a), Ink::Guide)
        .line(x, extend(touch_b), Ink::Guide)
        .line(x, c, Ink::Guide)
        .dot(c, Ink::Light)
        .line(c, touch_a, Ink::Guide)
        .label(
            ((c.0 + touch_a.0) / 2.0, (c.1 + touch_a.1) / 2.0 + 0.06),
            "R",
            Anchor::Below,
            Ink::Guide,
        )
        .dot(touch_a, Ink::Surface)
        .dot(touch_b, Ink::Surface);
    for (_, sample) in &scene.samples {
        diagram
            .arrow(x, point(sample.p), Ink::Ray)
            .dot(point(sample.p), Ink::Ray);
    }
    let axis = heading(scene.cone.axis);
    let rim_a = heading(scene.rims[0]);
    let mid_axis = polar(x, 0.62 * f64::from(scene.cone.distance), axis);
    diagram
        .arc(x, 0.5, axis.min(rim_a), axis.max(rim_a), Ink::OtherRay)
        .label(
            polar(x, 0.55, axis.max(rim_a) + 0.08),
            "θ_max",
            Anchor::Right,
            Ink::OtherRay,
        )
        .label(
            (mid_axis.0 + 0.06, mid_axis.1 - 0.05),
            "d",
            Anchor::Left,
            Ink::Guide,
        )
        .label(
            (c.0, c.1 + r + 0.06),
            "sphere light",
            Anchor::Below,
            Ink::Light,
        )
        .label(
            polar(c, r + 0.1, towards_x + 0.9),
            "visible cap",
            Anchor::Left,
            Ink::Surface,
        );
    diagram
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solid_angle::pdf_area_to_solid_angle;
    use approx::assert_relative_eq;
    use glam::DVec3;
    use workbench::test_support::written_diagrams;

    /// The solid angle of the triangle `a b c` seen from the origin (Van Oosterom and
    /// Strackee), in `f64`: a measure computed without the chapter's conversion.
    fn triangle_solid_angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
        let (la, lb, lc) = (a.length(), b.length(), c.length());
        let numerator = a.dot(b.cross(c)).abs();
        let denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
        2.0 * numerator.atan2(denominator)
    }

    #[test]
    fn the_panels_points_lie_on_it_with_its_density() {
        let scene = PanelScene::new();
        let normal = scene.quad.normal();
        for sample in scene.samples.iter().chain([&scene.chosen]) {
            assert!((sample.p - scene.quad.corner()).dot(normal).abs() < 1e-5);
            assert!(sample.p.z.abs() < 1e-6, "drawn in the page's plane");
            assert_relative_eq!(sample.pdf, 1.0 / scene.quad.area(), max_relative = 1e-5);
            // The panel faces the receiver: the light reaches it.
            assert!(sample.n.dot(RECEIVER - sample.p) > 0.0);
        }
    }

    #[test]
    fn the_patch_covers_cos_theta_prime_da_over_r_squared() {
        // The patch of the diagram, as a square of the panel, measured exactly from the
        // receiver; the label's cos θ′ dA / r² and the chapter's conversion of densities must
        // agree with it.
        let scene = PanelScene::new();
        let corner = |dx: f32, dy: f32| {
            let u = scene.chosen_u + Vec2::new(dx, dy) * PATCH / 2.0;
            sample_parallelogram_light(&scene.quad, u)
                .unwrap()
                .p
                .as_dvec3()
        };
        let [a, b, c, d] = [
            corner(-1.0, -1.0),
            corner(1.0, -1.0),
            corner(1.0, 1.0),
            corner(-1.0, 1.0),
        ];
        let d_omega = triangle_solid_angle(a, b, c) + triangle_solid_angle(a, c, d);
        let d_area = f64::from(scene.quad.area() * PATCH * PATCH);
        let y = scene.chosen.p;
        let r2 = (y - RECEIVER).length_squared();
        let cos_prime = scene.chosen.n.dot((RECEIVER - y).normalize());
        assert_relative_eq!(
            d_omega,
            f64::from(cos_prime / r2) * d_area,
            max_relative = 0.02
        );
        // A density per area becomes one per solid angle by the inverse ratio dA / dω.
        let per_solid_angle = pdf_area_to_solid_angle(1.0, r2, cos_prime);
        assert_relative_eq!(
            f64::from(per_solid_angle),
            d_area / d_omega,
            max_relative = 0.02
        );
        // The drawn patch is the square's middle line: its ends are two of the square's
        // edge midpoints' projections, and the wedge drawn is the cone's cross-section.
        let [end_a, end_b] = scene.patch_ends.map(|s| s.p);
        assert_relative_eq!(((end_a + end_b) / 2.0 - y).length(), 0.0, epsilon = 1e-5);
    }

    #[test]
    fn the_tangent_lines_touch_the_sphere() {
        let scene = SphereScene::new();
        let centre = scene.sphere.center;
        for (rim, touch) in scene.rims.iter().zip(scene.tangent_points()) {
            // The line from the receiver along the rim passes the centre at distance R.
            let to_centre = centre - RECEIVER;
            let distance = (to_centre - to_centre.dot(*rim) * *rim).length();
            assert_relative_eq!(distance, scene.sphere.radius, max_relative = 1e-5);
            assert_relative_eq!(
                (touch - centre).length(),
                scene.sphere.radius,
                max_relative = 1e-5
            );
            assert!(rim.z.abs() < 1e-6, "drawn in the page's plane");
        }
    }

    #[test]
    fn the_sampled_directions_end_on_the_visible_cap_inside_the_cone() {
        let scene = SphereScene::new();
        let centre = scene.sphere.center;
        let cos_max = 1.0 - scene.cone.one_minus_cos_theta_max;
        let cone_solid_angle = f64::from(TAU) * f64::from(scene.cone.one_minus_cos_theta_max);
        for (u, sample) in &scene.samples {
            let p = sample.p;
            assert_relative_eq!(
                (p - centre).length(),
                scene.sphere.radius,
                max_relative = 1e-5
            );
            assert!(p.z.abs() < 1e-5, "drawn in the page's plane");
            let d = (p - RECEIVER).normalize();
            assert!(d.dot(scene.cone.axis) >= cos_max - 1e-6, "inside the cone");
            // On the side that faces the receiver: the outward normal points back at it.
            assert!(sample.n.dot(RECEIVER - p) >= 0.0, "on the visible cap");
            // Uniform in the cone: the share ξ2 of its solid angle lies nearer the axis.
            let within = f64::from(TAU) * f64::from(1.0 - d.dot(scene.cone.axis));
            assert_relative_eq!(within / cone_solid_angle, f64::from(u.y), epsilon = 1e-3);
        }
    }

    #[test]
    fn write_all_writes_each_diagram_as_svg_with_its_description() {
        assert_eq!(
            written_diagrams(write_all, &["area-to-solid-angle.svg", "sphere-cone.svg"]),
            [PANEL_DESCRIPTION, SPHERE_DESCRIPTION]
        );
    }
}
