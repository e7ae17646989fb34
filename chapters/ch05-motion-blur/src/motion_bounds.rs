//! Motion bounds: one box that holds a moving object at every time of an interval.
//!
//! A BVH needs a box per primitive. For a moving object the box must hold it at *every* time a
//! ray may have, or the BVH would skip the object for rays at the times it is outside.
//!
//! The method here (conservative, simple, and checked by tests): the object at any time lies
//! inside the transformed corners of its object-space box, so it is enough to bound the paths
//! of the eight corners. Each path is sampled at `steps` times per keyframe segment, and the
//! box of the samples is grown so that no corner, between two samples, can stray outside it:
//! how far can it stray, when the corner's **speed bound** limits its path? Within a
//! segment, with `u` running from 0 to 1, a point `x` of object space is at
//! `T(u) + R(u) S(u) x`; its speed is at most `|T1 - T0| + θ max(|S0 x|, |S1 x|) + |(S1 - S0) x|`,
//! where `θ` is the angle the rotation turns through (the interpolated rotation turns at the
//! constant speed `θ`).
//! pbrt-v4 instead solves for the exact extrema of each corner's path; more work for a box
//! that is only slightly smaller.

use crate::animated_transform::{AnimatedTransform, Decomposed};
use common::geometry::Aabb;
use glam::Vec3;

/// The eight corners of `b`.
pub fn corners(b: &Aabb) -> [Vec3; 8] {
    std::array::from_fn(|i| {
        Vec3::new(
            if i & 1 == 0 { b.min.x } else { b.max.x },
            if i & 2 == 0 { b.min.y } else { b.max.y },
            if i & 4 == 0 { b.min.z } else { b.max.z },
        )
    })
}

/// An upper bound on the speed (distance per unit of segment fraction `u`) of the
/// object-space point `x` moving from keyframe parts `a` to `b`.
pub fn speed_bound(x: Vec3, a: &Decomposed, b: &Decomposed) -> f32 {
    let angle = a.rotation.angle_between(b.rotation);
    let (sa, sb) = ((a.scale * x).length(), (b.scale * x).length());
    (b.translation - a.translation).length()
        + angle * sa.max(sb)
        + ((b.scale - a.scale) * x).length()
}

// ANCHOR: segment_bounds
/// A box holding the `corners` (in object space) at every fraction `u` in `[u0, u1]` of the
/// segment from keyframe parts `a` to `b`, from the corners placed at `steps + 1` evenly spaced
/// fractions. Between two of those fractions a corner moves on: how far from the nearer one
/// can it stray, given `speed_bound`, and what does the box need for it?
pub fn segment_bounds(
    corners: &[Vec3; 8],
    a: &Decomposed,
    b: &Decomposed,
    u0: f32,
    u1: f32,
    steps: usize,
) -> Aabb {
    // BEGIN SOLUTION
    use crate::animated_transform::interpolate;
    let steps = steps.max(1);
    let mut bounds = Aabb::empty();
    for i in 0..=steps {
        let u = u0 + (u1 - u0) * (i as f32 / steps as f32);
        let m = interpolate(a, b, u).matrix();
        for &corner in corners {
            bounds = bounds.union_point(m.transform_point3(corner));
        }
    }
    let half_step = 0.5 * (u1 - u0) / steps as f32;
    let margin = corners
        .iter()
        .map(|&corner| speed_bound(corner, a, b) * half_step)
        .fold(0.0, f32::max);
    bounds.expanded(Vec3::splat(margin))
    // END SOLUTION
}
// ANCHOR_END: segment_bounds

/// A box holding the object whose object-space box is `object_box` at every time in
/// `[time0, time1]` under `motion`, with `steps` samples per keyframe segment.
pub fn motion_bounds(
    object_box: &Aabb,
    motion: &AnimatedTransform,
    time0: f32,
    time1: f32,
    steps: usize,
) -> Aabb {
    let corners = corners(object_box);
    let keyframes = motion.keyframes();
    let place_all = |time: f32| {
        let m = motion.at(time);
        corners
            .iter()
            .fold(Aabb::empty(), |b, &c| b.union_point(m.transform_point3(c)))
    };
    let mut bounds = place_all(time0).union(place_all(time1));
    for (i, pair) in keyframes.windows(2).enumerate() {
        let (ka, kb) = (&pair[0], &pair[1]);
        let (start, end) = (time0.max(ka.time), time1.min(kb.time));
        if start >= end {
            continue;
        }
        let span = kb.time - ka.time;
        let (u0, u1) = ((start - ka.time) / span, (end - ka.time) / span);
        debug_assert!(i < keyframes.len());
        bounds = bounds.union(segment_bounds(
            &corners, &ka.parts, &kb.parts, u0, u1, steps,
        ));
    }
    // The interpolation and the boxes are rounded in f32: a relative margin keeps a corner
    // that is exactly on the box from falling out by an ulp.
    let size = bounds.diagonal().abs().max_element()
        + bounds.min.abs().max(bounds.max.abs()).max_element();
    bounds.expanded(Vec3::splat(1e-5 * size))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::animated_transform::interpolate;
    use glam::Mat4;

    fn fast_spinning_mover() -> AnimatedTransform {
        AnimatedTransform::new(&[
            (0.0, Mat4::from_translation(Vec3::new(-3.0, 0.0, 0.0))),
            (
                0.5,
                Mat4::from_translation(Vec3::new(0.0, 1.0, 0.0))
                    * Mat4::from_rotation_z(2.0)
                    * Mat4::from_scale(Vec3::new(2.0, 0.5, 1.0)),
            ),
            (
                1.0,
                Mat4::from_translation(Vec3::new(3.0, 0.0, 0.0)) * Mat4::from_rotation_z(3.5),
            ),
        ])
        .unwrap()
    }

    fn unit_box() -> Aabb {
        Aabb::from_points(Vec3::splat(-1.0), Vec3::ONE)
    }

    #[test]
    fn exercise_segment_bounds_hold_every_corner_at_every_time() {
        let spinning = fast_spinning_mover();
        // A slide, where the speed bound is exact: a corner left out at a sampled fraction is
        // further from the others than the margin covers.
        let sliding = AnimatedTransform::new(&[
            (0.0, Mat4::from_translation(Vec3::new(-3.0, 0.0, 0.0))),
            (1.0, Mat4::from_translation(Vec3::new(3.0, 1.0, 0.0))),
        ])
        .unwrap();
        // Each motion with its number of steps and the fractions of the segment those steps
        // sample, worked out beforehand.
        let thirds: &[f32] = &[0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];
        let halves: &[f32] = &[0.0, 0.5, 1.0];
        for (what, motion, steps, samples) in [
            ("spun", &spinning, 3, thirds),
            ("slid", &sliding, 2, halves),
        ] {
            let (a, b) = (&motion.keyframes()[0].parts, &motion.keyframes()[1].parts);
            let corners = corners(&unit_box());
            // Few steps: only the margin keeps the corners in between the samples inside.
            let (u0, u1) = (0.0, 1.0);
            let bounds = segment_bounds(&corners, a, b, u0, u1, steps);
            // The sampled fractions first: a corner missing there is a missing sample, not a
            // missing margin.
            let dense = (0..=1000).map(|i| i as f32 / 1000.0);
            for u in samples.iter().copied().chain(dense) {
                let m = interpolate(a, b, u).matrix();
                for &c in &corners {
                    let p = m.transform_point3(c);
                    if bounds.contains(p) {
                        continue;
                    }
                    let why = if samples.iter().any(|&s| (s - u).abs() < 1e-6) {
                        "at one of the sampled fractions itself: are the corners placed at all \
                         steps + 1 fractions from u0 to u1, ends included?"
                    } else {
                        "between two sampled fractions: the sampled corners' box has to grow, \
                         since a corner between two samples can travel away from both (how far, \
                         at most, from the nearer one?)"
                    };
                    panic!(
                        "segment_bounds: the corner {c} {what} to {p} at u = {u} lies outside \
                         your box {bounds:?} ({steps} steps over [{u0}, {u1}]), {why}"
                    );
                }
            }
        }
    }

    #[test]
    fn exercise_segment_bounds_are_not_much_larger_than_the_swept_corners() {
        let motion = fast_spinning_mover();
        let (a, b) = (&motion.keyframes()[0].parts, &motion.keyframes()[1].parts);
        let corners = corners(&unit_box());
        let bounds = segment_bounds(&corners, a, b, 0.25, 0.75, 32);
        let mut dense = Aabb::empty();
        for i in 0..=2000 {
            let m = interpolate(a, b, 0.25 + 0.5 * i as f32 / 2000.0).matrix();
            for &c in &corners {
                dense = dense.union_point(m.transform_point3(c));
            }
        }
        assert!(
            bounds.contains_box(&dense),
            "segment_bounds: over [0.25, 0.75] with 32 steps the corners sweep through \
             {dense:?}, which your box {bounds:?} does not hold: are the fractions spread from \
             u0 to u1, not from 0 to 1?"
        );
        let grown = bounds.diagonal() - dense.diagonal();
        assert!(
            grown.max_element() < 0.05 * dense.diagonal().max_element(),
            "segment_bounds: your box {bounds:?} is larger than the corners' sweep {dense:?} by \
             {grown} along its sides: with 32 steps the margin should be a small fraction of a \
             step's travel, not the whole segment's (a box too large costs every ray that \
             passes near it)"
        );
    }

    #[test]
    fn motion_bounds_hold_the_object_over_a_part_of_the_shutter() {
        let motion = fast_spinning_mover();
        for (t0, t1) in [(0.0, 1.0), (0.1, 0.3), (0.4, 0.6), (0.9, 1.0), (-1.0, 2.0)] {
            let bounds = motion_bounds(&unit_box(), &motion, t0, t1, 4);
            for i in 0..=500 {
                let time = t0 + (t1 - t0) * i as f32 / 500.0;
                let m = motion.at(time);
                for c in corners(&unit_box()) {
                    assert!(
                        bounds.contains(m.transform_point3(c)),
                        "[{t0}, {t1}] at {time}"
                    );
                }
            }
        }
    }
}
