//! Walking the BVH: nearest child first, with a stack that never allocates.

use std::ops::ControlFlow;

use super::build::MAX_DEPTH;
use super::{Bvh, BvhHit, NodeKind};
use crate::Ray;
use crate::geometry::aabb::SlabRay;

/// The stack size of the walk through trees at most this deep.
pub(super) const SHALLOW_STACK: usize = 16;

impl Bvh {
    /// The primitive the ray hits first, found by asking `hit_primitive` about the candidates.
    ///
    /// `hit_primitive(i, t_max)` must test primitive `i` against the ray limited to
    /// `t < t_max` and return the hit's `t`. Every hit shrinks the `t_max` passed on, so every
    /// `Some` that is accepted is nearer than all earlier ones: a closure may keep the full
    /// record of its latest hit, knowing that it is the nearest one when the walk ends.
    /// Answers with `t >= t_max` (or NaN) are ignored.
    pub fn intersect<F>(&self, ray: &Ray, mut hit_primitive: F) -> Option<BvhHit>
    where
        F: FnMut(usize, f32) -> Option<f32>,
    {
        let mut nearest = None;
        self.walk(ray, |primitives, mut t_max| {
            for &primitive in primitives {
                let primitive = primitive as usize;
                if let Some(t) = hit_primitive(primitive, t_max)
                    && t < t_max
                {
                    t_max = t;
                    nearest = Some(BvhHit { primitive, t });
                }
            }
            ControlFlow::Continue(t_max)
        });
        nearest
    }

    /// Whether `hit_primitive(i)` holds for some primitive whose box the ray passes through
    /// before `ray.t_max`. Stops at the first one: a shadow ray needs no nearest hit.
    pub fn any_hit<F>(&self, ray: &Ray, mut hit_primitive: F) -> bool
    where
        F: FnMut(usize) -> bool,
    {
        let mut found = false;
        self.walk(ray, |primitives, t_max| {
            if primitives.iter().any(|&p| hit_primitive(p as usize)) {
                found = true;
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(t_max)
            }
        });
        found
    }

    /// Hands `visit_leaf` the primitives of every leaf whose box the ray enters before the
    /// current `t_max`, nearer subtrees first. `visit_leaf` returns the new `t_max`, or
    /// `Break` to stop.
    ///
    /// At an interior node both children's boxes are tested, and the one the ray enters first
    /// is visited first: a close hit found early shrinks `t_max`, which then culls most of the
    /// farther subtree. The farther child waits on the stack with the ray parameter where the
    /// ray enters its box. When its turn comes, that entry is compared with the `t_max` of the
    /// moment, which is the box test repeated for free: the box was entered before its exit
    /// (the first test said so), so it is still reached exactly when its entry is before the
    /// new `t_max`.
    fn walk<F>(&self, ray: &Ray, visit_leaf: F)
    where
        F: FnMut(&[u32], f32) -> ControlFlow<(), f32>,
    {
        // The stack is an array, so it is filled with zeros before the walk starts: for a
        // `MAX_DEPTH` stack that is 512 bytes per ray, a `memset` that cost 2.6 % of a
        // Cornell-box render. Shallow trees (every scene of this book but large meshes) get
        // a stack a quarter of that size, which the compiler clears with a few stores.
        if self.depth <= SHALLOW_STACK {
            self.walk_with_stack::<SHALLOW_STACK, F>(ray, visit_leaf);
        } else {
            self.walk_with_stack::<MAX_DEPTH, F>(ray, visit_leaf);
        }
    }

    /// [`walk`](Self::walk) with a stack of `STACK` entries, which must be at least the tree's
    /// depth.
    fn walk_with_stack<const STACK: usize, F>(&self, ray: &Ray, mut visit_leaf: F)
    where
        F: FnMut(&[u32], f32) -> ControlFlow<(), f32>,
    {
        debug_assert!(self.depth <= STACK);
        let Some(root) = self.nodes.first() else {
            return;
        };
        let slab = SlabRay::new(ray);
        let mut t_max = ray.t_max;
        if root.bounds.entry(&slab, t_max).is_none() {
            return;
        }
        // Each level of the current path defers at most one child, so the depth bounds the
        // stack. Each deferred node is kept with the ray parameter where the ray enters it.
        let mut deferred = [(0u32, 0.0f32); STACK];
        let mut deferred_count = 0;
        let mut current = 0;
        loop {
            match self.nodes[current].kind {
                NodeKind::Interior { second_child } => {
                    let (first, second) = (current + 1, second_child as usize);
                    let enter_first = self.nodes[first].bounds.entry(&slab, t_max);
                    let enter_second = self.nodes[second].bounds.entry(&slab, t_max);
                    match (enter_first, enter_second) {
                        (Some(t_first), Some(t_second)) => {
                            let (near, far, t_far) = if t_second < t_first {
                                (second, first, t_first)
                            } else {
                                (first, second, t_second)
                            };
                            deferred[deferred_count] = (far as u32, t_far);
                            deferred_count += 1;
                            current = near;
                            continue;
                        }
                        (Some(_), None) => {
                            current = first;
                            continue;
                        }
                        (None, Some(_)) => {
                            current = second;
                            continue;
                        }
                        (None, None) => {}
                    }
                }
                NodeKind::Leaf { first, count } => {
                    let range = first as usize..(first + count) as usize;
                    match visit_leaf(&self.primitive_indices[range], t_max) {
                        ControlFlow::Continue(new_t_max) => t_max = new_t_max,
                        ControlFlow::Break(()) => return,
                    }
                }
            }
            // The latest deferred subtree that the ray still reaches.
            loop {
                if deferred_count == 0 {
                    return;
                }
                deferred_count -= 1;
                let (node, t_enter) = deferred[deferred_count];
                if t_enter <= t_max {
                    current = node as usize;
                    break;
                }
            }
        }
    }
}
