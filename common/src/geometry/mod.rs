//! Shapes, bounding boxes, the BVH, and secondary rays that do not hit their own surface.
//!
//! The chapters only ever ask two questions of the scene: *what does this ray hit first?*
//! ([`Geometry::intersect`]) and *is anything in the way?* ([`Geometry::occluded`]). This
//! module answers them quickly (a [`Bvh`] over the shapes) and, above all, reliably.
//!
//! # Why so much care about rounding
//!
//! Every hit point is computed in `f32` and is therefore a little off the surface. A reflected
//! or shadow ray started right at it can hit the same surface again at a tiny `t`: black
//! speckles ("shadow acne"), or light that leaks through the crease where two surfaces touch.
//! Renderers used to hide this with a constant such as "ignore hits with `t < 0.001`", which is
//! wrong for a scene measured in micrometres, wrong for one 100 km from the origin, and wrong
//! at creases. Following pbrt-v4 (Pharr, Jakob, Humphreys, section 6.8), this module instead:
//!
//! 1. computes every hit point together with a conservative bound on its error
//!    ([`SurfaceHit::p_error`], using the [`gamma`] bounds of `float.rs`);
//! 2. starts secondary rays from an origin pushed off the surface by exactly that bound
//!    ([`offset_ray_origin`], [`SurfaceHit::spawn_ray`]);
//! 3. accepts a hit only when its `t` is positive beyond its own rounding error (interval
//!    arithmetic in `interval.rs` for spheres, parallelograms and discs; pbrt's error bound for the
//!    watertight triangle test).
//!
//! No constant in any of it depends on the scene's size or position.

mod aabb;
#[cfg(any(test, feature = "test-strategies"))]
pub mod awkward;
mod bvh;
mod cost;
mod float;
mod hit;
mod interval;
mod scene_geometry;
mod shapes;
mod spawn;

#[cfg(test)]
mod tests;

pub use aabb::{Aabb, SMALLEST_BOUND, SlabRay};
pub use bvh::{Bvh, BvhHit, EMPTY_SLOT, LEAF_BLOCK, MAX_PRIMITIVES_PER_LEAF};
pub use cost::{BvhCost, COUNTED_RAYS, measure_bvh_cost};
pub use float::{MACHINE_EPSILON, gamma, next_float_down, next_float_up};
pub use hit::SurfaceHit;
pub use scene_geometry::{Geometry, WalkCount};
pub use shapes::{Crossing, Disc, MeshError, Parallelogram, Shape, Sphere, Triangle, TriangleMesh};
pub use spawn::{SHADOW_EPSILON, offset_ray_origin};
