//! The directional quadtree: a distribution over the directions of the sphere, learnt from
//! the light that paths bring back, that refines itself where the light is.
//!
//! Müller, Gross and Novák (*Practical Path Guiding for Efficient Light-Transport
//! Simulation*, EGSR 2017) store the light arriving at a region of space as a quadtree over
//! the unit square of [`crate::directions`]. Each node splits its square into four quadrants
//! and keeps, for each, the sum of what was recorded there; a quadrant is either a leaf or a
//! node of its own. Sampling walks down from the root choosing quadrants in proportion to
//! their sums, then picks a point uniformly in the leaf it ends in; the density is what that
//! walk gives a point. After each training iteration the tree is rebuilt: a quadrant that
//! holds more than a small fraction of the whole is split, one that holds less is merged, so
//! that the cells are small where the light is bright and narrow, and large elsewhere.
//!
//! Quadrant `q` of a node is its left (`q & 1 == 0`) or right half along `x`, and its lower
//! (`q & 2 == 0`) or upper half along `y`.

use glam::Vec2;

/// The deepest a quadrant may be split: cells of `2^-20` of the square's side, far below
/// anything a training iteration can resolve.
pub const MAX_DEPTH: u32 = 20;

/// The share of the whole above which a quadrant is split when the tree is rebuilt: the
/// value Müller et al. use (`ρ = 0.01`).
pub const SPLIT_FRACTION: f32 = 0.01;

/// One node: four quadrants, each with its sum and its child (`0` for a leaf: the root, node
/// 0, is no one's child).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct QuadNode {
    /// What was recorded in each quadrant (after [`DirectionTree::build`], the sum over the
    /// quadrant's leaves).
    pub sums: [f32; 4],
    /// Each quadrant's child node, or `0` for a leaf.
    pub children: [u32; 4],
}

impl QuadNode {
    /// The sum of the four quadrants.
    pub fn total(&self) -> f32 {
        self.sums.iter().sum()
    }
}

/// The quadrant of `point` (in its node's square scaled to `[0, 1)²`) and the point in that
/// quadrant's square, scaled the same way.
pub fn quadrant_of(point: Vec2) -> (usize, Vec2) {
    let right = point.x >= 0.5;
    let upper = point.y >= 0.5;
    let corner = Vec2::new(f32::from(u8::from(right)), f32::from(u8::from(upper)));
    let q = usize::from(right) + 2 * usize::from(upper);
    (
        q,
        (point * 2.0 - corner).clamp(Vec2::ZERO, Vec2::splat(1.0)),
    )
}

/// A distribution over the unit square, as a quadtree of sums.
#[derive(Clone, Debug, PartialEq)]
pub struct DirectionTree {
    /// The nodes, the root first.
    pub nodes: Vec<QuadNode>,
}

impl Default for DirectionTree {
    fn default() -> Self {
        Self::new()
    }
}

impl DirectionTree {
    /// A tree of one node, four empty leaves: nothing learnt.
    pub fn new() -> Self {
        Self {
            nodes: vec![QuadNode::default()],
        }
    }

    /// The sum over the whole square.
    pub fn total(&self) -> f32 {
        self.nodes[0].total()
    }

    /// The bytes the tree's nodes take.
    pub fn memory_bytes(&self) -> usize {
        std::mem::size_of_val(self.nodes.as_slice())
    }

    /// Adds `value` to the leaf that holds `point`. A value that is negative or not finite is
    /// a bug upstream and is left out rather than spoiling the whole tree.
    pub fn record(&mut self, point: Vec2, value: f32) {
        if !(value.is_finite() && value > 0.0) {
            return;
        }
        let (mut node, mut point) = (0, point);
        loop {
            let (q, inner) = quadrant_of(point);
            let child = self.nodes[node].children[q];
            if child == 0 {
                self.nodes[node].sums[q] += value;
                return;
            }
            (node, point) = (child as usize, inner);
        }
    }

    /// Makes every node's sums the sums over its quadrants' leaves, after `leaf_weight(sum,
    /// area)` has turned each leaf's recorded sum into its weight (`area`: the leaf's share of
    /// the square). Sampling then picks a leaf in proportion to its weight.
    pub fn build(&mut self, leaf_weight: impl Fn(f32, f32) -> f32 + Copy) {
        self.build_node(0, 1.0, leaf_weight);
    }

    /// [`build`](Self::build) below node `node`, whose square has area `area`; returns its total.
    fn build_node(
        &mut self,
        node: usize,
        area: f32,
        leaf_weight: impl Fn(f32, f32) -> f32 + Copy,
    ) -> f32 {
        let quarter = 0.25 * area;
        for q in 0..4 {
            let child = self.nodes[node].children[q];
            self.nodes[node].sums[q] = if child == 0 {
                leaf_weight(self.nodes[node].sums[q], quarter)
            } else {
                self.build_node(child as usize, quarter, leaf_weight)
            };
        }
        self.nodes[node].total()
    }

    /// The shape of the next iteration's tree, its sums all 0: a quadrant of this (built) tree
    /// holding more than `split_fraction` of the total is split, where it was a leaf too (its
    /// sum then shared evenly by its four quadrants when deciding below it), down to
    /// [`MAX_DEPTH`]; every other quadrant is a leaf, so what held little is merged.
    pub fn refined(&self, split_fraction: f32) -> Self {
        let mut out = Self::new();
        let total = self.total();
        if !(total > 0.0 && total.is_finite()) {
            return out;
        }
        // A node of `out` to fill in, the node of `self` at the same place (if any), the sums
        // its quadrants had, and its depth (the root's is 1).
        let mut stack = vec![(0usize, Some(0usize), self.nodes[0].sums, 1u32)];
        while let Some((new, old, sums, depth)) = stack.pop() {
            for (q, &sum) in sums.iter().enumerate() {
                if depth >= MAX_DEPTH || sum.is_nan() || sum <= split_fraction * total {
                    continue;
                }
                let child = out.nodes.len();
                out.nodes.push(QuadNode::default());
                out.nodes[new].children[q] = child as u32;
                let old_child = old
                    .map(|o| self.nodes[o].children[q])
                    .filter(|&c| c != 0)
                    .map(|c| c as usize);
                let child_sums = match old_child {
                    Some(c) => self.nodes[c].sums,
                    None => [0.25 * sum; 4],
                };
                stack.push((child, old_child, child_sums, depth + 1));
            }
        }
        out
    }

    // ANCHOR: pdf
    /// The density on the unit square with which [`sample`](Self::sample) picks `point`:
    /// 0 where nothing was recorded, or everywhere when the tree is empty.
    ///
    /// A walk down the tree picks a quadrant in proportion to its sum, then the next, until a
    /// leaf, then a point uniformly in the leaf. What is the chance of each step, and over how
    /// much of the square is the leaf's share spread? Density times area must add up to 1
    /// over the square.
    pub fn pdf(&self, point: Vec2) -> f32 {
        let (mut node, mut point, mut density) = (0usize, point, 1.0f32);
        loop {
            let total = self.nodes[node].total();
            if total.is_nan() || total <= 0.0 {
                return 0.0;
            }
            let (q, inner) = quadrant_of(point);
            // The quadrant's share of its node, spread over a quarter of the node's area.
            density *= 4.0 * self.nodes[node].sums[q] / total;
            let child = self.nodes[node].children[q];
            if child == 0 {
                return density;
            }
            (node, point) = (child as usize, inner);
        }
    }
    // ANCHOR_END: pdf

    // ANCHOR: sample
    /// A point of the unit square drawn from the tree with the 2D number `u`, with the density
    /// [`pdf`](Self::pdf); `None` when nothing was recorded (a tree to sample from needs a
    /// positive total).
    ///
    /// One 2D number is enough for the whole walk: at each node, which part of `u` says left
    /// or right, which says lower or upper, and what is left of `u` for the next level once a
    /// quadrant is chosen? The point in the leaf is the last of it.
    pub fn sample(&self, u: Vec2) -> Option<Vec2> {
        if self.total().is_nan() || self.total() <= 0.0 {
            return None;
        }
        /// The largest number below 1, so that a rescaled number stays in `[0, 1)`.
        const BELOW_ONE: f32 = 1.0 - f32::EPSILON / 2.0;
        let (mut node, mut u) = (0usize, u);
        let (mut origin, mut size) = (Vec2::ZERO, 1.0f32);
        loop {
            let s = self.nodes[node].sums;
            // Left or right, by the columns' sums; then lower or upper inside the column.
            let left = s[0] + s[2];
            let left_share = left / (left + s[1] + s[3]);
            let right = u.x >= left_share;
            u.x = if right {
                (u.x - left_share) / (1.0 - left_share)
            } else {
                u.x / left_share
            };
            let column = usize::from(right);
            let lower_share = s[column] / (s[column] + s[column + 2]);
            let upper = u.y >= lower_share;
            u.y = if upper {
                (u.y - lower_share) / (1.0 - lower_share)
            } else {
                u.y / lower_share
            };
            u = u.clamp(Vec2::ZERO, Vec2::splat(BELOW_ONE));
            let q = column + 2 * usize::from(upper);
            size *= 0.5;
            origin += size * Vec2::new(f32::from(u8::from(right)), f32::from(u8::from(upper)));
            let child = self.nodes[node].children[q];
            if child == 0 {
                return Some(origin + u * size);
            }
            node = child as usize;
        }
    }
    // ANCHOR_END: sample
}

#[cfg(test)]
mod tests {
    use super::*;
    use ch02_monte_carlo::chi2::chi2_test_density;
    use ch02_monte_carlo::warps::{Domain, WarpPoint};

    /// A tree taught a lopsided distribution: most of its records in one small corner, the
    /// rest spread, rebuilt twice so that it has split where the records are.
    fn taught_tree() -> DirectionTree {
        let mut tree = DirectionTree::new();
        for _ in 0..3 {
            let mut next = tree.refined(SPLIT_FRACTION);
            let mut state = 7u32;
            let mut unit = || {
                state = state.wrapping_mul(747796405).wrapping_add(2891336453);
                (state >> 8) as f32 / (1u32 << 24) as f32
            };
            for i in 0..20_000 {
                let p = Vec2::new(unit(), unit());
                // Three records in four in the corner [0.6, 0.7) x [0.1, 0.15).
                let p = if i % 4 == 0 {
                    p
                } else {
                    Vec2::new(0.6 + 0.1 * p.x, 0.1 + 0.05 * p.y)
                };
                next.record(p, 1.0);
            }
            next.build(|sum, _| sum);
            tree = next;
        }
        tree
    }

    fn plane() -> Domain {
        Domain::Plane {
            min: Vec2::ZERO,
            max: Vec2::ONE,
        }
    }

    #[test]
    fn a_taught_tree_splits_where_its_records_are() {
        let tree = taught_tree();
        assert!(
            tree.nodes.len() > 8,
            "the tree split: {} nodes",
            tree.nodes.len()
        );
        let inside = tree.pdf(Vec2::new(0.65, 0.12));
        let outside = tree.pdf(Vec2::new(0.2, 0.8));
        // Three quarters of the records on 0.005 of the square, a quarter on the rest.
        assert!(
            inside > 50.0 && outside < 0.5,
            "pdf {inside} in the corner, {outside} away"
        );
    }

    #[test]
    fn exercise_quadtree_pdf_adds_up_to_one_over_the_square() {
        let tree = taught_tree();
        let n = 512;
        let mut integral = 0.0f64;
        for i in 0..n {
            for j in 0..n {
                let p = Vec2::new((i as f32 + 0.5) / n as f32, (j as f32 + 0.5) / n as f32);
                integral += f64::from(tree.pdf(p));
            }
        }
        integral /= (n * n) as f64;
        assert!(
            (integral - 1.0).abs() < 0.02,
            "pdf: the density integrates to {integral} over the unit square, not 1"
        );
        assert_eq!(DirectionTree::new().pdf(Vec2::splat(0.3)), 0.0);
    }

    #[test]
    fn exercise_quadtree_sample_draws_its_density() {
        let tree = taught_tree();
        let result = chi2_test_density(
            plane(),
            200_000,
            3,
            (64, 64),
            |u| WarpPoint::Plane(tree.sample(u).unwrap_or(Vec2::splat(f32::NAN))),
            |point| match point {
                WarpPoint::Plane(p) => tree.pdf(p),
                WarpPoint::Direction(_) => 0.0,
            },
        );
        assert!(
            result.p_value > 0.01,
            "sample: the points drawn do not follow the density pdf gives them: chi-square \
             {:.1} on {} degrees of freedom, p = {:.2e} ({} impossible samples)",
            result.statistic,
            result.dof,
            result.p_value,
            result.impossible_samples
        );
        assert_eq!(DirectionTree::new().sample(Vec2::splat(0.5)), None);
    }
}
