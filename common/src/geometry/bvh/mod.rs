//! A bounding volume hierarchy: the tree of boxes that makes "which shape does this ray hit
//! first?" cost `O(log n)` box tests instead of `n` shape tests.
//!
//! The BVH knows nothing about shapes: it is built from one box per primitive and asks a
//! closure to test the primitives it cannot rule out. So the same code serves the static
//! scene (boxes of shapes) and chapter 05's moving objects (boxes of whole motion paths).
//!
//! * [`build`](Bvh::build) (in `build.rs`) splits primitives with the surface-area heuristic.
//! * [`intersect`](Bvh::intersect) and [`any_hit`](Bvh::any_hit) (in `traverse.rs`) walk the
//!   tree, nearest child first, with a fixed-size stack.

mod build;
mod traverse;

use super::aabb::Aabb;

/// Leaves hold at most this many primitives.
pub const MAX_PRIMITIVES_PER_LEAF: usize = 4;

/// A bounding volume hierarchy over primitives known only by their index and box.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    /// The nodes in depth-first order: an interior node's first child is the next node.
    nodes: Vec<Node>,
    /// Primitive indices, ordered so that every leaf's primitives are one contiguous run.
    primitive_indices: Vec<u32>,
    /// Number of nodes on the longest path from the root to a leaf.
    depth: usize,
}

/// One node of the flattened tree.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    /// Contains every primitive below the node.
    bounds: Aabb,
    kind: NodeKind,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum NodeKind {
    /// The primitives `primitive_indices[first..first + count]`.
    Leaf { first: u32, count: u32 },
    /// Two children: the first is the next node in the array (depth-first order), so only the
    /// second needs an index.
    Interior { second_child: u32 },
}

/// The result of [`Bvh::intersect`]: which primitive was hit first, and where along the ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BvhHit {
    /// The primitive's index, as in the box slice given to [`Bvh::build`].
    pub primitive: usize,
    /// The ray parameter of the hit.
    pub t: f32,
}

impl Bvh {
    /// How many nodes the tree has (0 for no primitives).
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// How many nodes the longest root-to-leaf path has (0 for no primitives, 1 for one leaf).
    pub fn depth(&self) -> usize {
        self.depth
    }

    /// The box around all primitives ([`Aabb::empty`] for none).
    pub fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::empty(), |root| root.bounds)
    }
}

#[cfg(test)]
mod tests;
