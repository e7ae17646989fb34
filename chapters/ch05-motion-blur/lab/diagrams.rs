//! The chapter's diagrams: how far the shutter is open over the exposure, and where a moving
//! sphere is at the stratified times of one pixel's samples.
//!
//! The shutter's shapes are the chapter's [`trapezoid_opening_pdf`] (a ramp of 0 is the
//! lecture's box), its sample times the chapter's warp and [`Shutter::time_at`], and the
//! sphere's positions its [`AnimatedTransform`] at the times [`StratifiedTime`] hands out;
//! only the shutter, the ramp and the motion are chosen here.

use crate::animated_transform::AnimatedTransform;
use crate::shutter::Shutter;
use crate::shutter_opening::{sample_trapezoid_opening, trapezoid_opening_pdf};
use crate::time_sampling::{StratifiedTime, TimeSampler};
use common::sampler::{IndependentSampler, Sampler};
use glam::{Mat4, UVec2, Vec3};
use std::path::Path;
use workbench::output::figures::{Anchor, Diagram, Ink, Point};

/// Writes every diagram of the chapter into `out_dir`.
pub fn write_all(out_dir: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(out_dir)?;
    shutter_opening().save(&out_dir.join("shutter-opening.svg"))?;
    moving_sphere().save(&out_dir.join("moving-sphere.svg"))?;
    Ok(())
}

/// The exposure drawn: the shutter opens at 0 and closes at 1.
fn shutter() -> Shutter {
    Shutter::new(0.0, 1.0).expect("an interval")
}

/// The trapezoid's ramp: a quarter of the exposure to open and a quarter to close.
const RAMP: f32 = 0.25;
/// The shutter shapes drawn: the box (ramp 0) and the trapezoid.
const RAMPS: [f32; 2] = [0.0, RAMP];
/// Samples per pixel whose times are drawn under the shapes.
const SAMPLES: u32 = 12;
/// World units per unit of time, so that the exposure is wide and the weights readable.
const TIME_SCALE: f64 = 4.0;

/// The outline of the opening `w(t)` of the shutter with `ramp`, as points `(t, w)`: the ends,
/// the corners and points between, each weight the chapter's density.
fn opening_outline(ramp: f32) -> Vec<(f32, f32)> {
    let steps = 400;
    let shutter = shutter();
    let mut points = vec![(shutter.open, 0.0)];
    points.extend((0..=steps).map(|i| {
        let s = i as f32 / steps as f32;
        (
            shutter.time_at(s),
            trapezoid_opening_pdf(s, ramp) / shutter.length(),
        )
    }));
    points.push((shutter.close, 0.0));
    points
}

/// The times of one pixel's `SAMPLES` samples drawn from the shutter with `ramp`: stratified
/// numbers (the middle of each stratum) through the chapter's warp.
fn sample_times(ramp: f32) -> Vec<f32> {
    let shutter = shutter();
    (0..SAMPLES)
        .map(|i| {
            let u = (i as f32 + 0.5) / SAMPLES as f32;
            shutter.time_at(sample_trapezoid_opening(u, ramp))
        })
        .collect()
}

/// What the shutter diagram says.
const SHUTTER_OPENING: &str = "How far the shutter is open over the exposure, as a weight w over \
    the fraction s of the exposure that has passed, enclosing an area of one. The lecture's box \
    is open fully from the start (s = 0) to the end (s = 1). A trapezoid that \
    takes a quarter of the exposure to open and a quarter to close rises, stays at a greater \
    height in the middle, and falls. Below, the times of twelve samples drawn from each: evenly \
    spaced under the box, sparser in the first and last quarter under the trapezoid.";

/// The box and the trapezoid over the exposure, with the sample times each draws.
fn shutter_opening() -> Diagram {
    let mut diagram = Diagram::new(
        SHUTTER_OPENING,
        (-1.0, TIME_SCALE + 1.3),
        (-1.25, 1.75),
        720,
    );
    let x = |t: f32| TIME_SCALE * f64::from(t);
    diagram.arrow((-0.2, 0.0), (TIME_SCALE + 0.5, 0.0), Ink::Surface);
    diagram.arrow((0.0, -0.05), (0.0, 1.65), Ink::Surface);
    diagram.label((TIME_SCALE + 0.55, 0.0), "s", Anchor::Left, Ink::Surface);
    diagram.label((-0.1, 1.6), "w", Anchor::Right, Ink::Surface);
    for (ramp, ink) in RAMPS.into_iter().zip([Ink::Ray, Ink::OtherRay]) {
        let outline: Vec<Point> = opening_outline(ramp)
            .into_iter()
            .map(|(t, w)| (x(t), f64::from(w)))
            .collect();
        diagram.area(outline.clone(), ink, 0.12);
        diagram.polyline(outline, ink);
    }
    // The heights and the ramps, labelled.
    let plateau = f64::from(trapezoid_opening_pdf(0.5, RAMP));
    diagram.label((-0.1, 1.0), "1", Anchor::Right, Ink::Ray);
    diagram.label((-0.1, plateau), "h", Anchor::Right, Ink::OtherRay);
    diagram.line((-0.05, plateau), (x(RAMP), plateau), Ink::Guide);
    for (t, text) in [(0.0, "0"), (RAMP, "r"), (1.0 - RAMP, "1 − r"), (1.0, "1")] {
        diagram.line((x(t), 0.0), (x(t), -0.08), Ink::Surface);
        diagram.label((x(t), -0.1), text, Anchor::Above, Ink::Surface);
    }
    diagram.label((x(0.5), 1.0 - 0.08), "box", Anchor::Above, Ink::Ray);
    diagram.label(
        (x(0.5), plateau + 0.06),
        "trapezoid, r = ¼",
        Anchor::Below,
        Ink::OtherRay,
    );
    // The sample times of each shape, in two rows under the axis.
    for ((ramp, ink), y) in RAMPS
        .into_iter()
        .zip([Ink::Ray, Ink::OtherRay])
        .zip([-0.62, -1.0])
    {
        diagram.line((0.0, y), (TIME_SCALE, y), Ink::Guide);
        for t in sample_times(ramp) {
            diagram.dot((x(t), y), ink);
        }
        let name = if ramp == 0.0 { "box" } else { "trapezoid" };
        diagram.label((TIME_SCALE + 0.15, y), name, Anchor::Left, ink);
    }
    diagram
}

/// The sphere's motion: across from `x = -1` to `x = 1` while the shutter is open.
fn motion() -> AnimatedTransform {
    AnimatedTransform::new(&[
        (0.0, Mat4::from_translation(Vec3::new(-1.0, 0.0, 0.0))),
        (1.0, Mat4::from_translation(Vec3::new(1.0, 0.0, 0.0))),
    ])
    .expect("two keyframes")
}

/// Strata of the moving-sphere diagram, one per sample.
const STRATA: u32 = 8;
/// The sphere's radius.
const SPHERE_RADIUS: f64 = 0.11;
/// The seed of the drawn pixel's samples: one whose eight times lie far enough apart that the
/// drawn spheres do not hide one another (any seed gives one time per stratum).
const SEED: u64 = 9;

/// The times of one pixel's `STRATA` samples as the chapter's stratified time sampler hands
/// them out, in sample order, and the sphere's centre at each.
fn sphere_positions() -> Vec<(f32, Vec3)> {
    let shutter = shutter();
    let motion = motion();
    let mut sampler = StratifiedTime::new(IndependentSampler::new(SEED), u64::from(STRATA), SEED);
    (0..STRATA)
        .map(|i| {
            sampler.start_pixel_sample(UVec2::new(3, 5), u64::from(i));
            let time = shutter.time_at(sampler.get_time_1d());
            (time, motion.at(time).transform_point3(Vec3::ZERO))
        })
        .collect()
}

/// What the moving-sphere diagram says.
const MOVING_SPHERE: &str = "A sphere crossing from left to right while the shutter is open, \
    drawn where it is at the times of one pixel's eight samples. Stratified time cuts the \
    exposure into eight equal strata and draws one time in each, jittered inside it and in an \
    order shuffled per pixel; so the eight positions are spread evenly along the path, one in \
    each eighth of it.";

/// The sphere at the stratified times of one pixel's samples, each joined to its time.
fn moving_sphere() -> Diagram {
    let width = 2.0;
    let mut diagram = Diagram::new(MOVING_SPHERE, (-1.45, 1.45), (-0.95, 0.5), 720);
    let axis_y = -0.55;
    let x = |t: f32| -width / 2.0 + width * f64::from(t);
    diagram.line((x(0.0), axis_y), (x(1.0), axis_y), Ink::Surface);
    for k in 0..=STRATA {
        let t = k as f32 / STRATA as f32;
        diagram.line((x(t), axis_y - 0.05), (x(t), axis_y + 0.05), Ink::Surface);
    }
    diagram.label((x(0.0), axis_y - 0.08), "t₀", Anchor::Above, Ink::Surface);
    diagram.label((x(1.0), axis_y - 0.08), "t₁", Anchor::Above, Ink::Surface);
    diagram.label(
        (0.0, axis_y - 0.1),
        "one time in each stratum",
        Anchor::Above,
        Ink::Ray,
    );
    let path_y = 0.1;
    diagram.line((-1.0, path_y), (1.0, path_y), Ink::Guide);
    for (i, (time, centre)) in sphere_positions().into_iter().enumerate() {
        let c = (f64::from(centre.x), f64::from(centre.y) + path_y);
        diagram.circle(c, SPHERE_RADIUS, Ink::Surface);
        diagram.dot(c, Ink::Surface);
        diagram.dot((x(time), axis_y), Ink::Ray);
        diagram.line((x(time), axis_y), (c.0, c.1 - SPHERE_RADIUS), Ink::Guide);
        diagram.label(
            (c.0, c.1 + SPHERE_RADIUS + 0.03),
            &format!("{}", i + 1),
            Anchor::Below,
            Ink::Ray,
        );
    }
    diagram
}

#[cfg(test)]
mod tests {
    use super::*;
    use workbench::test_support::written_diagrams;

    /// The area a closed outline of points `(t, w)` encloses (the shoelace formula).
    fn area(outline: &[(f32, f32)]) -> f64 {
        let n = outline.len();
        (0..n)
            .map(|i| {
                let (a, b) = (outline[i], outline[(i + 1) % n]);
                f64::from(a.0) * f64::from(b.1) - f64::from(b.0) * f64::from(a.1)
            })
            .sum::<f64>()
            .abs()
            / 2.0
    }

    #[test]
    fn each_opening_encloses_an_area_of_one_and_the_trapezoid_is_higher_in_the_middle() {
        for ramp in RAMPS {
            let outline = opening_outline(ramp);
            let enclosed = area(&outline);
            assert!((enclosed - 1.0).abs() < 1e-3, "ramp {ramp}: {enclosed}");
            // The middle is as high as the outline goes, higher than the box when it ramps.
            let highest = outline.iter().map(|p| p.1).fold(0.0, f32::max);
            let middle = trapezoid_opening_pdf(0.5, ramp);
            assert_eq!(highest, middle, "ramp {ramp}");
            assert_eq!(highest > 1.0, ramp > 0.0, "ramp {ramp}: {highest}");
        }
        // The trapezoid is fully open exactly from r to 1 - r.
        let plateau = trapezoid_opening_pdf(0.5, RAMP);
        for (t, w) in opening_outline(RAMP) {
            let open_fully = (w - plateau).abs() < 1e-6;
            assert_eq!(open_fully, (RAMP..=1.0 - RAMP).contains(&t), "t {t}: w {w}");
        }
    }

    #[test]
    fn the_trapezoid_puts_fewer_samples_in_its_ramps() {
        let in_first_quarter = |ramp| sample_times(ramp).iter().filter(|&&t| t < RAMP).count();
        let in_last_quarter = |ramp| {
            sample_times(ramp)
                .iter()
                .filter(|&&t| t > 1.0 - RAMP)
                .count()
        };
        // The box: a quarter of the twelve; the trapezoid: its share of the weight under the
        // rising ramp, the area under the drawn outline up to r.
        assert_eq!(in_first_quarter(0.0), 3);
        assert_eq!(in_last_quarter(0.0), 3);
        let outline = opening_outline(RAMP);
        let ramp_weight: f32 = outline
            .windows(2)
            .filter(|pair| pair[1].0 <= RAMP)
            .map(|pair| 0.5 * (pair[0].1 + pair[1].1) * (pair[1].0 - pair[0].0))
            .sum();
        let expected = (ramp_weight * SAMPLES as f32).round() as usize;
        assert_eq!(expected, 2);
        assert_eq!(in_first_quarter(RAMP), expected);
        assert_eq!(in_last_quarter(RAMP), expected);
    }

    #[test]
    fn the_sphere_is_drawn_once_in_each_stratum_of_time_and_of_its_path() {
        let positions = sphere_positions();
        let mut strata: Vec<u32> = positions
            .iter()
            .map(|&(t, _)| (t * STRATA as f32) as u32)
            .collect();
        // Shuffled: not in stratum order (else time would follow the sample index).
        assert_ne!(strata, (0..STRATA).collect::<Vec<_>>());
        strata.sort_unstable();
        assert_eq!(strata, (0..STRATA).collect::<Vec<_>>());
        for (t, centre) in positions {
            // The motion is a straight line at constant speed: stratum k of the time is
            // stretch k of the path.
            assert!((centre.x - (2.0 * t - 1.0)).abs() < 1e-5, "{t}: {centre}");
            assert_eq!(centre.y, 0.0);
        }
    }

    #[test]
    fn write_all_writes_each_diagram_as_svg_with_its_description() {
        written_diagrams(write_all, &["shutter-opening.svg", "moving-sphere.svg"]);
    }
}
