//! The chapter's diagrams: Snell's law with total internal reflection, and the rays Whitted's
//! recursion sends from one camera ray through a glass ball.
//!
//! Every direction drawn is one the chapter's own optics returned (`refract`, `reflect`,
//! `dielectric`), and every hit point one the workbook's sphere found, so the pictures are as
//! exact as the code; only the scene (the interface, the ball, the floor, the light, the
//! camera) is set up here. Each diagram is computed as a list of segments first, which the
//! tests check, and then drawn.

use crate::optics::{critical_angle, reflect, refract};
use crate::tracer::dielectric;
use common::Ray;
use common::geometry::{Sphere, SurfaceHit};
use glam::Vec3;
use std::path::Path;
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

/// The page's description (and the SVG's title) of the Snell's law diagram.
const SNELL: &str = "Snell's law at a flat interface. Left: rays from air (η = 1) at three \
    angles enter glass (η = 1.5) and bend towards the normal. Right: rays from inside the glass \
    at three angles leave into air and bend away from the normal; the one beyond the critical \
    angle θc has no refracted ray and is reflected back into the glass (total internal \
    reflection).";

/// The page's description of the ray-tree diagram.
const RAY_TREE: &str = "Whitted's recursion for one camera ray: it hits a glass ball and splits \
    into a reflected ray, which leaves for the sky, and a refracted ray, which crosses the ball \
    and splits again where it leaves (a weak reflection stays inside, the refracted ray goes \
    on); that ray lands on the matte floor, which sends a shadow ray to the point light.";

/// Writes the chapter's diagrams into `out_dir` (the figures' `diagrams` folder).
pub fn write_all(out_dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)?;
    snell_diagram().save(&out_dir.join("snell.svg"))?;
    ray_tree_diagram().save(&out_dir.join("ray-tree.svg"))?;
    Ok(())
}

/// The index of the glass of the chapter's scenes, and of air.
const GLASS: f32 = 1.5;
const AIR: f32 = 1.0;

/// One ray meeting a flat interface at the origin, and where it goes on.
#[derive(Clone, Copy, Debug)]
struct Crossing {
    /// The unit direction the ray arrives along.
    incident: Vec3,
    /// The unit direction it leaves along: refracted, or reflected when `refract` has none.
    outgoing: Vec3,
    /// Whether `outgoing` is the refracted ray (else total internal reflection).
    refracted: bool,
}

/// Rays at `angles` (radians from the normal) reaching the interface `y = 0` at the origin from
/// the side of index `eta_i` (above when `from_above`) and going on into `eta_t`.
fn crossings(eta_i: f32, eta_t: f32, from_above: bool, angles: &[f32]) -> Vec<Crossing> {
    let side = if from_above { 1.0 } else { -1.0 };
    // The normal on the side the ray comes from, as `refract` wants it.
    let n = Vec3::Y * side;
    angles
        .iter()
        .map(|&theta| {
            let incident = Vec3::new(theta.sin(), -side * theta.cos(), 0.0);
            match refract(incident, n, eta_i / eta_t) {
                Some(outgoing) => Crossing {
                    incident,
                    outgoing,
                    refracted: true,
                },
                None => Crossing {
                    incident,
                    outgoing: reflect(incident, n),
                    refracted: false,
                },
            }
        })
        .collect()
}

/// The angles of the Snell diagram's rays: entering glass, and leaving it (the last beyond
/// the critical angle of glass into air, about 42°).
const ENTERING: [f32; 3] = [20.0, 45.0, 70.0];
const LEAVING: [f32; 3] = [20.0, 35.0, 60.0];

fn radians(degrees: &[f32]) -> Vec<f32> {
    degrees.iter().map(|d| d.to_radians()).collect()
}

/// A direction in the diagram's plane (`x`, `y`).
fn planar(v: Vec3) -> Point {
    (f64::from(v.x), f64::from(v.y))
}

fn plus(p: Point, v: Vec3, length: f64) -> Point {
    let (x, y) = planar(v);
    (p.0 + length * x, p.1 + length * y)
}

/// The angle of `v` in the plane, radians counter-clockwise from `+x`.
fn angle_of(v: Vec3) -> f64 {
    f64::from(v.y).atan2(f64::from(v.x))
}

fn snell_diagram() -> Diagram {
    let mut diagram = Diagram::new(SNELL, (-4.2, 4.2), (-1.75, 1.75), 760);
    let panels = [
        (-2.1, AIR, GLASS, true, ENTERING, "air into glass"),
        (2.1, GLASS, AIR, false, LEAVING, "glass into air"),
    ];
    for (cx, eta_i, eta_t, from_above, angles, title) in panels {
        let o = (cx, 0.0);
        let (left, right) = (cx - 1.95, cx + 1.95);
        // The glass half, lightly shaded, and the interface.
        let glass_y = if from_above { -1.75 } else { 1.75 };
        let glass_y = if eta_t > eta_i { glass_y } else { -glass_y };
        diagram.area(
            vec![(left, 0.0), (right, 0.0), (right, glass_y), (left, glass_y)],
            Ink::Guide,
            0.12,
        );
        diagram.line((left, 0.0), (right, 0.0), Ink::Surface);
        diagram.line((cx, -1.6), (cx, 1.6), Ink::Guide);
        let n_up = if from_above { 1.0 } else { -1.0 };
        diagram.arrow(o, (cx, 0.55 * n_up), Ink::Normal);
        diagram.label((cx + 0.08, 0.62 * n_up), "n̂", Anchor::Left, Ink::Normal);
        let (eta_above, eta_below) = if from_above {
            (eta_i, eta_t)
        } else {
            (eta_t, eta_i)
        };
        // The indices as the page writes them: 1 for air, 1.5 for glass.
        let name = |eta: f32| {
            if eta == GLASS {
                "1.5 (glass)"
            } else {
                "1 (air)"
            }
        };
        diagram.label(
            (right - 0.05, 1.45),
            &format!("η = {}", name(eta_above)),
            Anchor::Right,
            Ink::Surface,
        );
        diagram.label(
            (right - 0.05, -1.45),
            &format!("η = {}", name(eta_below)),
            Anchor::Right,
            Ink::Surface,
        );
        diagram.label(
            (left + 0.05, -1.45 * n_up),
            title,
            Anchor::Left,
            Ink::Surface,
        );
        let length = 1.45;
        let rays = crossings(eta_i, eta_t, from_above, &radians(&angles));
        for crossing in &rays {
            diagram.arrow(plus(o, crossing.incident, -length), o, Ink::Ray);
            let ink = if crossing.refracted {
                Ink::OtherRay
            } else {
                Ink::Warning
            };
            diagram.arrow(o, plus(o, crossing.outgoing, length), ink);
        }
        // The angles of the middle ray: θᵢ against the normal on its side, θₜ on the other.
        let middle = rays[1];
        let towards_source = angle_of(-middle.incident);
        let normal_in = angle_of(Vec3::Y * n_up as f32);
        diagram.arc(
            o,
            0.5,
            normal_in.min(towards_source),
            normal_in.max(towards_source),
            Ink::Guide,
        );
        diagram.label(
            plus(
                o,
                (-middle.incident + Vec3::Y * n_up as f32).normalize(),
                0.78,
            ),
            "θᵢ",
            Anchor::Centre,
            Ink::Ray,
        );
        let normal_out = angle_of(-Vec3::Y * n_up as f32);
        let outgoing = angle_of(middle.outgoing);
        diagram.arc(
            o,
            0.5,
            normal_out.min(outgoing),
            normal_out.max(outgoing),
            Ink::Guide,
        );
        diagram.label(
            plus(
                o,
                (middle.outgoing - Vec3::Y * n_up as f32).normalize(),
                0.78,
            ),
            "θₜ",
            Anchor::Centre,
            Ink::OtherRay,
        );
        if let Some(critical) = critical_angle(eta_i, eta_t) {
            // The critical angle, and the ray past it that stays in the glass.
            let edge = Vec3::new(-critical.sin(), critical.cos() * n_up as f32, 0.0);
            diagram.line(o, plus(o, edge, 1.6), Ink::Guide);
            diagram.label(plus(o, edge, 1.62), "θc", Anchor::Right, Ink::Guide);
            if let Some(reflected) = rays.iter().find(|c| !c.refracted) {
                let end = plus(o, reflected.outgoing, length);
                diagram.label(
                    (end.0, end.1 - 0.08),
                    "reflected",
                    Anchor::Above,
                    Ink::Warning,
                );
            }
        }
    }
    diagram
}

/// One segment of a ray tree, with what it is.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Segment {
    from: Vec3,
    to: Vec3,
    kind: Kind,
    /// The segment's number along its path, as `trace`'s `depth` counts (the camera ray is 1);
    /// a shadow ray carries the number of the segment that reached its point.
    depth: u32,
}

/// What a segment of the ray tree is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Camera,
    Reflected,
    Refracted,
    Shadow,
}

/// The scene of the ray-tree diagram: a glass ball resting on the floor `y = 0`, a point light,
/// a camera ray.
const BALL_CENTRE: Vec3 = Vec3::new(0.0, 1.0, 0.0);
const LIGHT: Vec3 = Vec3::new(3.55, 2.9, 0.0);
const EYE: Vec3 = Vec3::new(-3.4, 2.3, 0.0);
const AIM: Vec3 = Vec3::new(-0.45, 1.75, 0.0);

/// How far a ray that leaves the picture is drawn.
const TO_THE_SKY: f32 = 1.6;
/// How far a ray trapped inside the ball is drawn (it bounces on, faintly).
const INSIDE: f32 = 0.6;

/// The rays `glass` at `hit` sends on for `ray`, as the chapter's `dielectric` spawns them,
/// each with its weight: a stand-in for the rest of the path records each ray and answers a
/// radiance of its own colour, so the sum `dielectric` returns holds each ray's weight.
fn glass_split(ray: &Ray, hit: &SurfaceHit) -> Vec<(Ray, f32)> {
    let mut spawned = Vec::new();
    let answers = [Vec3::X, Vec3::Y, Vec3::Z];
    let total = dielectric(ray, hit, GLASS, AIR, &mut |next| {
        spawned.push(*next);
        answers[spawned.len() - 1]
    });
    spawned.into_iter().zip(total.to_array()).collect()
}

/// The ray tree of one camera ray, computed with the chapter's optics and the workbook's sphere.
fn ray_tree() -> Vec<Segment> {
    let ball = Sphere::new(BALL_CENTRE, 1.0);
    let camera = Ray::new(EYE, (AIM - EYE).normalize());
    let first = ball
        .intersect(&camera)
        .expect("the camera ray is aimed at the ball");
    let mut segments = vec![Segment {
        from: EYE,
        to: first.p,
        kind: Kind::Camera,
        depth: 1,
    }];
    for (ray, _) in glass_split(&camera, &first) {
        if ray.dir.dot(first.n) > 0.0 {
            // Reflected off the outside: nothing else in the scene lies that way.
            segments.push(Segment {
                from: first.p,
                to: ray.at(TO_THE_SKY),
                kind: Kind::Reflected,
                depth: 2,
            });
            continue;
        }
        let second = ball
            .intersect(&ray)
            .expect("a ray inside the ball leaves it");
        segments.push(Segment {
            from: first.p,
            to: second.p,
            kind: Kind::Refracted,
            depth: 2,
        });
        for (inner, _) in glass_split(&ray, &second) {
            if inner.dir.dot(second.n) < 0.0 {
                segments.push(Segment {
                    from: second.p,
                    to: inner.at(INSIDE),
                    kind: Kind::Reflected,
                    depth: 3,
                });
                continue;
            }
            // Out of the ball, down to the floor y = 0.
            let t = -inner.origin.y / inner.dir.y;
            let floor = inner.at(t);
            segments.push(Segment {
                from: second.p,
                to: floor,
                kind: Kind::Refracted,
                depth: 3,
            });
            segments.push(Segment {
                from: floor,
                to: LIGHT,
                kind: Kind::Shadow,
                depth: 3,
            });
        }
    }
    segments
}

/// Where a segment's label goes: beside its middle, on the side where it overlaps nothing in
/// this scene (inside the ball, centred under its segment).
fn label_place(segment: &Segment) -> (Point, Anchor) {
    let along = (segment.to - segment.from).normalize();
    let left = Vec3::new(-along.y, along.x, 0.0);
    let middle = planar((segment.from + segment.to) / 2.0);
    match (segment.kind, segment.depth) {
        // The weak reflection inside the ball: its number at its tip.
        (Kind::Reflected, 3) => (plus(planar(segment.to), along, 0.1), Anchor::Right),
        (Kind::Refracted, 2) => (plus(middle, -left, 0.5), Anchor::Centre),
        (Kind::Refracted, _) => (plus(middle, left, 0.6), Anchor::Centre),
        (Kind::Camera, _) => (plus(middle, -left, 0.22), Anchor::Right),
        _ => (plus(middle, left, 0.22), Anchor::Right),
    }
}

fn ray_tree_diagram() -> Diagram {
    let mut diagram = Diagram::new(RAY_TREE, (-3.8, 3.8), (-0.45, 3.45), 720);
    diagram.area(
        vec![(-3.8, 0.0), (3.8, 0.0), (3.8, -0.45), (-3.8, -0.45)],
        Ink::Guide,
        0.15,
    );
    diagram.line((-3.8, 0.0), (3.8, 0.0), Ink::Surface);
    diagram.label((-3.7, -0.22), "matte floor", Anchor::Left, Ink::Surface);
    diagram.area(
        (0..=96)
            .map(|i| {
                let a = std::f64::consts::TAU * f64::from(i) / 96.0;
                (a.cos(), 1.0 + a.sin())
            })
            .collect(),
        Ink::Guide,
        0.12,
    );
    diagram.circle((0.0, 1.0), 1.0, Ink::Surface);
    diagram.label((-0.95, 0.2), "glass, η = 1.5", Anchor::Right, Ink::Surface);
    diagram.dot(planar(LIGHT), Ink::Light);
    diagram.label(
        plus(planar(LIGHT), Vec3::X, -0.12),
        "point light",
        Anchor::Right,
        Ink::Light,
    );
    diagram.dot(planar(EYE), Ink::Surface);
    diagram.label(
        plus(planar(EYE), Vec3::Y, 0.15),
        "eye",
        Anchor::Below,
        Ink::Surface,
    );
    for segment in ray_tree() {
        let (from, to) = (planar(segment.from), planar(segment.to));
        let (ink, name) = match segment.kind {
            Kind::Camera => (Ink::Ray, "camera ray"),
            Kind::Reflected => (Ink::OtherRay, "reflected"),
            Kind::Refracted => (Ink::Ray, "refracted"),
            Kind::Shadow => (Ink::Light, "shadow ray"),
        };
        diagram.arrow(from, to, ink);
        diagram.dot(from, Ink::Surface);
        let (at, anchor) = label_place(&segment);
        let text = match segment.kind {
            Kind::Shadow => name.to_string(),
            Kind::Reflected if segment.depth == 3 => "3".to_string(),
            _ => format!("{name} ({})", segment.depth),
        };
        diagram.label(at, &text, anchor, ink);
    }
    diagram
}

#[cfg(test)]
mod tests {
    use super::*;
    use workbench::test_support::written_diagrams;

    /// `sin θ` of a unit direction against the normal `±y`.
    fn sine(v: Vec3) -> f32 {
        v.x.abs() / v.length()
    }

    #[test]
    fn the_drawn_rays_obey_snells_law_or_are_totally_reflected() {
        let panels = [(AIR, GLASS, true, ENTERING), (GLASS, AIR, false, LEAVING)];
        let mut reflected = 0;
        for (eta_i, eta_t, from_above, angles) in panels {
            for c in crossings(eta_i, eta_t, from_above, &radians(&angles)) {
                let same_side = c.incident.y.signum() == -c.outgoing.y.signum();
                if c.refracted {
                    // Snell: η_i sin θ_i = η_t sin θ_t, and the ray goes on through.
                    let (lhs, rhs) = (eta_i * sine(c.incident), eta_t * sine(c.outgoing));
                    assert!((lhs - rhs).abs() < 1e-5, "{lhs} against {rhs}");
                    assert!(!same_side && c.incident.x * c.outgoing.x > 0.0);
                    // It bends towards the normal in the denser medium.
                    assert_eq!(sine(c.outgoing) < sine(c.incident), eta_t > eta_i);
                } else {
                    // Only past the critical angle, and then mirrored on the same side.
                    reflected += 1;
                    assert!(eta_i * sine(c.incident) > eta_t);
                    assert!(same_side);
                    assert!((sine(c.outgoing) - sine(c.incident)).abs() < 1e-6);
                }
            }
        }
        assert_eq!(reflected, 1, "the diagram shows one totally reflected ray");
    }

    #[test]
    fn the_ray_tree_splits_twice_and_ends_in_a_shadow_ray_that_reaches_the_light() {
        let tree = ray_tree();
        let count = |kind| tree.iter().filter(|s| s.kind == kind).count();
        assert_eq!(count(Kind::Camera), 1);
        assert_eq!(count(Kind::Reflected), 2, "one reflection at each crossing");
        assert_eq!(count(Kind::Refracted), 2, "into the ball, and out of it");
        assert_eq!(count(Kind::Shadow), 1);
        // The segments join up: each starts where an earlier one ended.
        for (i, segment) in tree.iter().enumerate().skip(1) {
            assert!(
                tree[..i]
                    .iter()
                    .any(|s| (s.to - segment.from).length() < 1e-4),
                "segment {i} starts nowhere"
            );
        }
        // The refracted ray lands on the floor, in front of the ball, and nothing (the ball
        // least of all) stands between it and the light: the floor there is lit.
        let shadow = tree.iter().find(|s| s.kind == Kind::Shadow).unwrap();
        assert!(shadow.from.y.abs() < 1e-4 && shadow.from.x > 1.0);
        let ball = Sphere::new(BALL_CENTRE, 1.0);
        assert!(
            ball.intersect(&Ray {
                t_max: 1.0,
                ..Ray::new(shadow.from, shadow.to - shadow.from)
            })
            .is_none()
        );
        // The weights of each split add up to what glass passes on: the reflected share F and
        // the refracted share (1 - F) scaled by the squared ratio of the indices.
        let ball_ray = Ray::new(EYE, (AIM - EYE).normalize());
        let hit = ball.intersect(&ball_ray).unwrap();
        let split = glass_split(&ball_ray, &hit);
        let f = crate::optics::fresnel_dielectric(-ball_ray.dir.dot(hit.n), AIR / GLASS);
        assert!((split[0].1 - f).abs() < 1e-6);
        assert!((split[1].1 - (1.0 - f) * (AIR / GLASS).powi(2)).abs() < 1e-6);
    }

    #[test]
    fn write_all_writes_each_diagram_as_svg_with_its_description() {
        assert_eq!(
            written_diagrams(write_all, &["snell.svg", "ray-tree.svg"]),
            [SNELL, RAY_TREE]
        );
    }
}
