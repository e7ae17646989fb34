//! Walking the BVH: nearest child first, with a stack that never allocates.

use std::ops::ControlFlow;

use super::build::MAX_DEPTH;
use super::{Bvh, BvhHit, NodeKind};
use crate::Ray;
use crate::geometry::aabb::SlabRay;

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
    /// At an interior node the ray's direction decides the order: if it travels towards
    /// smaller coordinates on the node's split axis, the second child (the one with the larger
    /// coordinates) is nearer. Visiting it first finds a close hit early, and that hit's smaller
    /// `t_max` then culls most of the farther subtree.
    fn walk<F>(&self, ray: &Ray, mut visit_leaf: F)
    where
        F: FnMut(&[u32], f32) -> ControlFlow<(), f32>,
    {
        if self.nodes.is_empty() {
            return;
        }
        let slab = SlabRay::new(ray);
        let mut t_max = ray.t_max;
        // Each level of the current path defers at most one child, so the depth bounds the stack.
        let mut deferred = [0u32; MAX_DEPTH];
        let mut deferred_count = 0;
        let mut current = 0;
        loop {
            let node = &self.nodes[current];
            if node.bounds.hit_by(&slab, t_max) {
                match node.kind {
                    NodeKind::Interior {
                        second_child,
                        split_axis,
                    } => {
                        let first_child = current as u32 + 1;
                        let (near, far) = if slab.dir_is_negative[split_axis as usize] {
                            (second_child, first_child)
                        } else {
                            (first_child, second_child)
                        };
                        deferred[deferred_count] = far;
                        deferred_count += 1;
                        current = near as usize;
                        continue;
                    }
                    NodeKind::Leaf { first, count } => {
                        let range = first as usize..(first + count) as usize;
                        match visit_leaf(&self.primitive_indices[range], t_max) {
                            ControlFlow::Continue(new_t_max) => t_max = new_t_max,
                            ControlFlow::Break(()) => return,
                        }
                    }
                }
            }
            if deferred_count == 0 {
                return;
            }
            deferred_count -= 1;
            current = deferred[deferred_count] as usize;
        }
    }
}
