//! The chapter's diagrams: the thin lens with its film, and the chapter's own model of it, with
//! the circle of confusion in each.
//!
//! Every image point is the chapter's thin lens equation ([`image_distance`]), every ray of
//! the chapter's model is its [`thin_lens_ray`], and every circle of confusion drawn is the
//! chapter's [`circle_of_confusion`] or [`circle_of_confusion_on_film`]; the tests hold the
//! rays' spread against those marks. Only the lens, the distances and the points looked at are
//! chosen here.

use crate::circle_of_confusion::{circle_of_confusion, circle_of_confusion_on_film};
use crate::lens::image_distance;
use crate::thin_lens::thin_lens_ray;
use glam::{Vec2, Vec3};
use std::path::Path;
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

/// Writes every diagram of the chapter into `out_dir`.
pub fn write_all(out_dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)?;
    thin_lens().save(&out_dir.join("thin-lens.svg"))?;
    focal_plane().save(&out_dir.join("focal-plane.svg"))?;
    Ok(())
}

/// The photographer's lens of the first diagram: focal length, aperture diameter `D` and focus
/// distance `d_f`, in the diagram's units.
const FOCAL_LENGTH: f32 = 1.0;
const DIAMETER: f32 = 1.2;
const FOCUS: f32 = 2.5;

/// The light of one point through the lens: where it starts, the lens points it passes
/// (the rim and the centre), the point where it meets again, and where it crosses the film.
#[derive(Clone, Debug)]
struct Bundle {
    /// The object point, at `(-depth, height)` (the light travels in `+x`).
    object: Vec2,
    /// The lens points, on `x = 0`: top rim, centre, bottom rim.
    lens: [Vec2; 3],
    /// The image point the thin lens equation gives.
    image: Vec2,
    /// Where each ray crosses the film.
    on_film: [Vec2; 3],
}

/// Where the film sits: the image distance of the focal plane.
fn film_distance() -> f32 {
    image_distance(FOCAL_LENGTH, FOCUS).expect("the focus lies beyond the focal length")
}

/// The bundle of a point at `depth` in front of the lens and `height` above the axis.
fn bundle(depth: f32, height: f32) -> Bundle {
    let image_depth = image_distance(FOCAL_LENGTH, depth).expect("beyond the focal length");
    // The ray through the centre goes straight on: the image is scaled by -d'/d.
    let image = Vec2::new(image_depth, -height * image_depth / depth);
    let r = DIAMETER / 2.0;
    let lens = [Vec2::new(0.0, r), Vec2::ZERO, Vec2::new(0.0, -r)];
    let film = film_distance();
    let on_film = lens.map(|l| l + (image - l) * (film / image.x));
    Bundle {
        object: Vec2::new(-depth, height),
        lens,
        image,
        on_film,
    }
}

/// The point of each panel in focus, the nearer one and the farther one.
const IN_FOCUS: (f32, f32) = (FOCUS, 0.6);
const NEARER: (f32, f32) = (1.6, -0.45);
const FARTHER: (f32, f32) = (5.0, -0.5);

/// What the thin-lens diagram says.
const THIN_LENS: &str = "A thin lens of aperture diameter D with the film behind it, placed so \
    that the focal plane at the focus distance d_f is sharp. Top: the rays from a point on the \
    focal plane meet again on the film, while those from a nearer point would meet behind the \
    film and cut it in a disc, the circle of confusion c. Bottom: the rays from a farther point \
    meet in front of the film and have spread into a disc again when they reach it.";

/// The thin lens with its film: a point in focus, and a nearer (top) and a farther (bottom)
/// point whose light reaches the film as a disc.
fn thin_lens() -> Diagram {
    let film = f64::from(film_distance());
    let panel = 2.6;
    let mut diagram = Diagram::new(THIN_LENS, (-5.9, 3.3), (-panel - 1.45, 1.35), 720);
    for (k, out_of_focus, name) in [(0, NEARER, "nearer"), (1, FARTHER, "farther")] {
        let dy = -panel * k as f64;
        let at = |v: Vec2| -> Point { (f64::from(v.x), f64::from(v.y) + dy) };
        let r = f64::from(DIAMETER / 2.0);
        // The axis, the focal plane, the lens and the film.
        diagram.line((-5.4, dy), (3.1, dy), Ink::Guide);
        let focal = -f64::from(FOCUS);
        diagram.line((focal, dy - 1.0), (focal, dy + 1.0), Ink::Guide);
        // The lens, as tall as its aperture, with the aperture's ends marked.
        diagram.line((0.0, dy - r), (0.0, dy + r), Ink::Surface);
        for end in [dy - r, dy + r] {
            diagram.line((-0.1, end), (0.1, end), Ink::Surface);
        }
        diagram.line((film, dy - 1.0), (film, dy + 1.0), Ink::Surface);
        diagram.label((film + 0.1, dy + 0.95), "film", Anchor::Left, Ink::Surface);
        let lens_label = if k == 0 {
            "lens, aperture D"
        } else {
            "aperture D"
        };
        diagram.label(
            (0.0, dy + r + 0.08),
            lens_label,
            Anchor::Below,
            Ink::Surface,
        );
        if k == 0 {
            diagram.label((focal, dy + 1.05), "focal plane", Anchor::Below, Ink::Guide);
        }
        for (depth_height, ink) in [(IN_FOCUS, Ink::Ray), (out_of_focus, Ink::OtherRay)] {
            let b = bundle(depth_height.0, depth_height.1);
            for i in 0..3 {
                diagram.line(at(b.object), at(b.lens[i]), ink);
                if b.image.x <= film_distance() {
                    // Meets in front of (or on) the film, then spreads to it.
                    diagram.line(at(b.lens[i]), at(b.on_film[i]), ink);
                } else {
                    // Reaches the film first; where it would meet is drawn as a guide.
                    diagram.line(at(b.lens[i]), at(b.on_film[i]), ink);
                    diagram.line(at(b.on_film[i]), at(b.image), Ink::Guide);
                }
            }
            diagram.dot(at(b.object), ink);
        }
        // The circle of confusion, the chapter's, around the film point of the central ray:
        // the stretch of film the out-of-focus light covers.
        let b = bundle(out_of_focus.0, out_of_focus.1);
        let c = circle_of_confusion_on_film(FOCAL_LENGTH, DIAMETER, FOCUS, out_of_focus.0);
        let centre = at(b.on_film[1]);
        let (top, bottom) = (centre.1 + f64::from(c) / 2.0, centre.1 - f64::from(c) / 2.0);
        for x in [film - 0.03, film, film + 0.03] {
            diagram.line((x, top), (x, bottom), Ink::Warning);
        }
        diagram.label(
            (film + 0.1, 0.5 * (top + bottom)),
            "c",
            Anchor::Left,
            Ink::Warning,
        );
        let object = at(b.object);
        let below = object.1 < dy;
        diagram.label(
            (object.0, object.1 + if below { -0.12 } else { 0.12 }),
            name,
            if below { Anchor::Above } else { Anchor::Below },
            Ink::OtherRay,
        );
        let focus_object = at(bundle(IN_FOCUS.0, IN_FOCUS.1).object);
        diagram.label(
            (focus_object.0 - 0.1, focus_object.1 + 0.12),
            "in focus",
            Anchor::Below,
            Ink::Ray,
        );
    }
    // The focus distance, under the lower panel.
    let y = -panel - 1.15;
    diagram.line(
        (-f64::from(FOCUS), y - 0.1),
        (-f64::from(FOCUS), y + 0.1),
        Ink::Surface,
    );
    diagram.line((0.0, y - 0.1), (0.0, y + 0.1), Ink::Surface);
    diagram.arrow(
        (-1.25, y + 0.22),
        (-f64::from(FOCUS), y + 0.22),
        Ink::Surface,
    );
    diagram.arrow((-1.25, y + 0.22), (0.0, y + 0.22), Ink::Surface);
    diagram.label(
        (-1.25, y + 0.12),
        "focus distance d_f",
        Anchor::Above,
        Ink::Surface,
    );
    diagram
}

/// The chapter's model of the second diagram: lens radius `R`, focus distance `d_f`.
const MODEL_RADIUS: f32 = 0.7;
const MODEL_FOCUS: f32 = 2.5;
/// The depths of the nearer and the farther point of its two panels.
const MODEL_DEPTHS: [f32; 2] = [1.4, 5.5];

/// The chapter's camera rays that see the point at `depth` on the axis: for the rim points of
/// the lens and its centre, the focus point on the focal plane `P_f` and the ray
/// [`thin_lens_ray`] sends from the lens point towards it.
struct ModelRays {
    /// The lens points (top rim, centre, bottom rim) in the plane `z = 0`.
    lens: [Vec2; 3],
    /// The points of the focal plane whose film positions see the point through each lens
    /// point: where each ray crosses the focal plane.
    focus: [Vec3; 3],
    /// The rays, origin and direction, as the chapter's camera makes them.
    rays: [(Vec3, Vec3); 3],
}

fn model_rays(depth: f32) -> ModelRays {
    let q = Vec3::new(0.0, 0.0, depth);
    let lens = [
        Vec2::new(MODEL_RADIUS, 0.0),
        Vec2::ZERO,
        Vec2::new(-MODEL_RADIUS, 0.0),
    ];
    // For each lens point, the film position (its pinhole direction's x on z = 1) whose ray
    // from that lens point passes through the point looked at, found by bisection on where the
    // ray crosses the depth of the point: further right on the film, further right there.
    let rays = lens.map(|l| {
        let ray = |x: f32| thin_lens_ray(Vec3::new(x, 0.0, 1.0), l, MODEL_FOCUS);
        let x_at_depth = |x: f32| {
            let (origin, dir) = ray(x);
            origin.x + dir.x * ((q.z - origin.z) / dir.z)
        };
        let (mut left, mut right) = (-10.0f32, 10.0f32);
        for _ in 0..80 {
            let middle = 0.5 * (left + right);
            if x_at_depth(middle) < q.x {
                left = middle;
            } else {
                right = middle;
            }
        }
        ray(0.5 * (left + right))
    });
    // Each ray's direction is the way from its lens point to the focal plane.
    let focus = rays.map(|(origin, dir)| origin + dir);
    ModelRays { lens, focus, rays }
}

/// What the focal-plane diagram says.
const FOCAL_PLANE: &str = "The chapter's model of the thin lens: a lens of radius R at z = 0 \
    and the focal plane at z = d_f, with no film behind the lens. The camera rays that see a \
    point on the axis leave the lens's rim and centre through that point and cross the focal \
    plane over a small interval. Seen from the lens centre, as the pinhole sees it, that \
    interval covers the width c on the plane z = 1: the circle of confusion in tangent units. \
    Top: a point nearer than the focal plane; bottom: one farther away.";

/// The chapter's own model: the rays through one point on the axis, from the rim and centre of
/// the lens to the focal plane, and the pinhole's view of their spread on `z = 1`.
fn focal_plane() -> Diagram {
    let panel = 2.2;
    let far = f64::from(MODEL_DEPTHS[1]) + 0.3;
    let mut diagram = Diagram::new(FOCAL_PLANE, (-0.9, far + 0.4), (-panel - 1.3, 1.2), 720);
    let d_f = f64::from(MODEL_FOCUS);
    let r = f64::from(MODEL_RADIUS);
    for (k, depth) in MODEL_DEPTHS.into_iter().enumerate() {
        let dy = -panel * k as f64;
        // Camera z to the right, camera x up.
        let at = |v: Vec3| -> Point { (f64::from(v.z), f64::from(v.x) + dy) };
        diagram.line((-0.3, dy), (far, dy), Ink::Guide);
        diagram.line((0.0, dy - r - 0.1), (0.0, dy + r + 0.1), Ink::Surface);
        diagram.line((d_f, dy - 0.9), (d_f, dy + 0.9), Ink::Guide);
        diagram.line((1.0, dy - 0.9), (1.0, dy + 0.9), Ink::Guide);
        let rays = model_rays(depth);
        for i in 0..3 {
            let (origin, dir) = rays.rays[i];
            // From the lens point through the focus point, on to the point or past it.
            let end = if depth > MODEL_FOCUS {
                origin + dir * (depth / dir.z)
            } else {
                origin + dir
            };
            diagram.line(at(origin), at(end), Ink::OtherRay);
            diagram.dot(at(rays.lens[i].extend(0.0)), Ink::OtherRay);
            diagram.dot(at(rays.focus[i]), Ink::OtherRay);
            // The pinhole's line of sight to that focus point.
            diagram.line((0.0, dy), at(rays.focus[i]), Ink::Ray);
        }
        diagram.dot(at(Vec3::new(0.0, 0.0, depth)), Ink::Surface);
        let name = if depth < MODEL_FOCUS {
            "nearer point"
        } else {
            "farther point"
        };
        let (at_label, anchor) = if depth < MODEL_FOCUS {
            ((f64::from(depth), dy + 0.5), Anchor::Below)
        } else {
            ((f64::from(depth), dy - 0.15), Anchor::Above)
        };
        diagram.label(at_label, name, anchor, Ink::Surface);
        // On z = 1, the chapter's circle of confusion in tangent units, around the axis.
        let c = f64::from(circle_of_confusion(MODEL_RADIUS, MODEL_FOCUS, depth));
        let (top, bottom) = (dy + c / 2.0, dy - c / 2.0);
        for x in [0.98, 1.0, 1.02] {
            diagram.line((x, top), (x, bottom), Ink::Warning);
        }
        diagram.label((1.06, top + 0.14), "c", Anchor::Left, Ink::Warning);
        diagram.line((-0.08, dy + r), (0.08, dy + r), Ink::Surface);
        diagram.line((-0.08, dy), (0.08, dy), Ink::Surface);
        diagram.label((-0.12, dy + r / 2.0), "R", Anchor::Right, Ink::Surface);
        if k == 0 {
            diagram.label((0.0, dy + 0.95), "lens", Anchor::Below, Ink::Surface);
            diagram.label((1.0, dy + 0.95), "z = 1", Anchor::Below, Ink::Guide);
            diagram.label((d_f, dy + 0.95), "focal plane", Anchor::Below, Ink::Guide);
        }
    }
    let y = -panel - 1.0;
    diagram.arrow((d_f / 2.0, y + 0.22), (0.0, y + 0.22), Ink::Surface);
    diagram.arrow((d_f / 2.0, y + 0.22), (d_f, y + 0.22), Ink::Surface);
    diagram.label(
        (d_f / 2.0, y + 0.12),
        "focus distance d_f",
        Anchor::Above,
        Ink::Surface,
    );
    diagram
}

#[cfg(test)]
mod tests {
    use super::*;
    use workbench::test_support::written_diagrams;

    #[test]
    fn the_point_in_focus_meets_on_the_film_and_the_others_spread_by_the_circle_of_confusion() {
        let focused = bundle(IN_FOCUS.0, IN_FOCUS.1);
        for hit in focused.on_film {
            assert!(
                (hit - focused.image).length() < 1e-5,
                "{hit} {:?}",
                focused.image
            );
        }
        let film = film_distance();
        for (depth, height) in [NEARER, FARTHER] {
            let b = bundle(depth, height);
            // Each drawn ray passes through the object point, its lens point and the image.
            for i in 0..3 {
                let (a, l) = (b.object, b.lens[i]);
                let cross = |u: Vec2, v: Vec2| u.x * v.y - u.y * v.x;
                if i == 1 {
                    // The ray through the centre goes straight on.
                    assert!(cross(l - a, b.image - l).abs() < 1e-5);
                }
                assert!(cross(b.image - l, b.on_film[i] - l).abs() < 1e-5);
                assert!((b.on_film[i].x - film).abs() < 1e-6);
            }
            let spread = (b.on_film[0].y - b.on_film[2].y).abs();
            let c = circle_of_confusion_on_film(FOCAL_LENGTH, DIAMETER, FOCUS, depth);
            assert!(
                (spread - c).abs() < 1e-5,
                "depth {depth}: {spread} drawn, {c}"
            );
            // The same blur as the chapter's model sees it, in tangent units.
            let tangent = circle_of_confusion(DIAMETER / 2.0, FOCUS, depth);
            assert!((spread / film - tangent).abs() < 1e-5);
            // A nearer point meets behind the film, a farther one in front of it.
            assert_eq!(b.image.x > film, depth < FOCUS);
            assert!(c > 0.0);
        }
    }

    #[test]
    fn the_models_rays_pass_through_the_point_and_spread_by_the_circle_of_confusion() {
        for depth in MODEL_DEPTHS {
            let rays = model_rays(depth);
            for (i, &(origin, dir)) in rays.rays.iter().enumerate() {
                assert_eq!(origin, rays.lens[i].extend(0.0));
                // The camera ray reaches the focus point on the focal plane ...
                assert!((origin + dir - rays.focus[i]).length() < 1e-5);
                // ... and passes through the point looked at.
                let at_depth = origin + dir * (depth / dir.z);
                assert!(at_depth.truncate().length() < 1e-5, "{at_depth}");
            }
            // The pinhole sees the focus points on z = 1 where its lines of sight cross it.
            let on_unit = |f: Vec3| f.x / f.z;
            let spread = (on_unit(rays.focus[0]) - on_unit(rays.focus[2])).abs();
            let c = circle_of_confusion(MODEL_RADIUS, MODEL_FOCUS, depth);
            assert!(
                (spread - c).abs() < 1e-5,
                "depth {depth}: {spread} drawn, {c}"
            );
        }
    }

    #[test]
    fn write_all_writes_each_diagram_as_svg_with_its_description() {
        written_diagrams(write_all, &["thin-lens.svg", "focal-plane.svg"]);
    }
}
