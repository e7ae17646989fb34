//! Where a secondary ray may start so that it cannot hit the surface it leaves.
//!
//! A computed hit point is almost never *on* the surface: it is within a small, known distance
//! `p_error` of it, on either side. Start the next ray right there and it may "hit" the very
//! surface it leaves at some tiny `t`, which shows up as shadow acne and as dark speckles on
//! reflections. The old cure, ignoring hits with `t < 0.001`, fails at both ends: it is far too
//! large for a scene measured in micrometres and far too small for one 100 km from the origin,
//! and it lets shadow rays slip through the corner where a wall meets the floor.
//!
//! pbrt-v4's cure, used here, has two halves. The first is [`offset_ray_origin`]: move the
//! origin along the normal just far enough that it is certainly on the side the ray leaves
//! towards. The second lives in every intersection routine: a hit counts only if its `t` is
//! positive *beyond its own error bound*. Neither half needs a scene-dependent constant.

use glam::Vec3;

use super::float::{next_float_down, next_float_up};

/// Shadow rays stop this fraction of the way short of their target, so that the light (or the
/// other surface) they are aimed at does not count as a blocker. It is relative to the
/// segment's length, so it works at every scale.
pub const SHADOW_EPSILON: f32 = 1e-4;

/// pbrt-v4's `OffsetRayOrigin`: the origin for a ray leaving `p` in direction `w`.
///
/// `p` is within `p_error` (per axis) of the true surface point, whose geometric unit normal
/// is `n`. The worst case error along the normal is `d = dot(|n|, p_error)`: so moving `p` by
/// `d` along `±n`, towards the side `w` points to, puts it on that side of the true surface.
/// The addition `p + offset` rounds too; stepping each moved component one more float away
/// from `p` makes sure the rounding cannot undo the move.
///
/// Always inlined: every spawned ray calls it, and called out of line it received its vectors
/// through memory, where reading back what the caller had just written in other pieces made
/// the processor wait (an area-light render of chapter 07 ran 18 % faster inlined, chapter
/// 08's Cornell box 5 %).
#[inline(always)]
pub fn offset_ray_origin(p: Vec3, p_error: Vec3, n: Vec3, w: Vec3) -> Vec3 {
    let d = n.abs().dot(p_error);
    let offset = if w.dot(n) < 0.0 { -d * n } else { d * n };
    let moved = p + offset;
    let away = |moved: f32, offset: f32| {
        if offset > 0.0 {
            next_float_up(moved)
        } else if offset < 0.0 {
            next_float_down(moved)
        } else {
            moved
        }
    };
    Vec3::new(
        away(moved.x, offset.x),
        away(moved.y, offset.y),
        away(moved.z, offset.z),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_origin_moves_to_the_side_of_w_by_at_least_the_error() {
        let p = Vec3::new(1.0, 2.0, 3.0);
        let p_error = Vec3::splat(1e-3);
        let n = Vec3::Y;
        let above = offset_ray_origin(p, p_error, n, Vec3::new(0.3, 0.5, 0.0));
        assert!(above.y >= p.y + 1e-3);
        assert_eq!((above.x, above.z), (p.x, p.z));
        let below = offset_ray_origin(p, p_error, n, Vec3::new(0.3, -0.5, 0.0));
        assert!(below.y <= p.y - 1e-3);
    }

    #[test]
    fn the_move_survives_rounding_even_when_it_is_below_one_float() {
        // Far from the origin an error bound smaller than the spacing of floats would be
        // rounded away by `p + offset`; the extra step keeps the origin off `p`.
        let p = Vec3::splat(1e5);
        let n = Vec3::ONE.normalize();
        let o = offset_ray_origin(p, Vec3::splat(1e-6), n, n);
        assert!(o.cmpgt(p).all());
        let o = offset_ray_origin(p, Vec3::splat(1e-6), n, -n);
        assert!(o.cmplt(p).all());
    }

    #[test]
    fn no_error_means_no_move() {
        let p = Vec3::new(0.5, 0.0, 0.25);
        assert_eq!(offset_ray_origin(p, Vec3::ZERO, Vec3::Y, Vec3::Y), p);
    }
}
