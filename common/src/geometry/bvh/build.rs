//! Building the BVH top-down with the binned surface-area heuristic (SAH).
//!
//! The cost of a tree, for random rays, is roughly the sum over its nodes of
//! *probability that a ray entering the parent enters the node* × *cost of the node*, and that
//! probability is the ratio of the boxes' surface areas. So to split `n` primitives in two we
//! compare, for each candidate split, `area(A) · count(A) + area(B) · count(B)`, and keep the
//! cheapest. Trying every split is slow; *binning* sorts the primitives' centres into a few
//! equal slices along the longest axis and only tries the boundaries between slices (Wald 2007;
//! pbrt-v4, section 7.3.2).

use glam::Vec3;

use super::{Bvh, EMPTY_SLOT, LEAF_BLOCK, MAX_PRIMITIVES_PER_LEAF};
use crate::geometry::aabb::Aabb;

/// How many slices the centroid range is cut into; 12 is pbrt-v4's choice.
const BIN_COUNT: usize = 12;

/// The cost of visiting a node, relative to testing one primitive.
const TRAVERSAL_COST: f32 = 0.5;

/// Beyond this depth, nodes are split at the median instead of by the SAH.
///
/// The SAH may peel off one primitive at a time (think of spheres at positions 1, 2, 4, 8, …),
/// making the tree as deep as it has primitives. Median splits halve the count, so at most
/// 32 more levels follow for any `u32` number of primitives.
const MAX_SAH_DEPTH: usize = 32;

/// No tree is deeper than this; the traversal's fixed-size stack relies on it.
pub(super) const MAX_DEPTH: usize = MAX_SAH_DEPTH + 32;

/// A node over more primitives than this builds its two subtrees at once, on two threads
/// when there are two. Below it, a subtree is too quick to build for the hand-over to pay.
/// The threshold is a count, not a thread count, so the tree is the same on any machine.
const PARALLEL_BUILD: usize = 16 * 1024;

/// The binary tree the SAH builds, before [`super::wide`] collapses it into nodes of four.
#[derive(Clone, Debug, Default)]
pub(super) struct BinaryTree {
    /// The nodes in depth-first order: an interior node's first child is the next node.
    pub nodes: Vec<Node>,
    /// Primitive indices, each leaf's at the start of a block of [`LEAF_BLOCK`] (see
    /// [`Bvh::leaf_order`]).
    pub primitive_indices: Vec<u32>,
    /// Number of nodes on the longest path from the root to a leaf.
    pub depth: usize,
}

/// One node of the binary tree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Node {
    /// Contains every primitive below the node.
    pub bounds: Aabb,
    pub kind: NodeKind,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum NodeKind {
    /// The primitives `primitive_indices[first..first + count]`.
    Leaf { first: u32, count: u32 },
    /// Two children: the first is the next node in the array (depth-first order), so only the
    /// second needs an index.
    Interior { second_child: u32 },
}

/// A primitive while the tree is being built.
#[derive(Clone, Copy, Debug)]
struct BuildPrimitive {
    index: u32,
    /// Whether the caller tests this primitive together with the rest of its leaf's.
    batched: bool,
    bounds: Aabb,
    centroid: Vec3,
}

/// How to divide a node's primitives: after reordering, the first `mid` go to the first child.
struct Split {
    mid: usize,
}

impl Bvh {
    /// Builds the tree over one box per primitive; primitive `i` is `primitive_bounds[i]`.
    ///
    /// Any input works: no boxes, one box, flat or zero-size boxes, boxes whose centres all
    /// coincide. Empty (or NaN) boxes can never be hit and are left out of the tree.
    ///
    /// The SAH splits in two; the binary tree is then collapsed into nodes of four children
    /// (the `wide` module), which a ray tests at once.
    pub fn build(primitive_bounds: &[Aabb]) -> Bvh {
        Bvh::build_batched(primitive_bounds, &[])
    }

    /// [`build`](Self::build) for a caller that tests some primitives a leaf at a time:
    /// primitive `i` is one of them if `batched[i]` (missing entries are `false`). Testing a
    /// leaf of up to [`LEAF_BLOCK`] of them costs about one test, so the SAH weighs them by
    /// the block rather than one by one, and their leaves come out fuller and the tree
    /// shallower.
    pub fn build_batched(primitive_bounds: &[Aabb], batched: &[bool]) -> Bvh {
        Bvh::from_binary(BinaryTree::build(primitive_bounds, batched))
    }
}

impl BinaryTree {
    /// The binary SAH tree over the boxes (see [`Bvh::build`]).
    pub(super) fn build(primitive_bounds: &[Aabb], batched: &[bool]) -> BinaryTree {
        BinaryTree::build_splitting_work(primitive_bounds, batched, PARALLEL_BUILD)
    }

    /// [`build`](Self::build), building the two subtrees of a node over more than
    /// `parallel_above` primitives at once.
    fn build_splitting_work(
        primitive_bounds: &[Aabb],
        batched: &[bool],
        parallel_above: usize,
    ) -> BinaryTree {
        let mut primitives: Vec<BuildPrimitive> = primitive_bounds
            .iter()
            .enumerate()
            .filter(|(_, bounds)| !bounds.is_empty())
            .map(|(index, &bounds)| BuildPrimitive {
                index: u32::try_from(index).expect("at most u32::MAX primitives"),
                batched: batched.get(index).copied().unwrap_or(false),
                bounds,
                centroid: bounds.centroid(),
            })
            .collect();
        if primitives.is_empty() {
            return BinaryTree::default();
        }
        let tree = BinaryTree::subtree(&mut primitives, 1, parallel_above);
        debug_assert!(tree.depth <= MAX_DEPTH);
        tree
    }

    /// Appends the subtree over `primitives` (in depth-first order) and returns its root's index.
    fn add_subtree(
        &mut self,
        primitives: &mut [BuildPrimitive],
        depth: usize,
        parallel_above: usize,
    ) -> usize {
        self.depth = self.depth.max(depth);
        let bounds = primitives
            .iter()
            .fold(Aabb::empty(), |b, p| b.union(p.bounds));
        let index = self.nodes.len();
        match choose_split(primitives, &bounds, depth) {
            None => {
                // Every leaf starts a block of its own (see `Bvh::leaf_order`).
                let first = self.primitive_indices.len().next_multiple_of(LEAF_BLOCK);
                self.primitive_indices.resize(first, EMPTY_SLOT);
                self.primitive_indices
                    .extend(primitives.iter().map(|p| p.index));
                let first = first as u32;
                self.nodes.push(Node {
                    bounds,
                    kind: NodeKind::Leaf {
                        first,
                        count: primitives.len() as u32,
                    },
                });
            }
            Some(Split { mid }) => {
                // Reserve the slot; the second child's index is known only after the first
                // child's subtree has been laid out.
                self.nodes.push(Node {
                    bounds,
                    kind: NodeKind::Leaf { first: 0, count: 0 },
                });
                let parallel = primitives.len() > parallel_above;
                let (first_half, second_half) = primitives.split_at_mut(mid);
                let second_child = if parallel {
                    let (first, second) = rayon::join(
                        || BinaryTree::subtree(first_half, depth + 1, parallel_above),
                        || BinaryTree::subtree(second_half, depth + 1, parallel_above),
                    );
                    self.append(first);
                    self.append(second)
                } else {
                    self.add_subtree(first_half, depth + 1, parallel_above);
                    self.add_subtree(second_half, depth + 1, parallel_above)
                };
                self.nodes[index].kind = NodeKind::Interior {
                    second_child: second_child as u32,
                };
            }
        }
        index
    }

    /// The subtree over `primitives`, whose root is `depth` nodes deep, as a tree of its own.
    fn subtree(
        primitives: &mut [BuildPrimitive],
        depth: usize,
        parallel_above: usize,
    ) -> BinaryTree {
        let mut tree = BinaryTree {
            nodes: Vec::with_capacity(2 * primitives.len()),
            primitive_indices: Vec::with_capacity(primitives.len()),
            depth: 0,
        };
        tree.add_subtree(primitives, depth, parallel_above);
        tree
    }

    /// Appends a [`subtree`](Self::subtree) and returns its root's index: the nodes and
    /// primitives land exactly where [`add_subtree`](Self::add_subtree) would have put them,
    /// since its first leaf starts a block either way.
    fn append(&mut self, subtree: BinaryTree) -> usize {
        let root = self.nodes.len();
        let first_position = self.primitive_indices.len().next_multiple_of(LEAF_BLOCK);
        self.primitive_indices.resize(first_position, EMPTY_SLOT);
        self.primitive_indices.extend(subtree.primitive_indices);
        self.nodes
            .extend(subtree.nodes.into_iter().map(|node| Node {
                kind: match node.kind {
                    NodeKind::Leaf { first, count } => NodeKind::Leaf {
                        first: first + first_position as u32,
                        count,
                    },
                    NodeKind::Interior { second_child } => NodeKind::Interior {
                        second_child: second_child + root as u32,
                    },
                },
                ..node
            }));
        self.depth = self.depth.max(subtree.depth);
        root
    }
}

/// Decides whether to split `primitives` (whose union is `bounds`), reordering them if so.
fn choose_split(primitives: &mut [BuildPrimitive], bounds: &Aabb, depth: usize) -> Option<Split> {
    let count = primitives.len();
    if count == 1 {
        return None;
    }
    let centroid_bounds = Aabb::from_point_set(primitives.iter().map(|p| p.centroid));
    let axis = centroid_bounds.largest_axis();
    let (low, high) = (centroid_bounds.min[axis], centroid_bounds.max[axis]);
    let extent = high - low;
    let centroids_spread = extent > 0.0; // false if they coincide (or are NaN)
    if !centroids_spread || depth >= MAX_SAH_DEPTH {
        // All centres coincide (nothing to tell the primitives apart by position), or the tree
        // is already deep: keep leaves small by halving.
        return (count > MAX_PRIMITIVES_PER_LEAF).then(|| median_split(primitives, axis));
    }

    let bin_of = |p: &BuildPrimitive| {
        let relative = (p.centroid[axis] - low) / extent;
        // `as` saturates (and maps NaN to 0), so this is always a valid bin.
        ((relative * BIN_COUNT as f32) as usize).min(BIN_COUNT - 1)
    };
    let mut bin_bounds = [Aabb::empty(); BIN_COUNT];
    let mut bin_counts = [Tests::default(); BIN_COUNT];
    for p in primitives.iter() {
        let bin = bin_of(p);
        bin_bounds[bin] = bin_bounds[bin].union(p.bounds);
        bin_counts[bin].add(p);
    }

    // cost[i]: SAH cost (up to the common factor 1 / area(bounds)) of splitting after bin i.
    let mut cost = [0.0f32; BIN_COUNT - 1];
    let (mut below, mut below_count) = (Aabb::empty(), Tests::default());
    for i in 0..BIN_COUNT - 1 {
        below = below.union(bin_bounds[i]);
        below_count = below_count.and(bin_counts[i]);
        cost[i] = below_count.cost() * below.surface_area();
    }
    let (mut above, mut above_count) = (Aabb::empty(), Tests::default());
    for i in (1..BIN_COUNT).rev() {
        above = above.union(bin_bounds[i]);
        above_count = above_count.and(bin_counts[i]);
        cost[i - 1] += above_count.cost() * above.surface_area();
    }
    // Every primitive is in one bin: the set below the last boundary and the last bin.
    let all = below_count.and(bin_counts[BIN_COUNT - 1]);
    let best_boundary = (0..BIN_COUNT - 1)
        .min_by(|&a, &b| cost[a].total_cmp(&cost[b]))
        .expect("there are BIN_COUNT - 1 boundaries");

    let area = bounds.surface_area();
    let leaf_cost = all.cost() * area;
    let split_cost = TRAVERSAL_COST * area + cost[best_boundary];
    let split_pays_off = split_cost < leaf_cost;
    if count <= MAX_PRIMITIVES_PER_LEAF && !split_pays_off {
        return None;
    }
    let mid = partition(primitives, |p| bin_of(p) <= best_boundary);
    if mid == 0 || mid == count {
        // Cannot happen for finite centroids (the first and last bins are both occupied), but
        // a split must never leave a child empty.
        return Some(median_split(primitives, axis));
    }
    Some(Split { mid })
}

/// How many primitives of each kind a set holds, for the cost of testing them.
#[derive(Clone, Copy, Debug, Default)]
struct Tests {
    /// Primitives tested one by one.
    single: usize,
    /// Primitives tested a block of [`LEAF_BLOCK`] at a time.
    batched: usize,
}

impl Tests {
    fn add(&mut self, p: &BuildPrimitive) {
        if p.batched {
            self.batched += 1;
        } else {
            self.single += 1;
        }
    }

    fn and(self, other: Self) -> Self {
        Self {
            single: self.single + other.single,
            batched: self.batched + other.batched,
        }
    }

    /// The cost of the tests, in tests of one primitive: one per single primitive, one per
    /// block of batched ones.
    fn cost(self) -> f32 {
        (self.single + self.batched.div_ceil(LEAF_BLOCK)) as f32
    }
}

/// Splits at the median centroid along `axis`: both halves non-empty, whatever the centroids.
fn median_split(primitives: &mut [BuildPrimitive], axis: usize) -> Split {
    let mid = primitives.len() / 2;
    primitives.select_nth_unstable_by(mid, |a, b| a.centroid[axis].total_cmp(&b.centroid[axis]));
    Split { mid }
}

/// Moves the items for which `goes_first` holds to the front; returns how many there are.
fn partition<T>(items: &mut [T], goes_first: impl Fn(&T) -> bool) -> usize {
    let mut first_count = 0;
    for i in 0..items.len() {
        if goes_first(&items[i]) {
            items.swap(i, first_count);
            first_count += 1;
        }
    }
    first_count
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::TriangleMesh;

    /// Building subtrees apart and appending them must give exactly the tree built in one go,
    /// node for node and slot for slot, or the tree would depend on where the work was split.
    #[test]
    fn subtrees_built_apart_make_the_tree_built_in_one_go() {
        let mesh = TriangleMesh::bumpy_sphere(5_000);
        let mut bounds: Vec<Aabb> = mesh
            .triangles()
            .map(|triangle| Aabb::from_point_set(triangle.p))
            .collect();
        // A few primitives tested one by one, and an empty box, among the batched triangles.
        bounds[17] = Aabb::from_points(Vec3::splat(-0.1), Vec3::splat(0.1));
        bounds[400] = Aabb::empty();
        let batched: Vec<bool> = (0..bounds.len()).map(|i| i % 97 != 0).collect();
        let in_one_go = BinaryTree::build_splitting_work(&bounds, &batched, usize::MAX);
        for parallel_above in [0, 7, 64, 1000] {
            let apart = BinaryTree::build_splitting_work(&bounds, &batched, parallel_above);
            assert_eq!(apart.nodes, in_one_go.nodes, "split above {parallel_above}");
            assert_eq!(apart.primitive_indices, in_one_go.primitive_indices);
            assert_eq!(apart.depth, in_one_go.depth);
        }
    }
}
