//! Intersecting a moving object: take the ray into the object's own space at the ray's time.
//!
//! The object itself never moves. Its transform at the ray's `time` maps object space to
//! world space, so the inverse maps the *ray* into object space, where the shape sits still
//! and is intersected as it is. Transforming one ray is far cheaper than transforming every
//! triangle of an object for every time sample, and it works for any shape.
//!
//! The direction is transformed but **not normalised**: then the point at parameter `t` in
//! object space is the transform of the point at the same `t` in world space, so the hit's `t`
//! needs no conversion and the ray's `t_max` (a shadow ray stops at its light) stays valid.

use common::Ray;
use common::geometry::gamma;
use glam::{Mat3, Mat4, Vec3};

// ANCHOR: to_object_space
/// The world-space `ray` in object space, given the world-to-object matrix at the ray's time.
/// Same `t` for the same point in both spaces; same `t_max` and `time`.
pub fn to_object_space(ray: &Ray, world_to_object: &Mat4) -> Ray {
    // BEGIN SOLUTION
    Ray {
        origin: world_to_object.transform_point3(ray.origin),
        // Not normalised: keeps `t` the same in both spaces.
        dir: world_to_object.transform_vector3(ray.dir),
        t_max: ray.t_max,
        time: ray.time,
    }
    // END SOLUTION
}
// ANCHOR_END: to_object_space

/// The error bound of the world-space point `object_to_world · p`, for an object-space point
/// `p` known to within `p_error` (per component): the error already in `p` carried through the
/// transform, plus the rounding of the transform itself, as pbrt bounds it. A secondary ray
/// spawned from the point is offset by this bound, so it leaves from the right side of the
/// surface.
pub fn point_error_to_world(p: Vec3, p_error: Vec3, object_to_world: &Mat4) -> Vec3 {
    let linear = Mat3::from_mat4(*object_to_world);
    let abs = Mat3::from_cols(
        linear.x_axis.abs(),
        linear.y_axis.abs(),
        linear.z_axis.abs(),
    );
    // Rounding of `M p` is at most γ(3) (|M| |p| + |translation|) per component; the error
    // already in `p` is carried through `|M|`. The world-to-object matrix is itself rounded,
    // so spawned rays going back into object space land a few ulps off: a wider γ covers it.
    let g = gamma(8);
    (1.0 + g) * (abs * p_error) + g * (abs * p.abs() + object_to_world.w_axis.truncate().abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What is wrong with `local = to_object_space(ray, world_to_object)`, in words; `None`
    /// if it is right. Right means: the object's transform takes the object-space ray's point
    /// at every `t` back to the world ray's point at the same `t`.
    fn object_space_mistake(ray: &Ray, world_to_object: &Mat4, local: &Ray) -> Option<String> {
        let object_to_world = world_to_object.inverse();
        let close = |a: Vec3, b: Vec3| (a - b).length() <= 1e-4 * b.length().max(1.0);
        // The object-space ray's point at t, taken back to world space.
        let back = |t: f32| object_to_world.transform_point3(local.origin + local.dir * t);
        let world = |t: f32| ray.origin + ray.dir * t;
        let wrong_t = [0.0, 1.0, 2.5]
            .into_iter()
            .find(|&t| !close(back(t), world(t)));
        let mistake = if local.t_max != ray.t_max {
            format!(
                "t_max is {} instead of the ray's {}: a shadow ray must still stop at its light, \
                 so the object-space ray keeps the world ray's t_max",
                local.t_max, ray.t_max
            )
        } else if local.time != ray.time {
            format!(
                "the time is {} instead of the ray's {}: the ray keeps its shutter time, in \
                 every space and on every bounce",
                local.time, ray.time
            )
        } else if let Some(t) = wrong_t {
            // The step back to world space, and whether it runs along the world ray.
            let step = back(1.0) - back(0.0);
            let along = step.normalize().dot(ray.dir.normalize()) > 1.0 - 1e-5;
            if close(local.origin, world_to_object.transform_vector3(ray.origin)) {
                "the origin did not move with the object: it is a point, so the matrix's \
                 translation applies to it"
                    .to_string()
            } else if close(local.dir, world_to_object.transform_point3(ray.dir)) {
                "the direction was moved by the translation: it is a vector, which a \
                 translation leaves alone"
                    .to_string()
            } else if close(back(0.0), world(0.0))
                && along
                && (local.dir.length() - 1.0).abs() < 1e-5
            {
                "the direction was normalised: then t no longer means the same point in both \
                 spaces (a scaled object would report its hits at other distances)"
                    .to_string()
            } else if close(world_to_object.transform_point3(local.origin), ray.origin) {
                "the ray went the wrong way: the matrix given already takes world space to \
                 object space"
                    .to_string()
            } else {
                format!(
                    "taken back to world space by the object's transform, your ray's point at \
                     t = {t} is {}, but the world ray's is {}: the two rays must be the same \
                     line, point for point",
                    back(t),
                    world(t)
                )
            }
        } else {
            return None;
        };
        Some(format!(
            "{mistake}.\n  world ray {ray:?}: your to_object_space gave {local:?}"
        ))
    }

    fn check_object_space(ray: &Ray, world_to_object: &Mat4) {
        let local = to_object_space(ray, world_to_object);
        if let Some(mistake) = object_space_mistake(ray, world_to_object, &local) {
            panic!("to_object_space: {mistake}");
        }
    }

    #[test]
    fn exercise_to_object_space_keeps_t_the_same_in_both_spaces() {
        let object_to_world = Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0))
            * Mat4::from_rotation_y(0.7)
            * Mat4::from_scale(Vec3::new(2.0, 0.5, 3.0));
        let ray = Ray {
            origin: Vec3::new(-4.0, 1.0, 0.5),
            dir: Vec3::new(1.0, 0.2, 0.3).normalize(),
            t_max: 7.5,
            time: 0.25,
        };
        check_object_space(&ray, &object_to_world.inverse());
    }

    #[test]
    fn exercise_to_object_space_moves_the_ray_not_the_object() {
        // The object moved 5 to the right: in its own space the ray starts 5 further left.
        let moved = Mat4::from_translation(Vec3::new(5.0, 0.0, 0.0)).inverse();
        let ray = Ray::new(Vec3::new(0.0, 0.0, -3.0), Vec3::Z).with_time(0.5);
        check_object_space(&ray, &moved);
        // A scaled object sees a scaled direction: not normalised.
        check_object_space(&ray, &Mat4::from_scale(Vec3::splat(0.5)));
    }
}
