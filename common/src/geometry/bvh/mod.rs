//! A bounding volume hierarchy: the tree of boxes that makes "which shape does this ray hit
//! first?" cost `O(log n)` box tests instead of `n` shape tests.
//!
//! The BVH knows nothing about shapes: it is built from one box per primitive and asks a
//! closure to test the primitives it cannot rule out. So the same code serves the static
//! scene (boxes of shapes) and chapter 05's moving objects (boxes of whole motion paths).
//!
//! * [`build`](Bvh::build) (in `build.rs`) splits primitives in two with the surface-area
//!   heuristic, and `wide.rs` collapses that binary tree into nodes of four children.
//! * [`intersect`](Bvh::intersect) and [`any_hit`](Bvh::any_hit) (in `traverse.rs`) walk the
//!   tree, testing a node's four boxes at once, with a fixed-size stack: nearest child first
//!   for the nearest hit, in stored order for a shadow ray. [`nearest_leaves`](Bvh::nearest_leaves)
//!   and [`any_leaf`](Bvh::any_leaf) do the same a leaf at a time, for a caller that tests a
//!   leaf's primitives together ([`build_batched`](Bvh::build_batched) builds its tree).

mod build;
mod traverse;
mod wide;

use super::aabb::Aabb;
use wide::WideNode;

/// Leaves hold at most this many primitives.
pub const MAX_PRIMITIVES_PER_LEAF: usize = 4;

/// Positions per block of [`Bvh::leaf_order`]: each leaf starts a block of its own, so that a
/// caller can keep one record per leaf (four triangles tested at once, say) and find it as
/// `first / LEAF_BLOCK`.
pub const LEAF_BLOCK: usize = MAX_PRIMITIVES_PER_LEAF;

/// What [`Bvh::leaf_order`] holds in the positions of a block after its leaf's primitives.
pub const EMPTY_SLOT: u32 = u32::MAX;

/// A bounding volume hierarchy over primitives known only by their index and box.
#[derive(Clone, Debug)]
pub struct Bvh {
    /// The nodes, the root first; each holds up to four children.
    nodes: Vec<WideNode>,
    /// Primitive indices in leaf order (see [`leaf_order`](Self::leaf_order)).
    primitive_indices: Vec<u32>,
    /// Number of nodes on the longest path from the root to a leaf.
    depth: usize,
    /// The box around every primitive.
    bounds: Aabb,
}

/// The result of [`Bvh::intersect`]: which primitive was hit first, and where along the ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BvhHit {
    /// The primitive's index, as in the box slice given to [`Bvh::build`].
    pub primitive: usize,
    /// The ray parameter of the hit.
    pub t: f32,
}

impl Default for Bvh {
    /// The tree over no primitives.
    fn default() -> Self {
        Self {
            nodes: Vec::new(),
            primitive_indices: Vec::new(),
            depth: 0,
            bounds: Aabb::empty(),
        }
    }
}

impl Bvh {
    /// The wide tree over the binary tree's boxes and leaves.
    fn from_binary(tree: build::BinaryTree) -> Self {
        let (nodes, depth) = wide::collapse(&tree);
        Self {
            nodes,
            primitive_indices: tree.primitive_indices,
            depth,
            bounds: tree.nodes.first().map_or(Aabb::empty(), |root| root.bounds),
        }
    }

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
        self.bounds
    }

    /// The primitives' indices in the order of the leaves: each leaf's primitives are a
    /// contiguous run at the start of a block of [`LEAF_BLOCK`] positions, and the rest of
    /// the block holds [`EMPTY_SLOT`]. The leaf walks ([`nearest_leaves`](Self::nearest_leaves),
    /// [`any_leaf`](Self::any_leaf)) name a leaf by its block, `position / LEAF_BLOCK`.
    pub fn leaf_order(&self) -> &[u32] {
        &self.primitive_indices
    }

    /// The bytes the tree takes: its nodes and its primitive indices.
    pub fn memory_bytes(&self) -> usize {
        std::mem::size_of_val(self.nodes.as_slice())
            + std::mem::size_of_val(self.primitive_indices.as_slice())
    }
}

#[cfg(test)]
mod tests;
