//! Walking the BVH with a stack that never allocates: nearest child first for the nearest
//! hit, in the order the children are stored for a shadow ray, which any hit ends.

use std::ops::{ControlFlow, Range};

use glam::{Vec3, Vec4};

use super::build::MAX_DEPTH;
use super::wide::{WideNode, slab_sides};
use super::{Bvh, BvhHit, LEAF_BLOCK};
use crate::Ray;
use crate::geometry::float::gamma;

/// The stack of the walk through the smallest trees (a room of a few shapes).
const TINY_STACK: usize = 8;

/// The stack of the walk through shallow trees.
pub(super) const SHALLOW_STACK: usize = 24;

/// The stack of the walk through trees of meshes.
const MEDIUM_STACK: usize = 64;

/// The entries a walk's stack needs for a tree `depth` nodes deep: each level of the current
/// path defers at most three children, and the deepest node puts all four of its children on
/// the stack before it takes the nearest off.
pub(super) const fn stack_needed(depth: usize) -> usize {
    3 * depth + 1
}

impl Bvh {
    /// The primitive the ray hits first, found by asking `hit_primitive` about the candidates.
    ///
    /// `hit_primitive(i, t_max)` must test primitive `i` against the ray limited to
    /// `t < t_max` and return the hit's `t`. Every hit shrinks the `t_max` passed on, so every
    /// `Some` that is accepted is nearer than all earlier ones: a closure may keep the full
    /// record of its latest hit, knowing that it is the nearest one when the walk ends.
    /// Answers with `t >= t_max` (or NaN) are ignored.
    ///
    /// A ray that goes nowhere (an origin or a direction with a NaN or infinite component, a
    /// zero direction) or whose `t_max` is NaN reaches no box and hits nothing: a student's
    /// broken ray gets an answer, and the chapter's check can say what is wrong with it.
    pub fn intersect<F>(&self, ray: &Ray, mut hit_primitive: F) -> Option<BvhHit>
    where
        F: FnMut(usize, f32) -> Option<f32>,
    {
        let order = &self.primitive_indices;
        let mut nearest = None;
        self.nearest_leaves(ray, |leaf, count, mut t_max| {
            let first = leaf * LEAF_BLOCK;
            let mut leaf_hit = None;
            for &primitive in &order[first..first + count] {
                let primitive = primitive as usize;
                if let Some(t) = hit_primitive(primitive, t_max)
                    && t < t_max
                {
                    t_max = t;
                    leaf_hit = Some(t);
                    nearest = Some(BvhHit { primitive, t });
                }
            }
            leaf_hit
        });
        nearest
    }

    /// Whether `hit_primitive(i)` holds for some primitive whose box the ray passes through
    /// before `ray.t_max`. Stops at the first one: a shadow ray needs no more. False for a
    /// ray that goes nowhere, as [`intersect`](Self::intersect) says.
    pub fn any_hit<F>(&self, ray: &Ray, mut hit_primitive: F) -> bool
    where
        F: FnMut(usize) -> bool,
    {
        let order = &self.primitive_indices;
        self.any_leaf(ray, |leaf, count| {
            let first = leaf * LEAF_BLOCK;
            order[first..first + count]
                .iter()
                .any(|&primitive| hit_primitive(primitive as usize))
        })
    }

    /// [`intersect`](Self::intersect) a leaf at a time, for a caller that keeps a record per
    /// leaf: `visit_leaf(leaf, count, t_max)` tests the `count` primitives of the leaf whose
    /// block is `leaf` (see [`leaf_order`](Self::leaf_order)) against the ray limited to
    /// `t < t_max`, and returns the `t` of the nearest hit among them. The walk goes on with
    /// that `t` as its `t_max`, so every answer it accepts is nearer than all earlier ones: the
    /// closure may keep its latest hit, knowing that it is the nearest when the walk ends.
    /// Answers with `t >= t_max` (or NaN) are ignored.
    ///
    /// Returns how many nodes the walk tested the ray against: the structure's share of the
    /// work, which measurements count (a renderer ignores it).
    pub fn nearest_leaves<F>(&self, ray: &Ray, mut visit_leaf: F) -> usize
    where
        F: FnMut(usize, usize, f32) -> Option<f32>,
    {
        self.walk::<true, _>(ray, |positions, t_max| {
            let hit = visit_leaf(positions.start / LEAF_BLOCK, positions.len(), t_max);
            ControlFlow::Continue(match hit {
                Some(t) if t < t_max => t,
                _ => t_max,
            })
        })
    }

    /// [`any_hit`](Self::any_hit) a leaf at a time: whether `hit_leaf(leaf, count)` holds for
    /// some leaf whose box the ray passes through before `ray.t_max` (`leaf` and `count` as in
    /// [`nearest_leaves`](Self::nearest_leaves)).
    pub fn any_leaf<F>(&self, ray: &Ray, mut hit_leaf: F) -> bool
    where
        F: FnMut(usize, usize) -> bool,
    {
        let mut found = false;
        self.walk::<false, _>(ray, |positions, t_max| {
            if hit_leaf(positions.start / LEAF_BLOCK, positions.len()) {
                found = true;
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(t_max)
            }
        });
        found
    }

    /// Hands `visit_leaf` the positions (in leaf order) of the primitives of every leaf whose
    /// box the ray enters before the current `t_max`, nearer subtrees first if
    /// `NEAREST_FIRST`. `visit_leaf` returns the new `t_max`, or `Break` to stop.
    ///
    /// At a node, the ray is tested against its four children's boxes at once, and the ones it
    /// enters are visited nearest first: a close hit found early shrinks `t_max`, which then
    /// culls most of the farther subtrees. The farther children wait on the stack with the ray
    /// parameter where the ray enters their box. When a child's turn comes, that entry is
    /// compared with the `t_max` of the moment, which is the box test repeated for free: the
    /// box was entered before its exit (the first test said so), so it is still reached
    /// exactly when its entry is before the new `t_max`.
    ///
    /// A shadow ray's `t_max` never shrinks and its first hit ends the walk, so nothing is
    /// gained by sorting: without `NEAREST_FIRST` the children wait in the order their node
    /// stores them, which saves the comparisons and the mispredicted branches of the sort.
    ///
    /// Returns how many nodes it tested the ray against.
    fn walk<const NEAREST_FIRST: bool, F>(&self, ray: &Ray, visit_leaf: F) -> usize
    where
        F: FnMut(Range<usize>, f32) -> ControlFlow<(), f32>,
    {
        // The stack is an array, so it is filled with zeros before the walk starts: shallow
        // trees (every scene of this book but large meshes) get a short one, which costs a
        // few stores.
        let needed = stack_needed(self.depth);
        if needed <= TINY_STACK {
            self.walk_with_stack::<TINY_STACK, NEAREST_FIRST, F>(ray, visit_leaf)
        } else if needed <= SHALLOW_STACK {
            self.walk_with_stack::<SHALLOW_STACK, NEAREST_FIRST, F>(ray, visit_leaf)
        } else if needed <= MEDIUM_STACK {
            self.walk_with_stack::<MEDIUM_STACK, NEAREST_FIRST, F>(ray, visit_leaf)
        } else {
            self.walk_with_stack::<{ stack_needed(MAX_DEPTH) }, NEAREST_FIRST, F>(ray, visit_leaf)
        }
    }

    /// [`walk`](Self::walk) with a stack of `STACK` entries, at least
    /// [`stack_needed`]`(depth)`.
    fn walk_with_stack<const STACK: usize, const NEAREST_FIRST: bool, F>(
        &self,
        ray: &Ray,
        mut visit_leaf: F,
    ) -> usize
    where
        F: FnMut(Range<usize>, f32) -> ControlFlow<(), f32>,
    {
        debug_assert!(stack_needed(self.depth) <= STACK);
        let mut t_max = ray.t_max;
        // A NaN `t_max` reaches nothing (and would make every comparison below false), and
        // neither does a ray that goes nowhere (see `goes_somewhere`).
        if self.nodes.is_empty() || t_max.is_nan() {
            return 0;
        }
        let slabs = WideRay::new(ray);
        // A NaN-free ray goes somewhere: nearly every ray is decided by the first test.
        if !slabs.nan_free && !goes_somewhere(ray) {
            return 0;
        }
        let mut nodes_tested = 0;
        // A lane: a node's index and 0, or a leaf's first primitive and count.
        let mut deferred = [(0u32, 0u32, 0.0f32); STACK];
        let mut deferred_count = 0;
        let mut current = (0u32, 0u32);
        loop {
            let (index, count) = current;
            if count == 0 {
                nodes_tested += 1;
                let node = &self.nodes[index as usize];
                let (entered, t_enter) = node.entries(&slabs, t_max);
                if entered.is_power_of_two() {
                    // One child: nothing to order and nothing to defer.
                    let lane = entered.trailing_zeros() as usize;
                    current = (node.child[lane], u32::from(node.count[lane]));
                    continue;
                }
                if entered != 0 {
                    // The children the ray enters go on the stack, sorted so that the nearest
                    // is on top; it is visited now, and the others wait, the farthest deepest.
                    let first = deferred_count;
                    let mut lanes = entered;
                    while lanes != 0 {
                        let lane = lanes.trailing_zeros() as usize;
                        lanes &= lanes - 1;
                        let child = (node.child[lane], u32::from(node.count[lane]), t_enter[lane]);
                        let mut j = deferred_count;
                        while NEAREST_FIRST && j > first && deferred[j - 1].2 < child.2 {
                            deferred[j] = deferred[j - 1];
                            j -= 1;
                        }
                        deferred[j] = child;
                        deferred_count += 1;
                    }
                    deferred_count -= 1;
                    let (child, child_count, _) = deferred[deferred_count];
                    current = (child, child_count);
                    continue;
                }
            } else {
                match visit_leaf(index as usize..(index + count) as usize, t_max) {
                    ControlFlow::Continue(new_t_max) => t_max = new_t_max,
                    ControlFlow::Break(()) => return nodes_tested,
                }
            }
            // The latest deferred child that the ray still reaches.
            loop {
                if deferred_count == 0 {
                    return nodes_tested;
                }
                deferred_count -= 1;
                let (child, child_count, t_enter) = deferred[deferred_count];
                if t_enter <= t_max {
                    current = (child, child_count);
                    break;
                }
            }
        }
    }
}

/// A ray prepared for testing four boxes at once: each of its coordinates in all four lanes.
struct WideRay {
    origin: [Vec4; 3],
    /// `1 / dir`, componentwise; `±∞` where `dir` is `±0`.
    inv_dir: [Vec4; 3],
    /// Where in a node's `slabs` each axis's near side is: a box's `max` where the ray travels
    /// towards smaller coordinates, decided from the sign of `1 / dir`, so that `dir = -0`
    /// counts as negative, matching `inv_dir = -∞`.
    near: [usize; 3],
    /// Where each axis's far side is.
    far: [usize; 3],
    /// Whether no slab computation can give NaN: the origin is finite and every `1 / dir`
    /// finite and not zero. Then `(x - o) · (1 / dir)` is a number or `±∞` for every `x`,
    /// even the `±∞` of an empty lane, and the walk skips the NaN checks (nearly every ray).
    nan_free: bool,
}

/// Whether the ray goes anywhere: its origin and direction finite, its direction not zero.
/// One that does not reaches no box and hits nothing.
///
/// This is what lets the walk trust its slab test. With a finite origin and a finite,
/// non-zero direction, the only NaN a slab bound can be is `0 × ∞` (a ray parallel to a slab
/// starting on its plane) in a lane with a real box, which counts as inside that slab. A lane
/// without a child holds `±∞` bounds, which give `±∞ × 1 / dir`, never NaN, so the ray never
/// enters it. A NaN or infinite origin or direction would make bounds NaN (`NaN - x`, `∞ - ∞`,
/// `∞ × 0`), enter every lane, empty ones too, and follow an empty lane's child, which is no
/// node. A zero direction could be walked, but a ray that does not move crosses no surface.
fn goes_somewhere(ray: &Ray) -> bool {
    ray.origin.is_finite() && ray.dir.is_finite() && ray.dir != Vec3::ZERO
}

impl WideRay {
    #[inline]
    fn new(ray: &Ray) -> Self {
        let inv_dir = ray.dir.recip();
        let (near, far) = slab_sides(inv_dir.to_array().map(|d| d < 0.0));
        Self {
            origin: ray.origin.to_array().map(Vec4::splat),
            inv_dir: inv_dir.to_array().map(Vec4::splat),
            near,
            far,
            nan_free: ray.origin.is_finite()
                && inv_dir.is_finite()
                && inv_dir.cmpne(Vec3::ZERO).all(),
        }
    }
}

impl WideNode {
    /// Which of the four boxes the ray passes through before `t_max` (bit `i` for lane `i`),
    /// and where it enters each (0 if it starts inside).
    ///
    /// The slab test of [`Aabb::entry`](crate::geometry::Aabb::entry), made robust the same
    /// way, in four lanes at once: each exit is widened by `1 + 2 γ(3)` so that rounding never
    /// loses a box the exact ray touches, and a `0 × ∞` (a ray parallel to a slab, starting
    /// on its plane) counts as inside that slab. Each lane rounds exactly as the scalar test
    /// does, so the answer does not depend on the instruction set. `t_max` must not be NaN,
    /// and the ray must go somewhere ([`goes_somewhere`]): then no empty lane is ever entered.
    #[inline]
    fn entries(&self, ray: &WideRay, t_max: f32) -> (u32, [f32; 4]) {
        const EXIT_SLACK: f32 = 1.0 + 2.0 * gamma(3);
        let mut t_enter = Vec4::ZERO;
        let mut t_exit = Vec4::splat(t_max);
        for axis in 0..3 {
            let (near, far) = (self.slabs[ray.near[axis]], self.slabs[ray.far[axis]]);
            let t_near = (near - ray.origin[axis]) * ray.inv_dir[axis];
            let t_far = (far - ray.origin[axis]) * ray.inv_dir[axis] * EXIT_SLACK;
            let (t_near, t_far) = if ray.nan_free {
                (t_near, t_far)
            } else {
                (
                    Vec4::select(t_near.is_nan_mask(), Vec4::ZERO, t_near),
                    Vec4::select(t_far.is_nan_mask(), Vec4::INFINITY, t_far),
                )
            };
            t_enter = t_enter.max(t_near);
            t_exit = t_exit.min(t_far);
        }
        // The entries as an array: a lane picked at run time is then a load, where indexing
        // the vector would jump through a table on the lane.
        (t_enter.cmple(t_exit).bitmask(), t_enter.to_array())
    }
}
