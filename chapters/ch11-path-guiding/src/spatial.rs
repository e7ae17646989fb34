//! The spatial tree: which directional quadtree guides a point of the scene.
//!
//! Light arriving at one end of a room is not the light at the other, so each region of space
//! learns its own [`DirectionTree`]. Müller et al. cut the scene's box by a binary tree, each
//! split halving a box across one axis (x, then y, then z, then x again), and a leaf holds
//! the guide of its region: the quadtree sampled from in this iteration (`sampling`, learnt
//! in the one before), the one being learnt (`building`), and how often to ask the BSDF
//! rather than the guide (`fraction`). A leaf that received more than
//! a threshold of records in an iteration is split in two, each half starting from a copy of
//! its guide, so the tree is fine where paths are many. The threshold grows as the square
//! root of the iteration's samples: the leaves keep more records each as training goes on, so
//! their quadtrees get finer as well as more numerous.

use crate::quadtree::DirectionTree;
use crate::selection::LearntFraction;
use common::geometry::Aabb;
use glam::Vec3;

/// The deepest a spatial leaf may lie: boxes of `2^-8` of the scene's side on every axis, far
/// finer than a training iteration can fill with records.
pub const MAX_SPATIAL_DEPTH: u32 = 24;

/// What a spatial leaf holds: the quadtrees of its region and the records of this iteration.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Guide {
    /// The distribution sampled from during this iteration (learnt during the last one).
    pub sampling: DirectionTree,
    /// The distribution learnt during this iteration.
    pub building: DirectionTree,
    /// How many records `building` received.
    pub records: u64,
    /// The region's BSDF fraction, learnt with the quadtrees.
    pub fraction: LearntFraction,
}

/// A node of the spatial tree: a split of its box in two halves across `axis`, or a leaf
/// holding guide number `guide`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SpatialNode {
    /// The box's lower and upper halves across `axis` (0, 1, 2 for x, y, z).
    Split {
        /// The axis split.
        axis: u8,
        /// The node of the lower half, then the upper half's.
        children: [u32; 2],
    },
    /// A region guided by one [`Guide`].
    Leaf {
        /// Its index in [`SpatialTree::guides`].
        guide: u32,
    },
}

/// The binary tree over the scene's box, with the guides of its leaves.
#[derive(Clone, Debug, PartialEq)]
pub struct SpatialTree {
    /// The box split, made a cube so that the splits cycle through cells of equal sides.
    pub bounds: Aabb,
    /// The nodes, the root first.
    pub nodes: Vec<SpatialNode>,
    /// The leaves' guides.
    pub guides: Vec<Guide>,
}

impl SpatialTree {
    /// One leaf over `bounds` (grown to a cube around its centre; a unit cube for an empty or
    /// infinite box), nothing learnt.
    pub fn new(bounds: Aabb) -> Self {
        let finite = !bounds.is_empty() && bounds.min.is_finite() && bounds.max.is_finite();
        let (centre, side) = if finite {
            let side = (bounds.max - bounds.min).max_element();
            (
                (bounds.min + bounds.max) * 0.5,
                if side > 0.0 { side } else { 1.0 },
            )
        } else {
            (Vec3::ZERO, 1.0)
        };
        // A little larger than the scene, so that its outermost surfaces lie inside.
        let half = Vec3::splat(0.5 * side * (1.0 + 1e-3));
        Self {
            bounds: Aabb {
                min: centre - half,
                max: centre + half,
            },
            nodes: vec![SpatialNode::Leaf { guide: 0 }],
            guides: vec![Guide::default()],
        }
    }

    /// The guide of the region holding `p`. A point outside the box goes to the leaf nearest
    /// it, as every split sends it to the half on its side.
    pub fn guide_of(&self, p: Vec3) -> u32 {
        let (mut node, mut min, mut max) = (0usize, self.bounds.min, self.bounds.max);
        loop {
            match self.nodes[node] {
                SpatialNode::Leaf { guide } => return guide,
                SpatialNode::Split { axis, children } => {
                    let a = usize::from(axis);
                    let middle = 0.5 * (min[a] + max[a]);
                    if p[a] < middle {
                        max[a] = middle;
                        node = children[0] as usize;
                    } else {
                        min[a] = middle;
                        node = children[1] as usize;
                    }
                }
            }
        }
    }

    /// Splits every leaf whose guide received more than `most_records` records, and its
    /// halves again while they would (each half counted as holding half the records), down to
    /// [`MAX_SPATIAL_DEPTH`]. Each half starts from a copy of the leaf's guide.
    pub fn refine(&mut self, most_records: f64) {
        let mut stack = vec![(0usize, 0u32)];
        while let Some((node, depth)) = stack.pop() {
            match self.nodes[node] {
                SpatialNode::Split { children, .. } => {
                    stack.push((children[0] as usize, depth + 1));
                    stack.push((children[1] as usize, depth + 1));
                }
                SpatialNode::Leaf { guide } => {
                    let records = self.guides[guide as usize].records;
                    if depth >= MAX_SPATIAL_DEPTH
                        || most_records.is_nan()
                        || records as f64 <= most_records
                    {
                        continue;
                    }
                    let mut half = self.guides[guide as usize].clone();
                    half.records = records / 2;
                    self.guides[guide as usize] = half.clone();
                    let other = self.guides.len() as u32;
                    self.guides.push(half);
                    let lower = self.nodes.len() as u32;
                    self.nodes.push(SpatialNode::Leaf { guide });
                    self.nodes.push(SpatialNode::Leaf { guide: other });
                    self.nodes[node] = SpatialNode::Split {
                        axis: (depth % 3) as u8,
                        children: [lower, lower + 1],
                    };
                    stack.push((lower as usize, depth + 1));
                    stack.push((lower as usize + 1, depth + 1));
                }
            }
        }
    }

    /// The bytes the tree takes: its nodes and both quadtrees of every leaf.
    pub fn memory_bytes(&self) -> usize {
        std::mem::size_of_val(self.nodes.as_slice())
            + self
                .guides
                .iter()
                .map(|g| {
                    std::mem::size_of::<Guide>()
                        + g.sampling.memory_bytes()
                        + g.building.memory_bytes()
                })
                .sum::<usize>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_split_sends_each_point_to_its_half_and_splits_cycle_the_axes() {
        let mut tree = SpatialTree::new(Aabb::from_points(Vec3::ZERO, Vec3::new(2.0, 1.0, 1.0)));
        // The box became a cube of side 2 (and a little) around (1, 0.5, 0.5).
        tree.guides[0].records = 100;
        tree.refine(30.0);
        // 100 > 30: split into 50 and 50, each > 30 again: split into 25s.
        assert_eq!(tree.guides.len(), 4);
        assert!(tree.guides.iter().all(|g| g.records == 25));
        let a = tree.guide_of(Vec3::new(0.1, -0.4, 0.5));
        let b = tree.guide_of(Vec3::new(1.9, -0.4, 0.5));
        let c = tree.guide_of(Vec3::new(0.1, 1.4, 0.5));
        let d = tree.guide_of(Vec3::new(1.9, 1.4, 0.5));
        let mut all = vec![a, b, c, d];
        all.sort();
        assert_eq!(all, vec![0, 1, 2, 3], "x, then y, split the box in four");
        // Points outside the box go to the leaf on their side.
        assert_eq!(tree.guide_of(Vec3::new(-50.0, -50.0, 0.5)), a);
        assert_eq!(tree.guide_of(Vec3::new(50.0, 50.0, 9.0)), d);
    }

    #[test]
    fn an_empty_or_infinite_box_gives_a_unit_cube() {
        for bounds in [Aabb::empty(), Aabb::from_points(Vec3::ZERO, Vec3::INFINITY)] {
            let tree = SpatialTree::new(bounds);
            assert!(tree.bounds.min.is_finite() && tree.bounds.max.is_finite());
            assert_eq!(tree.guide_of(Vec3::new(f32::NAN, 0.0, 0.0)), 0);
        }
    }
}
