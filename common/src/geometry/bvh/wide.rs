//! Nodes of four: the binary SAH tree collapsed so that a ray tests four boxes at once.
//!
//! A binary tree asks one question per box and walks about twice as many levels. Collapsing
//! it (Wald, Benthin and Boulos 2008; Embree and pbrt-v4's "wide BVH" do the same) keeps the
//! SAH's boxes and leaves exactly, but stores a node's grandchildren as its children: each node
//! holds up to four child boxes side by side, axis by axis (all four `min.x`, then all four
//! `min.y`, ...), so that one set of SIMD instructions tests the ray against all four. Fewer
//! levels mean fewer dependent memory loads per ray, which is where a walk spends its time.

use glam::Vec4;

use super::build::{BinaryTree, NodeKind};
use crate::geometry::aabb::Aabb;

/// Children per node: the lanes of one SIMD register of `f32`s.
pub const WIDTH: usize = 4;

/// A node: up to four children's boxes, one per lane, and where each child is.
///
/// A lane without a child holds an empty box (`min = +∞`, `max = -∞`), which no ray enters.
///
/// A node is 116 bytes; aligned to 64, it fills exactly two cache lines, which a walk that
/// waits on memory loads together, instead of straddling three.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(align(64))]
pub(super) struct WideNode {
    /// The children's boxes, side by side: `slabs[axis]` holds each lane's `min[axis]` and
    /// `slabs[3 + axis]` its `max[axis]`. One array, so that a walk picks a ray's near and far
    /// side of each axis by index ([`slab_sides`]) instead of by a branch at every node.
    pub slabs: [Vec4; 6],
    /// For each lane: the child node's index if `count` is 0, or the first of its primitives
    /// in `primitive_indices` if it is a leaf.
    pub child: [u32; WIDTH],
    /// For each lane: how many primitives the leaf holds; 0 for an inner node or no child.
    pub count: [u8; WIDTH],
}

/// Where in [`WideNode::slabs`] a ray meets each axis's slab first and last: `(min, max)`
/// for a ray travelling towards larger coordinates, `(max, min)` otherwise.
pub(super) fn slab_sides(negative: [bool; 3]) -> ([usize; 3], [usize; 3]) {
    let side = |axis: usize, upper: bool| axis + if upper { 3 } else { 0 };
    (
        std::array::from_fn(|axis| side(axis, negative[axis])),
        std::array::from_fn(|axis| side(axis, !negative[axis])),
    )
}

/// What sits in one lane of a node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Child {
    /// Another node.
    Node(u32),
    /// The primitives `primitive_indices[first..first + count]`.
    Leaf { first: u32, count: u32 },
}

impl WideNode {
    const EMPTY: WideNode = WideNode {
        slabs: [
            Vec4::INFINITY,
            Vec4::INFINITY,
            Vec4::INFINITY,
            Vec4::NEG_INFINITY,
            Vec4::NEG_INFINITY,
            Vec4::NEG_INFINITY,
        ],
        child: [u32::MAX; WIDTH],
        count: [0; WIDTH],
    };

    /// What lane `lane` holds (`None` for no child).
    #[cfg(test)]
    pub fn child(&self, lane: usize) -> Option<Child> {
        match (self.count[lane], self.child[lane]) {
            (0, u32::MAX) => None,
            (0, node) => Some(Child::Node(node)),
            (count, first) => Some(Child::Leaf {
                first,
                count: u32::from(count),
            }),
        }
    }

    /// The box of lane `lane` (empty for no child).
    #[cfg(test)]
    pub fn bounds(&self, lane: usize) -> Aabb {
        Aabb {
            min: glam::Vec3::from_array(std::array::from_fn(|axis| self.slabs[axis][lane])),
            max: glam::Vec3::from_array(std::array::from_fn(|axis| self.slabs[3 + axis][lane])),
        }
    }

    fn set(&mut self, lane: usize, bounds: Aabb, child: Child) {
        for axis in 0..3 {
            self.slabs[axis][lane] = bounds.min[axis];
            self.slabs[3 + axis][lane] = bounds.max[axis];
        }
        (self.child[lane], self.count[lane]) = match child {
            Child::Node(index) => (index, 0),
            Child::Leaf { first, count } => (
                first,
                u8::try_from(count).expect("leaves hold a few primitives"),
            ),
        };
    }
}

/// The collapsed tree: its nodes (the root first) and the number of nodes on its longest
/// root-to-leaf path.
pub(super) fn collapse(tree: &BinaryTree) -> (Vec<WideNode>, usize) {
    let mut nodes = Vec::with_capacity(tree.nodes.len() / 2 + 1);
    let depth = if tree.nodes.is_empty() {
        0
    } else {
        add_node(tree, 0, &mut nodes, 1)
    };
    (nodes, depth)
}

/// Appends the wide node standing for binary node `index` (and its subtree); returns the
/// depth of the deepest wide node below it, counting from `depth`.
fn add_node(tree: &BinaryTree, index: usize, nodes: &mut Vec<WideNode>, depth: usize) -> usize {
    // Open the largest inner node among the children until there are four: the SAH's most
    // probable boxes are the ones worth testing side by side.
    let mut lanes = vec![index];
    loop {
        let widest_inner = lanes
            .iter()
            .enumerate()
            .filter(|&(_, &node)| matches!(tree.nodes[node].kind, NodeKind::Interior { .. }))
            .max_by(|&(_, &a), &(_, &b)| {
                let area = |node: usize| tree.nodes[node].bounds.surface_area();
                area(a).total_cmp(&area(b))
            })
            .map(|(lane, _)| lane);
        let Some(lane) = widest_inner else { break };
        if lanes.len() + 1 > WIDTH {
            break;
        }
        let node = lanes.remove(lane);
        let NodeKind::Interior { second_child } = tree.nodes[node].kind else {
            unreachable!("only inner nodes are opened")
        };
        lanes.insert(lane, second_child as usize);
        lanes.insert(lane, node + 1);
    }

    let position = nodes.len();
    nodes.push(WideNode::EMPTY);
    let mut deepest = depth;
    for (lane, &node) in lanes.iter().enumerate() {
        let child = match tree.nodes[node].kind {
            NodeKind::Leaf { first, count } => Child::Leaf { first, count },
            NodeKind::Interior { .. } => {
                let child_index = nodes.len() as u32;
                deepest = deepest.max(add_node(tree, node, nodes, depth + 1));
                Child::Node(child_index)
            }
        };
        nodes[position].set(lane, tree.nodes[node].bounds, child);
    }
    deepest
}
